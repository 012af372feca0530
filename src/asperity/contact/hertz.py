"""Hertz's solution for smooth non-conforming contact, with exact complete elliptic integrals.

The undeformed gap is ``x^2 / (2 rx) + y^2 / (2 ry)``. The contact is an ellipse with
semi-axes ``a`` (along x) and ``b`` (along y) carrying the pressure
``p_max sqrt(1 - x^2/a^2 - y^2/b^2)``.

With the major semi-axis ``m``, the minor ``n``, eccentricity ``e^2 = 1 - n^2/m^2``, and K, E
the complete elliptic integrals of modulus e (Johnson 1985, eqs. 3.39-3.43, 3.35)::

    A_m / A_n = [K - E] / [E / (1 - e^2) - K]  (curvature ratio, A = 1/(2 R))
    m^3 = 3 P (K - E) / (2 pi E* e^2 A_m)
    p_max = 3 P / (2 pi m n),  approach = p_max n K / E*

with the circle (rx == ry) as the limit e -> 0: a^3 = 3 P R / (4 E*).

References
----------
K. L. Johnson, *Contact Mechanics*, 1985, sec. 3.4 and 4.2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from ..errors import InputError, check_positive
from ..materials import Material, contact_modulus

__all__ = ["HertzPoint", "HertzLine", "hertz_point", "hertz_line", "radius_ratio"]


@dataclass(frozen=True)
class HertzPoint:
    """Result of :func:`hertz_point` (SI units)."""

    a: float
    """Semi-axis along x, m."""
    b: float
    """Semi-axis along y, m."""
    p_max: float
    """Maximum (central) pressure, Pa."""
    approach: float
    """Mutual approach of distant points of the two bodies, m."""
    load: float
    """Normal load, N."""
    rx: float
    ry: float
    modulus: float
    """Composite modulus E*, Pa."""

    @property
    def area(self) -> float:
        """Contact area pi a b, m^2."""
        return np.pi * self.a * self.b

    @property
    def mean_pressure(self) -> float:
        """Mean pressure P / (pi a b) = 2 p_max / 3, Pa."""
        return self.load / self.area

    def pressure(self, x, y):
        """Hertz pressure p_max sqrt(1 - x^2/a^2 - y^2/b^2) at (x, y), zero outside, Pa."""
        r2 = (np.asarray(x) / self.a) ** 2 + (np.asarray(y) / self.b) ** 2
        return self.p_max * np.sqrt(np.clip(1.0 - r2, 0.0, None))


def _curvature_ratio(m: float) -> float:
    """A_m/A_n (<= 1), the ratio of the gap's curvatures along the major and minor axes of
    the Hertz ellipse of eccentricity e^2 = m (Johnson 1985, eq. 4.39):
    ``(K - E) / (E / (1 - m) - K)``."""
    k, e = ellipk(m), ellipe(m)
    return (k - e) / (e / (1.0 - m) - k)


def radius_ratio(aspect_ratio: float) -> float:
    """Rx/Ry of the gap whose Hertz ellipse has ``a/b = aspect_ratio`` (a along x).

    The major axis lies along the larger radius, so ``Rx/Ry = (A_m/A_n)^-1`` for
    ``a/b > 1`` and ``A_m/A_n`` for ``a/b < 1`` with ``m = 1 - (minor/major)^2``
    (:func:`_curvature_ratio`); independent of the load and the materials.
    """
    k = check_positive("aspect_ratio", aspect_ratio)
    if k == 1.0:
        return 1.0
    ratio = _curvature_ratio(1.0 - min(k, 1.0 / k) ** 2)
    return 1.0 / ratio if k > 1.0 else ratio


def _eccentricity_squared(ratio: float) -> float:
    """Solve A_m/A_n = ratio (<= 1) for e^2, with parameter m = e^2 as scipy takes it."""
    if 1.0 - ratio < 1e-7:  # nearly circular: ratio = 1 - 3 m / 4 + O(m^2)
        return max(4.0 * (1.0 - ratio) / 3.0, 0.0)

    def f(m):
        return _curvature_ratio(m) - ratio

    lower = 2.0 * (1.0 - ratio) / 3.0  # f(lower) > 0 since ratio(m) ~ 1 - 3 m / 4
    return brentq(f, lower, 1.0 - 1e-16, xtol=1e-16, rtol=1e-15, maxiter=400)


def hertz_point(load, rx, ry, body1: Material, body2: Material) -> HertzPoint:
    """Elliptical (or circular) Hertz contact of two bodies.

    Parameters
    ----------
    load : float
        Normal load P, N.
    rx, ry : float
        Radii of relative curvature in the x and y directions, m (``np.inf`` is not allowed:
        use :func:`hertz_line`).
    body1, body2 : Material
        The two elastic bodies.

    Returns
    -------
    HertzPoint
        Semi-axes ``a`` (x) and ``b`` (y), ``p_max``, ``approach``.
    """
    P = check_positive("load", load)
    rx = check_positive("rx", rx)
    ry = check_positive("ry", ry)
    if not (np.isfinite(rx) and np.isfinite(ry)):
        raise InputError("rx, ry", "finite radii (use hertz_line for a line contact)")
    E = contact_modulus(body1, body2)
    # major axis lies along the direction of the larger radius (smaller curvature)
    r_major, r_minor = max(rx, ry), min(rx, ry)
    a_m, a_n = 0.5 / r_major, 0.5 / r_minor
    m = _eccentricity_squared(a_m / a_n)
    k = ellipk(m)
    k_minus_e_over_m = (k - ellipe(m)) / m if m > 1e-6 else 0.25 * np.pi * (1 + 0.375 * m)
    major = (3.0 * P * k_minus_e_over_m / (2.0 * np.pi * E * a_m)) ** (1.0 / 3.0)
    minor = major * np.sqrt(1.0 - m)
    p0 = 3.0 * P / (2.0 * np.pi * major * minor)
    approach = p0 * minor * k / E
    a, b = (major, minor) if rx > ry else (minor, major)
    return HertzPoint(a, b, p0, approach, P, rx, ry, E)


@dataclass(frozen=True)
class HertzLine:
    """Result of :func:`hertz_line`: half-width ``a`` (m) and ``p_max`` (Pa) per unit length."""

    a: float
    p_max: float
    load_per_length: float
    radius: float
    modulus: float

    def pressure(self, x):
        """p_max sqrt(1 - x^2/a^2), zero outside, Pa."""
        return self.p_max * np.sqrt(np.clip(1.0 - (np.asarray(x) / self.a) ** 2, 0.0, None))


def hertz_line(load_per_length, radius, body1: Material, body2: Material) -> HertzLine:
    """Two-dimensional (line) Hertz contact: a = sqrt(4 w' R / (pi E*)), p_max = 2 w'/(pi a).

    (Johnson 1985, eqs. 4.43-4.45.)
    """
    w = check_positive("load_per_length", load_per_length)
    R = check_positive("radius", radius)
    E = contact_modulus(body1, body2)
    a = np.sqrt(4.0 * w * R / (np.pi * E))
    return HertzLine(a, 2.0 * w / (np.pi * a), w, R, E)
