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
