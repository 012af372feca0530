"""Dry normal contact (Polonsky-Keer CCG) against Hertz, against itself, and on rough surfaces."""

import numpy as np
import pytest

from asperity.contact import hertz_point, solve_normal
from asperity.elastic import normal_influence
from asperity.errors import InputError
from asperity.materials import Material, contact_modulus

BODY = Material(200e9, 0.3)


def centred(n, length):
    """n cell centres (n odd puts one at 0) on a segment of the given length."""
    return (np.arange(n) - (n - 1) / 2) * length / n


def hertz_problem(rx, ry, load, cells_across=50, span=1.5):
    """Gap x^2/(2 rx) + y^2/(2 ry) with ~cells_across cells over each contact diameter."""
    hz = hertz_point(load, rx, ry, BODY, BODY)
    n = int(round(span * cells_across)) | 1
    x = centred(n, span * 2 * hz.a)
    y = centred(n, span * 2 * hz.b)
    gap0 = x[:, None] ** 2 / (2 * rx) + y[None, :] ** 2 / (2 * ry)
    return hz, gap0, x, y


def semi_axis(coord, pressure_line):
    """Semi-axis from p^2 = p0^2 (1 - s^2/c^2) fitted on the inner 80 % of the contact."""
    inside = pressure_line > 0
    extent = np.abs(coord[inside]).max()
    use = inside & (np.abs(coord) < 0.8 * extent)
    slope, intercept = np.polyfit(coord[use] ** 2, pressure_line[use] ** 2, 1)
    return np.sqrt(-intercept / slope)


@pytest.mark.parametrize("rx, ry", [(0.01, 0.01), (0.0191, 0.151)])
def test_hertz_non_periodic(rx, ry):
    """p_max, semi-axes and approach within 1 % of Hertz with 50 cells across the contact."""
    hz, gap0, x, y = hertz_problem(rx, ry, 962.0)
    res = solve_normal(gap0, x, y, BODY, BODY, load=962.0)
    assert res.converged and res.residual < 1e-8
    ix, iy = len(x) // 2, len(y) // 2
    assert res.max_pressure == pytest.approx(hz.p_max, rel=0.01)
    assert semi_axis(x, res.pressure[:, iy]) == pytest.approx(hz.a, rel=0.01)
    assert semi_axis(y, res.pressure[ix, :]) == pytest.approx(hz.b, rel=0.01)
    assert res.approach == pytest.approx(hz.approach, rel=0.01)
    assert res.contact_area == pytest.approx(hz.area, rel=0.02)
    assert res.load == pytest.approx(962.0, rel=1e-12)
    # the deformed gap closes where the pressure acts
    assert np.abs(res.gap[res.contact]).max() < 1e-6 * hz.approach


def rough_surface(n, length, hurst, seed):
    """Periodic self-affine heights (std 1 um) by spectral filtering of white noise."""
    rng = np.random.default_rng(seed)
    qx = np.fft.fftfreq(n, length / n)
    qy = np.fft.rfftfreq(n, length / n)
    q = np.hypot(qx[:, None], qy[None, :])
    amplitude = np.zeros_like(q)
    amplitude[q > 0] = q[q > 0] ** (-1.0 - hurst)
    noise = rng.normal(size=q.shape) + 1j * rng.normal(size=q.shape)
    heights = np.fft.irfft2(amplitude * noise, s=(n, n))
    return heights * (1e-6 / heights.std())


LENGTH = 1e-4


@pytest.fixture(scope="module")
def rough():
    n = 128
    heights = rough_surface(n, LENGTH, 0.8, seed=1)
    x = (np.arange(n) + 0.5) * LENGTH / n
    return heights.max() - heights, x


@pytest.mark.parametrize(
    "mean_pressure, fraction",
    [(1e8, (0.005, 0.02)), (1.2e9, (0.07, 0.14)), (2.5e10, (0.85, 0.95)),
     (4e10, (0.97, 0.999)), (1e11, (1.0, 1.0))],
)
def test_rough_periodic_converges_from_sparse_to_full_contact(rough, mean_pressure, fraction):
    """~1 %, ~10 %, ~90 %, ~99 % and full contact all converge to the tolerance.

    Near full contact is where ContactMechanics' CCG stagnates (its issue 3).
    """
    gap0, x = rough
    load = mean_pressure * LENGTH**2
    seen = []
    res = solve_normal(gap0, x, x, BODY, BODY, load=load, periodic=True,
                       callback=lambda it, r: seen.append((it, r)))
    assert res.converged and res.residual < 1e-8
    assert res.iterations < 150
    assert [it for it, _ in seen] == list(range(1, res.iterations + 1))
    assert fraction[0] <= res.contact_fraction <= fraction[1]
    # equilibrium
    assert res.pressure.sum() * (x[1] - x[0]) ** 2 == pytest.approx(load, rel=1e-8)
    # complementarity: p >= 0; no pressure where the gap is open; no penetration
    scale = np.ptp(res.displacement)
    assert res.pressure.min() >= 0.0
    assert np.all(res.gap[~res.contact] > -1e-8 * scale)
    assert np.sqrt(np.mean(res.gap[res.contact] ** 2)) < 1e-8 * scale
    assert np.all(res.pressure[res.gap > 1e-6 * scale] == 0.0)
    # the periodic displacement has zero mean; the approach shifts the mean gap
    assert abs(res.displacement.mean()) < 1e-12 * scale
    assert res.approach == pytest.approx(gap0.mean() - res.gap.mean(), rel=1e-9)


def test_full_contact_is_the_linear_solution(rough):
    """In full contact p = P/A - K^-1 (gap0 - mean gap0): check in Fourier space."""
    gap0, x = rough
    mean_pressure = 1e11
    res = solve_normal(gap0, x, x, BODY, BODY, load=mean_pressure * LENGTH**2, periodic=True)
    assert res.contact.all()
    n = len(x)
    q = 2 * np.pi * np.hypot(np.fft.fftfreq(n, LENGTH / n)[:, None],
                             np.fft.rfftfreq(n, LENGTH / n)[None, :])
    spectrum = np.fft.rfft2(gap0 - gap0.mean())
    stiffness = contact_modulus(BODY, BODY) * q / 2
    expected = mean_pressure - np.fft.irfft2(stiffness * spectrum, s=(n, n))
    np.testing.assert_allclose(res.pressure, expected, rtol=0, atol=1e-6 * mean_pressure)


def test_load_and_approach_control_agree_periodic(rough):
    gap0, x = rough
    by_load = solve_normal(gap0, x, x, BODY, BODY, load=1.2e9 * LENGTH**2, periodic=True)
    by_approach = solve_normal(gap0, x, x, BODY, BODY, approach=by_load.approach, periodic=True)
    assert by_approach.converged
    assert by_approach.load == pytest.approx(by_load.load, rel=1e-6)
    assert np.array_equal(by_approach.contact, by_load.contact)
    scale = np.abs(by_load.pressure).max()
    np.testing.assert_allclose(by_approach.pressure, by_load.pressure, rtol=0, atol=1e-6 * scale)


