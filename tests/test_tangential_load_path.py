"""Load paths: Masing unloading against the closed form, energy per cycle, load sharing."""

import numpy as np
import pytest

from asperity.contact import hertz_point
from asperity.contact import reference as ref
from asperity.contact.load_path import proportional_path, tangential_load_path
from asperity.materials import Material

STEEL = Material(206e9, 0.3, "steel")
P, MU = 1000.0, 0.3
HZ = hertz_point(P, 0.01, 0.01, STEEL, STEEL)
A = HZ.a


def hertz_grid(n=48):
    x = (np.arange(n) - (n - 1) / 2) * (2.1 * A / n)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = HZ.pressure(X, Y)
    return x, p * P / (p.sum() * (x[1] - x[0]) ** 2)


def test_masing_cycle_and_dissipation():
    x, p = hertz_grid()
    peak = 0.6 * MU * P
    loads = proportional_path((peak, 0.0), 0.0, steps=3, cycle=True)
    path = tangential_load_path(p, x, x, MU, STEEL, STEEL, loads)
    assert path.converged and path.gross_slip_step == -1
    # loading branch (first 3 steps): Cattaneo-Mindlin
    for k in range(3):
        cm = ref.cattaneo_mindlin(P, loads[k, 0], MU, A, STEEL, STEEL)
        assert path.shift[k, 0] == pytest.approx(cm.shift, rel=0.02)
    # unloading branch from the peak: Masing
    for k in range(3, 9):
        expected = ref.masing_unloading_shift(loads[k, 0], peak, P, MU, A, STEEL, STEEL)
        assert path.shift[k, 0] == pytest.approx(expected, rel=0.02, abs=0.02 * path.shift[2, 0])
    # reloading ends where loading ended: the loop closes
    assert path.shift[-1, 0] == pytest.approx(path.shift[2, 0], rel=0.01)
    # energy per cycle: the same trapezoidal loop area on the closed-form Masing loop
    def unload(q):
        return ref.masing_unloading_shift(q, peak, P, MU, A, STEEL, STEEL)

    exact = np.array([unload(q) for q in loads[2:9, 0]] + [-unload(-q) for q in loads[9:, 0]])
    q = loads[2:, 0]
    loop = np.sum(0.5 * (q[1:] + q[:-1]) * np.diff(exact))
    assert loop > 0
    assert path.dissipated_energy == pytest.approx(loop, rel=0.03)


def test_path_stops_at_gross_slip_and_shares_load():
    n = 36
    x = np.linspace(-1e-3, 1e-3, n)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = np.where((np.abs(X + 5e-4) < 3e-4) & (np.abs(Y) < 3e-4), 2e8, 0.0)
    p += np.where((np.abs(X - 5e-4) < 3e-4) & (np.abs(Y) < 3e-4), 1e8, 0.0)
    capacity = MU * p.sum() * (x[1] - x[0]) ** 2
    loads = proportional_path((1.2 * capacity, 0.0), 0.0, steps=6)
    path = tangential_load_path(p, x, x, MU, STEEL, STEEL, loads)
    assert path.gross_slip_step == 4  # 1.0 capacity is gross slip
    assert path.region_force.shape[1] == 2
    total = path.region_force[:4].sum(axis=1)
    np.testing.assert_allclose(total[:, 0], loads[:4, 0], rtol=1e-8)
    assert np.all(np.diff(path.stick_fraction[:4]) < 0)


def test_masing_history_follows_mindlin_deresiewicz_and_closes_its_loop():
    """A cycle 0 -> Q* -> -Q* -> Q*: the loading branch is Cattaneo-Mindlin's shift, the
    unloading one Johnson's eq. 7.56 (masing_unloading_shift), and the reloading branch ends
    where the first loading did (Masing's loop closes); a history past mu P ends at mu P."""
    peak = 0.8 * MU * P
    shift, force = ref.masing_history([peak, -peak, peak], P, MU, A, STEEL, STEEL, points=8)
    loading = slice(1, 9)
    for q, d in zip(force[loading], shift[loading], strict=True):
        assert d == pytest.approx(ref.cattaneo_mindlin(P, q, MU, A, STEEL, STEEL).shift,
                                  rel=1e-12)
    for q, d in zip(force[9:17], shift[9:17], strict=True):
        assert d == pytest.approx(ref.masing_unloading_shift(q, peak, P, MU, A, STEEL, STEEL),
                                  rel=1e-12, abs=1e-15)
    assert force[-1] == pytest.approx(peak) and shift[-1] == pytest.approx(shift[8], rel=1e-12)
    assert shift[16] == pytest.approx(-shift[8], rel=1e-12)  # the loop is odd
    over, f_over = ref.masing_history([2 * MU * P], P, MU, A, STEEL, STEEL)
    assert f_over[-1] == pytest.approx(MU * P) and over[-1] == pytest.approx(
        ref.cattaneo_mindlin(P, MU * P, MU, A, STEEL, STEEL).shift)


def test_a_path_past_gross_slip_says_so_in_the_headline_and_the_applied_load_matches_mindlin():
    """A steel ball (R = 10 mm, 50 N, mu = 0.3: mu P = 15 N, a = 148.1 um) under 10 N, its
    load path continued to twice that (20 N, past gross slip). At 10 N, Cattaneo-Mindlin:
    c/a = (1 - Q / mu P)^(1/3) = 0.693 (c = 102.7 um), and the relative shift
    3 mu P / (16 a) (2 (2 - nu) / G) (1 - (1 - Q / mu P)^(2/3)) = 415.1 nm. The headline said
    "gross slip: no" only, for the applied load; it now also shows the path's "yes"."""
    from asperity.cases import load_case
    from asperity.report import render_report
    from asperity.runners import run_case

    case = {"analysis": "tangential", "mu": 0.3,
            "body1": {"youngs_modulus": "210 GPa"}, "body2": {"youngs_modulus": "210 GPa"},
            "pressure": {"source": "hertz", "load": "50 N", "rx": "10 mm"},
            "loading": {"force": "10 N"}, "load_path": {"steps": 8, "scale": 2.0}}
    out = run_case(load_case(case))
    e_star = 210e9 / (2 * (1 - 0.3**2))
    a = (3 * 50 * 0.01 / (4 * e_star)) ** (1 / 3)
    g = 210e9 / 2.6
    shift = 3 * 15 / (16 * a) * 2 * 1.7 / g * (1 - (1 / 3) ** (2 / 3))
    s = out.summary
    assert s["stick_radius_m"] == pytest.approx(a * (1 / 3) ** (1 / 3), rel=0.01)
    assert s["shift_m"] == pytest.approx(shift, rel=0.01)
    assert not s["gross_slip"] and s["path_gross_slip"]
    headline = render_report("t", case, out, {}).split("<div class=headline>")[1]
    headline = headline.split("</div></div>" * 4)[0]
    assert "gross slip at the applied load" in headline
    assert "gross slip on the load path" in headline
