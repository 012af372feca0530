"""Steady EHL solver: the seed's smooth gear case, relaxation variants, limits and bad input."""

import numpy as np
import pytest

from asperity.ehl import LineContact, Lubricant, PointContact, nijenbanning_point, solve_steady
from asperity.errors import InputError
from asperity.materials import Material

# Table 1 of the seed (Holmes et al. 2005): E' = 227 GPa from two equal bodies
STEEL = Material(227e9 * (1 - 0.3**2), 0.3, "steel")
MOBIL_JET_2 = Lubricant(viscosity=0.005, pressure_viscosity=11.1e-9, eyring_stress=10e6)


def gear_point(xi=0.25, u=25.0):
    return PointContact(0.0191, 0.151, 962.0, u * (1 - xi / 2), u * (1 + xi / 2), STEEL, STEEL,
                        MOBIL_JET_2)


@pytest.fixture(scope="module")
def gear_129():
    return solve_steady(gear_point(), nx=129, ny=65, levels=2)


def test_gear_case_coarse_matches_paper(gear_129):
    """129 x 65 nodes: within 3 % of the paper's 0.48 / 0.42 um and 1.03 GPa (see report)."""
    r = gear_129
    assert r.converged and r.residual < 1e-5
    assert r.central_film == pytest.approx(0.48e-6, rel=0.03)
    assert r.minimum_film_centreline == pytest.approx(0.42e-6, rel=0.03)
    assert r.max_pressure == pytest.approx(1.03e9, rel=0.01)
    assert abs(r.load_error) < 1e-5
    assert r.minimum_film <= r.minimum_film_centreline
    # Eyring traction at xi = 0.25: tau ~ tau0 asinh(...) ~ 13 MPa over ~ 0.7 GPa mean pressure
    assert 0.005 < r.friction_coefficient < 0.03
    x, p, h = r.centre_line()
    assert p.min() >= 0.0 and h.min() > 0
    # load balance: the integral of p equals the applied load
    dx, dy = x[1] - x[0], r.y[1] - r.y[0]
    assert r.pressure.sum() * dx * dy == pytest.approx(962.0, rel=1e-4)


def test_point_and_line_relaxation_agree():
    """The seed's point update and the x-line relaxation converge to the same solution."""
    prob = gear_point()
    a = solve_steady(prob, nx=65, ny=33, method="point", tol=2e-6, max_iter=6000)
    b = solve_steady(prob, nx=65, ny=33, method="line", tol=2e-6)
    assert a.converged and b.converged
    assert b.sweeps < a.sweeps / 5
    assert b.central_film == pytest.approx(a.central_film, rel=2e-3)
    np.testing.assert_allclose(b.pressure, a.pressure, atol=5e-3 * a.max_pressure)


def test_film_solution_is_consistent_with_integral_deflection(gear_129):
    """Interior h equals h0 + geometry + D*p summed directly (the differential form is exact)."""
    from asperity.ehl import EHLState

    r = gear_129
    prob = gear_point()
    state = EHLState(prob, r.x, r.y)
    state.P = r.pressure / prob.p_hertz
    state.H0 = r.separation / prob.film_scale
    h_int = state.film_from_pressure() * prob.film_scale
    assert np.max(np.abs(h_int - r.film)) < 1e-3 * r.central_film


@pytest.mark.parametrize("M, L", [(20.0, 10.0), (50.0, 10.0), (100.0, 10.0)])
def test_newtonian_barus_point_vs_nijenbanning(M, L):
    """Circular contact, Newtonian incompressible Barus: central film within 5 % of the fit."""
    body = Material(2e11, 0.3)
    ep = 2e11 / (1 - 0.09)
    alpha, eta0, r = 2e-8, 0.04, 0.01
    two_u = (L / (alpha * ep)) ** 4
    u = 0.5 * two_u * ep * r / eta0
    load = M * two_u**0.75 * ep * r**2
    lub = Lubricant(eta0, alpha, viscosity_model="barus", compressible=False)
    prob = PointContact(r, r, load, u, u, body, body, lub)
    res = solve_steady(prob, nx=129, ny=65, levels=2,
                       domain=((-3.5 * prob.a, 1.5 * prob.a), (-2 * prob.b, 2 * prob.b)))
    ref = nijenbanning_point(load, r, r, u, eta0, alpha, ep).central
    assert res.converged
    assert res.central_film == pytest.approx(ref, rel=0.05)