def test_load_and_approach_control_agree_non_periodic():
    hz, gap0, x, y = hertz_problem(0.0191, 0.151, 962.0, cells_across=30)
    by_load = solve_normal(gap0, x, y, BODY, BODY, load=962.0)
    by_approach = solve_normal(gap0, x, y, BODY, BODY, approach=by_load.approach)
    assert by_approach.converged
    assert by_approach.approach == by_load.approach
    assert by_approach.load == pytest.approx(962.0, rel=1e-6)
    np.testing.assert_allclose(by_approach.pressure, by_load.pressure, rtol=0,
                               atol=1e-6 * hz.p_max)


def test_no_contact_under_approach_control():
    hz, gap0, x, y = hertz_problem(0.01, 0.01, 10.0, cells_across=10)
    res = solve_normal(gap0 + 1e-6, x, y, BODY, BODY, approach=0.5e-6)
    assert res.converged and res.load == 0.0 and not res.contact.any()


def test_iteration_limit_reports_non_convergence(rough):
    gap0, x = rough
    res = solve_normal(gap0, x, x, BODY, BODY, load=1.2e9 * LENGTH**2, periodic=True,
                       max_iter=3)
    assert not res.converged
    assert res.iterations == 3 and res.residual > 1e-8


def test_agrees_with_contactmechanics(rough):
    """Same discrete problem (periodic continuum kernel) solved by ContactMechanics' CCG."""
    pytest.importorskip("ContactMechanics")
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients

    gap0, x = rough
    n, load = len(x), 1.2e9 * LENGTH**2
    substrate = PeriodicFFTElasticHalfSpace((n, n), contact_modulus(BODY, BODY),
                                            physical_sizes=(LENGTH, LENGTH))
    peer = constrained_conjugate_gradients(substrate, -gap0, external_force=load,
                                           pentol=1e-9 * gap0.std())
    assert peer.success
    peer_pressure = peer.jac / (LENGTH / n) ** 2
    ours = solve_normal(gap0, x, x, BODY, BODY, load=load, periodic=True)
    error = np.linalg.norm(ours.pressure - peer_pressure) / np.linalg.norm(peer_pressure)
    assert error < 1e-5
    assert abs(np.count_nonzero(peer_pressure > 0) - np.count_nonzero(ours.contact)) <= 2


def test_bad_input(rough):
    gap0, x = rough
    ok = {"load": 1.0}
    with pytest.raises(InputError, match="gap0"):
        solve_normal(np.where(gap0 > gap0.mean(), np.nan, gap0), x, x, BODY, BODY, **ok)
    with pytest.raises(InputError, match="gap0"):
        solve_normal(gap0[:, :-1], x, x, BODY, BODY, **ok)
    with pytest.raises(InputError, match="load"):
        solve_normal(gap0, x, x, BODY, BODY, load=-1.0)
    with pytest.raises(InputError, match="load, approach"):
        solve_normal(gap0, x, x, BODY, BODY)
    with pytest.raises(InputError, match="load, approach"):
        solve_normal(gap0, x, x, BODY, BODY, load=1.0, approach=1e-6)
    with pytest.raises(InputError, match="approach"):
        solve_normal(gap0, x, x, BODY, BODY, approach=float("nan"))
    with pytest.raises(InputError, match="approach"):  # periodic: mean gap must stay open
        solve_normal(gap0, x, x, BODY, BODY, approach=gap0.mean(), periodic=True)
    bent = x.copy()
    bent[5] += 0.3 * (x[1] - x[0])
    with pytest.raises(InputError, match="x"):
        solve_normal(gap0, bent, x, BODY, BODY, **ok)
    with pytest.raises(InputError, match="tol"):
        solve_normal(gap0, x, x, BODY, BODY, tol=0.0, **ok)
    with pytest.raises(InputError, match="max_iter"):
        solve_normal(gap0, x, x, BODY, BODY, max_iter=0, **ok)


@pytest.mark.parametrize("bow", [0.0, 1e-15])
def test_flat_full_contact_converges_to_the_direct_solution(bow):
    """A flat (or nearly flat) punch in full contact on a non-periodic grid.

    Reference: the linear system of Love's influence matrix with the load equation,
    K p - delta 1 = -gap0, sum p A = P, solved directly. The displacement is then uniform on
    the grid, so a measure divided by its range never converged (500 of 500 iterations,
    converged False, although the pressure matched to 2e-13).
    """
    n, length, load = 16, 1e-3, 100.0
    x = (np.arange(n) + 0.5) * length / n - 0.5 * length
    X, Y = np.meshgrid(x, x, indexing="ij")
    gap0 = bow * (X**2 + Y**2) / length**2
    res = solve_normal(gap0, x, x, BODY, BODY, load=load, max_iter=500)
    dx = x[1] - x[0]
    xf, yf = X.ravel(), Y.ravel()
    K = normal_influence(xf[:, None] - xf[None, :], yf[:, None] - yf[None, :], dx, dx, BODY,
                         BODY)
    m = n * n
    system = np.zeros((m + 1, m + 1))
    system[:m, :m], system[:m, m], system[m, :m] = K, -1.0, dx * dx
    solution = np.linalg.solve(system, np.r_[-gap0.ravel(), load])
    expected = solution[:m].reshape(n, n)
    assert expected.min() > 0  # full contact
    assert res.converged and res.iterations < 50 and res.contact.all()
    np.testing.assert_allclose(res.pressure, expected, rtol=0, atol=1e-7 * expected.max())
    assert res.approach == pytest.approx(solution[m], rel=1e-7)


def test_nearly_flat_periodic_full_contact_converges():
    """Periodic full contact of a wave 1e-14 m high: the exact pressure is the linear response
    P/A - E* k h / 2 cos(k x) (Westergaard); the displacement's range (2e-14 m) made the old
    measure stall at 6.5e-7 for 300 of 300 iterations."""
    n, length, amp = 32, 1e-3, 1e-14
    x = (np.arange(n) + 0.5) * length / n
    X, _ = np.meshgrid(x, x, indexing="ij")
    gap0 = 1e-6 + amp * np.cos(2 * np.pi * X / length)
    mean = 1e8
    res = solve_normal(gap0, x, x, BODY, BODY, load=mean * length**2, periodic=True,
                       max_iter=300)
    assert res.converged and res.iterations < 10 and res.contact.all()
    k = 2 * np.pi / length
    expected = mean - contact_modulus(BODY, BODY) * k * amp / 2 * np.cos(k * X)
    np.testing.assert_allclose(res.pressure, expected, rtol=0, atol=1e-9 * mean)


