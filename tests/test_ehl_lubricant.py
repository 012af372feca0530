"""Lubricant models against closed forms and an exact integration of the Eyring film flux."""

import warnings

import numpy as np
import pytest

from asperity.ehl import (
    Lubricant,
    barus_viscosity,
    dowson_higginson_density,
    eyring_flow_factors,
    eyring_mean_shear_stress,
    friction_coefficient,
    roelands_index,
    roelands_viscosity,
    wall_shear_stress,
)
from asperity.errors import InputError

ETA0, ALPHA = 0.005, 11.1e-9  # seed Table 1 (point contact)


# --- viscosity and density -----------------------------------------------------------------


def test_barus_slope_and_cavitation():
    p = np.array([-1e8, 0.0, 0.5e9, 1e9])
    eta = barus_viscosity(p, ETA0, ALPHA)
    assert eta[0] == ETA0 and eta[1] == ETA0  # negative pressure treated as 0
    np.testing.assert_allclose(np.log(eta[3] / eta[2]) / 0.5e9, ALPHA, rtol=1e-12)


def test_roelands_index_for_seed_lubricant():
    # Z = alpha / (chi ln(eta0/kappa)) = 11.1e-9 / (5.1e-9 ln(0.005/63.2e-6))
    assert roelands_index(ETA0, ALPHA) == pytest.approx(11.1 / (5.1 * np.log(0.005 / 63.2e-6)))
    assert roelands_index(ETA0, ALPHA) == pytest.approx(0.49795, abs=1e-5)


def test_roelands_initial_slope_is_alpha():
    dp = 1e3
    eta = roelands_viscosity(np.array([0.0, dp]), ETA0, ALPHA)
    assert np.log(eta[1] / eta[0]) / dp == pytest.approx(ALPHA, rel=1e-5)


def test_roelands_with_unit_index_is_barus():
    # Z = 1 makes (1 + chi p)^Z - 1 = chi p: Roelands = Barus with alpha = chi ln(eta0/kappa)
    chi, kappa = 5.1e-9, 63.2e-6
    alpha = chi * np.log(ETA0 / kappa)
    p = np.linspace(0, 2e9, 7)
    np.testing.assert_allclose(
        roelands_viscosity(p, ETA0, alpha), barus_viscosity(p, ETA0, alpha), rtol=1e-12
    )


def test_roelands_below_barus_at_high_pressure():
    # Z < 1: ln(eta) is concave in p and lies below its tangent alpha p (the Barus law)
    p = np.array([0.3e9, 1e9, 2e9])
    assert np.all(roelands_viscosity(p, ETA0, ALPHA) < barus_viscosity(p, ETA0, ALPHA))
    assert roelands_viscosity(-1e9, ETA0, ALPHA) == pytest.approx(ETA0)  # p < -1/chi is safe


def test_dowson_higginson_density():
    rho = dowson_higginson_density(np.array([-1e9, 0.0, 1e9, 1e15]), rho0=850.0)
    assert rho[0] == 850.0 and rho[1] == 850.0
    assert rho[2] == pytest.approx(850.0 * 3.27 / 2.68, rel=1e-12)
    assert rho[3] == pytest.approx(850.0 * 2.27 / 1.68, rel=1e-5)  # asymptote gamma/lambda


def test_lubricant_dispatch_and_validation():
    oil = Lubricant(ETA0, ALPHA, eyring_stress=10e6, name="Mobil Jet 2")
    p = np.array([0.0, 1e9])
    np.testing.assert_allclose(oil.eta(p), roelands_viscosity(p, ETA0, ALPHA))
    np.testing.assert_allclose(oil.rho(p), 850.0 * dowson_higginson_density(p))
    assert oil.roelands_z == pytest.approx(roelands_index(ETA0, ALPHA))
    assert not oil.newtonian
    barus = Lubricant(ETA0, ALPHA, viscosity_model="barus", compressible=False)
    np.testing.assert_allclose(barus.eta(p), barus_viscosity(p, ETA0, ALPHA))
    np.testing.assert_array_equal(barus.density_ratio(p), 1.0)
    assert barus.newtonian
    bad = [
        ({"viscosity": -1.0}, "viscosity"),
        ({"pressure_viscosity": -1e-9}, "pressure_viscosity"),
        ({"viscosity_model": "vogel"}, "viscosity_model"),
        ({"viscosity": 1e-5}, "viscosity"),  # below Roelands' kappa
        ({"density": 0.0}, "density"),
        ({"eyring_stress": 0.0}, "eyring_stress"),
        ({"compressible": "yes"}, "compressible"),
        ({"viscosity": float("nan")}, "viscosity"),
    ]
    for change, name in bad:
        kwargs = {"viscosity": ETA0, "pressure_viscosity": ALPHA, **change}
        with pytest.raises(InputError, match=name):
            Lubricant(**kwargs)