def test_line_contact_gear_centre_line():
    """Seed's line column: hc, hmin close to the point contact's centre line (paper Fig. 10)."""
    prob = LineContact(0.0191, 527e3, 25 * 0.875, 25 * 1.125, STEEL, STEEL,
                       Lubricant(0.0048, 11.1e-9, eyring_stress=10e6))
    r = solve_steady(prob, nx=101, tol=1e-5, max_iter=20000)
    assert r.converged
    assert r.central_film == pytest.approx(0.48e-6, rel=0.05)
    assert r.minimum_film == pytest.approx(0.42e-6, rel=0.05)


def test_not_converged_is_reported():
    r = solve_steady(gear_point(), nx=33, ny=17, max_iter=5, refresh=5)
    assert not r.converged
    assert r.sweeps == 5


@pytest.mark.parametrize("limit", [3, 5, 13])
def test_the_sweep_limit_is_the_count_reported(limit):
    """``max_iter`` 3 or 5 ran a whole refresh cycle of 10 sweeps and reported 10 (13: 20);
    the limit is now the number of sweeps run and reported, the residual taken at its end."""
    r = solve_steady(gear_point(), nx=33, ny=17, levels=1, max_iter=limit)
    assert not r.converged
    assert r.sweeps == r.total_sweeps == limit
    assert r.history[-1][0] == limit


def test_separated_iterate_is_reported_not_converged(monkeypatch):
    """An iteration that lost all its pressure (surfaces separated, as a ball bearing's did
    before the density term) ends as a result that says it did not converge, with no
    friction coefficient, instead of the friction's 'positive resultant' input error."""
    from asperity.ehl.solver import EHLState

    def lose_pressure(self, method):
        self.P = np.zeros_like(self.P)
        return 0.0, 0.0

    monkeypatch.setattr(EHLState, "sweep", lose_pressure)
    r = solve_steady(gear_point(), nx=33, ny=17, levels=1, max_iter=6)
    assert not r.converged and r.load_error == pytest.approx(-1.0)
    assert np.isnan(r.friction_coefficient)


def test_bad_input():
    with pytest.raises(InputError, match="u1, u2"):
        PointContact(0.0191, 0.151, 962.0, 0.0, 0.0, STEEL, STEEL, MOBIL_JET_2)
    with pytest.raises(InputError, match="viscosity"):
        Lubricant(viscosity=-0.005, pressure_viscosity=11.1e-9)
    prob = gear_point()
    with pytest.raises(InputError, match="domain"):
        solve_steady(prob, nx=33, ny=17, domain=((-0.5 * prob.a, 1.5 * prob.a),
                                                 (-2 * prob.b, 2 * prob.b)))
    with pytest.raises(InputError, match="domain"):
        solve_steady(prob, nx=33, ny=17, domain=((-2.5 * prob.a, 1.5 * prob.a),
                                                 (-0.5 * prob.b, 2 * prob.b)))
    with pytest.raises(InputError, match="load"):
        PointContact(0.0191, 0.151, -1.0, 10.0, 10.0, STEEL, STEEL, MOBIL_JET_2)
    with pytest.raises(InputError, match="levels"):
        solve_steady(prob, nx=34, ny=17, levels=2)


@pytest.mark.slow
def test_gear_case_paper_mesh():
    """Paper mesh a/200 x b/50 (801 x 201): 0.48 / 0.42 um, 1.03 GPa within 5 %."""
    r = solve_steady(gear_point(), nx=801, ny=201, levels=4)
    assert r.converged
    assert r.central_film == pytest.approx(0.48e-6, rel=0.05)
    assert r.minimum_film_centreline == pytest.approx(0.42e-6, rel=0.05)
    assert r.max_pressure == pytest.approx(1.03e9, rel=0.05)