def test_a_rough_case_reports_greenwood_tripp_and_a_flat_its_mean_separation():
    """The rough-sphere example (R = 10 mm, E* = 115.4 GPa, 10 N: a0 = 148.1 um by Hertz,
    a0^3 = 3 F R / (4 E*)) reports Greenwood & Tripp's alpha = sigma R / a0^2 with the rms of
    the heights it ran on; the rough flat reports its mean separation, which on a periodic
    cell is minus the approach (the elastic displacement of a periodic cell has zero mean)."""
    from asperity.cases import load_case
    from asperity.cases.roughness import roughness_on_grid
    from asperity.examples import example_text
    from asperity.runners import run_case

    case = load_case(example_text("rough-sphere-normal"))
    out = run_case(case)
    e_star = case.body1.youngs_modulus / (2 * (1 - case.body1.poisson_ratio**2))
    load = out.summary["load_n"]
    a0 = (3 * load * 0.01 / (4 * e_star)) ** (1 / 3)
    assert out.summary["hertz_a_m"] == pytest.approx(a0, rel=1e-9)
    sigma = np.std(roughness_on_grid(case.roughness, *case.grid.coordinates()).heights)
    assert out.summary["greenwood_tripp_alpha"] == pytest.approx(sigma * 0.01 / a0**2,
                                                                  rel=1e-9)
    flat = run_case(load_case(example_text("rough-flat-normal")))
    assert flat.summary["mean_separation_m"] == pytest.approx(-flat.summary["approach_m"],
                                                              rel=1e-9)
    assert "greenwood_tripp_alpha" not in flat.summary


def test_rough_asperity_pressures_without_a_hardness_are_noted_and_one_hardness_is_one_line():
    """The rough flat's largest pressure is above 0.05 E* (E* = E / (2 (1 - nu^2)) = 115.4
    GPa for its two steel bodies): with no hardness given the report notes that plasticity
    was not checked. Given the same hardness for both bodies, the hardness is exceeded and
    said once, naming both, not twice."""
    import tomllib

    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    data = tomllib.loads(example_text("rough-flat-normal"))
    out = run_case(load_case(data))
    e_star = 210e9 / (2 * (1 - 0.3**2))
    ratio = out.summary["max_pressure_pa"] / e_star
    assert ratio > 0.05
    noted = [n for n in out.notes if "plasticity was not checked" in n]
    assert len(noted) == 1 and f"is {ratio:.3g} E*" in noted[0]
    for body in ("body1", "body2"):
        data[body]["hardness"] = "6 GPa"
    hard = run_case(load_case(data))
    lines = [w for w in hard.warnings if w.startswith("pressure:")]
    assert len(lines) == 1 and "hardness of body1 and body2" in lines[0]
    assert not [n for n in hard.notes if "plasticity was not checked" in n]


def _rough_ball(load, rms):
    from asperity.cases import load_case
    from asperity.runners import run_case

    return run_case(load_case({
        "analysis": "normal",
        "body1": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
        "body2": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
        "geometry": {"shape": "sphere", "rx": "10 mm"}, "loading": {"load": load},
        "grid": {"nx": 128, "ny": 128, "x_extent": "0.6 mm", "y_extent": "0.6 mm"},
        "roughness": {"kind": "gaussian", "rms": rms, "correlation_length": "12 um",
                      "seed": 3}}))


def test_a_rough_balls_approach_is_also_given_from_first_contact():
    """A user's rough steel ball (R = 10 mm, 20 N, rms 0.5 um) was reported with "approach
    544.5 nm" beside Hertz's 1.191 um (-54 %), unsaid that it is measured from the roughness's
    mean plane: the highest peak stands 1.27 um above the sphere there, so from first contact,
    Hertz's datum, the approach is 1.81 um (+52 %, the asperities' compliance added). Now both
    are given and the note says which is which. Independent checks: at 0.01 N the mean-plane
    approach is negative (the peaks hold the apex off the mean plane) while the approach from
    first contact is small and positive (21 nm, a few asperities carry the load: more than
    the smooth ball's 7.5 nm, their radii being smaller than 10 mm); at rms 2 nm the approach
    from first contact is Hertz's, delta = a^2 / R with a = (3 P R / (4 E*))^(1/3)
    (1.191 um), within 1 %."""
    e_star = 210e9 / (2 * (1 - 0.3**2))

    def hertz_approach(load):
        return (3 * load * 10e-3 / (4 * e_star)) ** (2 / 3) / 10e-3

    light = _rough_ball("0.01 N", "0.5 um").summary
    assert light["approach_m"] < -0.5e-6
    assert hertz_approach(0.01) < light["approach_from_first_contact_m"] < 0.05e-6
    smooth = _rough_ball("20 N", "2 nm")
    assert smooth.summary["approach_from_first_contact_m"] == pytest.approx(
        hertz_approach(20.0), rel=0.01)
    assert any("measured from the roughness's mean plane" in n for n in smooth.notes)
    (row,) = [r for r in smooth.comparisons if r.quantity == "approach from first contact"]
    assert row.reference == pytest.approx(hertz_approach(20.0), rel=1e-9)


