"""The command line: the default run writes its files; bad input is one line and exit 2."""

import itertools
import json
import math
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from asperity.cli import app

runner = CliRunner()


def test_default_run_is_the_reduced_gear_case(tmp_path):
    """``asperity run`` with no case: the reduced mixed-EHL gear case (about a minute)."""
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    for name in ("result.nc", "summary.json", "report.html", "contact_count_rate.png",
                 "centre_line.png", "checkpoint.npz"):  # the files the README names
        assert (out / name).is_file(), name
    assert len(list(out.glob("*.png"))) == 4
    summary = json.loads((out / "summary.json").read_text())
    for key in ("contact_time_fraction", "max_pressure_pa", "minimum_film_thickness_m"):
        assert key in summary
    assert summary["converged"] is True
    assert 0.0 < summary["contact_time_fraction"] <= 1.0
    assert summary["minimum_film_thickness_m"] >= 0.0  # contact is h = 0, never below
    with xr.open_dataset(out / "result.nc") as ds:
        assert ds["contact_count_rate"].attrs["units"] == "1/ms"
        assert ds["contact_count_rate"].dims == ("x", "y")
        q = ds["contact_count_rate"].values
        X, Y = np.meshgrid(ds["x"].values, ds["y"].values, indexing="ij")
    # the seed's finding (Figs. 4-8): contact concentrates at the transverse edges of the Hertz
    # ellipse, downstream of the centre line
    a, b = summary["hertz_a_m"], 1.3045e-3
    r = np.hypot(X / a, Y / b)
    edge = (np.abs(Y) > 0.8 * b) & (r < 1.0)
    centre = (np.abs(Y) < 0.3 * b) & (r < 1.0)
    assert q[edge].mean() > 2.0 * q[centre].mean()
    assert q[edge & (X > 0)].sum() > q[edge & (X < 0)].sum()
    i, j = np.unravel_index(np.argmax(q), q.shape)
    assert X[i, j] > 0 and abs(Y[i, j]) > 0.7 * b
    assert "Table 2" in (out / "report.html").read_text()


def test_normal_run_writes_every_file(tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", "gear-dry-hertz", "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    for name in ("result.nc", "summary.json", "report.html", "pressure_map.png",
                 "centre_line.png"):
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    for key in ("max_pressure_pa", "contact_area_m2", "approach_m", "load_n", "converged"):
        assert key in summary
    assert summary["converged"] is True
    with xr.open_dataset(out / "result.nc") as ds:
        assert ds["pressure"].attrs["units"] == "Pa"
        assert ds["x"].attrs["units"] == "m"
        for name in ds.variables:
            assert "units" in ds[name].attrs and "long_name" in ds[name].attrs, name
    html = (out / "report.html").read_text()
    assert "data:image/png;base64," in html and "Hertz" in html


def test_examples_and_example(tmp_path):
    result = runner.invoke(app, ["examples"])
    assert result.exit_code == 0 and "gear-dry-hertz" in result.output
    result = runner.invoke(app, ["example", "gear-dry-hertz"])
    assert result.exit_code == 0 and 'analysis = "normal"' in result.output


HELP_SCREENS = [[], ["run"], ["examples"], ["example"], ["validate"], ["sweep"], ["schema"],
                ["gear"], ["surface"], ["surface", "stats"], ["surface", "generate"],
                ["surface", "plot"]]


@pytest.mark.parametrize("command", HELP_SCREENS, ids=lambda c: " ".join(c) or "asperity")
def test_help_text_is_filled_paragraphs(command):
    """Each help screen's text reads as filled paragraphs at 80 columns: no line of a paragraph
    (before the option boxes) stops short where the source's docstring broke its line."""
    result = runner.invoke(app, [*command, "--help"], env={"COLUMNS": "80"})
    assert result.exit_code == 0, result.output
    text = result.output.split("╭", 1)[0].split("Usage:", 1)[1].split("\n", 1)[1]
    lines = [ln.strip() for ln in text.splitlines()]
    for line, following in itertools.pairwise(lines):
        if line and following:  # within a paragraph: the next word would have fitted here
            assert len(line) + 1 + len(following.split()[0]) > 78, (line, following)
    if "Commands" in result.output:  # the list: each command's first line, in at most two
        rows = result.output.split("Commands", 1)[1].splitlines()[1:-1]
        starts = [n for n, row in enumerate(rows) if row[2:3].strip()]
        assert starts and max(np.diff([*starts, len(rows)])) <= 2, result.output


BAD_EDITS = [
    ('rx = "19.1 mm"', 'rx = "19.1 parsec per kg"', "geometry.rx"),
    ('load = "962 N"', 'load = "-962 N"', "loading.load"),
    ('load = "962 N"', 'lod = "962 N"', "loading"),
    ("nx = 128", "nx = nan", "grid.nx"),
    ('shape = "ellipsoid"', 'shape = "ellipsoid"\ncolour = "red"', "geometry.colour"),
]


def _edited_example(name, path, edits):
    """A built-in example with each ``(old, new)`` text edit made (every ``old`` must be in
    it), written to ``path``."""
    text = runner.invoke(app, ["example", name]).output
    for old, new in edits:
        assert old in text
        text = text.replace(old, new)
    path.write_text(text)
    return path


def _run_quietly(case, out, timeout):
    """``asperity run CASE --out OUT --quiet`` in a fresh process, as a user types it."""
    return subprocess.run([sys.executable, "-m", "asperity.cli", "run", str(case), "--out",
                           str(out), "--quiet"], capture_output=True, text=True,
                          timeout=timeout)


@pytest.mark.parametrize("old, new, field", BAD_EDITS)
def test_bad_case_file_exits_2_with_one_line(tmp_path, old, new, field):
    text = runner.invoke(app, ["example", "gear-dry-hertz"]).output
    assert old in text
    case = tmp_path / "bad.toml"
    case.write_text(text.replace(old, new))
    proc = _run_quietly(case, tmp_path / "o", timeout=120)
    assert proc.returncode == 2, proc.stderr
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}"), proc.stderr
    assert "Traceback" not in proc.stderr + proc.stdout




