"""Isothermal lubricant models: pressure-viscosity, pressure-density, Eyring shear thinning.

Pressures are gauge pressures in Pa. A negative pressure (which a cavitating film cannot carry)
is treated as zero wherever a model would otherwise leave its range of validity: the viscosity
and density laws are evaluated at ``max(p, 0)``.

Models
------
Barus:
    eta = eta0 exp(alpha p).
Roelands (seed eq. 3; Roelands 1966):
    eta = eta0 exp{ ln(eta0/kappa) [(1 + chi p)^Z - 1] },  Z = alpha / (chi ln(eta0/kappa)),
    so that d(ln eta)/dp = alpha at p = 0.
Dowson-Higginson (seed eq. 4; Dowson & Higginson 1966):
    rho = rho0 (1 + gamma p) / (1 + lambda p).
Eyring (Conry, Wang & Cusano 1987 linearisation, in two dimensions; see
:func:`eyring_flow_factors`):
    shear rate = (tau0/eta) sinh(tau/tau0).

References
----------
C. J. A. Roelands, *Correlational aspects of the viscosity-temperature-pressure relationship of
lubricating oils*, PhD thesis, TU Delft, 1966.
D. Dowson and G. R. Higginson, *Elasto-hydrodynamic Lubrication*, Pergamon, 1966.
T. F. Conry, S. Wang and C. Cusano, "A Reynolds-Eyring equation for elastohydrodynamic
lubrication in line contacts", J. Tribol. 109 (1987) 648-658.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from ..errors import InputError, check_positive

__all__ = [
    "Lubricant",
    "barus_viscosity",
    "roelands_viscosity",
    "roelands_index",
    "dowson_higginson_density",
    "eyring_flow_factors",
    "eyring_mean_shear_stress",
    "wall_shear_stress",
    "friction_coefficient",
]

ROELANDS_KAPPA = 63.2e-6
"""Roelands' pole viscosity kappa, Pa s."""
ROELANDS_CHI = 5.1e-9
"""Roelands' pressure constant chi = 1/p_r = 1/(196 MPa), 1/Pa."""
DH_GAMMA = 2.27e-9
"""Dowson-Higginson gamma, 1/Pa."""
DH_LAMBDA = 1.68e-9
"""Dowson-Higginson lambda, 1/Pa."""


# The laws, once, as compiled scalar functions returning the value and its derivative (they
# share their transcendental functions): the public functions below apply the values to arrays
# (as ufuncs), and Lubricant.flow_field evaluates values and, on request, derivatives in one
# parallel pass over the nodes of an EHL solution. Pressures p < 0 are evaluated at 0 (the
# derivative there is the right derivative at 0).

@numba.njit(cache=True)
def _barus_law(p, eta0, alpha):
    """Barus eta and d eta/dp."""
    eta = eta0 * math.exp(alpha * max(p, 0.0))
    return eta, alpha * eta


@numba.njit(cache=True)
def _roelands_law(p, eta0, log_ratio, chi, z):
    """Roelands eta and d eta/dp, ``log_ratio = ln(eta0/kappa)``:
    ``d eta/dp = eta ln(eta0/kappa) Z chi (1 + chi p)^(Z - 1)``."""
    q = 1.0 + chi * max(p, 0.0)
    t = math.exp(z * math.log(q))  # q**z: libm's pow costs about twice exp and log
    eta = eta0 * math.exp(log_ratio * (t - 1.0))
    return eta, eta * log_ratio * z * chi * t / q


@numba.njit(cache=True)
def _dowson_higginson_law(p, gamma, lam):
    """rho/rho0 and its derivative ``(gamma - lambda)/(1 + lambda p)^2`` (1, 0 for
    gamma = lam = 0)."""
    q = 1.0 + lam * max(p, 0.0)
    return (1.0 + gamma * max(p, 0.0)) / q, (gamma - lam) / (q * q)