def test_a_ball_past_first_yield_below_the_hardness_warns():
    """A user's steel ball (R 5 mm) on aluminium 6061 (70 GPa, nu 0.33, hardness 1.1 GPa),
    50 N: p0 = 1.0995 GPa, 99.96 % of the hardness, ran without a word (the hardness check
    starts at H). First yield beneath the surface is at p0 = 1.60 Y (von Mises, depth 0.48 a;
    Johnson 1985 sec. 6.2) with Tabor's H = 2.8 Y: 0.57 H = 0.627 GPa, reached at
    50 (0.627 / 1.0995)^3 = 9.27 N. E* and p0 written out here."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    e_star = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.33**2) / 70e9)
    a = (3 * 50 * 5e-3 / (4 * e_star)) ** (1 / 3)
    p0 = 3 * 50 / (2 * np.pi * a * a)
    assert p0 == pytest.approx(1.0995e9, rel=1e-4)

    def run(load, hardness="1.1 GPa"):
        return run_case(load_case({
            "analysis": "normal",
            "body1": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3, "hardness": "7 GPa"},
            "body2": {"youngs_modulus": "70 GPa", "poisson_ratio": 0.33,
                      "name": "aluminium", "hardness": hardness},
            "geometry": {"shape": "sphere", "rx": "5 mm"}, "loading": {"load": load},
            "grid": {"nx": 48, "ny": 48, "x_extent": "0.45 mm", "y_extent": "0.45 mm"}}))

    (line,) = run("50 N").warnings
    assert line.startswith("pressure: the Hertz peak p0 = 1.1 GPa is 100 % of the hardness "
                           "of body2 (aluminium")
    assert "limit 0.57 H = 0.627 GPa" in line
    assert f"keep loading.load below {50 * (0.57 * 1.1e9 / p0) ** 3:.4g} N" in line
    assert not [w for w in run("9 N").warnings if w.startswith("pressure")]  # p0 = 0.563 H
    above = run("50 N", hardness="1 GPa").warnings  # above H: the hardness line alone
    assert len(above) == 1 and "exceeds the hardness" in above[0]


def _egg_crate(cells_per_period, shift=0.0):
    """One period of z = amp (cos kx + cos ky) on a periodic grid, loaded so that each peak's
    Hertz radius is 0.07 of the wavelength: the peak's radius of curvature is 1 / (amp k^2),
    the load P = 4 E* a^3 / (3 R), the area pi a^2 and the peak pressure 3 P / (2 pi a^2)
    (Johnson, Greenwood & Higginson 1985: an isolated Hertz contact at light load).
    ``shift`` moves the peak by that fraction of the period along x and y."""
    from asperity.contact.spots import contact_spots

    e, nu = 210e9, 0.3
    e_star = e / (2 * (1 - nu**2))
    wavelength, amp = 100e-6, 0.5e-6
    k = 2 * np.pi / wavelength
    radius = 1 / (amp * k**2)
    a = 0.07 * wavelength
    load = 4 * e_star * a**3 / (3 * radius)
    h = wavelength / cells_per_period
    x = (np.arange(cells_per_period) + 0.5) * h - wavelength / 2
    xs = x[:, None] - shift * wavelength
    ys = x[None, :] - shift * wavelength
    gap0 = amp * (2 - np.cos(k * xs) - np.cos(k * ys))
    res = solve_normal(gap0, x, x, Material(e, nu), Material(e, nu), load=load, periodic=True)
    spots = contact_spots(res.contact, res.pressure, h * h, periodic=True)
    reference = {"area": np.pi * a**2, "p0": 3 * load / (2 * np.pi * a**2), "load": load}
    return res, spots, x, reference


def test_spots_of_a_few_cells_are_reported_where_the_peak_pressure_is_not_converged():
    """A periodic egg-crate at light load: each peak is a Hertz contact of radius 0.07
    wavelengths. With 16 cells a period the spot is 4 cells and its peak pressure 34 % below
    Hertz's: the spot check warns (limit 50 cells at the load's median) and names a grid that
    resolves it. With 128 cells (a spot of 256 cells) there is no line, the peak pressure is
    within 2 % of Hertz's p0 and the real area within 3 % of pi a^2."""
    from asperity import diagnostics

    coarse, spots, x, ref = _egg_crate(16)
    assert spots.count == 1 and spots.load_median_cells() < diagnostics.MIN_CELLS_PER_SPOT
    assert coarse.pressure.max() < 0.8 * ref["p0"]
    (line,) = diagnostics.spot_resolution(spots, x, x)
    assert line.startswith("mesh: half the load is carried by contact spots of 4 cells")
    assert "(1 spot of 4, 4 and 4 cells at the 10th, 50th and 90th percentiles" in line
    assert "nx >= 57 and ny >= 57" in line  # 16 sqrt(50 / 4) = 56.6
    fine, spots, x, ref = _egg_crate(128)
    assert diagnostics.spot_resolution(spots, x, x) == []
    assert fine.pressure.max() == pytest.approx(ref["p0"], rel=0.02)
    assert fine.contact_area == pytest.approx(ref["area"], rel=0.03)
    assert spots.loads.sum() == pytest.approx(ref["load"], rel=1e-9)


def test_a_spot_across_the_periodic_edge_is_one_spot():
    """The egg-crate's peak moved onto the corner of the periodic cell is cut into four
    pieces by the grid's edges; labelled periodically it is still one spot of the same cells
    as the centred one (the same lattice, shifted by half a period)."""
    _, centred_spots, _, _ = _egg_crate(64)
    _, corner, _, _ = _egg_crate(64, shift=0.5)
    assert corner.count == 1 and corner.cells[0] == centred_spots.cells[0]


def test_a_user_rough_flat_with_spots_of_a_few_cells_is_warned_and_told_to_fix_the_cutoff():
    """The self-affine rough flat example as it was (H = 0.8, Sq = 0.5 um, 25 N on 0.5 mm, 128
    cells, no short_cutoff) carries half its load on spots of 16 cells or fewer. With its
    shortest wavelength fixed at 7.81 um the real area fraction was 4.14 % on 128 cells, 3.43 %
    on 256, 3.144 % on 512 and 3.153 % on 1024 (docs/tangential.md): the line says a finer grid
    adds roughness without short_cutoff and names that key. The example itself now fixes the
    cutoff and runs on 512 cells, where it is silent."""
    import tomllib

    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    data = tomllib.loads(example_text("rough-flat-normal"))
    data["grid"].update(nx=128, ny=128)
    del data["roughness"]["short_cutoff"]
    out = run_case(load_case(data))
    assert out.summary["load_median_spot_cells"] == 16
    (line,) = [w for w in out.warnings if "contact spots" in w]
    assert "nx >= 227 and ny >= 227" in line and "give roughness.short_cutoff" in line
    example = run_case(load_case(example_text("rough-flat-normal")))
    assert example.warnings == []
    assert example.summary["load_median_spot_cells"] >= 50
    assert example.summary["contact_area_fraction"] == pytest.approx(0.03144, rel=0.01)


def test_a_nominally_flat_periodic_patch_near_full_contact_is_not_told_its_images_interact():
    """The rough-flat-normal example at 500 N (2 GPa nominal, the load sweep's last case) is in
    contact over half its patch (49 %), which percolates across the period: that is the
    representative patch's answer, not periodic images of a single contact, and the line that
    said "use a period at least twice the patch" is left to curved bodies."""
    import tomllib

    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    data = tomllib.loads(example_text("rough-flat-normal"))
    data["loading"]["load"] = "500 N"
    out = run_case(load_case(data))
    assert out.summary["contact_area_fraction"] > 0.4
    assert not [w for w in out.warnings if w.startswith("contact:")], out.warnings


def _greenwood_tripp(load, radius, e_star, eta, beta, sigma_s, rings=120, reach=3.0):
    """Nominal pressure of a smooth sphere on a rough flat by Greenwood & Tripp (1967),
    solved here from the paper's equations, not by asperity: summits of density ``eta``,
    radius ``beta`` and Gaussian heights of rms ``sigma_s``, each a Hertz contact, carry
    ``p = (4/3) eta E* beta^(1/2) sigma_s^(3/2) F_3/2(d / sigma_s)`` at the separation
    ``d(r) = -delta + r^2 / (2 R) + w(r)`` of the sphere from the summits' mean plane; ``w``
    is the half-space's displacement under the axisymmetric p (ring kernel
    ``4 / (pi E*) s / (r + s) K(k)``, ``k^2 = 4 r s / (r + s)^2``); the approach ``delta``
    gives the load. Returns the ring radii and the pressure."""
    from scipy.special import ellipk

    a0 = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    edges = np.linspace(0.0, reach * a0, rings + 1)
    r = 0.5 * (edges[1:] + edges[:-1])
    dr = edges[1] - edges[0]
    sub = 16
    s = (edges[:-1, None] + (np.arange(sub) + 0.5) * dr / sub).ravel()
    k2 = np.minimum(4 * r[:, None] * s[None, :] / (r[:, None] + s[None, :]) ** 2, 1 - 1e-12)
    kernel = (4 / (np.pi * e_star)) * s / (r[:, None] + s[None, :]) * ellipk(k2) * dr / sub
    kernel = kernel.reshape(rings, rings, sub).sum(axis=2)
    t = np.linspace(-8.0, 8.0, 3201)
    phi = np.exp(-0.5 * t**2) / np.sqrt(2 * np.pi)
    table_d = np.linspace(-8.0, 8.0, 801)
    table = np.array([np.trapezoid(np.clip(t - d, 0, None) ** 1.5 * phi, t) for d in table_d])
    scale = (4 / 3) * eta * e_star * np.sqrt(beta) * sigma_s**1.5

    def pressure(separation):
        return scale * np.interp(separation / sigma_s, table_d, table, right=0.0)

    def total(p):
        return 2 * np.pi * np.sum(p * r) * dr

    p = np.zeros_like(r)
    for _ in range(300):
        w = kernel @ p
        lo, hi = -10 * sigma_s - 10 * a0**2 / radius, 10 * sigma_s + 10 * a0**2 / radius
        for _ in range(70):
            delta = 0.5 * (lo + hi)
            new = pressure(-delta + r**2 / (2 * radius) + w)
            lo, hi = (lo, delta) if total(new) > load else (delta, hi)
        if p.any() and np.abs(new - p).max() < 1e-6 * new.max():
            break
        p = new if not p.any() else 0.7 * p + 0.3 * new
    return r, new