def test_unconverged_run_exits_3_saying_why_and_what_to_change(tmp_path):
    """The seed's smooth point contact given 3 sweeps does not converge: exit code 3 and one
    error line with the solver's own reason and the key to raise (it had said only "the solver
    did not converge; see report.html")."""
    case = _edited_example("holmes-smooth-point", tmp_path / "point.toml", (
        ("nx = 257", "nx = 81"), ("ny = 129", "ny = 65"),
        ("levels = 3 ", "levels = 1\nmax_sweeps = 3 ")))
    proc = _run_quietly(case, tmp_path / "o", timeout=300)
    assert proc.returncode == 3, proc.stderr
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("error:")]
    assert len(errors) == 1 and "Traceback" not in proc.stderr, proc.stderr
    assert "did not converge in" in errors[0] and "solver.max_sweeps (now 3)" in errors[0]
    # its cells are 4.6 dx across y, shorter than the relaxation needs on fine meshes
    assert "cells at least 6 dx across y" in errors[0]
    assert str(tmp_path / "o" / "report.html") in errors[0]


def test_missing_case_file_and_unknown_example():
    assert runner.invoke(app, ["run", "does-not-exist.toml"]).exit_code == 2
    result = runner.invoke(app, ["example", "nope"])
    assert result.exit_code == 2


def test_starved_inlet_is_one_warning_line(tmp_path):
    """An EHL domain starting inside the pressure build-up runs, with one ``warning:`` line."""
    case = _edited_example("holmes-smooth-point", tmp_path / "short.toml",
                           (("x_min = -2.5", "x_min = -1.1"), ("nx = 257", "nx = 105")))
    proc = _run_quietly(case, tmp_path / "o", timeout=300)
    assert proc.returncode == 0, proc.stderr
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(
        "warning: inlet: x_min = -1.1 a leaves pressure"), proc.stderr
    assert lines[0].endswith("use x_min <= -2.5 a")
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["warnings"] == [lines[0].removeprefix("warning: ")]
    assert "Converged." not in proc.stdout


def _turned(tmp_path, feed):
    case = tmp_path / f"turned_{feed}.toml"
    case.write_text(f'analysis = "surface"\n[surface]\nkind = "turned"\nfeed = "{feed} mm"\n'
                    'nose_radius = "0.4 mm"\nlength = "4 mm"\n')
    return runner.invoke(app, ["run", str(case), "--out", str(tmp_path / str(feed)), "--quiet"])


