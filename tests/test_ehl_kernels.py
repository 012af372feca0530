"""Compiled EHL kernels: the block elimination against a dense solve of the same rows and
columns, the y-line sweep at a converged state, the density's Newton term against a finite
difference of the wedge term, the oscillation damping against its definition."""

import numpy as np
import pytest

from asperity.ehl import Lubricant, PointContact
from asperity.ehl.kernels import (
    CAVITATED,
    CONTACT,
    _assemble_column,
    _assemble_row,
    _block_band_solve,
    column_sweep,
    damp_oscillations,
)
from asperity.ehl.solver import EHLState, solve_steady
from asperity.materials import Material

STEEL = Material(227e9 * (1 - 0.3**2), 0.3, "steel")
GEAR = PointContact(0.0191, 0.151, 962.0, 28.125, 21.875, STEEL, STEEL,
                    Lubricant(viscosity=0.005, pressure_viscosity=11.1e-9, eyring_stress=10e6))


def dense(m, bl):
    """The full matrix of block-band storage ``m[i, j - i + bl]`` (2 x 2 blocks)."""
    n, w = m.shape[:2]
    a = np.zeros((2 * n, 2 * n))
    for i in range(n):
        for d in range(w):
            j = i + d - bl
            if 0 <= j < n:
                a[2 * i:2 * i + 2, 2 * j:2 * j + 2] = m[i, d]
    return a


@pytest.fixture(scope="module")
def rough_state():
    """A Hertzian start on rough surfaces, with nodes forced to contact and cavitation."""
    x, y = GEAR.grid(161, 21, None)
    s = EHLState(GEAR, x, y, near=2)
    s.hertz_start(GEAR.film_estimate() / GEAR.film_scale)
    rng = np.random.default_rng(3)
    s.roughness = 0.3 * s.H.max() * rng.standard_normal(s.P.shape)
    s.refresh()
    s.kind[40:60:3] = CONTACT
    s.kind[100:130:4] = CAVITATED
    return s


@pytest.mark.parametrize("near", [0, 2, 4])
def test_block_elimination_equals_dense_solve(rough_state, near):
    """Rows of fluid, contact and cavitated nodes: agreement to 1e-10 of the solution."""
    s = rough_state
    f_near = EHLState(GEAR, s.x, s.y, near=near).f_near
    ex, ey, rho, dex, dey, _ = s.flow_coefficients(slopes=True)
    bl, bu = max(2, near), max(1, near)
    nx = s.P.shape[0]
    for j in (3, 10, 17):
        m = np.empty((nx, bl + bu + 1, 2, 2))
        b = np.empty((nx, 2))
        _assemble_row(s.P, s.H, ex, ey, rho, s.efar, s.rhs_t, s.lam, s.dX, s.dY, 0.5,
                      s.lam / 1e-3, s.c, f_near, j, s.kind[:, j], m, b, bl, dex, dey, None)
        expected = np.linalg.solve(dense(m, bl), b.ravel()).reshape(nx, 2)
        _block_band_solve(m, b, bl, bu)
        for k in range(2):
            scale = np.abs(expected[:, k]).max()
            assert np.max(np.abs(b[:, k] - expected[:, k])) < 1e-10 * scale
        assert np.all(b[s.kind[:, j] == CONTACT, 1] == pytest.approx(0.0, abs=1e-12))
        assert np.all(b[s.kind[:, j] == CAVITATED, 0] == pytest.approx(0.0, abs=1e-12))


def test_column_elimination_equals_dense_solve(rough_state):
    """Columns (the y-line update) of fluid, contact and cavitated nodes: the block-tridiagonal
    elimination agrees with a dense solve of the same system to 1e-10."""
    s = rough_state
    s.kind[70:90, 5:15:2] = CONTACT
    s.kind[95, 3:18:3] = CAVITATED
    ex, ey, rho, dex, dey, _ = s.flow_coefficients(slopes=True)
    ny = s.P.shape[1]
    loaded = 0.0
    for i in (35, 65, 80, 90):  # (rows 40-60 and 100-130 are all contact or cavitated)
        m = np.empty((ny, 3, 2, 2))
        b = np.empty((ny, 2))
        _assemble_column(s.P, s.H, ex, ey, rho, s.efar, s.rhs_t, s.lam, s.dX, s.dY, 0.5,
                         s.lam / 1e-3, s.c, s.f_near, i, s.kind, m, b, dex, dey)
        expected = np.linalg.solve(dense(m, 1), b.ravel()).reshape(ny, 2)
        _block_band_solve(m, b, 1, 1)
        for k in range(2):
            scale = np.abs(expected[:, k]).max()
            assert np.max(np.abs(b[:, k] - expected[:, k])) < 1e-10 * scale + 1e-12
        assert np.all(b[s.kind[i] == CONTACT, 1] == pytest.approx(0.0, abs=1e-12))
        assert np.all(b[s.kind[i] == CAVITATED, 0] == pytest.approx(0.0, abs=1e-12))
        loaded = max(loaded, b[:, 0].max())
    assert loaded > 0.1  # columns through the loaded zone