def test_a_rough_ball_spreads_its_load_as_greenwood_and_tripp_predict_within_their_model():
    """A steel ball (R = 10 mm, E* = 115.4 GPa, 50 N: a0 = 148.1 um, p0 = 1.088 GPa) on a
    gaussian surface of our own (Sq 0.3 um, correlation length 12 um, 1.95 um cells; alpha =
    sigma R / a0^2 = 0.137). Greenwood & Tripp's model with McCool's summit parameters from
    the surface's spectral moments (eta = m4 / (6 pi sqrt 3 m2), beta = 0.375 sqrt(pi / m4),
    sigma_s^2 = (1 - 0.8968 / alpha_b) m0) spreads the load to an rms radius 0.738 a0 (Hertz
    0.632 a0) and lowers the mean pressure inside a0 / 4 to 0.879 GPa (Hertz 1.07). The
    deterministic solve gives 0.711 a0 (-3.6 %) and 0.882 GPa; on a 1024-point surface of
    the same statistics 0.706 a0 and 0.953 GPa (+8.5 %: the centre holds about nine
    summits, and one surface's scatter). GT's summits carry load without interacting, so the
    tolerances are 6 % on the rms radius and 10 % on the centre (docs/tangential.md)."""
    e, nu = 210e9, 0.3
    e_star = e / (2 * (1 - nu**2))
    radius, load = 0.01, 50.0
    n, length, rms, ell = 256, 0.5e-3, 0.3e-6, 12e-6
    h = length / n
    beta_acf = ell / np.sqrt(np.log(5.0))
    q = 2 * np.pi * np.fft.fftfreq(n, h)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    noise = np.random.default_rng(7).standard_normal((n, n))
    z = np.real(np.fft.ifft2(np.exp(-(qx**2 + qy**2) * beta_acf**2 / 8) * np.fft.fft2(noise)))
    z *= rms / z.std()
    spectrum = np.abs(np.fft.fft2(z) / z.size) ** 2
    m0 = spectrum.sum()
    m2 = 0.5 * ((qx**2 + qy**2) * spectrum).sum()
    m4 = 3 / 8 * ((qx**2 + qy**2) ** 2 * spectrum).sum()
    eta = m4 / (6 * np.pi * np.sqrt(3) * m2)
    beta = 0.375 * np.sqrt(np.pi / m4)
    sigma_s = np.sqrt((1 - 0.8968 * m2**2 / (m0 * m4)) * m0)
    r, p_gt = _greenwood_tripp(load, radius, e_star, eta, beta, sigma_s)
    a0 = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    rms_gt = np.sqrt(np.sum(p_gt * r**3) / np.sum(p_gt * r))
    inner = r < a0 / 4
    centre_gt = np.sum((p_gt * r)[inner]) / np.sum(r[inner])

    x = (np.arange(n) + 0.5) * h - length / 2
    gap0 = (x[:, None] ** 2 + x[None, :] ** 2) / (2 * radius) - z
    res = solve_normal(gap0, x, x, Material(e, nu), Material(e, nu), load=load)
    rr = np.hypot(x[:, None], x[None, :])
    rms_num = np.sqrt((res.pressure * rr**2).sum() / res.pressure.sum())
    centre_num = res.pressure[rr < a0 / 4].mean()
    assert rms_gt / a0 == pytest.approx(0.738, abs=0.01)
    assert np.sqrt(0.4) * a0 < rms_num == pytest.approx(rms_gt, rel=0.06)
    assert centre_num == pytest.approx(centre_gt, rel=0.10)
    assert centre_num < 0.95 * 1.5 * load / (np.pi * a0**2)


def test_a_measured_flat_patch_on_an_open_grid_is_not_told_to_enlarge_the_grid(tmp_path):
    """A user's measured 64 x 64 patch (0.49 um points) pressed flat on a non-periodic grid
    the file's size: the contact reaches every edge, as a flat's does on any grid. The line
    said "enlarge the grid", which the file's size does not allow; it now says what the
    answer is (a rough punch of the grid's size), that the file bounds the grid, and names
    grid.periodic. On the periodic grid the same patch's real area differs by a few per cent
    (docs/tangential.md)."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    n, h = 64, 0.48828125e-6
    q = 2 * np.pi * np.fft.fftfreq(n, h)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    noise = np.random.default_rng(3).standard_normal((n, n))
    z = np.real(np.fft.ifft2(np.exp(-(qx**2 + qy**2) * (6e-6) ** 2 / 8) * np.fft.fft2(noise)))
    np.save(tmp_path / "patch.npy", 0.3e-6 * z / z.std())
    case = {"analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
            "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "flat"},
            "loading": {"load": "0.5 N"},
            "grid": {"nx": n, "ny": n, "x_extent": n * h, "y_extent": n * h},
            "roughness": {"kind": "file", "path": str(tmp_path / "patch.npy"),
                          "spacing": h}}
    out = run_case(load_case(case))
    (line,) = [w for w in out.warnings if w.startswith("domain:")]
    assert "enlarge the grid" not in line and "rough punch the size of the grid" in line
    assert "cannot be enlarged" in line and "grid.periodic = true" in line


def test_a_steel_ball_on_peek_past_first_yield_is_noted_and_a_rubber_is_not_told_to_yield():
    """Steel ball (210 GPa, 0.3) on PEEK (3.6 GPa, 0.4), R = 10 mm, 200 N: E* = 4.208 GPa,
    a = (3 P R / 4 E*)^(1/3) = 709 um, p0 = 3 P / (2 pi a^2) = 189.9 MPa, p0/E* = 0.0451,
    past PEEK's first yield (p0 = 1.6 Y near 160 MPa) but under the 0.05 strain warning; the
    run was silent and now notes it, naming both bodies' hardness. A 5 MPa rubber ball
    (R = 2 mm, 1 N; E* = 6.58 MPa, p0/E* = 0.194) is warned that its law, not plasticity, is
    unchecked, and not told to give a hardness."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    def case(e1, nu1, e2, nu2, radius, load, extent):
        return {"analysis": "normal",
                "body1": {"youngs_modulus": e1, "poisson_ratio": nu1},
                "body2": {"youngs_modulus": e2, "poisson_ratio": nu2},
                "geometry": {"rx": radius}, "loading": {"load": load},
                "grid": {"nx": 48, "ny": 48, "x_extent": extent, "y_extent": extent}}

    e_star = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.4**2) / 3.6e9)
    a = (3 * 200 * 0.01 / (4 * e_star)) ** (1 / 3)
    p0 = 3 * 200 / (2 * np.pi * a**2)
    out = run_case(load_case(case("210 GPa", 0.3, "3.6 GPa", 0.4, "10 mm", "200 N", "2.2 mm")))
    assert out.summary["hertz_max_pressure_pa"] == pytest.approx(p0, rel=1e-9)
    assert out.warnings == []
    (note,) = [n for n in out.notes if n.startswith("p0/E*")]
    assert f"p0/E* = {p0 / e_star:.3g}" in note and "give body1.hardness and body2.hardness" \
        in note
    rubber = run_case(load_case(case("5 MPa", 0.49, "210 GPa", 0.3, "2 mm", "1 N", "3 mm")))
    (strain,) = [w for w in rubber.warnings if "p0/E*" in w]
    assert "elastomer (body1)" in strain and "hardness" not in strain
    assert "E* = 6.58 MPa" in strain


