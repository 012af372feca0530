"""A measured roughness file in a contact case (``[roughness] kind = "file"``): levelled by
default, placed from its own start, refused when the grid is longer, reported when sampled more
coarsely than the grid, and keys that the kind does not use refused.

Expected numbers come from closed forms: a cosine over whole periods symmetric about the
trace's centre has zero mean and zero least-squares slope, so levelling a trace
``c + t x + A cos(...)`` leaves exactly the cosine; a plane levelled away leaves a smooth sphere,
which is Hertz's (a^3 = 3 F R / (4 E*), approach a^2 / R, p0 = 3 F / (2 pi a^2)); a sphere on a
plane of slope t keeps it and has its gap x^2 / (2 R) - t x least at x = t R.
"""

import math

import numpy as np
import pytest

from asperity import diagnostics
from asperity.cases import load_case
from asperity.cases.ehl_transient import MovingSurfaceSpec
from asperity.cases.roughness import RoughnessSpec, roughness_on_grid
from asperity.errors import InputError
from asperity.runners import run_case

H = 0.5e-6                 # sampling interval of the traces, m
N = 2000                   # points: 1 mm, 20 periods of 50 um
WAVELENGTH, AMPLITUDE = 50e-6, 0.2e-6
OFFSET, TILT = 12e-6, 5e-3  # an unlevelled scan: 12 um above the instrument's zero, 5 mrad
LOAD, RADIUS, E, NU = 20.0, 10e-3, 210e9, 0.3

SPHERE = """analysis = "normal"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[geometry]
shape = "sphere"
rx = "10 mm"
[loading]
load = "20 N"
[grid]
nx = 64
ny = 64
x_extent = "0.4 mm"
y_extent = "0.4 mm"
[roughness]
kind = "file"
path = "trace.csv"
"""


def _trace(tmp_path, z, start=0.0, spacing=H, name="trace.csv"):
    """A two-column CSV export, x in mm and z in um (units from the column names)."""
    x = start + spacing * np.arange(z.size)
    np.savetxt(tmp_path / name, np.c_[x * 1e3, z * 1e6], delimiter=",", header="x_mm,z_um",
               comments="", fmt="%.10g")
    return tmp_path / name


def _cosine(x):
    centre = 0.5 * (N - 1) * H
    return AMPLITUDE * np.cos(2 * np.pi * (x - centre) / WAVELENGTH)


def _grid(n=64, extent=0.4e-3):
    d = extent / n
    return -extent / 2 + d * (np.arange(n) + 0.5), d


def _run(tmp_path, text):
    case = tmp_path / "case.toml"
    case.write_text(text)
    return run_case(load_case(case))


def _hertz():
    e_star = E / (2 * (1 - NU**2))
    a = (3 * LOAD * RADIUS / (4 * e_star)) ** (1 / 3)
    return a, a**2 / RADIUS, 3 * LOAD / (2 * np.pi * a**2)


def test_a_trace_is_referred_to_its_mean_line(tmp_path):
    x = H * np.arange(N)
    path = _trace(tmp_path, OFFSET + TILT * x + _cosine(x))
    xg, d = _grid()
    rough = roughness_on_grid(RoughnessSpec(kind="file", path=str(path)), xg, xg[:3])
    # the grid's cell centres, from the trace's start at x = 0
    expected = _cosine(d * (np.arange(xg.size) + 0.5))
    np.testing.assert_allclose(rough.heights[:, 1], expected, rtol=0, atol=1e-4 * AMPLITUDE)
    note = next(n for n in rough.notes if "removed" in n)
    mean = OFFSET + TILT * 0.5 * (N - 1) * H   # the line's height at the centre: 14.5 um
    assert f"offset {mean * 1e6:.4g} um" in note and "tilt 5 mrad along x" in note
    assert rough.file_spacing == pytest.approx((H,))


def test_form_degree_zero_removes_the_mean_only(tmp_path):
    x = H * np.arange(N)
    path = _trace(tmp_path, OFFSET + TILT * x + _cosine(x))
    xg, d = _grid()
    spec = RoughnessSpec(kind="file", path=str(path), form_degree=0)
    rough = roughness_on_grid(spec, xg, xg[:3])
    xs = d * (np.arange(xg.size) + 0.5)
    centre = 0.5 * (N - 1) * H
    np.testing.assert_allclose(rough.heights[:, 0], TILT * (xs - centre) + _cosine(xs), rtol=0,
                               atol=1e-4 * AMPLITUDE)
    assert any("tilt of 5 mrad along x is kept" in n for n in rough.notes)