def test_dry_limit_converges_on_a_fixed_film_scale():
    """At 0.5 m/s the central film is ~0: p, h and load converge and so does the solve.

    The film change is measured against the larger of the central and the mean edge film
    (dividing by H_c alone made this report converged=False).
    """
    prob = gear_point(u=0.5)
    r = solve_steady(prob, nx=65, ny=33, levels=2)
    assert r.converged and abs(r.load_error) < 1e-5
    assert r.max_pressure == pytest.approx(prob.p_hertz, rel=5e-3)  # dry: Hertz (+0.02 %)
    assert r.central_film < 0.05e-6
    assert r.history[-1, 2] < 1e-5


def test_damping_keeps_the_solution(gear_129):
    """Oscillation damping changes the path, not the converged solution."""
    damped = solve_steady(gear_point(), nx=129, ny=65, levels=2, damping=0.5)
    assert damped.converged
    assert damped.central_film == pytest.approx(gear_129.central_film, rel=1e-3)
    assert damped.max_pressure == pytest.approx(gear_129.max_pressure, rel=1e-3)
    with pytest.raises(InputError, match="damping"):
        solve_steady(gear_point(), nx=65, ny=33, damping=0.0)


def test_inlet_inside_the_pressure_build_up_warns():
    """An inlet at -1.1a (smooth pressure there ~0.1 p_h) starves the film: a warning naming
    the domain, the central film 47 % low; the reduced domain's -2a inlet is quiet."""
    import warnings

    prob = gear_point()
    a, b = prob.a, prob.b
    with pytest.warns(RuntimeWarning, match="^domain: the inlet at x = -1.10 a"):
        short = solve_steady(prob, nx=95, ny=29, domain=((-1.1 * a, 1.25 * a), (-1.4 * b, 1.4 * b)))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        full = solve_steady(prob, nx=131, ny=29, domain=((-2.0 * a, 1.25 * a), (-1.4 * b, 1.4 * b)))
    assert short.inlet_pressure > 0.05 and full.inlet_pressure < 0.002
    assert short.central_film < 0.6 * full.central_film


@pytest.mark.parametrize("line", [False, True])
def test_refresh_far_field_equals_direct_convolution(line):
    """``efar`` from the Laplacian of D * P equals the direct sum f * P (interior, 1e-9)."""
    from asperity.ehl.solver import EHLState
    from asperity.elastic.convolution import Convolution
    from asperity.elastic.differential import (
        differential_coefficients,
        line_differential_coefficients,
    )

    if line:
        prob = LineContact(0.0191, 527e3, 21.875, 28.125, STEEL, STEEL, MOBIL_JET_2)
        x, y = prob.grid(161, 1)
    else:
        prob = gear_point()
        x, y = prob.grid(81, 33)
    s = EHLState(prob, x, y, near=2)
    rng = np.random.default_rng(0)
    s.P = rng.random(s.P.shape)
    s.refresh()
    shape = s.P.shape
    if line:
        f = Convolution.from_coefficients(
            lambda X, Y: line_differential_coefficients(X, s.dX), s.dX, 1.0, shape, False)
    else:
        f = Convolution.from_coefficients(
            lambda X, Y: differential_coefficients(X, Y, s.dX, s.dY), s.dX, s.dY, shape, False)
    near = s.f_near[0] * s.P
    for k in (1, 2):
        near[k:] += s.f_near[k] * s.P[:-k]
        near[:-k] += s.f_near[k] * s.P[k:]
    expected = s.laplacian(s.roughness) + prob.curvature + s.c * (f(s.P) - near)
    inner = (slice(1, -1), slice(None) if line else slice(1, -1))
    scale = np.abs(s.c * f(s.P)).max()
    assert np.max(np.abs(s.efar[inner] - expected[inner])) < 1e-9 * scale