# --- Eyring film: exact flux by quadrature across the film ------------------------------------

_ZETA, _WEIGHT = np.polynomial.legendre.leggauss(48)
_ZETA, _WEIGHT = 0.5 * (_ZETA + 1.0), 0.5 * _WEIGHT


def _exact_eyring(x_slide, gx, gy):
    """Exact Eyring film in units of tau0: wall stress t0 and pressure flux factors.

    Isotropic Eyring law shear_rate = (tau0/eta) sinh(|tau|/tau0) tau/|tau|, with
    tau(z) = tau(0) + z grad p. Scaled by tau0, h and tau0 h/eta, the wall stress t0 solves
    int_0^1 g(t0 + zeta G) dzeta = (X, 0) (the sliding speed), and the flux relative to the
    mean speed is Q = int_0^1 (1 - zeta) g dzeta - (X, 0)/2, G = h grad p / tau0.
    Returns t0 and sigma / (rho h^3 / 12 eta) = -12 Q . G / |G|^2 .
    """
    grad = np.array([gx, gy])

    def g_and_jacobian(t0):
        t = t0[:, None] + _ZETA[None, :] * grad[:, None]
        mag = np.maximum(np.hypot(t[0], t[1]), 1e-300)
        shx = np.where(mag > 1e-8, np.sinh(mag) / mag, 1.0)  # sinh|t| / |t|
        g = t * shx
        unit = t / mag
        # d g / d t = (sinh m / m) I + (cosh m - sinh m / m) t_hat t_hat^T
        jac = shx * np.eye(2)[:, :, None] + (np.cosh(mag) - shx) * unit[:, None] * unit[None]
        return g, jac

    t0 = np.array([np.arcsinh(x_slide) - gx / 2, -gy / 2])
    for _ in range(50):
        g, jac = g_and_jacobian(t0)
        residual = g @ _WEIGHT - [x_slide, 0.0]
        if np.max(np.abs(residual)) < 1e-13 * max(1.0, x_slide):
            break
        t0 = t0 - np.linalg.solve(jac @ _WEIGHT, residual)
    else:
        raise AssertionError("Newton did not converge")
    q = g @ (_WEIGHT * (1.0 - _ZETA)) - np.array([x_slide, 0.0]) / 2
    return t0, -12.0 * (q @ grad) / (grad @ grad)


def _linearised(x_slide):
    sx, sy = eyring_flow_factors(1.0, 1.0, 1.0, x_slide, 1.0)  # h = eta = rho = tau0 = 1
    return 12.0 * sx, 12.0 * sy


@pytest.mark.parametrize("x_slide", [0.3, 2.0, 20.0])
def test_flow_factors_match_exact_flux_for_small_pressure_gradient(x_slide):
    fx, fy = _linearised(x_slide)
    g = 1e-2
    _, ex = _exact_eyring(x_slide, g, 0.0)
    _, ey = _exact_eyring(x_slide, 0.0, g)
    assert fx == pytest.approx(ex, rel=1e-4)
    assert fy == pytest.approx(ey, rel=1e-4)


def test_flow_factor_error_grows_like_g_squared():
    # EHL-NOTES sec. 3: <= 1.3 % at G = 0.5, <= 5.1 % at G = 1 (over sliding speeds)
    for g, bound in ((0.1, 6e-4), (0.5, 0.013), (1.0, 0.051)):
        worst = 0.0
        for x_slide in (0.1, 1.0, 5.0, 50.0):
            fx, fy = _linearised(x_slide)
            for lin, (gx, gy) in ((fx, (g, 0.0)), (fy, (0.0, g))):
                worst = max(worst, abs(lin / _exact_eyring(x_slide, gx, gy)[1] - 1.0))
        assert worst < bound, (g, worst)