def test_a_y_line_sweep_leaves_a_converged_state_unchanged():
    """The y-line update solves the same discrete equations as the x-line update: from a
    smooth state converged by x-line sweeps to 1e-11, one column sweep changes p and h by no
    more than 1e-8 (a column that dropped or doubled a term, e.g. the implicit y-Laplacian of
    h or an explicit x-neighbour's near-field pressure, moves them by 1e-3 or more)."""
    res = solve_steady(GEAR, nx=65, ny=17, tol=1e-11, max_iter=20000)
    assert res.converged
    s = EHLState(GEAR, res.x, res.y, near=4)
    s.P = res.pressure / GEAR.p_hertz
    s.H = res.film / GEAR.film_scale
    s.H0 = res.separation / GEAR.film_scale
    s.kind[(s.P <= 0.0) & ~s.edge] = CAVITATED
    s.refresh()
    p, h = s.P.copy(), s.H.copy()
    ex, ey, rho, dex, dey, _ = s.flow_coefficients(slopes=True)
    dp, dh = column_sweep(s.P, s.H, ex, ey, rho, s.efar, s.rhs_t, s.lam, s.dX, s.dY, s.theta,
                          s.mass, s.c, s.f_near, s.kind, dex, dey)
    assert dp < 1e-8 and dh < 1e-8
    assert np.abs(s.P - p).max() < 1e-8 and np.abs(s.H - h).max() < 1e-8
    s.P, s.H = p, h  # the x-line sweep from there: converged by the same measure
    assert max(s.sweep("line")) < 1e-8
    assert s.P.max() > 0.5  # a loaded contact, not a trivial state
    # a sweep that did nothing would pass the above: a column of the first colour (solved
    # first, its neighbours at the converged state) knocked off by 2 % in p and 1 % in h at
    # its fluid nodes is put back by one column sweep (Newton terms off, so the column's
    # equations are those of the fixed point exactly)
    colours = max(3, s.f_near.size)
    i = 1 + colours * int(np.argmin(np.abs(s.X[1::colours])))
    fluid = (s.P[i] > 0.0) & ~s.edge[i]
    assert fluid.sum() >= 5
    s.P, s.H = p.copy(), h.copy()
    s.P[i, fluid] *= 1.02
    s.H[i, fluid] *= 1.01
    assert np.abs(s.P - p).max() > 1e-3
    zero = np.zeros_like(dex)
    column_sweep(s.P, s.H, ex, ey, rho, s.efar, s.rhs_t, s.lam, s.dX, s.dY, s.theta, s.mass,
                 s.c, s.f_near, s.kind, zero, zero)
    assert np.abs(s.P - p).max() < 1e-8 and np.abs(s.H - h).max() < 1e-8