@numba.njit(cache=True)
def _eyring_x(h, eta, shear):
    """``sigma_x / rho = h^2 sqrt((h/eta)^2 + shear^2) / 12`` (``shear = |du|/tau0``, 0:
    Newtonian) and its derivative in eta, ``-h^2 (h/eta)^2 / (12 eta sqrt(...))``."""
    if h <= 0.0:
        return 0.0, 0.0
    u = h / eta
    root = math.sqrt(u * u + shear * shear)
    if root == 0.0:  # Newtonian film whose h/eta underflows (eta overflowing at huge p): limit 0
        return 0.0, 0.0
    return h * h * root / 12.0, -h * h * u * u / (12.0 * eta * root)


@numba.njit(cache=True)
def _eyring_y(h, eta, shear):
    """``sigma_y / rho = h^3 g / 12``, ``g = X / (eta asinh X)``, ``X = eta shear / h``, and its
    derivative in eta with ``dg/deta = -(shear/h)^2 / (asinh(X)^2 sqrt(1 + X^2))``; near
    X = 0 the series ``g = (1 + X^2/6) / eta``, ``dg/deta = -1/eta^2 + shear^2/(6 h^2)``."""
    if h <= 0.0:
        return 0.0, 0.0
    x = eta * shear / h if shear > 0.0 else 0.0
    if x == math.inf:  # eta overflowing at huge p: g -> shear / (h asinh X) -> 0
        return 0.0, 0.0
    if x < 1e-4:
        g = (1.0 + x * x / 6.0) / eta
        dg = -1.0 / (eta * eta)
        if shear > 0.0:  # (not 0/0 where h^2 underflows without sliding)
            dg += shear * shear / (6.0 * h * h)
    else:  # asinh X = ln(X + sqrt(1 + X^2)) (X >= 1e-4: no cancellation), the root shared
        r = 1.0 / x
        root = x * math.sqrt(1.0 + r * r)  # (not X^2, which overflows at a huge eta)
        s = math.log(x + root)
        g = x / (eta * s)
        dg = -(shear / h) ** 2 / (s * s * root)
    return h * h * h * g / 12.0, h * h * h * dg / 12.0


@numba.vectorize(cache=True)
def _barus(p, eta0, alpha):
    return _barus_law(p, eta0, alpha)[0]


@numba.vectorize(cache=True)
def _roelands(p, eta0, log_ratio, chi, z):
    return _roelands_law(p, eta0, log_ratio, chi, z)[0]


@numba.vectorize(cache=True)
def _dowson_higginson(p, gamma, lam):
    return _dowson_higginson_law(p, gamma, lam)[0]


@numba.vectorize(cache=True)
def _sigma_x(h, eta, rho, shear):
    return rho * _eyring_x(h, eta, shear)[0]


@numba.vectorize(cache=True)
def _sigma_y(h, eta, rho, shear):
    return rho * _eyring_y(h, eta, shear)[0]


@numba.njit(cache=True)
def _pressure_laws(p, roelands, eta0, v1, v2, v3, gamma, lam):
    """(eta, d eta/dp, rho/rho0, d(rho/rho0)/dp) at pressure p (arguments of
    :func:`_flow_field`); d eta/dp is 0 where eta overflows."""
    if roelands:
        eta, deta = _roelands_law(p, eta0, v1, v2, v3)
    else:
        eta, deta = _barus_law(p, eta0, v1)
    if eta == math.inf:  # overflow at a huge pressure: the flow factors and slopes -> 0
        deta = 0.0
    r, dr = _dowson_higginson_law(p, gamma, lam)
    return eta, deta, r, dr


