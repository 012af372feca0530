"""Frictional contact solver (method="fft") against closed forms and brute-force references."""

import numpy as np
import pytest

from asperity.contact import hertz_point
from asperity.contact import reference as ref
from asperity.contact.tangential import friction_capacity, solve_tangential
from asperity.errors import InputError
from asperity.materials import Material

STEEL = Material(206e9, 0.3, "steel")
P, MU = 1000.0, 0.3
HZ = hertz_point(P, 0.01, 0.01, STEEL, STEEL)
A = HZ.a
N = 64


def grid(n=N, half=1.05 * A):
    x = (np.arange(n) - (n - 1) / 2) * (2 * half / n)
    return x, x.copy(), *np.meshgrid(x, x, indexing="ij")


def hertz_pressure(n=N):
    """Hertz pressure at the cell centres, scaled so that the discrete load is exactly P."""
    x, y, X, Y = grid(n)
    p = HZ.pressure(X, Y)
    return x, y, X, Y, p * P / (p.sum() * (x[1] - x[0]) ** 2)


def stick_radius(result, x):
    return np.sqrt(result.stick.sum() * (x[1] - x[0]) ** 2 / np.pi)


@pytest.mark.parametrize("ratio", [0.25, 0.5, 0.75, 0.9])
def test_cattaneo_mindlin(ratio):
    x, y, X, Y, p = hertz_pressure()
    Q = ratio * MU * P
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, force=(Q, 0.0))
    cm = ref.cattaneo_mindlin(P, Q, MU, A, STEEL, STEEL)
    assert r.converged and not r.gross_slip
    assert stick_radius(r, x) == pytest.approx(cm.stick_radius, rel=0.02)
    assert r.shift[0] == pytest.approx(cm.shift, rel=0.02)
    assert abs(r.shift[1]) < 1e-6 * cm.shift and abs(r.rotation) * A < 1e-6 * cm.shift
    np.testing.assert_allclose(r.force, [Q, 0.0], atol=1e-9 * Q)
    exact = cm.traction(np.hypot(X, Y))
    contact = p > 0
    rms = np.sqrt(np.mean((r.traction[0][contact] - exact[contact]) ** 2))
    assert rms < 0.02 * MU * HZ.p_max
    # stick where |q| < mu p, slip parallel to the traction elsewhere
    slip = ~r.stick & contact
    cosine = np.sum(r.slip * r.traction, axis=0)[slip] / (
        np.hypot(*r.slip)[slip] * np.hypot(*r.traction)[slip])
    assert np.all(cosine > 0.99)


@pytest.mark.parametrize("fraction", [0.3, 0.6, 0.85])
def test_lubkin_torsion(fraction):
    x, y, X, Y, p = hertz_pressure()
    m_gs = ref.gross_slip_moment_hertz(MU, P, A)
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, moment=fraction * m_gs)
    c = ref.lubkin_stick_radius(fraction * m_gs, A, MU, HZ.p_max)
    assert r.converged
    assert stick_radius(r, x) == pytest.approx(c, rel=0.02)
    # relative twist of two identical spheres: twice one body's
    assert r.rotation == pytest.approx(ref.lubkin_twist(c, A, MU, HZ.p_max, STEEL, STEEL),
                                       rel=0.02)
    assert r.moment == pytest.approx(fraction * m_gs, rel=1e-9)
    np.testing.assert_allclose(r.center_of_rotation, [0, 0], atol=1e-6 * A)


def test_lubkin_gross_slip_moment():
    x, y, X, Y, p = hertz_pressure()
    m_gs = ref.gross_slip_moment_hertz(MU, P, A)
    t, _ = friction_capacity(p, x, y, MU, moment=m_gs)
    assert t == pytest.approx(1.0, rel=0.01)
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, moment=1.1 * m_gs)
    assert r.gross_slip and r.converged
    assert r.load_capacity * 1.1 * m_gs == pytest.approx(m_gs, rel=0.01)
    assert r.excess[2] == pytest.approx((1 - r.load_capacity) * 1.1 * m_gs)
    np.testing.assert_allclose(np.hypot(*r.traction), MU * p, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("fraction", [0.3, 0.6, 0.85])
def test_uniform_pressure_torsion(fraction):
    x, y, X, Y = grid()
    pu = 1e8
    p = np.where(X**2 + Y**2 <= A * A, pu, 0.0)
    m = fraction * ref.gross_slip_moment_uniform(MU, pu, A)
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, moment=m)
    c = ref.uniform_torsion_stick_radius(m, A, MU, pu)
    assert r.converged
    assert stick_radius(r, x) == pytest.approx(c, rel=0.02)
    assert r.rotation == pytest.approx(ref.uniform_torsion_twist(c, A, MU, pu, STEEL, STEEL),
                                       rel=0.02)


