"""The Python API: one result protocol for every solver, renamed keywords, surface objects as
input, the ellipsoid gap, examples by name, Outcome.write."""

import json
import math
import warnings

import numpy as np
import pytest

from asperity.cases import load_case
from asperity.contact import (
    ellipsoid_gap,
    proportional_path,
    solve_normal,
    solve_tangential,
    surface_gap,
    tangential_load_path,
)
from asperity.ehl import LineContact, Lubricant, solve_steady, solve_transient
from asperity.errors import InputError
from asperity.materials import Material
from asperity.runners import run_case
from asperity.surfaces import Profile, Topography, cell_centres

STEEL = Material(210e9, 0.3)
E_STAR = 210e9 / (2 * (1 - 0.3**2))  # two steel bodies


def _protocol(result, iterations_field):
    assert isinstance(result.converged, bool) and result.converged
    assert result.iterations == getattr(result, iterations_field) > 0
    assert math.isfinite(result.residual)
    assert "converged" in result.message and str(result.iterations) in result.message
    assert result.warnings == ()
    text = repr(result)
    assert len(text) < 600 and "array(" not in text and text.startswith(
        f"<{type(result).__name__} ")


def _dataset(result, names):
    ds = result.to_dataset()
    for name in ("x", "y"):
        assert ds[name].attrs["units"] == "m" and ds[name].attrs["long_name"]
    for name in names:
        assert {"units", "long_name"} <= set(ds[name].attrs), name
        assert ds[name].dims[-2:] == ("x", "y") or ds[name].dims[-1] in ("step", "x", "film_bin")
    assert ds.attrs["converged"] == 1
    return ds


def _sphere(n=48):
    """A sphere R = 10 mm on a flat under 100 N: Hertz a = (3 P R / 4 E*)^(1/3)."""
    a = (3 * 100.0 * 0.01 / (4 * E_STAR)) ** (1 / 3)
    x = (np.arange(n) + 0.5 - n / 2) * (3 * a / n)
    return a, x


def test_normal_result_protocol_and_dataset_like_the_command_line():
    a, x = _sphere()
    res = solve_normal(ellipsoid_gap(0.01, 0.01, x, x), x, x, STEEL, STEEL, load=100.0)
    _protocol(res, "iterations")
    ds = _dataset(res, ["pressure", "gap", "displacement", "contact"])
    # the names, units and long names asperity run writes for analysis = "normal"
    cli = run_case(load_case("gear-dry-hertz")).dataset
    for name in ("pressure", "gap", "contact"):
        assert ds[name].attrs["units"] == cli[name].attrs["units"]
        assert ds[name].attrs["long_name"] == cli[name].attrs["long_name"]
    # Hertz: p0 = 3 P / (2 pi a^2) (Johnson eq. 4.14) from the ellipsoid gap
    assert float(ds["pressure"].max()) == pytest.approx(3 * 100.0 / (2 * math.pi * a**2),
                                                        rel=0.02)


def test_tangential_result_protocol():
    a, x = _sphere(32)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p0 = 3 * 100.0 / (2 * math.pi * a**2)
    p = p0 * np.sqrt(np.clip(1 - (X**2 + Y**2) / a**2, 0, None))
    res = solve_tangential(p, x, x, 0.3, STEEL, STEEL, force=(10.0, 0.0))
    _protocol(res, "iterations")
    ds = _dataset(res, ["traction_x", "traction_y", "stick", "slip_x", "region"])
    np.testing.assert_array_equal(ds["region"], res.labels)
    # the traction carries the applied force
    cell = (x[1] - x[0]) ** 2
    assert float(ds["traction_x"].sum()) * cell == pytest.approx(10.0, rel=1e-6)
    assert ds["traction_x"].attrs["units"] == "Pa"


def test_ehl_steady_result_protocol_and_starved_inlet_warning():
    body = Material(2e11, 0.3)
    lub = Lubricant(0.04, 2e-8, viscosity_model="barus", compressible=False)
    prob = LineContact(0.01, 2e5, 1.0, 1.0, body, body, lub)
    res = solve_steady(prob, nx=129, max_iter=40000)
    _protocol(res, "sweeps")
    ds = res.to_dataset()
    assert ds["pressure"].attrs == {"units": "Pa", "long_name": "film pressure"}
    assert ds["film"].dims == ("x", "y")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        starved = solve_steady(prob, nx=65, max_iter=2000,
                               domain=((-1.05 * prob.a, 1.5 * prob.a), (0.0, 0.0)))
    assert any("inlet" in w for w in starved.warnings)