def test_heights_in_nm_declared_um_are_doubted(tmp_path):
    """A trace whose heights are in nm under a 'z_um' column: its rms slope (Rdq, forward
    differences) is 2 pi A / (sqrt(2) lambda) = 0.0178 as measured and 1000 times that as
    read, above the plausible 1 and (session 48) the 10 at which a contact case refuses the
    file. It says so and names roughness.z_unit, as ``asperity surface stats`` names
    --z-unit; the same trace in um is silent."""
    x = H * np.arange(N)
    nm = _trace(tmp_path, _cosine(x) * 1e3, name="trace.csv")  # nm values in a um column
    assert nm.exists()
    with pytest.raises(InputError) as info:
        _run(tmp_path, SPHERE)
    doubt = str(info.value)
    assert doubt.startswith("roughness.path (trace.csv): heights with an rms slope Rdq = ")
    assert 'roughness.z_unit = "nm"' in doubt and "--x-unit" not in doubt
    rdq = float(doubt.split("Rdq = ")[1].split()[0])
    assert rdq == pytest.approx(1e3 * 2 * np.pi * AMPLITUDE / (np.sqrt(2) * WAVELENGTH),
                                rel=0.01)
    _trace(tmp_path, _cosine(x), name="trace.csv")
    assert not any("Rdq: rms slope" in w for w in _run(tmp_path, SPHERE).warnings)


def test_absolute_positions_are_taken_from_the_start(tmp_path):
    """An export with x from 12.5 mm gives the heights of the same trace from 0."""
    x = H * np.arange(N)
    z = _cosine(x)
    xg, _ = _grid()
    at_zero = roughness_on_grid(RoughnessSpec(kind="file", path=str(_trace(tmp_path, z))),
                                xg, xg[:2])
    far = _trace(tmp_path, z, start=12.5e-3, name="far.csv")
    moved = roughness_on_grid(RoughnessSpec(kind="file", path=str(far)), xg, xg[:2])
    np.testing.assert_allclose(moved.heights, at_zero.heights, rtol=0, atol=1e-12)
    assert any("x = 12.5 mm lies at the grid's lower edge" in n for n in moved.notes)


def test_an_unlevelled_plane_leaves_a_hertz_contact(tmp_path):
    """Before levelling the 12 um offset made the approach -11.7 um (-1079 % of Hertz)."""
    x = H * np.arange(N)
    _trace(tmp_path, OFFSET + TILT * x)
    out = _run(tmp_path, SPHERE)
    a, approach, p0 = _hertz()   # 109 um, 1.19 um, 0.80 GPa
    assert out.summary["approach_m"] == pytest.approx(approach, rel=0.01)
    assert out.summary["max_pressure_pa"] == pytest.approx(p0, rel=0.02)
    assert any("mean line was removed" in n for n in out.notes)


def test_a_kept_tilt_moves_the_contact_to_t_r(tmp_path):
    x = H * np.arange(N)
    _trace(tmp_path, OFFSET + TILT * x)
    out = _run(tmp_path, SPHERE + "form_degree = 0\n")
    p = out.dataset["pressure"]
    centroid = float((p * p["x"]).sum() / p.sum())
    assert centroid == pytest.approx(TILT * RADIUS, abs=0.2 * 6.25e-6)   # 50 um


def test_a_grid_longer_than_the_file_is_refused_naming_both(tmp_path):
    _trace(tmp_path, _cosine(H * np.arange(600)))   # 0.3 mm, the grid 0.4 mm
    with pytest.raises(InputError) as err:
        _run(tmp_path, SPHERE)
    text = str(err.value)
    assert text.startswith("grid.x_extent: expected at most")
    assert "roughness.path (trace.csv)" in text
    assert "300 um long along x (600 points 0.5 um apart), the grid 400 um" in text
    assert "e-2" not in text   # no float noise (it was "[-6.03011e-21, 0.0002995] m")


def test_a_coarse_file_is_reported(tmp_path):
    """A trace every 40 um on 6.25 um cells: 6.4 times the grid's spacing; at most
    0.4 mm x 2 / 40 um = 20 cells would do."""
    _trace(tmp_path, _cosine(40e-6 * np.arange(30)), spacing=40e-6)
    out = _run(tmp_path, SPHERE)
    lines = [w for w in out.warnings if w.startswith("roughness.path:")]
    assert len(lines) == 1
    assert "40 um apart along x, 6.4 times the grid's dx = 6.25 um (limit 2)" in lines[0]
    assert "grid.nx <= 20" in lines[0] and "<= 12.5 um along x" in lines[0]