@pytest.mark.parametrize("key", ["coating_thickness", "layer", "substrate_modulus"])
def test_a_coated_body_is_told_that_bodies_are_homogeneous_not_to_check_the_spelling(key):
    """A user's DLC-coated PEEK disc: a coating key was refused as "unknown key (check the
    spelling)", as if a layer could be spelt right; the line now says that the bodies are
    homogeneous half-spaces and which modulus stands for a thick or a thin coating."""
    from asperity.cases import load_case

    case = {"analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
            "body2": {"youngs_modulus": "3.6 GPa", key: "5 um"},
            "geometry": {"rx": "10 mm"}, "loading": {"load": "200 N"},
            "grid": {"x_extent": "2 mm", "y_extent": "2 mm"}}
    with pytest.raises(InputError) as err:
        load_case(case)
    line = str(err.value)
    assert line.startswith("body2: expected a homogeneous body, got " + key)
    assert "no coating or layer" in line and "spelling" not in line


def test_a_ground_plate_is_judged_along_its_profile_not_across_its_ridges():
    """A user's ball on a ground plate (R = 10 mm, 100 N, Ra 0.2 um, default correlation
    length 15 um) on 128 x 64 cells over 0.6 mm: 3.2 cells per correlation length along x,
    the profile's direction; across y the ridges are the same on every row. The run warned
    that 15 um was 1.6 cells across y and asked for 3.8 um cells there; it is now silent, and
    on 32 cells along x (0.8 cells) it still warns along x."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    def run(nx):
        return run_case(load_case({
            "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
            "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"rx": "10 mm"},
            "loading": {"load": "100 N"},
            "grid": {"nx": nx, "ny": 64, "x_extent": "0.6 mm", "y_extent": "0.6 mm"},
            "roughness": {"kind": "ground", "ra": "0.2 um"}}))

    assert not [w for w in run(128).warnings if w.startswith("roughness:")]
    (line,) = [w for w in run(32).warnings if w.startswith("roughness:")]
    assert "0.8 cells of 18.7 um along x" in line


def _gaussian_heights(n, spacing, rms, correlation, seed):
    """Our own gaussian surface: white noise filtered to a gaussian ACF (falls to 0.2 at the
    correlation length), scaled to its rms."""
    beta_acf = correlation / np.sqrt(np.log(5.0))
    q = 2 * np.pi * np.fft.fftfreq(n, spacing)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    noise = np.random.default_rng(seed).standard_normal((n, n))
    z = np.real(np.fft.ifft2(np.exp(-(qx**2 + qy**2) * beta_acf**2 / 8) * np.fft.fft2(noise)))
    return z * rms / z.std(), qx, qy


def test_greenwood_tripp_sphere_against_the_papers_equations_solved_here():
    """The package's Greenwood-Tripp solve (exact annulus displacements, F_n by the parabolic
    cylinder function, brentq on the approach) against this file's own solve of the same
    equations (sub-sampled ring kernel, tabulated F_n, bisection) and F_n by quadrature: the
    steel ball of the test above (R = 10 mm, 50 N) on Sq 0.3 um, correlation 12 um
    (eta = 2035 /mm^2, beta = 58.4 um, sigma_s = 0.252 um): rms radius 0.738 a0, largest
    nominal pressure 0.894 GPa, real area 0.01142 mm^2 (pi eta beta sigma_s F_1 on each ring,
    F_1(h) = phi(h) - h Q(h))."""
    from scipy.integrate import quad
    from scipy.stats import norm

    from asperity.contact.greenwood_tripp import (
        greenwood_tripp_sphere,
        gw_integral,
        summit_parameters,
    )

    for h in (-3.0, -0.5, 0.0, 1.2, 4.0):
        exact, _ = quad(lambda s, h=h: (s - h) ** 1.5 * norm.pdf(s), h, np.inf, epsrel=1e-12)
        assert gw_integral(1.5, h) == pytest.approx(exact, rel=1e-9)
        assert gw_integral(1.0, h) == pytest.approx(norm.pdf(h) - h * norm.sf(h), rel=1e-9)
    n, h = 256, 0.5e-3 / 256
    z, qx, qy = _gaussian_heights(n, h, 0.3e-6, 12e-6, 7)
    s = summit_parameters(z, h, h)
    spectrum = np.abs(np.fft.fft2(z) / z.size) ** 2
    m2 = 0.5 * ((qx**2 + qy**2) * spectrum).sum()
    m4 = 3 / 8 * ((qx**2 + qy**2) ** 2 * spectrum).sum()
    assert s.density == pytest.approx(m4 / (6 * np.pi * np.sqrt(3) * m2), rel=1e-12)
    assert s.anisotropy == pytest.approx(1.0, abs=0.05)
    e_star = 210e9 / (2 * (1 - 0.3**2))
    gt = greenwood_tripp_sphere(50.0, 0.01, e_star, s)
    assert gt.converged and gt.load == pytest.approx(50.0, rel=1e-9)
    r, p = _greenwood_tripp(50.0, 0.01, e_star, s.density, s.radius, s.sigma)
    assert gt.rms_radius == pytest.approx(np.sqrt(np.sum(p * r**3) / np.sum(p * r)), rel=2e-3)
    assert gt.pressure.max() == pytest.approx(p.max(), rel=5e-3)
    # the real area of this file's solve: invert its pressure for the separation, then F_1
    t = np.linspace(-8.0, 8.0, 3201)
    table_d = np.linspace(-8.0, 8.0, 801)
    f32 = np.array([np.trapezoid(np.clip(t - d, 0, None) ** 1.5 * norm.pdf(t), t)
                    for d in table_d])
    scale = (4 / 3) * s.density * e_star * np.sqrt(s.radius) * s.sigma**1.5
    d = np.interp(p / scale, f32[::-1], table_d[::-1])
    f1 = norm.pdf(d) - d * norm.sf(d)
    area = np.sum(2 * np.pi * r * np.where(p > 0, np.pi * s.density * s.radius * s.sigma * f1,
                                           0.0)) * (r[1] - r[0])
    assert gt.real_area == pytest.approx(area, rel=5e-3)
    assert gt.real_area == pytest.approx(0.01142e-6, rel=0.01)


def test_a_rough_ball_run_shows_greenwood_tripp_beside_its_real_area_and_load(tmp_path):
    """A user's rough ball (R = 10 mm, 50 N, our own gaussian file, Sq 0.3 um, correlation
    12 um, 128 x 128 on 0.5 mm) was set beside smooth Hertz only. The run now has Greenwood &
    Tripp's rms radius of the load and real area as estimates, from McCool's summits of the
    heights it ran on, which this test recomputes with its own solve; a ground (anisotropic)
    surface gets no such row."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    n, h = 128, 0.5e-3 / 128
    z, _, _ = _gaussian_heights(n, h, 0.3e-6, 12e-6, 5)
    np.save(tmp_path / "lapped.npy", z)
    data = {"analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
            "body2": {"youngs_modulus": "210 GPa"},
            "geometry": {"shape": "sphere", "rx": "10 mm"}, "loading": {"load": "50 N"},
            "grid": {"nx": n, "ny": n, "x_extent": "0.5 mm", "y_extent": "0.5 mm"},
            "roughness": {"kind": "file", "path": str(tmp_path / "lapped.npy"),
                          "spacing": h, "form_degree": 0}}
    out = run_case(load_case(data))
    x = out.dataset.x.values
    heights = (x[:, None] ** 2 + x[None, :] ** 2) / 0.02 - out.dataset.undeformed_gap.values
    heights -= heights.mean()
    spectrum = np.abs(np.fft.fft2(heights) / heights.size) ** 2
    q = 2 * np.pi * np.fft.fftfreq(n, h)
    q2 = q[:, None] ** 2 + q[None, :] ** 2
    m0, m2, m4 = spectrum.sum(), 0.5 * (q2 * spectrum).sum(), 3 / 8 * (q2**2 * spectrum).sum()
    e_star = 210e9 / (2 * (1 - 0.3**2))
    r, p = _greenwood_tripp(out.summary["load_n"], 0.01, e_star,
                            m4 / (6 * np.pi * np.sqrt(3) * m2), 0.375 * np.sqrt(np.pi / m4),
                            np.sqrt((1 - 0.8968 * m2**2 / (m0 * m4)) * m0))
    rms_gt = np.sqrt(np.sum(p * r**3) / np.sum(p * r))
    rows = {c.quantity: c for c in out.comparisons if "Greenwood" in c.source}
    assert rows["load rms radius"].reference == pytest.approx(rms_gt, rel=3e-3)
    assert rows["load rms radius"].passed is None and rows["real contact area"].passed is None
    pressure = out.dataset.pressure.values
    rms = np.sqrt((pressure * (x[:, None] ** 2 + x[None, :] ** 2)).sum() / pressure.sum())
    assert out.summary["load_rms_radius_m"] == pytest.approx(rms, rel=1e-9)
    assert rms == pytest.approx(rms_gt, rel=0.08)  # 4-5 % under GT (docs/tangential.md)
    assert 1.1 < out.summary["contact_area_m2"] / out.summary["greenwood_tripp_real_area_m2"]
    data["roughness"] = {"kind": "ground", "ra": "0.2 um"}
    ground = run_case(load_case(data))
    assert "greenwood_tripp_real_area_m2" not in ground.summary