def test_flow_factor_limits():
    h = np.array([0.0, 1e-9, 1e-6])
    rho, eta, tau0 = 850.0, 0.01, 5e6
    newtonian = rho * h**3 / (12 * eta)
    for sx_sy in (
        eyring_flow_factors(h, eta, rho, 3.0, None),
        eyring_flow_factors(h, eta, rho, 0.0, tau0),
    ):
        np.testing.assert_allclose(sx_sy[0], newtonian, rtol=1e-14, atol=0)
        np.testing.assert_allclose(sx_sy[1], newtonian, rtol=1e-14, atol=0)
    # tiny X: sqrt(1 + X^2) and X / asinh X -> 1 + O(X^2)
    sx, sy = eyring_flow_factors(1e-6, eta, rho, 1e-9, tau0)
    assert sx == pytest.approx(rho * 1e-18 / (12 * eta), rel=1e-12)
    assert sy == pytest.approx(rho * 1e-18 / (12 * eta), rel=1e-12)
    # h -> 0 with sliding: finite, zero at h = 0, and sigma_x -> rho h^2 |du| / (12 tau0)
    sx, sy = eyring_flow_factors(h, eta, rho, -3.0, tau0)
    assert np.all(np.isfinite(sx)) and np.all(np.isfinite(sy))
    assert sx[0] == 0.0 and sy[0] == 0.0
    assert sx[1] == pytest.approx(rho * 1e-18 * 3.0 / (12 * tau0), rel=1e-6)
    # X >> 1: sigma_x / sigma_y -> ln 2X (relative error ~ 1/(2 X^2))
    sx, sy = eyring_flow_factors(1e-12, eta, rho, 3.0, tau0)
    assert sx / sy == pytest.approx(np.log(2 * eta * 3.0 / (tau0 * 1e-12)), rel=1e-6)
    # the same where X^2 would overflow (a Barus viscosity at a pressure spike), without an
    # overflow warning: X = 6e209
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        sx, sy = eyring_flow_factors(1e-6, 1e214, rho, 3.0, tau0)
    assert sy > 0.0
    assert sx / sy == pytest.approx(np.log(2 * 1e214 * 3.0 / (tau0 * 1e-6)), rel=1e-12)
    with pytest.raises(InputError, match="h"):
        eyring_flow_factors(-1e-9, eta, rho, 1.0, tau0)
    with pytest.raises(InputError, match="tau0"):
        eyring_flow_factors(1e-6, eta, rho, 1.0, -1.0)


@pytest.mark.parametrize("model", ["roelands", "barus"])
@pytest.mark.parametrize("compressible", [True, False])
@pytest.mark.parametrize("tau0", [10e6, None])
@pytest.mark.parametrize("shape", [(7, 5), (9,)])
def test_flow_field_is_the_laws_at_every_node(model, compressible, tau0, shape):
    """The compiled one-pass field equals the public laws composed, p and h < 0 as 0."""
    oil = Lubricant(ETA0, ALPHA, viscosity_model=model, compressible=compressible,
                    eyring_stress=tau0)
    rng = np.random.default_rng(1)
    p = rng.uniform(-0.2e9, 2e9, shape)
    h = rng.uniform(-0.1e-6, 1e-6, shape)
    h.flat[0] = 0.0
    sx, sy, rho = oil.flow_field(p, h, -5.0)
    ex, ey = eyring_flow_factors(np.maximum(h, 0.0), oil.eta(p), oil.density_ratio(p), -5.0,
                                 tau0)
    assert sx.shape == sy.shape == rho.shape == shape
    np.testing.assert_allclose(sx, ex, rtol=1e-13, atol=0)
    np.testing.assert_allclose(sy, ey, rtol=1e-13, atol=0)
    np.testing.assert_allclose(rho, oil.density_ratio(p), rtol=1e-15)
    assert np.all(sx[h <= 0] == 0.0) and np.all(sy[h <= 0] == 0.0)


