"""The command line: the default run writes its files; bad input is one line and exit 2."""

import json
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
                 "centre_line.png"):
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    for key in ("contact_time_fraction", "max_pressure_pa", "minimum_film_thickness_m"):
        assert key in summary
    assert summary["converged"] is True
    assert 0.0 < summary["contact_time_fraction"] <= 1.0
    assert summary["minimum_film_thickness_m"] >= 0.0  # contact is h = 0, never below
    with xr.open_dataset(out / "result.nc") as ds:
        assert ds["contact_count_rate"].attrs["units"] == "ms-1"
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


BAD_EDITS = [
    ('rx = "19.1 mm"', 'rx = "19.1 parsec per kg"', "geometry.rx"),
    ('load = "962 N"', 'load = "-962 N"', "loading.load"),
    ('load = "962 N"', 'lod = "962 N"', "loading"),
    ("nx = 128", "nx = nan", "grid.nx"),
    ('shape = "ellipsoid"', 'shape = "ellipsoid"\ncolour = "red"', "geometry.colour"),
]


@pytest.mark.parametrize("old, new, field", BAD_EDITS)
def test_bad_case_file_exits_2_with_one_line(tmp_path, old, new, field):
    text = runner.invoke(app, ["example", "gear-dry-hertz"]).output
    assert old in text
    case = tmp_path / "bad.toml"
    case.write_text(text.replace(old, new))
    proc = subprocess.run([sys.executable, "-m", "asperity.cli", "run", str(case), "--out",
                           str(tmp_path / "o"), "--quiet"], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 2, proc.stderr
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}"), proc.stderr
    assert "Traceback" not in proc.stderr + proc.stdout


def test_missing_case_file_and_unknown_example():
    assert runner.invoke(app, ["run", "does-not-exist.toml"]).exit_code == 2
    result = runner.invoke(app, ["example", "nope"])
    assert result.exit_code == 2


def test_starved_inlet_is_one_warning_line(tmp_path):
    """An EHL domain starting inside the pressure build-up runs, with one ``warning:`` line."""
    text = runner.invoke(app, ["example", "holmes-smooth-point"]).output
    for old, new in (("x_min = -2.5", "x_min = -1.1"), ("nx = 257", "nx = 105")):
        assert old in text
        text = text.replace(old, new)
    case = tmp_path / "short.toml"
    case.write_text(text)
    proc = subprocess.run([sys.executable, "-m", "asperity.cli", "run", str(case), "--out",
                           str(tmp_path / "o"), "--quiet"], capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(
        "warning: inlet: x_min = -1.1 a leaves pressure"), proc.stderr
    assert lines[0].endswith("use x_min <= -2.5 a")
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["warnings"] == [lines[0].removeprefix("warning: ")]
    assert "Converged." not in proc.stdout