def test_a_smooth_flat_punch_says_its_largest_pressure_is_the_meshs():
    """A user's 1 mm square steel punch on steel (1 kN, open 1 mm grid): the edge singularity
    of a rigid punch made "maximum pressure 5.58 GPa" on 32 x 32 cells and 9.02 GPa on
    64 x 64 (+62 %), with nothing said but the flat-on-an-open-grid line. The approach is
    checked against our own direct solve of Love's (1929) coefficients of a uniformly loaded
    rectangle with a uniform approach, 7.6009 um on 32 x 32; a note now says the largest pressure is
    the mesh's and names what converges."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    def run(n):
        return run_case(load_case({
            "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
            "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "flat"},
            "loading": {"load": "1 kN"},
            "grid": {"nx": n, "ny": n, "x_extent": "1 mm", "y_extent": "1 mm"}}))

    n, side, e_star = 32, 1e-3, 210e9 / (2 * (1 - 0.3**2))
    d = side / n
    c = (np.arange(n) + 0.5) * d
    X, Y = (v.ravel() for v in np.meshgrid(c, c, indexing="ij"))

    def f(a, b):
        r = np.hypot(a, b)
        return a * np.log(b + r) + b * np.log(a + r)

    dx, dy = X[:, None] - X[None, :], Y[:, None] - Y[None, :]
    love = (f(dx + d / 2, dy + d / 2) - f(dx + d / 2, dy - d / 2) - f(dx - d / 2, dy + d / 2)
            + f(dx - d / 2, dy - d / 2)) / (np.pi * e_star)
    p = np.linalg.solve(love, np.ones(n * n))  # unit approach
    coarse, fine = run(32), run(64)
    assert coarse.summary["approach_m"] == pytest.approx(1e3 / (p.sum() * d * d), rel=1e-6)
    assert coarse.summary["max_pressure_pa"] == pytest.approx(1e3 / (p.sum() * d * d)
                                                              * p.max(), rel=1e-5)
    assert fine.summary["max_pressure_pa"] > 1.5 * coarse.summary["max_pressure_pa"]
    (note,) = [s for s in fine.notes if s.startswith("A smooth flat on an open grid")]
    assert "9.02 GPa" in note and "set by the cell size" in note
    assert not [s for s in run_case(load_case({
        "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
        "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "sphere", "rx": "10 mm"},
        "loading": {"load": "50 N"},
        "grid": {"nx": 32, "ny": 32, "x_extent": "0.4 mm", "y_extent": "0.4 mm"}})).notes
        if s.startswith("A smooth flat")]


def _ball_case(geometry, modulus="210 GPa", load="50 N"):
    """A steel ball's normal case (R = 10 mm unless ``geometry`` says otherwise)."""
    return {"analysis": "normal",
            "body1": {"youngs_modulus": modulus, "poisson_ratio": 0.3},
            "body2": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
            "geometry": geometry, "loading": {"load": load},
            "grid": {"nx": 48, "ny": 48, "x_extent": "0.6 mm", "y_extent": "0.6 mm"}}