def test_turned_feed_up_to_twice_the_nose_radius(tmp_path):
    """f = 2 r = 0.8 mm runs (it ended "error: z: expected finite heights"), its Rt the arcs'
    r less the valley half a cell off the grid; at f = 0.79 mm eq. (4.1)'s f^2/(8 r) = 195 um
    is 42 % below the arcs' 337 um, which a warning says with both numbers."""
    import math

    result = _turned(tmp_path, 0.8)
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "0.8" / "summary.json").read_text())
    r, h = 0.4e-3, summary["spacing_m"]
    assert summary["rt_m"] == pytest.approx(math.sqrt(r * r - h * h / 4), rel=1e-9)
    assert summary["kinematic_rt_arc_m"] == pytest.approx(r, rel=1e-12)

    result = _turned(tmp_path, 0.79)
    assert result.exit_code == 0, result.output
    f = 0.79e-3
    arc = r - math.sqrt(r * r - f * f / 4)
    lines = [ln for ln in result.output.splitlines() if ln.startswith("warning: kinematic Rt")]
    assert len(lines) == 1, result.output
    assert f"= {f * f / (8 * r) * 1e6:.4g} um is 42.1 % below" in lines[0]
    assert f"r - sqrt(r^2 - f^2/4) = {arc * 1e6:.4g} um" in lines[0]
    summary = json.loads((tmp_path / "0.79" / "summary.json").read_text())
    assert summary["kinematic_rt_arc_m"] == pytest.approx(arc, rel=1e-12)
    assert summary["rt_m"] == pytest.approx(arc, rel=1e-4)
    result = _turned(tmp_path, 0.2)   # 1.6 % low: no warning
    assert result.exit_code == 0 and "warning: kinematic Rt" not in result.output


def _steps_of(model):
    """(nx, ny, steps) as the transient runner states them before its steady start."""
    import re

    from asperity.runners import ehl_transient

    said = []

    def progress(done, total=None, description=None):
        said.append(description)
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ehl_transient.run(model, progress=progress)
    steps, nx, ny = re.search(r"then (\d+) steps on (\d+) x (\d+) nodes", said[0]).groups()
    return int(nx), int(ny), int(steps)


