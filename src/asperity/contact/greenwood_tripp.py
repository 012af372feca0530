"""Greenwood & Tripp's rough sphere: the statistical estimate a rough dry ball is set beside.

Greenwood & Tripp (1967) press a smooth sphere of radius R on a rough flat whose summits have a
density ``eta`` (per area), a radius ``beta`` and Gaussian heights of rms ``sigma_s``; each
summit is a Hertz contact and the summits do not interact. At the separation ``d`` of the
sphere from the summits' mean plane the nominal pressure and the real area per nominal area are
(Greenwood & Williamson 1966)::

    p = (4/3) eta E* beta^(1/2) sigma_s^(3/2) F_3/2(d / sigma_s)
    A_real / A = pi eta beta sigma_s F_1(d / sigma_s)

with ``F_n(h) = int_h^inf (s - h)^n phi(s) ds``, ``phi`` the standard normal density, and
``d(r) = -delta + r^2 / (2 R) + w(r)``, ``w`` the half-space's displacement under the
axisymmetric nominal pressure. The summit parameters come from the surface's spectral moments
(McCool 1986, isotropic): ``eta = m4 / (6 pi sqrt(3) m2)``, ``beta = 0.375 sqrt(pi / m4)``,
``sigma_s^2 = (1 - 0.8968 / alpha_b) m0``, ``alpha_b = m0 m4 / m2^2``, with ``m0, m2, m4`` a
profile's moments (``m2`` half the areal mean squared gradient, ``m4`` 3/8 of the areal
``<q^4>``).

Its known accuracy (docs/tangential.md, "A rough ball against Greenwood and Tripp"): on our own
gaussian surfaces the deterministic solve's load spreads to an rms radius 4-5 % under GT's and
its real area is 28 % above GT's on a converged mesh (more on a coarse one); ``m4`` of a
sampled surface depends on its shortest wavelengths, so the estimate follows the sampling.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.fft
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk, gamma, pbdv

__all__ = ["GreenwoodTripp", "SummitParameters", "greenwood_tripp_sphere", "gw_integral",
           "summit_parameters"]


@dataclass(frozen=True)
class SummitParameters:
    """McCool's summit statistics of an isotropic Gaussian surface."""

    density: float
    """eta, summits per m^2."""
    radius: float
    """beta, mean summit radius, m."""
    sigma: float
    """sigma_s, rms of the summit heights, m."""
    bandwidth: float
    """Nayak's alpha_b = m0 m4 / m2^2 (1.5 at the narrow-band limit)."""
    anisotropy: float
    """m2 along x over m2 along y (1 for an isotropic surface)."""


def summit_parameters(heights, dx, dy) -> SummitParameters | None:
    """Summit density, radius and height rms of a sampled surface (McCool 1986).

    Parameters
    ----------
    heights : ndarray, shape (nx, ny)
        Surface heights, m (their mean is removed).
    dx, dy : float
        Sampling intervals, m.

    Returns
    -------
    SummitParameters or None
        None for a surface without curvature or with ``alpha_b <= 0.8968`` (no summit
        height distribution).
    """
    z = np.asarray(heights, dtype=float)
    z = z - z.mean()
    nx, ny = z.shape
    qx = 2.0 * np.pi * scipy.fft.fftfreq(nx, dx)[:, None]
    qy = 2.0 * np.pi * scipy.fft.fftfreq(ny, dy)[None, :]
    power = np.abs(scipy.fft.fft2(z, workers=-1) / z.size) ** 2
    q2 = qx**2 + qy**2
    m0 = float(power.sum())
    m2 = 0.5 * float((q2 * power).sum())
    m4 = 0.375 * float((q2**2 * power).sum())
    if not (m0 > 0.0 and m2 > 0.0 and m4 > 0.0):
        return None
    alpha_b = m0 * m4 / m2**2
    if alpha_b <= 0.8968:
        return None
    m2y = float((qy**2 * power).sum())
    return SummitParameters(density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
                            radius=0.375 * math.sqrt(math.pi / m4),
                            sigma=math.sqrt((1.0 - 0.8968 / alpha_b) * m0), bandwidth=alpha_b,
                            anisotropy=float((qx**2 * power).sum()) / m2y if m2y > 0 else math.inf)


def gw_integral(order, h):
    """``F_n(h) = int_h^inf (s - h)^n phi(s) ds`` exactly, by the parabolic cylinder function:
    ``F_n(h) = Gamma(n + 1) exp(-h^2 / 4) D_-(n+1)(h) / sqrt(2 pi)`` (Abramowitz & Stegun
    19.5.3 with ``int_0^inf t^n exp(-(t + h)^2 / 2) dt``). ``h`` is clipped to [-30, 38],
    where the two factors stay finite (F_n(38) < 1e-300; the load searches probe below -30)."""
    h = np.clip(np.asarray(h, dtype=float), -30.0, 38.0)
    d, _ = pbdv(-(order + 1.0), h)
    return gamma(order + 1.0) * np.exp(-0.25 * h * h) * d / math.sqrt(2.0 * math.pi)