def test_density_newton_term_is_the_wedge_derivative(rough_state):
    """With ``drho`` the row's pressure coefficients gain the derivative of the Reynolds wedge
    and time terms ``-theta lam (c0 (rho h)_i - c1 (rho h)_{i-1} + c2 (rho h)_{i-2})/dX
    - mass (rho h)_i`` with respect to p_i, p_{i-1}, p_{i-2} through the Dowson-Higginson
    density: against a central difference of those terms with ``density_ratio`` (1e-6
    relative) at the fluid nodes; the right-hand side moves by the same coefficients times
    the current pressures, so the row's equations are unchanged at the current iterate."""
    s = rough_state
    prob = s.problem
    ex, ey, rho, dex, dey, drho = prob.lubricant.flow_field(
        s.P, s.H, prob.sliding_speed, slopes=True, density_slope=True,
        units=(prob.p_hertz, prob.film_scale, 1.0))
    theta, mass, bl, j = 0.5, s.lam / 1e-3, 2, 10
    nx = s.P.shape[0]
    rows = []
    for d in (None, drho):
        m = np.empty((nx, 5, 2, 2))
        b = np.empty((nx, 2))
        _assemble_row(s.P, s.H, ex, ey, rho, s.efar, s.rhs_t, s.lam, s.dX, s.dY, theta, mass,
                      s.c, s.f_near, j, s.kind[:, j], m, b, bl, dex, dey, d)
        rows.append((m, b))
    (m0, b0), (m1, b1) = rows
    density = prob.lubricant.density_ratio

    def wedge(i, p):  # the terms at node i with p the pressures of nodes i, i-1, i-2 (GPa units)
        c0, c1, c2 = (1.5, 2.0, 0.5) if i >= 2 else (1.0, 1.0, 0.0)
        q = [density(max(pk, 0.0) * prob.p_hertz) * s.H[i - k, j]
             for k, pk in enumerate(p[:min(i, 2) + 1])]
        q += [0.0] * (3 - len(q))
        return -theta * s.lam * (c0 * q[0] - c1 * q[1] + c2 * q[2]) / s.dX - mass * q[0]

    checked = 0
    for i in range(1, nx - 1):
        if s.kind[i, j] != 0 or s.P[i, j] <= 0.01:
            continue
        p = [s.P[i - k, j] for k in range(min(i, 2) + 1)]
        for k in range(len(p)):
            if p[k] <= 0.01:
                continue
            step = 1e-6
            up, down = list(p), list(p)
            up[k] += step
            down[k] -= step
            expected = (wedge(i, up) - wedge(i, down)) / (2 * step)
            got = m1[i, bl - k, 0, 0] - m0[i, bl - k, 0, 0]
            assert got == pytest.approx(expected, rel=1e-6, abs=1e-9 * abs(m0[i, bl, 0, 1]))
            checked += 1
        moved = sum((m1[i, bl - k, 0, 0] - m0[i, bl - k, 0, 0]) * p[k] for k in range(len(p)))
        assert b1[i, 0] - b0[i, 0] == pytest.approx(moved, rel=1e-9, abs=1e-12)
    assert checked > 100


def _sweep_changes(seed):
    """A random iterate before a sweep, the sweep's result and the previous change of p on
    9 x 4 nodes, and where the change reverses sign (some nodes, not all)."""
    rng = np.random.default_rng(seed)
    before_p, before_h = rng.uniform(0, 1, (2, 9, 4))
    new_p = before_p + rng.standard_normal((9, 4))
    new_h = before_h + rng.standard_normal((9, 4))
    last = rng.standard_normal((9, 4))
    reverse = (new_p - before_p) * last < 0
    assert 0 < reverse.sum() < reverse.size
    return before_p, before_h, new_p, new_h, last, reverse


def test_damping_scales_only_the_reversing_changes():
    """Nodes whose p change reverses sign are moved back to before + damping * change (p and
    h); the others keep the sweep's result; the recorded change is the damped one."""
    before_p, before_h, p, h, last, reverse = _sweep_changes(5)
    expected_p = np.where(reverse, before_p + 0.7 * (p - before_p), p)
    expected_h = np.where(reverse, before_h + 0.7 * (h - before_h), h)
    damp_oscillations(p, h, before_p, before_h, last, 0.7, True, 1.0)
    np.testing.assert_allclose(p, expected_p, rtol=1e-15)
    np.testing.assert_allclose(h, expected_h, rtol=1e-15)
    np.testing.assert_allclose(last, expected_p - before_p, rtol=1e-12)
    p2, h2 = p + 1.0, h.copy()
    damp_oscillations(p2, h2, p, h, last, 0.7, False, 1.0)  # no previous change: nothing damped
    np.testing.assert_array_equal(p2, p + 1.0)
    np.testing.assert_allclose(last, 1.0)


def test_relaxation_scales_every_change_and_the_reversing_ones_again():
    """Under-relaxation 0.5 moves every node to before + 0.5 * change, a reversing node to
    before + 0.5 * 0.7 * change (independent expressions of the two factors)."""
    before_p, before_h, new_p, new_h, last, reverse = _sweep_changes(8)
    factor = np.where(reverse, 0.35, 0.5)
    p, h = new_p.copy(), new_h.copy()
    damp_oscillations(p, h, before_p, before_h, last, 0.7, True, 0.5)
    np.testing.assert_allclose(p - before_p, factor * (new_p - before_p), rtol=1e-12)
    np.testing.assert_allclose(h - before_h, factor * (new_h - before_h), rtol=1e-12)
    np.testing.assert_allclose(last, p - before_p, rtol=1e-12)