def test_coarse_file_limit_is_twice_the_grid_spacing():
    x, _ = _grid(128)                            # 3.125 um cells
    assert diagnostics.coarse_roughness_file("roughness", (6.25e-6,), x, x) == []
    assert diagnostics.coarse_roughness_file("roughness", (6.5e-6,), x, x)
    # a topography: each axis on its own (y cells of 1 um against 4 um points: 4 times)
    y = (np.arange(64) + 0.5) * 1e-6
    line, = diagnostics.coarse_roughness_file("roughness", (3e-6, 4e-6), x, y)
    assert "along y, 4 times" in line and "along x" not in line
    assert "grid.ny <= 32" in line            # 64 um x 2 / 4 um


def test_a_coarse_file_under_a_tangential_normal_solve_is_reported(tmp_path):
    _trace(tmp_path, _cosine(40e-6 * np.arange(30)), spacing=40e-6)
    text = ('analysis = "tangential"\nmu = 0.1\n[body1]\nyoungs_modulus = "210 GPa"\n'
            '[body2]\nyoungs_modulus = "210 GPa"\n[pressure]\nsource = "normal"\n'
            'load = "20 N"\nrx = "10 mm"\n[pressure.roughness]\nkind = "file"\n'
            'path = "trace.csv"\n[loading]\nforce = "0.5 N"\n[grid]\nnx = 32\nny = 32\n'
            'x_extent = "0.4 mm"\ny_extent = "0.4 mm"\n')
    out = _run(tmp_path, text)
    assert any(w.startswith("pressure.roughness.path: the file's points are 40 um apart")
               for w in out.warnings)
    assert any("pressure.roughness.path (trace.csv): its least-squares mean line" in n
               for n in out.notes)


@pytest.mark.parametrize("key, value", [("rms", '"0.2 um"'), ("seed", "3"),
                                        ("correlation_length", '"10 um"')])
def test_keys_a_file_does_not_use_are_refused(tmp_path, key, value):
    _trace(tmp_path, _cosine(H * np.arange(N)))
    case = tmp_path / "case.toml"
    case.write_text(SPHERE + f"{key} = {value}\n")
    with pytest.raises(InputError, match=rf'^roughness.{key}: expected no {key} for kind = '
                                         r'"file"'):
        load_case(case)


def test_keys_of_another_kind_are_refused():
    with pytest.raises(ValueError, match="seed"):
        RoughnessSpec(kind="builtin", profile="A", seed=2)
    with pytest.raises(ValueError, match="form_degree"):
        RoughnessSpec(kind="gaussian", rms=1e-7, correlation_length=1e-5, form_degree=0)


def test_spacing_is_refused_for_a_file_with_positions_and_used_without(tmp_path):
    _trace(tmp_path, _cosine(H * np.arange(N)))
    with pytest.raises(InputError, match=r"^roughness.spacing: expected no spacing for a file "
                                         r"that gives its own positions \(its points are 0.5 um"):
        _run(tmp_path, SPHERE + 'spacing = "2 um"\n')
    # heights alone: positions (i + 1/2) spacing, so a 2 um spacing stretches the cosine
    z = AMPLITUDE * np.cos(2 * np.pi * (np.arange(400) + 0.5) * 2e-6 / WAVELENGTH)
    np.savetxt(tmp_path / "heights.txt", z * 1e6)
    xg, d = _grid()
    spec = RoughnessSpec(kind="file", path=str(tmp_path / "heights.txt"), spacing=2e-6,
                         z_unit="um")
    got = roughness_on_grid(spec, xg, xg[:2]).heights[:, 0]
    expected = AMPLITUDE * np.cos(2 * np.pi * d * (np.arange(xg.size) + 0.5) / WAVELENGTH)
    np.testing.assert_allclose(got, expected, rtol=0, atol=2e-3 * AMPLITUDE)


def test_a_moving_surface_file_is_levelled_too(tmp_path):
    """The transient EHL case's [surface1] reads files the same way: the scan's offset would
    enter the inlet as a 12 um step."""
    x = H * np.arange(N)
    path = _trace(tmp_path, OFFSET + TILT * x + _cosine(x))
    surf = MovingSurfaceSpec(kind="file", path=str(path)).build(1e-3, H, np.zeros(1), 2e-6)
    np.testing.assert_allclose(surf.z, _cosine(surf.x), rtol=0, atol=1e-12)
    assert math.isclose(float(np.mean(surf.z)), 0.0, abs_tol=1e-15)