@numba.njit(parallel=True, cache=True)
def _flow_field(p, h, units, roelands, eta0, v1, v2, v3, gamma, lam, shear, sx, sy, rho,
                slopes, dsx, dsy, drho):
    """sigma_x, sigma_y and rho/rho0 at every node into ``sx, sy, rho`` (1-D arrays, the nodes
    in memory order), and with ``slopes`` their derivatives in p at constant h into ``dsx, dsy``
    and ``d(rho/rho0)/dp`` into ``drho`` (in 1/``p_unit``; ``drho`` may be empty).

    ``units = (p_unit, h_unit, s_unit, ds_unit)``: the node's pressure is ``p_unit p`` (Pa)
    and film ``h_unit h`` (m); ``sx, sy`` get ``s_unit sigma`` and ``dsx, dsy``
    ``ds_unit d sigma/dp``. Viscosity: Roelands (``v1 = ln(eta0/kappa), v2 = chi, v3 = Z``)
    or Barus (``v1 = alpha``). Films ``h < 0`` count as 0. Chain rule: ``d sigma/dp =
    (sigma/rho) rho' + rho d(sigma/rho)/d eta eta'``. The laws at p <= 0 (a cavitated
    region) are those at 0, evaluated once.
    """
    p_unit, h_unit, s_unit, ds_unit = units
    at_zero = _pressure_laws(0.0, roelands, eta0, v1, v2, v3, gamma, lam)
    for k in numba.prange(p.size):
        pk = p[k] * p_unit
        hk = max(h[k] * h_unit, 0.0)
        if pk <= 0.0:
            eta, deta, r, dr = at_zero
        else:  # p > 0 or NaN
            eta, deta, r, dr = _pressure_laws(pk, roelands, eta0, v1, v2, v3, gamma, lam)
        fx, dfx = _eyring_x(hk, eta, shear)
        fy, dfy = _eyring_y(hk, eta, shear)
        sx[k] = r * fx * s_unit
        sy[k] = r * fy * s_unit
        rho[k] = r
        if slopes:
            dsx[k] = (fx * dr + r * dfx * deta) * ds_unit
            dsy[k] = (fy * dr + r * dfy * deta) * ds_unit
            if drho.size:
                drho[k] = dr * p_unit


def barus_viscosity(p, eta0, alpha):
    """Barus viscosity eta = eta0 exp(alpha p).

    Parameters
    ----------
    p : array_like
        Pressure, Pa; negative values are treated as 0.
    eta0 : float
        Viscosity at ambient pressure, Pa s.
    alpha : float
        Pressure-viscosity coefficient, 1/Pa (>= 0).

    Returns
    -------
    ndarray
        Viscosity, Pa s, shaped like ``p``.
    """
    with np.errstate(over="ignore"):  # beyond about 1e308 Pa s the law's value is inf
        return _barus(np.asarray(p, dtype=float), eta0, alpha)


def roelands_index(eta0, alpha, kappa=ROELANDS_KAPPA, chi=ROELANDS_CHI):
    """Roelands pressure-viscosity index Z = alpha / (chi ln(eta0/kappa)).

    Chosen so that the Roelands law has the slope d(ln eta)/dp = alpha at p = 0.
    Requires ``eta0 > kappa``.
    """
    eta0 = check_positive("viscosity", eta0)
    alpha = check_positive("pressure_viscosity", alpha, allow_zero=True)
    kappa = check_positive("roelands_kappa", kappa)
    chi = check_positive("roelands_chi", chi)
    if not eta0 > kappa:
        raise InputError("viscosity", f"eta0 > roelands_kappa = {kappa} Pa s for Roelands", eta0)
    return alpha / (chi * np.log(eta0 / kappa))


def roelands_viscosity(p, eta0, alpha, kappa=ROELANDS_KAPPA, chi=ROELANDS_CHI):
    """Roelands viscosity (seed eq. 3).

    eta = eta0 exp{ ln(eta0/kappa) [(1 + chi p)^Z - 1] } with Z from :func:`roelands_index`.

    Parameters
    ----------
    p : array_like
        Pressure, Pa; negative values are treated as 0 (the law is undefined for
        ``p < -1/chi``).
    eta0 : float
        Viscosity at ambient pressure, Pa s (> ``kappa``).
    alpha : float
        Pressure-viscosity coefficient at p = 0, 1/Pa.
    kappa : float, optional
        Pole viscosity, Pa s (63.2e-6).
    chi : float, optional
        Pressure constant, 1/Pa (5.1e-9).

    Returns
    -------
    ndarray
        Viscosity, Pa s.
    """
    z = roelands_index(eta0, alpha, kappa, chi)
    with np.errstate(over="ignore"):  # beyond about 1e308 Pa s the law's value is inf
        return _roelands(np.asarray(p, dtype=float), eta0, math.log(eta0 / kappa), chi, z)


