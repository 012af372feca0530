"""Bad and borderline inputs, each with the outcome a user must see (issue 15).

``tests/corpus/*.toml`` are case files whose first line states the expected outcome::

    # expect: 2 error loading.load        one line "error: loading.load: ...", exit 2
    # expect: 0 warning domain mesh       a run whose warnings are exactly these kinds
    # expect: 3 warning steps surface1    the same, with exit code 3 (not converged)
    # expect: 0 ok                        a correct run: no warning, "Converged."

(the UTF-16 file states it in UTF-16). The command lines below are the rest of the corpus, and
Hypothesis varies case files and ``surface generate`` options: whatever it draws, the answer is
a run, or one ``error:`` line and exit code 2, never a traceback.
"""

import json
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import xarray as xr
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from asperity.cli import app

CORPUS = Path(__file__).parent / "corpus"
FILES = sorted(p for p in CORPUS.glob("*.toml") if p.name != "transient-line-long.toml")
runner = CliRunner()


def _expectation(path: Path):
    data = path.read_bytes()
    text = data.decode("utf-16") if data[:2] in (b"\xff\xfe", b"\xfe\xff") else data.decode(
        "utf-8", "replace")
    words = text.splitlines()[0].removeprefix("# expect:").split()
    return int(words[0]), words[1], words[2:]


def _lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.strip()]


def _no_traceback(result):
    assert result.exception is None or isinstance(result.exception, SystemExit), (
        repr(result.exception))
    assert "Traceback" not in result.output


def _one_error_line(result, field=None):
    lines = _lines(result.stderr)
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    if field is not None:
        assert lines[0].startswith(f"error: {field}"), lines[0]
    return lines[0]


def test_the_corpus_is_large_and_covers_every_outcome():
    kinds = [_expectation(p)[1] for p in FILES]
    assert len(FILES) + len(COMMANDS) >= 40
    assert {"error", "warning", "ok"} <= set(kinds)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_case_file(path, tmp_path):
    code, kind, names = _expectation(path)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "--quiet"])
    _no_traceback(result)
    assert result.exit_code == code, result.output
    if kind == "error":
        _one_error_line(result, None if names == ["*"] else names[0])
        return
    warnings = [line.removeprefix("warning: ") for line in _lines(result.stderr)
                if line.startswith("warning: ")]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "complete" and summary["warnings"] == warnings
    with xr.open_dataset(out / "result.nc") as ds:
        assert ds.attrs["status"] == "complete"
    report = (out / "report.html").read_text()
    if kind == "ok":
        assert warnings == [] and "Converged." in result.stdout
        assert "class='note ok'>Converged.</p>" in report and "class=warn" not in report
        return
    assert sorted({w.split(":")[0] for w in warnings}) == sorted(names), warnings
    for line in warnings:  # the quantity, its value, the limit, what to change
        assert "limit" in line and re.search(r"\d", line), line
    assert "class=warn" in report and "Converged." not in report
    assert "Converged." not in result.stdout


def _case(name: str) -> str:
    return str(CORPUS / f"{name}.toml")


def _generate(*options):
    return ["surface", "generate", "gaussian", "--rms", "1 um", "--correlation-length",
            "10 um", *options]