def test_ehl_transient_result_protocol():
    from asperity.ehl import PointContact

    body = Material(2e11, 0.3)
    lub = Lubricant(0.04, 2e-8, viscosity_model="barus", compressible=False)
    prob = PointContact(0.01, 0.01, 50.0, 1.0, 1.0, body, body, lub)
    res = solve_transient(prob, nx=33, ny=17, counting_steps=3, warmup_steps=0)
    assert res.converged and res.iterations == int(np.sum(res.sweeps))
    assert "converged" in res.message and len(repr(res)) < 800 and "array(" not in repr(res)
    ds = _dataset(res, ["pressure", "film", "contact_count", "max_pressure", "film_counts",
                        "centre_film"])
    assert ds["step"].size == res.steps and ds["max_pressure"].dims == ("step",)
    assert ds["centre_film"].dims == ("snapshot", "x")
    assert ds["contact_count_rate"].attrs["units"] == "1/ms"


def test_not_converged_says_so():
    a, x = _sphere()
    res = solve_normal(ellipsoid_gap(0.01, 0.01, x, x), x, x, STEEL, STEEL, load=100.0,
                       max_iter=2)
    assert not res.converged and "did not converge" in res.message
    assert len(res.warnings) == 1 and "2 iterations" in res.warnings[0]
    assert res.to_dataset().attrs["converged"] == 0


def test_old_spellings_warn_and_still_work():
    a, x = _sphere(24)
    gap = ellipsoid_gap(0.01, 0.01, x, x)
    with pytest.warns(DeprecationWarning, match="max_iterations.*max_iter"):
        old = solve_normal(gap, x, x, STEEL, STEEL, load=100.0, max_iterations=3)
    new = solve_normal(gap, x, x, STEEL, STEEL, load=100.0, max_iter=3)
    np.testing.assert_array_equal(old.pressure, new.pressure)
    with pytest.raises(TypeError, match="both"):
        solve_normal(gap, x, x, STEEL, STEEL, load=100.0, max_iter=3, max_iterations=3)
    p = np.where(new.pressure > 0, new.pressure, 0.0)
    with pytest.warns(DeprecationWarning, match="'center' is deprecated"):
        old = solve_tangential(p, x, x, 0.3, STEEL, STEEL, moment=1e-3, center=(0.0, 0.0))
    new = solve_tangential(p, x, x, 0.3, STEEL, STEEL, moment=1e-3, centre=(0.0, 0.0))
    assert old.rotation == new.rotation


def test_old_result_field_names_warn_and_read_the_new_fields():
    a, x = _sphere(24)
    p = solve_normal(ellipsoid_gap(0.01, 0.01, x, x), x, x, STEEL, STEEL, load=100.0).pressure
    res = solve_tangential(p, x, x, 0.3, STEEL, STEEL, force=(5.0, 0.0), moment=1e-3,
                           centre=(0.2 * a, 0.0))
    assert np.all(np.isfinite(res.centre_of_rotation))
    with pytest.warns(DeprecationWarning, match="TangentialResult.center is deprecated"):
        np.testing.assert_array_equal(res.center, res.centre)
    np.testing.assert_array_equal(res.centre, [0.2 * a, 0.0])
    with pytest.warns(DeprecationWarning, match="center_of_rotation is deprecated"):
        np.testing.assert_array_equal(res.center_of_rotation, res.centre_of_rotation)
    with pytest.raises(AttributeError):
        res.center = (0.0, 0.0)
    path = tangential_load_path(p, x, x, 0.3, STEEL, STEEL,
                                proportional_path(moment=1e-3, steps=2))
    with pytest.warns(DeprecationWarning, match="LoadPathResult.center_of_rotation"):
        np.testing.assert_array_equal(path.center_of_rotation, path.centre_of_rotation)
    assert path.centre_of_rotation.shape == (2, 2)