def dowson_higginson_density(p, rho0=1.0, gamma=DH_GAMMA, lam=DH_LAMBDA):
    """Dowson-Higginson density rho = rho0 (1 + gamma p) / (1 + lam p) (seed eq. 4).

    Parameters
    ----------
    p : array_like
        Pressure, Pa; negative values are treated as 0.
    rho0 : float, optional
        Density at ambient pressure (kg/m^3); the default 1 returns the ratio rho/rho0.
    gamma, lam : float, optional
        Coefficients, 1/Pa (2.27e-9 and 1.68e-9); rho/rho0 -> gamma/lam (= 1.35) as p -> inf.

    Returns
    -------
    ndarray
        Density, in the units of ``rho0``.
    """
    return rho0 * _dowson_higginson(np.asarray(p, dtype=float), gamma, lam)


@dataclass(frozen=True)
class Lubricant:
    """An isothermal lubricant: viscosity and density laws and an Eyring stress.

    Parameters
    ----------
    viscosity : float
        eta0, viscosity at ambient pressure, Pa s.
    pressure_viscosity : float
        alpha, pressure-viscosity coefficient at p = 0, 1/Pa (0 = isoviscous).
    viscosity_model : {"roelands", "barus"}
        Pressure-viscosity law.
    roelands_kappa, roelands_chi : float
        Roelands constants kappa (Pa s) and chi (1/Pa).
    density : float
        rho0, density at ambient pressure, kg/m^3.
    compressible : bool
        Use the Dowson-Higginson density law; otherwise rho = rho0.
    dh_gamma, dh_lambda : float
        Dowson-Higginson constants, 1/Pa.
    eyring_stress : float or None
        Eyring stress tau0, Pa; ``None`` for a Newtonian lubricant.
    name : str
        A label for reports.
    """

    viscosity: float
    pressure_viscosity: float
    viscosity_model: str = "roelands"
    roelands_kappa: float = ROELANDS_KAPPA
    roelands_chi: float = ROELANDS_CHI
    density: float = 850.0
    compressible: bool = True
    dh_gamma: float = DH_GAMMA
    dh_lambda: float = DH_LAMBDA
    eyring_stress: float | None = None
    name: str = "lubricant"

    def __post_init__(self):
        def setf(field, value):
            object.__setattr__(self, field, value)

        setf("viscosity", check_positive("viscosity", self.viscosity))
        setf(
            "pressure_viscosity",
            check_positive("pressure_viscosity", self.pressure_viscosity, allow_zero=True),
        )
        if self.viscosity_model not in ("roelands", "barus"):
            raise InputError("viscosity_model", '"roelands" or "barus"', self.viscosity_model)
        setf("roelands_kappa", check_positive("roelands_kappa", self.roelands_kappa))
        setf("roelands_chi", check_positive("roelands_chi", self.roelands_chi))
        if self.viscosity_model == "roelands":
            roelands_index(
                self.viscosity, self.pressure_viscosity, self.roelands_kappa, self.roelands_chi
            )
        setf("density", check_positive("density", self.density))
        if not isinstance(self.compressible, bool | np.bool_):
            raise InputError("compressible", "true or false", self.compressible)
        setf("compressible", bool(self.compressible))
        setf("dh_gamma", check_positive("dh_gamma", self.dh_gamma, allow_zero=True))
        setf("dh_lambda", check_positive("dh_lambda", self.dh_lambda, allow_zero=True))
        if self.eyring_stress is not None:
            setf("eyring_stress", check_positive("eyring_stress", self.eyring_stress))

    @property
    def newtonian(self) -> bool:
        """True when no Eyring stress is given."""
        return self.eyring_stress is None

    @property
    def roelands_z(self) -> float:
        """Roelands index Z (see :func:`roelands_index`)."""
        return float(
            roelands_index(
                self.viscosity, self.pressure_viscosity, self.roelands_kappa, self.roelands_chi
            )
        )

    def eta(self, p):
        """Viscosity at pressure ``p`` (Pa; negative treated as 0), Pa s."""
        if self.viscosity_model == "barus":
            return barus_viscosity(p, self.viscosity, self.pressure_viscosity)
        return roelands_viscosity(
            p, self.viscosity, self.pressure_viscosity, self.roelands_kappa, self.roelands_chi
        )

    def density_ratio(self, p):
        """rho/rho0 at pressure ``p``: Dowson-Higginson when compressible, else 1."""
        if not self.compressible:
            return np.ones_like(np.asarray(p, dtype=float))
        return dowson_higginson_density(p, 1.0, self.dh_gamma, self.dh_lambda)

    def rho(self, p):
        """Density at pressure ``p``, kg/m^3."""
        return self.density * self.density_ratio(p)

    def flow_field(self, p, h, sliding_speed: float, slopes: bool = False, *,
                   units=(1.0, 1.0, 1.0), density_slope: bool = False):
        """Flow factors and density ratio of a pressure and film field, in one parallel pass.

        The same as ``eyring_flow_factors(h, eta(p), density_ratio(p), sliding_speed,
        eyring_stress)`` and ``density_ratio(p)``, compiled and evaluated node by node on the
        available cores (the EHL solvers call it at every sweep, on their dimensionless
        fields: ``units``).

        Parameters
        ----------
        p : array_like
            Pressure, in units of ``units[0]`` Pa (negative counts as 0).
        h : array_like
            Film thickness, in units of ``units[1]`` m, shaped like ``p`` (negative counts
            as 0).
        sliding_speed : float
            du = u2 - u1, m/s.
        slopes : bool
            Also return the derivatives of the flow factors with respect to p at constant h
            (analytic, through eta(p) and rho(p); the right derivative at p <= 0).
        units : (float, float, float)
            Units of ``p`` (Pa) and ``h`` (m), and a factor on the returned flow factors and
            slopes; the default: SI in and out.
        density_slope : bool
            With ``slopes``, also return the density ratio's derivative (the Newton term of a
            compressible lubricant in :mod:`asperity.ehl.kernels`).

        Returns
        -------
        sigma_x, sigma_y, rho_ratio : ndarray
            Flow factors (in rho0 m^3/(Pa s), times ``units[2]``) and rho/rho0, shaped like
            ``p``.
        dsigma_x, dsigma_y : ndarray
            With ``slopes``: d sigma/dp times ``units[2]``, p in the units of ``p``
            (SI: rho0 m^3/(Pa^2 s)).
        drho_ratio : ndarray
            With ``slopes`` and ``density_slope``: d(rho/rho0)/dp, p in the units of ``p``
            (the right derivative at p <= 0; zero for an incompressible lubricant).
        """
        p = np.asarray(p, dtype=float)
        h = np.asarray(h, dtype=float)
        if h.shape != p.shape:
            raise InputError("h", f"the shape of p {p.shape}", h.shape)
        # the nodes in p's memory order (a field of the EHL solver is stored x-fastest)
        order = "F" if p.ndim > 1 and p.flags.f_contiguous and not p.flags.c_contiguous else "C"
        p = np.asarray(p, order=order)
        h = np.asarray(h, order=order)
        sizes = (1, 1, 1, slopes, slopes, slopes and density_slope)
        out = [np.empty(p.shape if size else 0, order=order) for size in sizes]
        flat = [a.ravel(order=order) for a in (p, h, *out)]
        p_unit, h_unit, scale = (float(u) for u in units)
        _flow_field(*flat[:2], (p_unit, h_unit, scale, scale * p_unit),
                    *self.flow_law_parameters(sliding_speed), *flat[2:5], slopes, *flat[5:])
        return tuple(out[:(6 if density_slope else 5) if slopes else 3])

    def flow_law_parameters(self, sliding_speed: float) -> tuple:
        """The laws of :meth:`flow_field` as numbers: ``(roelands, eta0, v1, v2, v3, gamma,
        lam, shear)``.

        ``roelands`` whether the viscosity is Roelands' (``v1 = ln(eta0/kappa)``, ``v2 =
        chi``, ``v3 = Z``) or Barus' (``v1 = alpha``); ``gamma, lam`` Dowson-Higginson's
        constants (0 incompressible); ``shear = |du|/tau0`` (0 Newtonian). For another
        implementation of the same laws (``benchmarks/ehl_sweep_gpu.cu``).
        """
        roelands = self.viscosity_model == "roelands"
        if roelands:
            v1 = math.log(self.viscosity / self.roelands_kappa)
            v2, v3 = self.roelands_chi, self.roelands_z
        else:
            v1, v2, v3 = self.pressure_viscosity, 0.0, 0.0
        gamma, lam = (self.dh_gamma, self.dh_lambda) if self.compressible else (0.0, 0.0)
        shear = 0.0 if self.newtonian else abs(float(sliding_speed)) / self.eyring_stress
        return roelands, self.viscosity, v1, v2, v3, gamma, lam, shear