#: (id, argv with {tmp} for the test's folder, exit code, start of the one error line or None)
COMMANDS = [
    ("validate-no-such-check", ["validate", "-k", "NOSUCH"], 2, "error: --select"),
    ("out-is-a-file", ["run", _case("ok-sphere"), "--out", "{tmp}/file"], 2, "error: --out"),
    ("out-unwritable", ["run", _case("ok-sphere"), "--out", "/proc/asperity/out"], 2,
     "error: --out"),
    ("out-under-a-file", ["run", _case("ok-sphere"), "--out", "{tmp}/file/out"], 2,
     "error: --out"),
    ("case-missing", ["run", "{tmp}/missing.toml", "--out", "{tmp}/o"], 2, "error: case"),
    ("case-too-large", ["run", "{tmp}/huge.toml", "--out", "{tmp}/o"], 2, "error: case"),
    ("case-is-a-folder", ["run", "{tmp}/folder.toml", "--out", "{tmp}/o"], 2, "error: case"),
    ("example-unknown", ["run", "no-such-example", "--out", "{tmp}/o"], 2, "error: "),
    ("print-unknown-example", ["example", "no-such-example"], 2, "error: "),
    ("strict-with-warnings", ["run", _case("warn-coarse-mesh"), "--out", "{tmp}/o", "-q",
                              "--strict"], 3, None),
    ("strict-without-warnings", ["run", _case("ok-sphere"), "--out", "{tmp}/o", "-q",
                                 "--strict"], 0, None),
    ("generate-parsec", _generate("--out", "{tmp}/s.npy", "--length", "5 parsec"), 2,
     "error: --length"),
    ("generate-too-large", _generate("--out", "{tmp}/s.npy", "--length", "5 m", "--width",
                                     "5 m"), 2, "error: --length, --width"),
    ("generate-length-in-kg", _generate("--out", "{tmp}/s.npy", "--length", "5 kg"), 2,
     "error: --length"),
    ("generate-zero-spacing", _generate("--out", "{tmp}/s.npy", "--spacing", "0 um"), 2,
     "error: --spacing"),
    ("generate-one-point", _generate("--out", "{tmp}/s.npy", "--spacing", "1 mm"), 2,
     "error: --length"),
    # 10 um on a 0.1 um profile: exp(-(q beta)^2 / 4) underflows at every wavevector (was NaN)
    ("generate-correlation-longer-than-surface",
     _generate("--out", "{tmp}/s.npy", "--length", "0.1 um", "--spacing", "0.01 um"), 2,
     "error: --correlation-length"),
    ("generate-cutoff-longer-than-surface",
     ["surface", "generate", "self-affine", "--rms", "1 um", "--cutoff", "2 mm", "--rolloff",
      "3 mm", "--out", "{tmp}/s.npy"], 2, "error: --cutoff"),
    ("generate-unknown-kind", ["surface", "generate", "fractal", "--out", "{tmp}/s.npy"], 2,
     "error: KIND"),
    ("generate-unwritable", _generate("--out", "/proc/asperity/s.npy"), 2, "error: "),
    ("stats-missing-file", ["surface", "stats", "{tmp}/missing.txt"], 2, "error: "),
]


@pytest.mark.parametrize("argv, code, start", [c[1:] for c in COMMANDS],
                         ids=[c[0] for c in COMMANDS])
def test_command_line(argv, code, start, tmp_path):
    (tmp_path / "file").write_text("not a folder\n")
    (tmp_path / "folder.toml").mkdir()
    if any("huge.toml" in a for a in argv):
        (tmp_path / "huge.toml").write_text("# padding\n" * 500_000)  # 5 MB of comments
    result = runner.invoke(app, [a.replace("{tmp}", str(tmp_path)) for a in argv])
    _no_traceback(result)
    assert result.exit_code == code, result.output
    if start is not None:
        assert _one_error_line(result).startswith(start)
    if argv[-1] == "--strict" and code == 3:
        lines = _lines(result.stderr)
        assert lines[0].startswith("warning: mesh:") and lines[-1].startswith("error: 1 warning")


# ------------------------------------------------------------------------------- Hypothesis
BASE = (CORPUS / "ok-sphere.toml").read_text()
#: line of the base case -> key it holds
KEYS = {'load = "50 N"': "load", "nx = 48": "nx", "ny = 48": "ny",
        'x_extent = "0.6 mm"': "x_extent", 'rx = "10 mm"': "rx",
        'youngs_modulus = "210 GPa"': "youngs_modulus", "poisson_ratio = 0.3": "poisson_ratio"}
UNITS = ["", "N", "kN", "kg", "mm", "um", "m", "parsec", "GPa", "psi", "lbf", "m/s", "furlong",
         "1/GPa", "deg"]
NUMBERS = st.one_of(st.floats(allow_nan=True, allow_infinity=True, width=32),
                    st.sampled_from([0.0, -1.0, 1e-30, 1e30, 0.3, 50.0, 0.6]))


def _toml_value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return {"nan": "nan", "inf": "inf", "-inf": "-inf"}.get(repr(value), repr(value))
    if isinstance(value, int):
        return str(value)
    return json.dumps(value)


VALUES = st.one_of(
    st.builds(lambda x, u: f"{x!r} {u}".strip(), NUMBERS, st.sampled_from(UNITS)),
    NUMBERS,
    st.integers(min_value=-10, max_value=64),
    st.sampled_from([10**9, True, "", "many", "50 N N", "1e400 mm"]),
    st.text(max_size=12),
)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(line=st.sampled_from(sorted(KEYS)), value=VALUES)
def test_hypothesis_case_files(tmp_path, line, value):
    """One key of a good case set to a drawn value: a run (warnings allowed) or one line."""
    text = BASE.replace(line, f"{KEYS[line]} = {_toml_value(value)}")
    case = tmp_path / "drawn.toml"
    case.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "o"), "--quiet",
                                 "--strict"])
    _no_traceback(result)
    assert result.exit_code in (0, 2, 3), result.output
    if result.exit_code == 2:
        _one_error_line(result)
    else:
        lines = _lines(result.stderr)
        assert all(ln.startswith("warning: ") for ln in lines[:-1]), lines
        assert (result.exit_code == 0) == (lines == []), lines


