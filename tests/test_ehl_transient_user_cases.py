"""Transient cases as a user writes them: a measured areal map under a point contact, and a
warm-up the user shortened (docs/ehl-transient.md, "A measured map, a short warm-up")."""

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from asperity.cases import load_case
from asperity.cli import app

runner = CliRunner()
CORPUS = Path(__file__).parent / "corpus"

POINT = """
analysis = "ehl-transient"
title = "rough disc, elliptical contact"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[contact]
rx = "10 mm"
ry = "40 mm"
load = "40 N"
[speeds]
u = "1 m/s"
xi = 0.2
[lubricant]
eta0 = "20 mPa*s"
alpha = "20 1/GPa"
[grid]
nx = 49
ny = 17
[time]
warmup_steps = 5
counting_steps = 5
[surface2]
kind = "file"
path = "map.csv"
"""


def _write_map(path, width_um: float, length_um: float = 1200.0, h: float = 4.0):
    """An interferometer-style x, y, z export in um, its y from 0 as instruments write it;
    heights z = 0.1 um * sin(2 pi y / width) * cos(2 pi x / 200 um), so that a row's place
    across y is known."""
    x = np.arange(0.0, length_um + h / 2, h)
    y = np.arange(0.0, width_um + h / 2, h)
    X, Y = np.meshgrid(x, y, indexing="ij")
    z = 0.1 * np.sin(2 * np.pi * Y / width_um) * np.cos(2 * np.pi * X / 200.0)
    rows = np.column_stack([X.ravel(order="F"), Y.ravel(order="F"), z.ravel(order="F")])
    with open(path, "w") as f:
        f.write("X (um),Y (um),Z (um)\n")
        np.savetxt(f, rows, fmt="%.5f", delimiter=",")
    return y * 1e-6


def test_a_measured_map_is_centred_across_the_contact(tmp_path):
    """A map whose y runs from 0 (1.2 mm wide, the domain +-2b = 1.07 mm) is placed with its
    middle on the contact's centre line: before, the solver refused it after the steady start,
    naming its own argument ``roughness2``, since no map from y = 0 covers y < 0."""
    y_file = _write_map(tmp_path / "map.csv", 1200.0)
    (tmp_path / "case.toml").write_text(POINT)
    case = load_case(tmp_path / "case.toml")
    problem = case.problem()
    nx, ny, domain = case.mesh(problem)
    x, y = problem.grid(nx, ny, domain)
    dt = case.timestep(problem, x)
    warmup, counting = case.steps(problem, x, dt)
    _, built = case.surface_records(problem, x, y, warmup, warmup + counting, dt)
    surface = built.surface
    # centred: the map's middle at the domain's middle (y = 0), its spacing kept
    assert abs(0.5 * (surface.y[0] + surface.y[-1])) < 1e-12
    assert np.isclose(surface.y[-1] - surface.y[0], y_file[-1] - y_file[0], rtol=1e-12)
    # the map's row at a quarter of its width (sin = 1 there) now lies at y = -0.3 mm
    row = int(np.argmin(abs(surface.y + 0.3e-3)))
    assert abs(surface.y[row] + 0.3e-3) < 1e-9
    profile = surface.z[:, row] + np.mean(surface.z)  # the form removed (its mean plane)
    assert np.isclose(profile.max(), 0.1e-6, rtol=1e-3)