ROLLER = """analysis = "ehl-transient"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[contact]
type = "line"
radius = "4 mm"
load_per_length = "500 kN/m"
[speeds]
u = "5 m/s"
xi = 0.05
[lubricant]
eta0 = "0.02 Pa s"
alpha = "18 1/GPa"
[grid]
nx = 129
[time]
warmup_steps = 1
counting_steps = 2
[surface2]
kind = "file"
path = "trace.csv"
"""


def test_a_moving_surface_file_reports_its_units_and_doubts_them(tmp_path):
    """A bearing engineer's race trace in a transient line contact: the notes name the units
    read and the form removed; heights in nm under a 'z_um' column (Rdq 1000 times the
    cosine's 2 pi A / (sqrt(2) lambda) = 0.0178) are doubted first, naming surface2.path and
    z_unit (before, the run diverged at step 31 with advice on the inlet and the time step);
    since session 48 the file is refused (Rdq above 10)."""
    x = H * np.arange(N)
    _trace(tmp_path, OFFSET + TILT * x + _cosine(x))
    out = _run(tmp_path, ROLLER)
    named = [n for n in out.notes if n.startswith("surface2.path (trace.csv):")]
    assert any("heights in um" in n for n in named) and any("x in mm" in n for n in named)
    # the mean height removed: 12 um + 5 mrad times the trace's mid-point, 0.49975 mm
    assert any("offset 14.5 um" in n and "tilt 5 mrad" in n for n in named)
    assert not any("rms slope" in w for w in out.warnings)
    _trace(tmp_path, (OFFSET + TILT * x + _cosine(x)) * 1e3)
    with pytest.raises(InputError) as info:
        _run(tmp_path, ROLLER)
    first = str(info.value)
    assert first.startswith("surface2.path (trace.csv): heights with an rms slope Rdq = ")
    assert 'surface2.z_unit = "nm"' in first
    # of the levelled heights: the cosine's alone, the tilt removed with the mean line
    assert float(first.split("Rdq = ")[1].split()[0]) == pytest.approx(
        1e3 * 2 * np.pi * AMPLITUDE / (np.sqrt(2) * WAVELENGTH), rel=0.01)


def test_a_moving_surface_file_too_short_for_the_run_is_refused_naming_it(tmp_path):
    """The trace must feed the whole run from the inlet: 0.2 mm against the 0.816 mm the
    slower surface travels in 541 steps of 0.5 dx / u_1 (dx = 4 b / 128 on the default
    domain -2.5b..1.5b, b = 148.6 um; u_2 = 4.875 m/s)."""
    _trace(tmp_path, _cosine(H * np.arange(400)))
    with pytest.raises(InputError, match=r"surface2\.path: expected a trace at least "
                                         r"[0-9.]+ mm long along x.*trace\.csv is 0\.1995 mm.*"
                                         r"time\.counting_steps"):
        _run(tmp_path, ROLLER.replace("warmup_steps = 1", "warmup_steps = 600"))


def test_a_grid_coarser_than_the_file_is_reported_with_the_slope_it_loses(tmp_path):
    """The 0.5 um trace of a 50 um cosine on the sphere's 6.25 um cells: the grid keeps one
    point in 12.5, and the rms slope by forward differences falls by the sampling's factor
    sin(pi d / lambda) / (pi d / lambda) = 0.9745 (d = 6.25 um); the line gives both slopes
    and nx >= 800 (0.4 mm over 0.5 um), and a note says how the heights were sampled."""
    _trace(tmp_path, _cosine(H * np.arange(N)))
    out = _run(tmp_path, SPHERE)
    lines = [w for w in out.warnings if w.startswith("roughness.path: the grid is coarser")]
    assert len(lines) == 1 and "grid.nx >= 800" in lines[0]
    grid, given = (float(v) for v in lines[0].split("its rms slope is ")[1]
                   .split(" (")[0].split(" against the file's "))
    d = 0.4e-3 / 64  # (both slopes printed to 3 digits: their ratio to about 1 %)
    assert grid / given == pytest.approx(np.sin(np.pi * d / WAVELENGTH) / (np.pi * d / WAVELENGTH),
                                         abs=0.012)
    assert given == pytest.approx(2 * np.pi * AMPLITUDE / (np.sqrt(2) * WAVELENGTH), rel=0.01)
    assert any("sampled by cubic spline at the grid's cell centres (6.25 um apart)"
               " from the file's points (0.5 um apart)" in n for n in out.notes)