def eyring_flow_factors(h, eta, rho, sliding_speed, tau0=None):
    """Poiseuille flow factors of an Eyring film sheared along x.

    Linearisation of the Eyring flux about the sliding (Couette) stress: Conry, Wang & Cusano
    (1987) for line contacts, written for two dimensions (EHL-NOTES sec. 3). With
    ``X = eta |du| / (tau0 h)`` and ``S = tau_m / tau0 = asinh X``::

        sigma_x = rho h^3 cosh(S) / (12 eta)        = rho h^3 sqrt(1 + X^2) / (12 eta)
        sigma_y = rho h^3 sinh(S) / (12 eta S)      = rho h^3 X / (12 eta asinh X)

    These enter the Reynolds equation
    ``d/dx(sigma_x dp/dx) + d/dy(sigma_y dp/dy) - d/dx(rho u h) - d/dt(rho h) = 0``
    (seed eq. 2). They are the effective x- and y-fluidities of the Eyring law at the Couette
    stress (d(shear rate)/d tau along and across the sliding direction) and are exact to first
    order in G = h |grad p| / tau0; the error grows as G^2 (about 1 % at G = 0.5).

    Both factors are evaluated without dividing by ``h`` (``sigma_x = rho h^2
    sqrt((h/eta)^2 + (du/tau0)^2) / 12``, ``sigma_y = rho h^2 |du| / (12 tau0 asinh X)``), so
    ``h = 0`` gives 0, not NaN. For ``tau0 = None`` or ``X -> 0`` both tend to the Newtonian
    ``rho h^3 / (12 eta)``.

    Parameters
    ----------
    h : array_like
        Film thickness, m (>= 0).
    eta : array_like
        Low-shear viscosity, Pa s (> 0).
    rho : array_like
        Density (any consistent unit; pass rho/rho0 for a scaled equation).
    sliding_speed : array_like
        du = u2 - u1, the sliding speed along x, m/s (its sign does not matter).
    tau0 : float or None
        Eyring stress, Pa; None for a Newtonian lubricant.

    Returns
    -------
    sigma_x, sigma_y : ndarray
        Flow factors, in units of rho m^3 / (Pa s).
    """
    h = np.asarray(h, dtype=float)
    eta = np.asarray(eta, dtype=float)
    if np.any(h < 0):
        raise InputError("h", "film thickness >= 0")
    if np.any(~(eta > 0)):
        raise InputError("eta", "viscosity > 0")
    rho = np.asarray(rho, dtype=float)
    if tau0 is None:
        shear = 0.0
    else:
        shear = np.abs(np.asarray(sliding_speed, dtype=float)) / check_positive("tau0", tau0)
    return _sigma_x(h, eta, rho, shear), _sigma_y(h, eta, rho, shear)