def test_a_map_narrower_than_the_domain_is_refused_naming_its_key(tmp_path):
    """0.6 mm across a domain of 1.07 mm: one line naming surface2.path, the width needed and
    grid.y_min/y_max, exit 2 (before: ``roughness2``, after the steady start)."""
    _write_map(tmp_path / "map.csv", 600.0)
    (tmp_path / "case.toml").write_text(POINT)
    result = runner.invoke(app, ["run", str(tmp_path / "case.toml"), "--out",
                                 str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: surface2.path: expected a map at "
                                                   "least 1.068 mm wide across y"), lines
    assert "map.csv is 0.6 mm wide" in lines[0] and "grid.y_min, grid.y_max" in lines[0]


def test_a_map_under_a_line_contact_is_refused_naming_its_key(tmp_path):
    """A line contact carries profiles; a map is refused in one line naming surface2.path
    (before: ``roughness2``, after the steady start)."""
    _write_map(tmp_path / "map.csv", 600.0)
    line = POINT.replace('rx = "10 mm"\nry = "40 mm"\nload = "40 N"',
                         'type = "line"\nradius = "10 mm"\nload_per_length = "200 kN/m"')
    (tmp_path / "case.toml").write_text(line.replace("ny = 17\n", ""))
    result = runner.invoke(app, ["run", str(tmp_path / "case.toml"), "--out",
                                 str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(
        "error: surface2.path: expected a profile (one trace along x) for a line contact"), lines


LINE = """
analysis = "ehl-transient"
title = "rough roller"
reduced_modulus = "227 GPa"
[contact]
type = "line"
radius = "10 mm"
load_per_length = "200 kN/m"
[speeds]
u = "2 m/s"
[lubricant]
eta0 = "0.02 Pa s"
alpha = "20 1/GPa"
[grid]
nx = 65
x_min = -2.5
x_max = 1.5
[time]
warmup_steps = {warmup}
counting_steps = {counting}
[surface1]
kind = "gaussian"
rms = "0.02 um"
correlation_length = "40 um"
"""


def _warnings(tmp_path, warmup, counting):
    case = tmp_path / f"w{warmup}.toml"
    case.write_text(LINE.format(warmup=warmup, counting=counting))
    out = tmp_path / f"out{warmup}"
    result = runner.invoke(app, ["run", str(case), "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    return json.loads((out / "summary.json").read_text())["warnings"]


def test_a_warm_up_too_short_for_the_roughness_warns(tmp_path):
    """The roughness enters at x = -2.5 a and moves u dx / (2 u) = dx / 2 per step (the seed's
    time step in rolling): on 65 nodes over 4 a, dx = a/16, it reaches x = +a after
    3.5 a / (a/32) = 112 steps and crosses the domain in 128. Warm-ups of 2 (never in the
    Hertz zone in 2 + 3 steps) and 100 steps warn with those numbers; 112 does not."""
    never = [w for w in _warnings(tmp_path, 2, 3) if w.startswith("surface1:")]
    assert len(never) == 1 and "never reaches the Hertz zone" in never[0], never
    assert "(the default, 128 steps" in never[0] and "set it >= 112" in never[0]
    assert "only to x = -2.34 a" in never[0]  # -2.5 a + 5 a/32
    partly = [w for w in _warnings(tmp_path, 100, 20) if w.startswith("surface1:")]
    assert len(partly) == 1 and "only to x = 0.625 a" in partly[0], partly  # -2.5 + 100/32
    assert "the first 12 of the 20 counting steps" in partly[0]
    assert not [w for w in _warnings(tmp_path, 112, 3) if w.startswith("surface1:")]


def test_a_feature_runs_snapshots_follow_it_through_the_hertz_zone():
    """The dent-rolling example on 65 x 17 nodes with its own counting period (the dent from
    the inlet until it has left): its 8 snapshots lie where the dent's centre, found as the
    deepest point of the recorded surface on y = 0, is between -a and +a (a = 106.8 um from
    a^3 = 3 F R / (4 E*)), the first at -a and the last at +a, each within a mesh spacing.
    Before, they were spread over the whole counting period, and the first (the dent not yet
    in the domain) and the last (it had left) showed the smooth contact."""
    import tomllib

    from asperity.examples import example_text
    from asperity.runners import run_case

    data = tomllib.loads(example_text("dent-rolling"))
    data["grid"].update(nx=65, ny=17)
    data["time"].pop("counting_steps")
    ds = run_case(load_case(data)).dataset
    a = (3 * 15.0 * 0.0125 / (4 * 210e9 / (2 * (1 - 0.3**2)))) ** (1 / 3)
    x = ds.x.values / a
    dx = x[1] - x[0]
    deepest = [x[int(np.argmin(z))] for z in ds["centre_surface1"].values]
    assert all(np.ptp(z) > 0 for z in ds["centre_surface1"].values)
    assert len(deepest) >= 8 and all(-1 - dx <= d <= 1 + dx for d in deepest), deepest
    assert deepest[0] == pytest.approx(-1.0, abs=dx) and \
        deepest[-1] == pytest.approx(1.0, abs=dx)


def test_a_map_coarser_than_the_rows_across_y_warns(tmp_path):
    """A measured map of isotropic random roughness (gaussian ACF, 0.2 at 25 um), sampled at
    the mesh's rows 66.8 um apart (17 rows over 4b): the asperities between rows are lost,
    which a generated topography was told and a map was not. The warning names surface2.path
    and the map's decay length across y, within 10 % of the one measured here from the
    written heights (numpy, the mean over x of z(y) z(y + lag))."""
    h, lc = 4.0, 25.0
    rng = np.random.default_rng(5)
    n = (300, 300)
    kx, ky = (2 * np.pi * np.fft.fftfreq(m, h) for m in n)
    ell = lc / np.sqrt(np.log(5.0))  # exp(-(r / ell)^2) = 0.2 at r = lc
    spectrum = np.exp(-(kx[:, None] ** 2 + ky[None, :] ** 2) * ell**2 / 8)
    z = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal(n)) * spectrum))
    z *= 0.2 / z.std()
    X, Y = np.meshgrid(np.arange(n[0]) * h, np.arange(n[1]) * h, indexing="ij")
    with open(tmp_path / "map.csv", "w") as f:
        f.write("X (um),Y (um),Z (um)\n")
        np.savetxt(f, np.column_stack([X.ravel(order="F"), Y.ravel(order="F"),
                                       z.ravel(order="F")]), fmt="%.5f", delimiter=",")
    r = z - z.mean()
    acf = np.array([np.mean(r[:, : n[1] - k] * r[:, k:]) for k in range(12)]) / np.mean(r * r)
    k = int(np.argmax(acf < 0.2))
    measured = h * (k - 1 + (acf[k - 1] - 0.2) / (acf[k - 1] - acf[k]))
    (tmp_path / "case.toml").write_text(POINT)
    result = runner.invoke(app, ["run", str(tmp_path / "case.toml"), "--out",
                                 str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 0, result.output
    warnings = json.loads((tmp_path / "out" / "summary.json").read_text())["warnings"]
    lines = [w for w in warnings if w.startswith("surface2.path: correlation_length_y")]
    assert len(lines) == 1 and "cells of 66.8 um across y" in lines[0], warnings
    said = float(lines[0].split("= ")[1].split(" um")[0])
    assert said == pytest.approx(measured, rel=0.1) and measured == pytest.approx(lc, rel=0.15)


def test_a_feature_amplitude_as_a_bare_number_is_refused(tmp_path):
    """``amplitude = 0.25`` for a dent of 15 um radius is read as 0.25 m: its flank slopes by
    pi 0.25 / (2 15e-6) = 2.62e4, far past the half-space's small slopes, and the run took it
    without a word; now one line naming surface1.amplitude with that slope, exit 2. A dent
    of 0.25 um (slope 0.026) loads."""
    text = (CORPUS / "error-transient-feature-amplitude-bare-number.toml").read_text()
    (tmp_path / "case.toml").write_text(text)
    result = runner.invoke(app, ["run", str(tmp_path / "case.toml"), "--out",
                                 str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    slope = np.pi * 0.25 / (2 * 15e-6)
    assert len(lines) == 1 and lines[0].startswith("error: surface1.amplitude: expected a "
                                                   "feature whose flank slopes"), lines
    assert f"slopes by {slope:.3g}" in lines[0] and '"0.25 um"' in lines[0]
    assert load_case(text.replace("amplitude = 0.25", 'amplitude = "0.25 um"'))