def test_gross_slip_moment_is_min_over_centres():
    """Two unequal patches: capacity = min_c sum mu p |r - c| dA, by brute force."""
    n = 40
    x = np.linspace(-1.5e-3, 1.5e-3, n)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = np.where((np.abs(X + 7e-4) < 5e-4) & (np.abs(Y) < 5e-4), 2e8, 0.0)
    p += np.where((X - 8e-4) ** 2 + (Y - 3e-4) ** 2 < (4e-4) ** 2, 1e8, 0.0)
    area = (x[1] - x[0]) ** 2
    cs = np.linspace(-1.5e-3, 1.5e-3, 121)
    best = min(np.sum(MU * p * np.hypot(X - cx, Y - cy)) * area for cx in cs for cy in cs)
    r = solve_tangential(p, x, x, MU, STEEL, STEEL, moment=2 * best)
    assert r.gross_slip
    assert r.load_capacity * 2 * best == pytest.approx(best, rel=0.01)
    assert r.load_capacity * 2 * best <= best * (1 + 1e-9)  # a minimum: never above the search
    assert len(r.regions) == 2
    np.testing.assert_allclose(sum(reg.moment for reg in r.regions), r.moment, rtol=1e-9)


def test_force_beyond_friction_is_reported():
    x, y, X, Y, p = hertz_pressure(32)
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, force=(0.0, 1.5 * MU * P))
    assert r.gross_slip and r.converged
    assert r.load_capacity == pytest.approx(1 / 1.5, rel=1e-6)
    np.testing.assert_allclose(r.force, [0.0, MU * P], atol=1e-6 * P)
    np.testing.assert_allclose(r.excess, [0.0, 0.5 * MU * P, 0.0], atol=1e-6 * P)
    assert np.all(np.isnan(r.shift)) and not r.stick.any()


def test_combined_load_equilibrium_and_callback():
    x, y, X, Y, p = hertz_pressure(32)
    seen = []
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, force=(40.0, -30.0), moment=0.02,
                         center=(1e-5, 0.0), callback=lambda i, res: seen.append((i, res)))
    assert r.converged and seen and seen[-1][1] <= 1e-8
    np.testing.assert_allclose(r.force, [40.0, -30.0], rtol=1e-9)
    assert r.moment == pytest.approx(0.02, rel=1e-9)
    assert np.all(np.hypot(*r.traction) <= MU * p * (1 + 1e-12) + 1e-9)


def test_dissimilar_materials_run_with_coupling():
    x, y, X, Y, p = hertz_pressure(32)
    soft = Material(70e9, 0.33, "aluminium")
    r = solve_tangential(p, x, y, MU, STEEL, soft, force=(0.5 * MU * P, 0.0))
    assert r.converged and not r.gross_slip


def test_not_converged_is_flagged():
    x, y, X, Y, p = hertz_pressure(32)
    r = solve_tangential(p, x, y, MU, STEEL, STEEL, force=(0.5 * MU * P, 0.0), max_iter=5)
    assert not r.converged and r.iterations == 5


def test_bad_input():
    x, y, X, Y, p = hertz_pressure(16)
    with pytest.raises(InputError, match="mu"):
        solve_tangential(p, x, y, 0.0, STEEL, STEEL, force=(1.0, 0.0))
    with pytest.raises(InputError, match="mu"):
        solve_tangential(p, x, y, -0.1, STEEL, STEEL, force=(1.0, 0.0))
    with pytest.raises(InputError, match="pressure"):
        solve_tangential(-p, x, y, MU, STEEL, STEEL, force=(1.0, 0.0))
    with pytest.raises(InputError, match="pressure"):
        solve_tangential(p[:-1], x, y, MU, STEEL, STEEL, force=(1.0, 0.0))
    with pytest.raises(InputError, match="force"):
        solve_tangential(p, x, y, MU, STEEL, STEEL, force=(np.nan, 0.0))
    with pytest.raises(InputError, match="method"):
        solve_tangential(p, x, y, MU, STEEL, STEEL, method="simplex")