def eyring_mean_shear_stress(h, eta, sliding_speed, tau0=None):
    """Couette (mean) shear stress of the film, tau_m = tau0 asinh(eta du / (tau0 h)).

    Exact for pure sliding of an Eyring fluid (shear rate du/h = (tau0/eta) sinh(tau/tau0));
    ``eta du / h`` when ``tau0`` is None. Signed like ``sliding_speed = u2 - u1``. At ``h = 0``
    the stress is unbounded (+-inf; 0 where du = 0): dry nodes need a boundary-friction law.

    Parameters
    ----------
    h : array_like
        Film thickness, m (>= 0).
    eta : array_like
        Viscosity, Pa s.
    sliding_speed : array_like
        du = u2 - u1, m/s.
    tau0 : float or None
        Eyring stress, Pa.

    Returns
    -------
    ndarray
        tau_m, Pa.
    """
    h = np.asarray(h, dtype=float)
    if np.any(h < 0):
        raise InputError("h", "film thickness >= 0")
    du = np.asarray(sliding_speed, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        newtonian = np.where(du == 0, 0.0, np.asarray(eta, dtype=float) * du / h)
    if tau0 is None:
        return newtonian
    tau0 = check_positive("tau0", tau0)
    return tau0 * np.arcsinh(newtonian / tau0)


def wall_shear_stress(h, eta, sliding_speed, dpdx, tau0=None):
    """Shear stress tau_zx of the film at the lower (z = 0) and upper (z = h) surfaces.

    ``tau_zx(0) = tau_m - (h/2) dp/dx`` and ``tau_zx(h) = tau_m + (h/2) dp/dx`` with tau_m from
    :func:`eyring_mean_shear_stress`: exact for a Newtonian film, first order in
    G = h |dp/dx| / tau0 for an Eyring film (EHL-NOTES sec. 3). Surface 1 (z = 0, speed u1)
    feels the traction ``+tau_zx(0)`` along x; surface 2 feels ``-tau_zx(h)``.

    Returns
    -------
    tau_lower, tau_upper : ndarray
        Pa.
    """
    tau_m = eyring_mean_shear_stress(h, eta, sliding_speed, tau0)
    half = 0.5 * np.asarray(h, dtype=float) * np.asarray(dpdx, dtype=float)
    return tau_m - half, tau_m + half


def friction_coefficient(x, p, h, eta, sliding_speed, tau0=None, boundary_friction=0.1):
    """Traction coefficient of the film on surface 1: mu = sum tau_zx(z=0) / sum p.

    Film nodes (h > 0) carry the wall stress of :func:`wall_shear_stress` with dp/dx by
    second-order central differences (``numpy.gradient``) along axis 0; dry nodes (h = 0)
    carry the boundary friction ``boundary_friction * p * sign(du)``. On a uniform grid the
    area integrals reduce to sums. Positive along +x (for u2 > u1 the film drags surface 1
    forward).

    Parameters
    ----------
    x : array_like
        Cell-centre coordinates along x (axis 0 of the fields), m, uniform.
    p, h, eta : array_like
        Pressure (Pa), film (m) and viscosity (Pa s) on the grid, indexed ``[ix, iy]`` (or
        ``[ix]`` for a line contact).
    sliding_speed : float or array_like
        du = u2 - u1, m/s.
    tau0 : float or None
        Eyring stress, Pa.
    boundary_friction : float
        Friction coefficient of dry (h = 0) nodes.

    Returns
    -------
    float
        mu.
    """
    from ..elastic.convolution import grid_spacing

    p = np.asarray(p, dtype=float)
    h = np.asarray(h, dtype=float)
    if h.shape != p.shape:
        raise InputError("h", f"the shape of p {p.shape}", h.shape)
    dx = grid_spacing(x, "x")
    if p.shape[0] != len(x):
        raise InputError("x", f"{p.shape[0]} coordinates (axis 0 of p)", len(x))
    boundary_friction = check_positive("boundary_friction", boundary_friction, allow_zero=True)
    load = p.sum()
    if not load > 0:
        raise InputError("p", "a pressure field with a positive resultant")
    du = np.broadcast_to(np.asarray(sliding_speed, dtype=float), p.shape)
    wet = h > 0
    eta = np.broadcast_to(np.asarray(eta, dtype=float), p.shape)
    tau_wet, _ = wall_shear_stress(np.where(wet, h, 1.0), eta, du, np.gradient(p, dx, axis=0), tau0)
    tau = np.where(wet, tau_wet, boundary_friction * p * np.sign(du))
    return float(tau.sum() / load)