def test_sweep_says_its_cases_and_time_before_it_starts_and_stops_in_one_line(tmp_path,
                                                                             monkeypatch):
    """Before it runs a study says how many cases and, for transient cases, their time on
    2 cores (nodes x steps x 2e-6 s); stopped, it says so in one line with the command that
    goes on, and no case is recorded as failed."""
    import asperity.sweep
    from asperity.cases import load_case
    from asperity.runners.ehl_transient import SECONDS_PER_NODE_STEP

    study = tmp_path / "study.toml"
    study.write_text('title = "t"\nbase = "holmes-rough-CC"\n[[axis]]\nname = "mesh"\n'
                     'keys = ["grid.nx", "grid.ny", "time.warmup_steps", "time.counting_steps"]\n'
                     'values = [[257, 65, 100, 1000], [513, 129, 100, 1000]]\n')
    spec = asperity.sweep.load_study(study)
    seconds = [math.prod(_steps_of(load_case(case))) * SECONDS_PER_NODE_STEP
               for _, case, _ in spec.cases]

    def stopped(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(asperity.sweep, "run_study", stopped)
    out = tmp_path / "out"
    result = runner.invoke(app, ["sweep", str(study), "--out", str(out), "--serial", "-q"])
    assert result.exit_code == 130, result.output
    lines = result.output.splitlines()
    assert lines[0] == (f"t: 2 cases (cross); estimated {sum(seconds) / 60:.2g} min on 2 cores "
                        f"in all (within a factor of 2; {max(seconds) / 60:.2g} min for the "
                        "longest case)")
    assert lines[-1] == (f"stopped: SIGINT with 0 of 2 cases finished (kept in {out}/cases); "
                         f"run the same command again to go on: asperity sweep {study} --out "
                         f"{out} --serial --quiet")
    assert "Traceback" not in result.output


def test_sweep_stopped_by_sigterm_says_so_in_one_line(tmp_path):
    """SIGTERM (a batch system's stop) printed no stop line; now the one line, exit 143."""
    import signal
    import time

    (tmp_path / "base.toml").write_text(
        'analysis = "normal"\n[body1]\nyoungs_modulus = "210 GPa"\n[body2]\n'
        'youngs_modulus = "210 GPa"\n[geometry]\nshape = "sphere"\nrx = "10 mm"\n[loading]\n'
        'load = "20 N"\n[grid]\nnx = 32\nny = 32\nx_extent = "0.5 mm"\ny_extent = "0.5 mm"\n')
    study = tmp_path / "study.toml"
    study.write_text('base = "base.toml"\n[[axis]]\nkey = "loading.load"\n'
                     'range = {start = 5, stop = 40, num = 200, unit = "N"}\n')
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "asperity.cli", "sweep", str(study), "--out",
                             str(out), "--serial", "--quiet"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while time.time() < deadline and len(list(out.glob("cases/*/status.json"))) < 2:
        time.sleep(0.02)
    assert proc.poll() is None, "the study ended before it could be stopped"
    proc.send_signal(signal.SIGTERM)
    _, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 128 + signal.SIGTERM, stderr
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("stopped: SIGTERM with "), stderr
    assert lines[0].endswith(f"run the same command again to go on: asperity sweep {study} "
                             f"--out {out} --serial --quiet")
    states = {json.loads(p.read_text())["state"] for p in out.glob("cases/*/status.json")}
    assert states == {"done"}


@pytest.mark.parametrize("args, line", [
    (["run", "case.toml", "--bogus"], "error: --bogus: no such option (Possible options: --out)"),
    (["example", "--nope"], "error: --nope: no such option"),
    (["example"], "error: name: missing (a value is required)"),
    (["surface", "generate", "--nope"], "error: --nope: no such option"),
    (["run", "case.toml", "--out"], "error: --out: requires an argument"),
    (["frob"], "error: command: no such command 'frob'"),
    (["--bogus"], "error: --bogus: no such option"),
])
def test_a_command_line_click_cannot_parse_is_one_error_line(args, line):
    """An unknown option or a missing argument was click's boxed error panel; it is one
    ``error:`` line like the other input errors, then at most a pointer to ``--help``."""
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    lines = [text for text in result.stderr.splitlines() if text.strip()]
    assert lines[0].startswith(line), result.stderr
    assert len(lines) <= 2 and all("--help" in text for text in lines[1:]), result.stderr
    assert "╭" not in result.stderr and "Usage:" not in result.stderr


def test_asperity_alone_still_prints_its_help():
    result = runner.invoke(app, [])
    assert "Usage" in result.output and "error:" not in result.output


def test_a_reference_beyond_its_tolerance_is_named_on_the_terminal(tmp_path):
    """A user's own reference 60 % above the solution was a "differs" row of report.html
    alone; the terminal now names it, and the run still exits 0 (a number that differs from
    a reference is a finding, not a failure)."""
    text = runner.invoke(app, ["example", "holmes-smooth-line"]).output
    text += ('\n[reference]\nsource = "my calculation"\ncentral_film = "1 um"\n'
             'tolerance = "5 %"\n')
    case = tmp_path / "line.toml"
    case.write_text(text)
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 0, result.output
    (line,) = [ln for ln in result.output.splitlines() if ln.startswith("differs:")]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    error = summary["central_film_thickness_m"] / 1e-6 - 1
    assert f"{100 * error:+.1f} %" in line and "(my calculation)" in line and "5 %" in line


def test_unit_doubts_are_said_before_the_solve_and_once(tmp_path):
    """A bare 210000 modulus (meant in MPa, read in Pa) was warned about only after the
    solve, 163 s into a bearing user's run; the doubt needs no solve. It comes before the
    summary, and is not repeated after it."""
    case = tmp_path / "c.toml"
    case.write_text('analysis = "normal"\n[body1]\nyoungs_modulus = 210000\n'
                    '[body2]\nyoungs_modulus = "210 GPa"\n[geometry]\nshape = "sphere"\n'
                    'rx = "10 mm"\n[loading]\nload = "1 N"\n[grid]\nnx = 32\nny = 32\n'
                    'x_extent = "0.4 mm"\ny_extent = "0.4 mm"\n')
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "o"), "-q"])
    text = result.output
    doubt = [line for line in text.splitlines() if line.startswith("warning: body1.youngs")]
    assert len(doubt) == 1, text
    assert text.index(doubt[0]) < text.index("wrote ")