def _disc_displacement(r, c, e_star):
    """Surface displacement at radius r under unit pressure on a disc of radius c, m/Pa
    (Johnson 1985, eqs. 3.24a, b): ``(4 c / (pi E*)) E(r/c)`` inside,
    ``(4 r / (pi E*)) [E(c/r) - (1 - c^2/r^2) K(c/r)]`` outside (scipy takes m = k^2)."""
    r = np.asarray(r, dtype=float)
    out = np.empty(np.broadcast(r, c).shape)
    inside = r <= c
    rc = np.broadcast_to(r, out.shape)
    cc = np.broadcast_to(c, out.shape)
    ki = (rc[inside] / cc[inside]) ** 2
    out[inside] = 4.0 * cc[inside] / (math.pi * e_star) * ellipe(ki)
    ro, co = rc[~inside], cc[~inside]
    ko = (co / ro) ** 2
    out[~inside] = 4.0 * ro / (math.pi * e_star) * (ellipe(ko) - (1.0 - ko) * ellipk(ko))
    return out


@dataclass(frozen=True)
class GreenwoodTripp:
    """Greenwood & Tripp's nominal pressure of a rough sphere, on rings."""

    radii: np.ndarray
    """Ring centres, m."""
    pressure: np.ndarray
    """Nominal pressure on each ring, Pa."""
    area_fraction: np.ndarray
    """Real area per nominal area on each ring."""
    width: float
    """Ring width, m."""
    converged: bool

    @property
    def real_area(self) -> float:
        """Real contact area, m^2."""
        return float(2.0 * math.pi * np.sum(self.area_fraction * self.radii) * self.width)

    @property
    def load(self) -> float:
        """Load carried, N."""
        return float(2.0 * math.pi * np.sum(self.pressure * self.radii) * self.width)

    @property
    def rms_radius(self) -> float:
        """``sqrt(int p r^2 dA / int p dA)``, the load's rms radius, m."""
        return math.sqrt(float(np.sum(self.pressure * self.radii**3))
                         / float(np.sum(self.pressure * self.radii)))


def greenwood_tripp_sphere(load, radius, e_star, summits: SummitParameters, rings=160,
                           reach=3.0, tol=1e-7, iterations=400) -> GreenwoodTripp:
    """Solve Greenwood & Tripp's rough sphere under a load (module docstring).

    The pressure is constant on each of ``rings`` rings out to ``reach`` Hertz radii; the
    displacement is that of those annuli, exactly (:func:`_disc_displacement`, outer disc minus
    inner); the approach is found by ``brentq`` for the load at each damped fixed-point step,
    until the pressure changes by less than ``tol`` of its largest value.
    """
    a0 = (3.0 * load * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    edges = np.linspace(0.0, reach * a0, rings + 1)
    r = 0.5 * (edges[1:] + edges[:-1])
    width = float(edges[1] - edges[0])
    kernel = (_disc_displacement(r[:, None], edges[None, 1:], e_star)
              - np.where(edges[None, :-1] > 0.0,
                         _disc_displacement(r[:, None], np.maximum(edges[None, :-1], 1e-300),
                                            e_star), 0.0))
    eta, beta, sigma = summits.density, summits.radius, summits.sigma
    scale = (4.0 / 3.0) * eta * e_star * math.sqrt(beta) * sigma**1.5

    def separation(delta, w):
        return (-delta + r * r / (2.0 * radius) + w) / sigma

    def pressure(delta, w):
        return scale * gw_integral(1.5, separation(delta, w))

    def carried(p):
        return 2.0 * math.pi * float(np.sum(p * r)) * width

    p = np.zeros_like(r)
    converged = False
    span = 20.0 * sigma + 20.0 * a0 * a0 / radius
    for _ in range(iterations):
        w = kernel @ p
        delta = brentq(lambda d, w=w: carried(pressure(d, w)) - load, -span, span,
                       xtol=1e-16, rtol=1e-13)
        new = pressure(delta, w)
        if p.any() and np.abs(new - p).max() < tol * new.max():
            converged = True
            break
        p = new if not p.any() else 0.7 * p + 0.3 * new
    return GreenwoodTripp(radii=r, pressure=new, area_fraction=math.pi * eta * beta * sigma
                          * gw_integral(1.0, separation(delta, w)), width=width,
                          converged=converged)