@pytest.mark.parametrize("model", ["roelands", "barus"])
@pytest.mark.parametrize("compressible", [True, False])
@pytest.mark.parametrize("tau0", [10e6, 1e3, None])
def test_flow_field_slopes_are_the_derivatives_in_p(model, compressible, tau0):
    """Analytic d sigma/dp equals a central difference (1e-6 relative, or its round-off) at
    p > 0, h > 0, including tiny Eyring arguments (series branch) and strongly shear-thinned
    films."""
    oil = Lubricant(ETA0, ALPHA, viscosity_model=model, compressible=compressible,
                    eyring_stress=tau0)
    rng = np.random.default_rng(2)
    p = rng.uniform(0.05e9, 1.5e9, 40)
    h = np.concatenate([rng.uniform(1e-8, 1e-6, 38), [1.0, 0.0]])
    sx, sy, rho, dsx, dsy = oil.flow_field(p, h, -5.0, slopes=True)
    np.testing.assert_array_equal(oil.flow_field(p, h, -5.0)[0], sx)
    step = 1e-5 * p
    up = oil.flow_field(p + step, h, -5.0)
    down = oil.flow_field(p - step, h, -5.0)
    for k, d in ((0, dsx), (1, dsy)):
        central = (up[k] - down[k]) / (2 * step)
        roundoff = 1e-9 * up[k] / p  # where sigma hardly depends on p (sigma_x at large X)
        assert np.all(np.abs(d - central)[:-1] <= (1e-6 * np.abs(central) + roundoff)[:-1])
    assert dsx[-1] == dsy[-1] == 0.0  # no film, no flow at any pressure


# --- shear stress and friction --------------------------------------------------------------


def test_mean_shear_stress_is_exact_couette_stress():
    h, eta, du, tau0 = 0.4e-6, 0.2, 2.5, 10e6
    tau = eyring_mean_shear_stress(h, eta, du, tau0)
    assert tau0 / eta * np.sinh(tau / tau0) == pytest.approx(du / h, rel=1e-13)
    assert eyring_mean_shear_stress(h, eta, -du, tau0) == pytest.approx(-tau)
    assert eyring_mean_shear_stress(h, eta, du) == pytest.approx(eta * du / h)
    assert eyring_mean_shear_stress(0.0, eta, du, tau0) == np.inf
    assert eyring_mean_shear_stress(0.0, eta, 0.0, tau0) == 0.0


def test_wall_shear_stress_newtonian_is_exact():
    # Couette-Poiseuille: tau(z) = eta du/h + (z - h/2) dp/dx exactly
    h, eta, du, dpdx = 1e-6, 0.05, 2.0, 3e12
    lower, upper = wall_shear_stress(h, eta, du, dpdx)
    assert lower == pytest.approx(eta * du / h - h * dpdx / 2, rel=1e-14)
    assert upper - lower == pytest.approx(h * dpdx, rel=1e-14)


def test_wall_shear_stress_eyring_against_exact_film():
    # in tau0 units: tau_m - G/2 vs the exact wall stress, error O(G^2)
    for x_slide in (0.5, 10.0):
        for g in (1e-2, 0.2):
            t0, _ = _exact_eyring(x_slide, g, 0.0)
            lower, _ = wall_shear_stress(1.0, 1.0, x_slide, g, tau0=1.0)
            assert lower == pytest.approx(t0[0], abs=0.1 * g**2)


def test_friction_coefficient_newtonian_and_dry_nodes():
    x = np.linspace(-1e-3, 1e-3, 201)
    a = 0.8e-3
    p = 1e9 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))[:, None] * np.ones((1, 3))
    h = np.full_like(p, 0.5e-6)
    eta, du = 0.1, 1.0
    # symmetric p: the Poiseuille terms cancel, mu = sum(eta du / h) / sum(p)
    mu = friction_coefficient(x, p, h, eta, du)
    assert mu == pytest.approx(eta * du / 0.5e-6 * p.size / p.sum(), rel=1e-10)
    # one dry node carries boundary_friction * p there
    h_dry = h.copy()
    h_dry[100, 1] = 0.0
    mu_dry = friction_coefficient(x, p, h_dry, eta, du, boundary_friction=0.1)
    expected = (eta * du / 0.5e-6 * (p.size - 1) + 0.1 * p[100, 1]) / p.sum()
    assert mu_dry == pytest.approx(expected, rel=1e-10)
    with pytest.raises(InputError, match="h"):
        friction_coefficient(x, p, h[:, :2], eta, du)
    with pytest.raises(InputError, match="p"):
        friction_coefficient(x, 0 * p, h, eta, du)


def test_flow_field_keeps_the_memory_order_of_p():
    """Fields stored x-fastest (Fortran order, as the EHL solver keeps them) come back so and
    equal the C-ordered evaluation, also when h is stored the other way."""
    oil = Lubricant(ETA0, ALPHA, eyring_stress=10e6)
    rng = np.random.default_rng(3)
    p = rng.uniform(0.0, 2e9, (11, 6))
    h = rng.uniform(0.0, 1e-6, (11, 6))
    expected = oil.flow_field(p, h, -5.0, slopes=True)
    got = oil.flow_field(np.asfortranarray(p), h, -5.0, slopes=True)
    for e, g in zip(expected, got, strict=True):
        assert g.flags.f_contiguous
        np.testing.assert_array_equal(g, e)