def test_ehl_max_sweeps_is_the_old_spelling_of_max_iter():
    body = Material(2e11, 0.3)
    lub = Lubricant(0.04, 2e-8, viscosity_model="barus", compressible=False)
    prob = LineContact(0.01, 2e5, 1.0, 1.0, body, body, lub)
    new = solve_steady(prob, nx=33, max_iter=30)
    with pytest.warns(DeprecationWarning, match="'max_sweeps' is deprecated, use 'max_iter'"):
        old = solve_steady(prob, nx=33, max_sweeps=30)
    assert new.sweeps == old.sweeps == 30 and not new.converged
    np.testing.assert_array_equal(old.pressure, new.pressure)
    with pytest.raises(TypeError, match="both"):
        solve_steady(prob, nx=33, max_iter=30, max_sweeps=30)
    # refresh 1: an unconverged step is relaxed again with half the load gain, twice, then
    # under-relaxed, each try limited to max_iter sweeps; later steps keep the quartered gain
    # and the under-relaxation and are not retried
    options = dict(nx=33, counting_steps=2, warmup_steps=0, steady=new, refresh=1)
    new = solve_transient(prob, max_iter=3, **options)
    with pytest.warns(DeprecationWarning, match="solve_transient: 'max_sweeps'"):
        old = solve_transient(prob, max_sweeps=3, **options)
    assert list(new.sweeps) == [12, 3]
    np.testing.assert_allclose(new.load_gains, 0.03 / 4)
    np.testing.assert_allclose(new.relaxation, 0.5)
    np.testing.assert_array_equal(old.sweeps, new.sweeps)
    np.testing.assert_array_equal(old.pressure, new.pressure)


def test_solve_normal_takes_a_topography():
    # a periodic wave z = D cos(2 pi x / lam) pressed flat: full contact above p* = pi E* D / lam
    # with p = p_mean + p* cos(2 pi x / lam) (Johnson 1985, sec. 13.2; Westergaard 1939)
    lam, amp, n = 100e-6, 0.1e-6, 64
    x = cell_centres(n, lam / n)
    y = cell_centres(8, lam / n)
    topo = Profile(x, amp * np.cos(2 * np.pi * x / lam), periodic=True).extrude(y)
    p_star = math.pi * E_STAR * amp / lam
    mean = 2 * p_star
    load = mean * lam * y.size * (lam / n)
    res = solve_normal(topo, STEEL, STEEL, load=load)
    assert res.converged and res.contact.all()
    np.testing.assert_allclose(res.pressure[:, 0], mean + p_star * np.cos(2 * np.pi * x / lam),
                               rtol=0, atol=1e-3 * p_star)
    # the same as the gap max(z) - z on the topography's grid, periodic from the topography
    same = solve_normal(surface_gap(topo), x, y, STEEL, STEEL, load=load, periodic=True)
    np.testing.assert_allclose(res.pressure, same.pressure, rtol=1e-12)
    with pytest.raises(InputError, match="x, y"):
        solve_normal(topo, x, y, STEEL, STEEL, load=load)
    with pytest.raises(InputError, match="gap0, x, y, body1, body2"):
        solve_normal(np.zeros((8, 8)), load=1.0)


def test_ellipsoid_gap_with_roughness():
    x, y = cell_centres(20, 1e-6) - 10e-6, cell_centres(10, 2e-6) - 10e-6
    X, Y = np.meshgrid(x, y, indexing="ij")
    smooth = ellipsoid_gap(0.01, 0.04, x, y)
    # at (x, y) = (10 um, 10 um)... checked on the paraboloid x^2/(2 rx) + y^2/(2 ry)
    assert smooth[-1, -1] == pytest.approx(x[-1] ** 2 / 0.02 + y[-1] ** 2 / 0.08, rel=1e-12)
    wave = Profile(x, 1e-7 * np.sin(2 * np.pi * x / 5e-6))
    rough = ellipsoid_gap(0.01, 0.04, x, y, wave)
    np.testing.assert_allclose(smooth - rough, 1e-7 * np.sin(2 * np.pi * X / 5e-6), atol=1e-20)
    topo = Topography(x, y, 1e-7 * np.cos(2 * np.pi * Y / 8e-6))
    np.testing.assert_allclose(ellipsoid_gap(0.01, 0.04, roughness=topo),
                               smooth - topo.z, atol=1e-20)
    assert np.all(ellipsoid_gap(np.inf, np.inf, x, y) == 0.0)
    with pytest.raises(InputError, match="rx"):
        ellipsoid_gap(-1.0, 1.0, x, y)
    with pytest.raises(InputError, match="roughness"):
        ellipsoid_gap(0.01, 0.01, x, y, np.zeros((3, 3)))


def test_examples_load_by_name_and_outcome_writes_what_the_command_line_writes(tmp_path):
    case = load_case("gear-dry-hertz")
    assert case.analysis == "normal"
    with pytest.raises(InputError, match="gear-dry-hertz"):
        load_case("no-such-example")
    outcome = run_case(case)
    files = outcome.write(tmp_path)
    names = {p.name for p in tmp_path.iterdir()}
    assert {"result.nc", "summary.json", "report.html"} <= names
    assert {f"{stem}.png" for stem in outcome.figures} <= names
    assert files["report"] == tmp_path / "report.html"
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["status"] == "complete" and summary["converged"] is True
    assert case.title in (tmp_path / "report.html").read_text()
