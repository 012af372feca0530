"""The reference of case-file keys (asperity schema, docs/cases.md) and the terminal listings.

docs/cases.md is generated: when a case model changes, regenerate it with
``asperity schema --markdown > docs/cases.md``.
"""

import io
from pathlib import Path

import pytest
from rich.console import Console
from typer.testing import CliRunner

from asperity.cases import ANALYSES, load_case, parse_toml
from asperity.cases.keys import case_keys
from asperity.cli import app
from asperity.cli.app import show_examples
from asperity.cli.schema import markdown
from asperity.errors import InputError
from asperity.examples import example_text, list_examples, list_studies

DOCS = Path(__file__).resolve().parents[1] / "docs" / "cases.md"


def test_docs_cases_md_is_up_to_date():
    assert DOCS.read_text(encoding="utf-8") == markdown(), (
        "docs/cases.md is stale: asperity schema --markdown > docs/cases.md")


@pytest.mark.parametrize("analysis", list(ANALYSES))
def test_every_key_has_a_type_and_a_meaning(analysis):
    for key in case_keys(ANALYSES[analysis]):
        assert key.type and key.default, key
        assert key.meaning, f"{analysis}: {key.key} has no description (add a field docstring)"


@pytest.mark.parametrize(("analysis", "key", "unit", "default"), [
    ("normal", "body1.youngs_modulus", "Pa", "required"),
    ("normal", "loading.load", "N", "-"),
    ("normal", "grid.nx", "", "128"),
    ("ehl-steady", "lubricant.alpha", "1/Pa", "required"),
    ("ehl-steady", "lubricant.lambda", "1/Pa", None),           # the TOML spelling, not lambda_
    ("ehl-steady", "contact.load_per_length", "N/m", "-"),
    ("ehl-transient", "time.dt", "s", "-"),
    ("tangential", "loading.moment", "N*m", "0"),
    ("tangential", "pressure.regions[].size", "m", "-"),
    ("surface", "surface.natural_frequency", "Hz", "-"),
    ("gear", "operation.speed", "rad/s", "required"),             # plain numbers with a unit
    ("gear", "operation.bulk_temperature", "°C", "90"),
    ("gear", "thermal.conductivity", "W/(m*K)", "[45, 45]"),
])
def test_units_and_defaults_of_some_keys(analysis, key, unit, default):
    keys = {k.key: k for k in case_keys(ANALYSES[analysis])}
    assert keys[key].unit == unit
    if default is not None:
        assert keys[key].default == default


def test_every_key_of_every_example_is_in_the_reference():
    """The reference is complete: each key used by a built-in example is listed."""
    for example in list_examples():
        case = load_case(example_text(example.name))
        listed = {k.key for k in case_keys(type(case))}
        for key in _keys(case.model_dump(by_alias=True, exclude_none=True)):
            assert key in listed, f"{example.name}: {key}"


def _keys(data, prefix=""):
    for key, value in data.items():
        path = prefix + key
        yield path
        if isinstance(value, dict):
            yield from _keys(value, path + ".")
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for item in value:
                yield from _keys(item, path + "[].")


def test_schema_command_prints_one_analysis_and_refuses_unknown():
    runner = CliRunner()
    result = runner.invoke(app, ["schema", "normal"])
    assert result.exit_code == 0
    assert "body1.youngs_modulus" in result.output and "quantity in Pa" in result.output
    assert "ehl-steady" not in result.output
    bad = runner.invoke(app, ["schema", "nope"])
    assert bad.exit_code == 2


def test_ehl_grid_bounds_accept_lengths_as_well_as_semi_axes():
    data = parse_toml(example_text("holmes-smooth-point"))
    data.setdefault("grid", {})["x_min"] = -2.0                 # in Hertz semi-axes a
    case = load_case(data)
    prob = case.problem()
    a, b = prob.a, prob.b
    assert case.grid.domain(prob)[0][0] == pytest.approx(-2.0 * a, rel=1e-12)
    data["grid"]["x_min"] = f"{-2.0 * a * 1e3:.12g} mm"           # the same bound as a length
    data["grid"]["y_max"] = f"{2.5 * b * 1e6:.12g} um"
    (x0, _), (_, y1) = load_case(data).grid.domain(prob)
    assert x0 == pytest.approx(-2.0 * a, rel=1e-9)
    assert y1 == pytest.approx(2.5 * b, rel=1e-9)
    data["grid"]["x_min"] = f"{-0.5 * a * 1e3:.12g} mm"           # inside the contact
    with pytest.raises(InputError, match="grid.x_min"):
        load_case(data).grid.domain(prob)


def test_examples_listing_reads_in_80_columns():
    console = Console(width=80, record=True, color_system=None, file=io.StringIO())
    show_examples(console)
    lines = console.export_text().splitlines()
    assert max(len(line) for line in lines) <= 80
    for example in list_examples():   # every name whole on a line, never folded
        assert any(line.strip().startswith(example.name) for line in lines), example.name
    # prose wraps between words only: every word shown is a whole word of the listing
    words = set()
    for example in list_examples():
        words.update(f"{example.description or example.title} Source: {example.source}".split())
    words.update(w for _, d in list_studies() for w in d.split())
    shown = {w for line in lines if line.startswith(" " * 6) for w in line.split()}
    assert shown <= words, sorted(shown - words)[:5]


def test_schema_listing_reads_in_80_columns(monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    result = CliRunner().invoke(app, ["schema", "tangential"])
    lines = result.output.splitlines()
    assert max(len(line.rstrip()) for line in lines) <= 80
    assert any(line.startswith("reference.closed_form_rotation_per_body") for line in lines)
