"""``asperity example NAME`` prints (or writes) a built-in study as well as an example; the
one-line messages of a study's keys and of ``--scheduler`` name what they expected."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from asperity.cases import load_case, parse_toml
from asperity.cli import app
from asperity.errors import InputError
from asperity.examples import builtin_text, example_text

runner = CliRunner()


def _errors(output: str) -> list[str]:
    return [ln for ln in output.splitlines() if ln.startswith("error:")]


def test_example_prints_a_built_in_study():
    """``asperity examples`` listed holmes-smooth-xi as a study, and ``asperity example
    holmes-smooth-xi`` answered "no built-in example"."""
    result = runner.invoke(app, ["example", "holmes-smooth-xi"])
    assert result.exit_code == 0, result.output
    assert 'base = "holmes-smooth-point"' in result.output
    assert 'key = "speeds.xi"' in result.output
    assert "values = [0.1, 0.25, 0.5]" in result.output


def test_example_writes_a_built_in_study_that_sweeps_from_its_folder(tmp_path):
    from asperity.sweep import load_study

    result = runner.invoke(app, ["example", "holmes-smooth-xi", "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    written = tmp_path / "holmes-smooth-xi.toml"
    assert "".join(result.output.split()) == f"wrote{written}"  # as wrapped at 80 columns
    study = load_study(written)
    assert study.base == "holmes-smooth-point"
    assert [values for _, values in ((c, v["speeds__xi"]) for _, c, v in study.cases)] == [
        0.1, 0.25, 0.5]


def test_an_example_keeps_its_name_before_a_study():
    kind, text = builtin_text("holmes-smooth-point")
    assert kind == "example" and text == example_text("holmes-smooth-point")
    assert builtin_text("holmes-smooth-xi")[0] == "study"


def test_an_unknown_name_is_looked_for_among_examples_and_studies():
    result = runner.invoke(app, ["example", "holmes-smooth-x"])
    assert result.exit_code == 2
    assert _errors(result.output) == [
        "error: example: no built-in example or study 'holmes-smooth-x'; did you mean "
        "holmes-smooth-xi or holmes-smooth-line or holmes-smooth-point? (asperity examples "
        "lists them)"]
    line = _errors(runner.invoke(app, ["example", "nosuch"]).output)[0]
    assert line.startswith("error: example: expected an example (ball-on-disc-slow, ")
    assert "or a study (gear-torque-speed, " in line and line.endswith(", got 'nosuch'")


def test_the_examples_list_says_example_prints_a_study():
    text = " ".join(runner.invoke(app, ["examples"]).output.split())
    assert "parameter studies (asperity example NAME prints one, asperity sweep NAME runs it)" \
        in text


@pytest.mark.parametrize(("teeth", "got"), [("25", "25"), ("[30]", "[30]"),
                                             ("[25, 50, 75]", "[25, 50, 75]")])
def test_teeth_that_are_not_a_pair_say_a_pair_is_expected(teeth, got):
    """``gear.teeth`` swept with ``values = [25, 30]`` read "expected a valid tuple, got 25"."""
    text = example_text("gear-fzg-c").replace("teeth = [16, 24]", f"teeth = {teeth}")
    with pytest.raises(InputError) as info:
        load_case(text)
    assert str(info.value) == ("gear.teeth: expected a pair [pinion, wheel] of tooth counts "
                               f"such as [25, 50], got {got}")


def test_a_list_given_for_a_load_is_shown():
    """``values = [[10, 20], [30, 40]]`` on contact.load did not say what it got."""
    data = parse_toml(example_text("holmes-smooth-point"))
    data["contact"]["load"] = [10, 20]
    with pytest.raises(InputError) as info:
        load_case(data)
    assert str(info.value) == ("contact.load: expected a number or a string like '1.0 N', "
                               "got [10, 20]")


@pytest.mark.parametrize(("address", "detail"), [
    ("tcp://127.0.0.1:1", "[Errno 111] Connection refused"),
    ("nonsense", "missing port number in address 'nonsense'"),
])
def test_an_unreachable_scheduler_is_one_line_naming_the_option(tmp_path, address, detail):
    """It read "error: file: Timed out ... after 30 s". The failed client also stayed dask's
    scheduler, so that a later xarray write in the same process went to 'nonsense' (a test
    run's netCDF write failed so), and waited a minute at exit for its own close; the address
    is now checked before a client is made."""
    import dask
    import distributed  # noqa: F401 - its defaults in dask's config before it is set below

    study = tmp_path / "study.toml"
    study.write_text('title = "t"\nbase = "holmes-smooth-point"\n[[axis]]\n'
                     'key = "speeds.xi"\nvalues = [0.1, 0.25]\n')
    with dask.config.set({"distributed.comm.timeouts.connect": "1s"}):
        result = runner.invoke(app, ["sweep", str(study), "--out", str(tmp_path / "out"),
                                     "--scheduler", address, "-q"])
    assert result.exit_code == 2, result.output
    assert _errors(result.output) == [
        f"error: --scheduler: could not connect to a Dask scheduler at {address} ({detail}); "
        "give the address of a running one (tcp://HOST:8786) or leave --scheduler out for a "
        "local cluster"]
    assert not (tmp_path / "out" / "cases").exists()
    assert dask.config.get("scheduler", None) is None