LENGTHS = st.builds(lambda x, u: f"{x!r} {u}".strip(), NUMBERS,
                    st.sampled_from(["", "mm", "um", "nm", "m", "km", "parsec", "kg", "s"]))


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(length=LENGTHS, spacing=LENGTHS, width=st.one_of(st.none(), LENGTHS))
def test_hypothesis_surface_generate(tmp_path, length, spacing, width):
    """Drawn sizes for ``surface generate``: a surface of at most MAX_POINTS, or one line."""
    argv = _generate("--out", str(tmp_path / "s.npy"), "--length", length, "--spacing", spacing)
    if width is not None:
        argv += ["--width", width]
    result = runner.invoke(app, argv)
    _no_traceback(result)
    assert result.exit_code in (0, 2), result.output
    if result.exit_code == 2:
        assert _one_error_line(result).startswith(("error: --length", "error: --spacing",
                                                   "error: --width", "error: --rms",
                                                   "error: --correlation-length"))


# ------------------------------------------------------------------------------ interrupts
def _wait_for_partial(out: Path, proc, timeout: float = 240.0) -> None:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        assert proc.poll() is None, proc.communicate()
        try:
            with xr.open_dataset(out / "result.nc") as ds:
                if ds.attrs.get("status") == "partial" and ds.attrs.get("steps_done", 0) >= 5:
                    return
        except (OSError, ValueError):
            pass
        time.sleep(0.5)
    pytest.fail("no partial result.nc appeared")


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_interrupted_run_says_where_and_how_to_continue(tmp_path, sig):
    """A signal during a transient run: one line (where, the folder, the command to go on),
    status "partial" in result.nc and summary.json; the printed command resumes the run."""
    case, out = CORPUS / "transient-line-long.toml", tmp_path / "out"
    command = [sys.executable, "-m", "asperity.cli", "run", str(case), "--out", str(out), "-q"]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _wait_for_partial(out, proc)
    proc.send_signal(sig)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode == 128 + sig, stderr
    lines = _lines(stderr)
    assert len(lines) == 1 and "Traceback" not in stdout + stderr, stderr
    line = lines[0]
    assert re.match(rf"stopped: {signal.Signals(sig).name} at (warm-up|counting): step \d+/\d+",
                    line), line
    assert f"are in {out}/" in line
    resume = line.split("continue with: ")[1]
    assert resume == f"asperity run {case} --out {out} --quiet --resume"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "partial" and summary["continue_with"] == resume
    with xr.open_dataset(out / "result.nc") as ds:
        assert ds.attrs["status"] == "partial"
        assert ds.attrs["steps_done"] == summary["steps_done"] >= 5
    if sig == signal.SIGTERM:
        return
    # the printed command goes on from the checkpoint (stopped again once it has moved on)
    first = summary["steps_done"]
    proc = subprocess.Popen([sys.executable, "-m", "asperity.cli", *resume.split()[1:]],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    end = time.monotonic() + 240
    while time.monotonic() < end:
        assert proc.poll() is None, proc.communicate()
        try:
            with xr.open_dataset(out / "result.nc") as ds:
                if ds.attrs["steps_done"] > first:
                    break
        except (OSError, ValueError):
            pass
        time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=60)
    assert json.loads((out / "summary.json").read_text())["steps_done"] > first


def test_sphere_on_an_absurdly_large_grid_is_reported_not_crashed(tmp_path):
    """Hypothesis found it: x_extent = 4.2e16 (metres) for a 10 mm sphere under 50 N. Every
    cell is 1e15 m wide, the Hertz contact 0.3 mm: the load-controlled solve lost all its
    pressure (a ZeroDivisionError in the load scaling, then the Hertz comparison of a zero
    load as an input error). Now: not converged (exit 3) and a mesh warning naming both
    sizes."""
    text = BASE.replace('x_extent = "0.6 mm"', "x_extent = 4.207052321927987e+16")
    case = tmp_path / "huge.toml"
    case.write_text(text, encoding="utf-8")
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "o"), "--quiet"])
    _no_traceback(result)
    assert result.exit_code == 3, result.output
    assert "mesh: no cell is in contact" in result.output
    assert "did not converge" in result.output