def test_a_sphere_with_two_radii_is_refused_not_solved_as_an_ellipsoid():
    """A user's ``shape = "sphere"`` with ``rx = "10 mm"`` and a stray ``ry = "40 mm"`` ran
    as an ellipsoid under the name of a sphere: Hertz semi-axes 145.0 and 362.5 um at 100 N
    on steel, not the sphere's a = (3 P R / (4 E*))^(1/3) = 186.6 um. Now it is one line
    naming geometry.ry; ``ry`` equal to ``rx`` is still a sphere, and a flat with a radius is
    refused likewise (it was ignored)."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    with pytest.raises(InputError, match=r'^geometry\.ry: expected no ry for a sphere.*'
                       r'"ellipsoid"'):
        load_case(_ball_case({"shape": "sphere", "rx": "10 mm", "ry": "40 mm"}, load="100 N"))
    with pytest.raises(InputError, match=r'^geometry\.rx: expected no rx for shape = "flat"'):
        load_case(_ball_case({"shape": "flat", "rx": "10 mm"}))
    out = run_case(load_case(_ball_case({"shape": "sphere", "rx": "10 mm", "ry": "10 mm"},
                                        load="100 N")))
    e_star = 210e9 / (2 * (1 - 0.3**2))
    a = (3 * 100.0 * 0.01 / (4 * e_star)) ** (1 / 3)
    assert out.summary["hertz_a_m"] == pytest.approx(a, rel=1e-9)
    assert out.summary["hertz_b_m"] == pytest.approx(a, rel=1e-9)


def test_a_modulus_stiffer_than_diamond_is_refused():
    """``youngs_modulus = "30e6 GPa"`` (GPa typed for psi) is 3e16 Pa, 25000 times diamond's
    1.2 TPa; it ran with only a mesh warning (a contact of 11 um on a 1 mm grid). Now it is
    refused, naming the key and the unit to check; 1.2 TPa itself (diamond) runs."""
    from asperity.cases import load_case

    with pytest.raises(InputError, match=r"^body1\.youngs_modulus: expected at most 1200 GPa "
                       r"\(diamond's.*check the unit"):
        load_case(_ball_case({"shape": "sphere", "rx": "10 mm"}, modulus="30e6 GPa"))
    load_case(_ball_case({"shape": "sphere", "rx": "10 mm"}, modulus="1.2 TPa"))


def test_a_bare_modulus_that_reads_as_psi_is_warned_about():
    """``youngs_modulus = 30e6`` (a bare TOML number: Pa) for a steel ball meant as 30e6 psi is
    30 MPa, 6895 times softer: the run warned only of the consequences (a/R = 0.48, a rubber's
    strains, the contact off the grid), never of the unit. Now the first line names
    body1.youngs_modulus with both readings: 30 MPa, and 30e6 psi = 30e6 x 6894.757 Pa =
    206.8 GPa. Written with its unit ("30e6 psi", "30 MPa"), or as a bare SI steel modulus
    (210e9), no such line; with "30e6 psi" the contact radius is Hertz's for E = 206.8 GPa."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    sphere = {"shape": "sphere", "rx": "10 mm"}
    out = run_case(load_case(_ball_case(sphere, modulus=30e6, load="0.001 N")))
    (line,) = [w for w in out.warnings if w.startswith("body1.youngs_modulus")]
    assert "bare number 3e7 is read in Pa, 30 MPa" in line
    assert "206.8 GPa" in line and '"3e7 psi"' in line
    for modulus in ("30e6 psi", "30 MPa", 210e9):
        quiet = run_case(load_case(_ball_case(sphere, modulus=modulus, load="0.001 N")))
        assert not [w for w in quiet.warnings if "youngs_modulus" in w]
    psi = run_case(load_case(_ball_case(sphere, modulus="30e6 psi", load="50 N")))
    e1 = 30e6 * 6894.757293168
    e_star = 1.0 / ((1 - 0.3**2) / e1 + (1 - 0.3**2) / 210e9)
    assert psi.summary["hertz_a_m"] == pytest.approx((3 * 50 * 0.01 / (4 * e_star)) ** (1 / 3),
                                                     rel=1e-9)


def test_a_bare_modulus_that_reads_as_psi_is_warned_about_in_an_ehl_run():
    """The same line leads an EHL run's warnings (:func:`asperity.cases.doubts.unit_doubts`,
    shared by every runner): a steel ball on steel, ``body1.youngs_modulus = 30e6``, 20 N,
    1 m/s, on a coarse mesh; with ``"30e6 psi"`` none."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    def case(modulus):
        return {"analysis": "ehl-steady",
                "body1": {"youngs_modulus": modulus, "poisson_ratio": 0.3},
                "body2": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
                "contact": {"type": "point", "rx": "10 mm", "ry": "10 mm", "load": "20 N"},
                "speeds": {"u": "1 m/s"}, "lubricant": {"eta0": "0.1 Pa s", "alpha": "20 1/GPa"},
                "grid": {"nx": 65, "ny": 17}}

    out = run_case(load_case(case(30e6)))
    assert out.warnings[0].startswith("body1.youngs_modulus: the bare number 3e7 is read in Pa")
    quiet = run_case(load_case(case("30e6 psi")))
    assert not [w for w in quiet.warnings if "youngs_modulus" in w]


def test_a_generator_refusal_names_the_key_in_its_table_with_the_value():
    """``correlation_length = 40`` (meant in um, read in m) was refused as "correlation_length:
    expected a length the surface can hold ...", naming a key no table has and no value. Now
    the line names ``roughness.correlation_length`` and the 40 m it read; a transient run's
    surface likewise (``surface2.correlation_length``)."""
    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    text = example_text("rough-flat-normal").replace('kind = "self-affine"', 'kind = "gaussian"')
    text = "\n".join(line for line in text.splitlines()
                     if not line.startswith(("hurst", "rolloff_wavelength", "short_cutoff")))
    text = text.replace('rms = "0.5 um"', 'rms = "0.5 um"\ncorrelation_length = 40')
    with pytest.raises(InputError, match=r"^roughness\.correlation_length: expected a length "
                       r"the surface can hold.*got '40 m'$"):
        run_case(load_case(text))
    transient = {"analysis": "ehl-transient", "reduced_modulus": "227 GPa",
                 "contact": {"type": "line", "radius": "19.1 mm",
                             "load_per_length": "527 kN/m"},
                 "speeds": {"u": "25 m/s", "xi": 0.25},
                 "lubricant": {"eta0": "0.0048 Pa s", "alpha": "11.1 1/GPa"},
                 "grid": {"nx": 81}, "time": {"counting_steps": 5},
                 "surface2": {"kind": "gaussian", "rms": "0.05 um", "correlation_length": 40}}
    with pytest.raises(InputError, match=r"^surface2\.correlation_length: .*got '40 m'$"):
        run_case(load_case(transient))


def test_a_roll_off_longer_than_the_patch_is_reported_by_the_run():
    """The runner's use of :func:`asperity.diagnostics.roughness_extent`: the built-in
    ``rough-flat-normal`` (roll-off 0.1 mm on a 0.5 mm patch) is silent; with
    ``rolloff_wavelength = 100`` (um meant, read in m) its run names the key and the grid."""
    from asperity.cases import load_case
    from asperity.examples import example_text
    from asperity.runners import run_case

    text = example_text("rough-flat-normal")
    assert not [w for w in run_case(load_case(text)).warnings if "rolloff" in w]
    text = text.replace('rolloff_wavelength = "0.1 mm"', "rolloff_wavelength = 100")
    (line,) = [w for w in run_case(load_case(text)).warnings if "rolloff" in w]
    assert line.startswith("roughness: rolloff_wavelength = 100 m is longer than the grid "
                           "(500 µm x 500 µm;")