@pytest.mark.parametrize("model", ["barus", "roelands"])
@pytest.mark.parametrize("tau0", [None, 5e6])
def test_flow_field_at_overflowing_viscosity_tends_to_zero(model, tau0):
    """A pressure spike whose viscosity overflows (exp(alpha p) > 1e308 for p > ~35 GPa at
    alpha = 2e-8 /Pa) or whose h/eta underflows must give the limit of a rigid film: flow
    factors and their slopes 0, finite (was NaN, or ZeroDivisionError in the compiled pass
    on a fine line-contact mesh). Against the limits sigma -> 0 as eta -> inf."""
    lub = Lubricant(viscosity=0.01, pressure_viscosity=2e-8, viscosity_model=model,
                    eyring_stress=tau0)
    p = np.array([3e10, 5e10, 1e12])
    h = np.full(3, 1e-7)
    sx, sy, rho, dsx, dsy = lub.flow_field(p, h, 1.0, slopes=True)
    for field in (sx, sy, dsx, dsy):
        assert np.all(np.isfinite(field))
    # Newtonian: sigma_x -> 0 (it is ~1e-20 at 1 MPa); Eyring: sigma_x -> rho h^2 (|du|/tau0)/12,
    # the limit of h^2 sqrt((h/eta)^2 + (du/tau0)^2)/12 as eta -> inf; sigma_y -> 0 for both
    limit_x = 0.0 if tau0 is None else rho * h**2 * (1.0 / tau0) / 12.0
    assert np.allclose(sx, limit_x, rtol=1e-12, atol=1e-23)
    assert np.all(np.abs(sy) < 1e-23)
    assert np.all(np.abs(dsx) < 1e-30) and np.all(np.abs(dsy) < 1e-30)
    assert np.allclose(rho, lub.density_ratio(p))


@pytest.mark.parametrize("compressible", [True, False])
def test_flow_field_density_slope_is_the_dowson_higginson_derivative(compressible):
    """``density_slope`` returns d(rho/rho0)/dp in the units of ``p``: against the closed-form
    derivative of Dowson-Higginson's ``(1 + gamma p)/(1 + lambda p)``,
    ``(gamma - lambda)/(1 + lambda p)^2`` (1e-12 relative), the right derivative at p <= 0,
    and 0 for an incompressible oil; the other outputs are those without it."""
    oil = Lubricant(ETA0, ALPHA, compressible=compressible)
    p = np.array([-0.2, 0.0, 0.3, 1.0, 2.5, 6.0])  # GPa, as units[0] = 1e9 Pa
    h = np.full(p.size, 0.2)
    units = (1e9, 1e-6, 1.0)
    *fields, drho = oil.flow_field(p, h, 1.0, slopes=True, units=units, density_slope=True)
    for got, expected in zip(fields, oil.flow_field(p, h, 1.0, slopes=True, units=units),
                             strict=True):
        np.testing.assert_array_equal(got, expected)
    gamma, lam = oil.dh_gamma * 1e9, oil.dh_lambda * 1e9  # 1/GPa
    pp = np.maximum(p, 0.0)
    expected = (gamma - lam) / (1 + lam * pp) ** 2 if compressible else np.zeros(p.size)
    np.testing.assert_allclose(drho, expected, rtol=1e-12, atol=0.0)
    assert not compressible or drho[-1] > 0.0


def test_flow_field_slopes_at_an_underflowing_film_without_sliding():
    """A film so thin that h^2 underflows (1e-170 m), with no sliding, gives finite flow factors
    and slopes (the series term shear^2/(6 h^2) was 0/0: ZeroDivisionError in the compiled
    pass), equal to the Newtonian rho h^3/(12 eta) limit: zero here."""
    oil = Lubricant(ETA0, ALPHA, eyring_stress=5e6)
    p = np.array([1e8, 5e8])
    h = np.array([1e-170, 1e-170])
    fields = oil.flow_field(p, h, 0.0, slopes=True)
    for field in fields:
        assert np.all(np.isfinite(field))
    assert np.all(fields[0] == 0.0) and np.all(fields[3] == 0.0)
