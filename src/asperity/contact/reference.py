"""Closed-form solutions of frictional contact used to validate the numerical solvers.

All functions take SI values. "Relative" shifts and twists are the rigid motion of body 1 with
respect to body 2 (distant points), the sum of the two bodies' motions relative to the
interface; closed forms for one body are obtained by passing a rigid ``body2``.

References
----------
C. Cattaneo, Rend. Accad. Lincei 27 (1938) 342-348; R. D. Mindlin, J. Appl. Mech. 16 (1949)
259-268; K. L. Johnson, *Contact Mechanics*, 1985, sec. 7.2 (eqs. 7.38-7.42, Masing 7.54-7.56)
and sec. 7.3 (torsion, eqs. 7.45-7.50); J. L. Lubkin, J. Appl. Mech. 18 (1951) 183-187.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq, minimize
from scipy.special import ellipe, ellipk

from ..errors import InputError, check_positive
from ..materials import Material, tangential_compliance

__all__ = [
    "gross_slip_moment_ellipse",
    "gross_slip_moment_rectangles",
    "rectangle_distance_integral",
    "CattaneoMindlin",
    "cattaneo_mindlin",
    "cattaneo_mindlin_ellipse",
    "masing_history",
    "masing_unloading_shift",
    "mindlin_deresiewicz_energy",
    "lubkin_moment",
    "lubkin_twist",
    "lubkin_stick_radius",
    "uniform_torsion_moment",
    "uniform_torsion_twist",
    "uniform_torsion_stick_radius",
    "gross_slip_moment_hertz",
    "gross_slip_moment_uniform",
]


def _shear_compliance(body1: Material, body2: Material | None) -> float:
    """1/G1 + 1/G2 (a rigid or absent body contributes nothing), 1/Pa."""
    return sum(0.0 if b is None or b.rigid else 1.0 / b.shear_modulus for b in (body1, body2))


@dataclass(frozen=True)
class CattaneoMindlin:
    """Cattaneo-Mindlin partial slip of a circular Hertz contact under a tangential force."""

    a: float
    """Contact radius, m."""
    stick_radius: float
    """c = a (1 - Q/(mu P))^(1/3), m."""
    shift: float
    """Relative rigid shift of body 1 with respect to body 2 along Q, m."""
    p0: float
    """Maximum Hertz pressure 3 P / (2 pi a^2), Pa."""
    mu: float
    force: float
    normal_load: float

    def traction(self, r):
        """Traction magnitude at radius r, Pa (Johnson eq. 7.39).

        mu p0 sqrt(1 - r^2/a^2) - (c/a) mu p0 sqrt(1 - r^2/c^2) inside the stick circle.
        """
        r = np.asarray(r, dtype=float)
        a, c, f = self.a, self.stick_radius, self.mu * self.p0
        q = f * np.sqrt(np.clip(1.0 - (r / a) ** 2, 0.0, None))
        if c > 0:
            q = q - (c / a) * f * np.sqrt(np.clip(1.0 - (r / c) ** 2, 0.0, None))
        return q


def _cattaneo_shift(force, normal_load, mu, a, compliance):
    """delta = (3 mu P / (16 a)) C [1 - (1 - Q/(mu P))^(2/3)], C = sum (2 - nu)/G."""
    ratio = force / (mu * normal_load)
    return 3.0 * mu * normal_load / (16.0 * a) * compliance * (1.0 - (1.0 - ratio) ** (2.0 / 3.0))


def cattaneo_mindlin(normal_load, force, mu, a, body1: Material, body2: Material):
    """Cattaneo-Mindlin solution for a tangential force below gross slip.

    Parameters
    ----------
    normal_load : float
        P, N.
    force : float
        Tangential force Q with 0 <= Q <= mu P, N.
    mu : float
        Coefficient of friction.
    a : float
        Hertz contact radius, m.
    body1, body2 : Material
        The bodies (the decoupled solution is exact for identical materials).

    Returns
    -------
    CattaneoMindlin
        Stick radius, relative shift (Mindlin 1949; Johnson eq. 7.42) and the traction profile.
    """
    P = check_positive("normal_load", normal_load)
    mu = check_positive("mu", mu)
    a = check_positive("a", a)
    Q = check_positive("force", force, allow_zero=True)
    if Q > mu * P:
        raise InputError("force", f"at most mu * normal_load = {mu * P:g} N (gross slip)", Q)
    c = a * (1.0 - Q / (mu * P)) ** (1.0 / 3.0)
    delta = _cattaneo_shift(Q, P, mu, a, tangential_compliance(body1, body2))
    return CattaneoMindlin(a, c, delta, 3.0 * P / (2.0 * np.pi * a * a), mu, Q, P)


def _centre_displacement_per_traction(sx, sy, body1: Material, body2: Material) -> tuple:
    """Relative displacement (along x, along y) at the centre of an ellipse of semi-axes sx, sy
    under the traction ``sqrt(1 - x^2/sx^2 - y^2/sy^2)`` (per unit amplitude) along x and
    along y, m/Pa.

    Cerruti's point force gives ``u_x = [(1 - nu) + nu cos^2 t] / (2 pi G r)`` at the angle t
    from the force; integrating the traction along each ray (``int_0^R sqrt(1 - r^2/R^2) dr =
    pi R / 4``) leaves ``(1 / (8 G)) int_0^2pi [(1 - nu) + nu cos^2 t] R(t) dt``, with
    ``R(t) = (cos^2 t / sx^2 + sin^2 t / sy^2)^(-1/2)``. With s the short semi-axis and
    ``m = 1 - s^2 / l^2``: ``int R dt = 4 s K(m)`` and, with t from the long axis,
    ``int cos^2 t R dt = 4 s (K(m) - E(m)) / m`` (pi s at m = 0: a circle gives
    ``pi a (2 - nu) / (8 G)``, Johnson eq. 7.8's centre value).
    """
    s, long_ = min(sx, sy), max(sx, sy)
    m = 1.0 - (s / long_) ** 2
    k = ellipk(m)
    along_long = (4.0 * s * (k - ellipe(m)) / m if m > 1e-6
                  else math.pi * s * (1.0 + 0.375 * m))
    whole = 4.0 * s * k
    along_x, along_y = ((along_long, whole - along_long) if sx >= sy
                        else (whole - along_long, along_long))
    out = []
    for along in (along_x, along_y):
        out.append(sum(((1.0 - b.poisson_ratio) * whole + b.poisson_ratio * along)
                       / (8.0 * b.shear_modulus)
                       for b in (body1, body2) if b is not None and not b.rigid))
    return tuple(out)


def cattaneo_mindlin_ellipse(normal_load, force, mu, a, b, body1: Material, body2: Material,
                             axis: str = "x") -> tuple[float, float, float]:
    """Mindlin's partial slip of an elliptical Hertz contact under a force along one of its axes.

    The traction is Cattaneo's construction on the ellipse: ``mu p0 sqrt(1 - x^2/a^2 -
    y^2/b^2)`` minus ``(c/a) mu p0 sqrt(1 - x^2/c^2 - y^2/d^2)`` on the similar stick ellipse
    ``c/a = d/b = (1 - Q/(mu P))^(1/3)`` (Mindlin 1949; Johnson 1985, sec. 7.2): a Hertz-shaped
    traction displaces the inside of its ellipse by a constant minus a quadratic whose
    coefficients depend only on the ellipse's shape, so those of the two terms cancel in the
    stick ellipse and the shift is the difference of their centre values,
    ``delta = mu p0 C (1 - (c/a)^2)``, C from :func:`_centre_displacement_per_traction`.
    Exact for similar bodies (Dundurs beta = 0) up to the slip's direction, which Mindlin's
    construction takes along the force (as on a circle).

    Parameters
    ----------
    normal_load, force : float
        P and Q (0 <= Q <= mu P), N.
    mu : float
        Coefficient of friction.
    a, b : float
        Semi-axes of the Hertz ellipse along x and along y, m.
    body1, body2 : Material
        The bodies.
    axis : {"x", "y"}
        The axis the force lies along.

    Returns
    -------
    tuple of float
        The relative shift along the force (m) and the stick ellipse's semi-axes along x and
        along y (m).
    """
    P = check_positive("normal_load", normal_load)
    mu = check_positive("mu", mu)
    Q = check_positive("force", force, allow_zero=True)
    if Q > mu * P:
        raise InputError("force", f"at most mu * normal_load = {mu * P:g} N (gross slip)", Q)
    if axis not in ("x", "y"):
        raise InputError("axis", '"x" or "y"', axis)
    scale = (1.0 - Q / (mu * P)) ** (1.0 / 3.0)
    p0 = 3.0 * P / (2.0 * math.pi * a * b)
    cx, cy = _centre_displacement_per_traction(a, b, body1, body2)
    shift = mu * p0 * (cx if axis == "x" else cy) * (1.0 - scale * scale)
    return float(shift), float(a * scale), float(b * scale)


def masing_unloading_shift(force, peak_force, normal_load, mu, a, body1, body2):
    """Shift on unloading from Q* to Q (Masing's rule; Johnson eq. 7.56), m.

    delta_unload(Q) = delta(Q*) - 2 delta_load((Q* - Q)/2), for -Q* <= Q <= Q* <= mu P.
    """
    C = tangential_compliance(body1, body2)
    Qs = check_positive("peak_force", peak_force, allow_zero=True)
    if Qs > mu * normal_load or not (-Qs <= force <= Qs):
        raise InputError("force", "-peak_force <= force <= peak_force <= mu * normal_load", force)
    peak = _cattaneo_shift(Qs, normal_load, mu, a, C)
    return peak - 2.0 * _cattaneo_shift(0.5 * (Qs - force), normal_load, mu, a, C)


def mindlin_deresiewicz_energy(peak_force, normal_load, mu, a, body1, body2):
    """Energy dissipated per cycle of a tangential force oscillating between -Q* and Q*, J.

    The area of the Masing loop (Mindlin & Deresiewicz 1953; Johnson eq. 7.60), written for
    the relative shift of the two bodies, C = (2 - nu1)/G1 + (2 - nu2)/G2, r = Q*/(mu P):

    ``dW = (9 mu^2 P^2 C / (10 a)) [1 - (1 - r)^(5/3) - (5 r / 6) (1 + (1 - r)^(2/3))]``

    (the loop integral 4 Q* delta(Q*) - 8 int_0^Q* delta(Q) dQ of Cattaneo-Mindlin's shift
    delta, eq. 7.42, in closed form); ``C Q*^3 / (36 mu P a)`` at small r.

    Parameters
    ----------
    peak_force : float
        Q*, the amplitude of the tangential force, 0 <= Q* <= mu P, N.
    normal_load, mu, a, body1, body2
        As :func:`cattaneo_mindlin`.

    Returns
    -------
    float
    """
    P = check_positive("normal_load", normal_load)
    Qs = check_positive("peak_force", peak_force, allow_zero=True)
    if Qs > mu * P:
        raise InputError("peak_force", f"at most mu * normal_load = {mu * P:g} N (gross slip)",
                         Qs)
    r = Qs / (mu * P)
    scale = 9.0 * (mu * P) ** 2 * tangential_compliance(body1, body2) / (10.0 * a)
    return scale * (1.0 - (1.0 - r) ** (5.0 / 3.0)
                    - 5.0 * r / 6.0 * (1.0 + (1.0 - r) ** (2.0 / 3.0)))


def masing_history(forces, normal_load, mu, a, body1, body2, points=16):
    """Shift against force along a history of tangential forces from zero (Cattaneo-Mindlin
    on the first loading, Masing's rule after each reversal), m and N.

    The first loading follows ``sign(Q) delta(|Q|)`` (Johnson eq. 7.42); after a reversal at
    ``(Q_r, delta_r)`` the shift is ``delta_r + 2 delta((Q - Q_r)/2)`` in the new direction
    (Mindlin & Deresiewicz 1953; Johnson eq. 7.56, :func:`masing_unloading_shift` for one
    reversal from the peak). The curve ends at ``|Q| = mu P`` (gross slip).

    Parameters
    ----------
    forces : array_like
        The tangential forces of the history's steps along one direction, N.
    normal_load, mu, a, body1, body2
        As :func:`cattaneo_mindlin`.
    points : int
        Points per step of the curve.

    Returns
    -------
    (ndarray, ndarray)
        Shift (m) and force (N), from (0, 0).
    """
    capacity = mu * normal_load
    compliance = tangential_compliance(body1, body2)

    def virgin(q):
        return _cattaneo_shift(min(q, capacity), normal_load, mu, a, compliance)

    qs = np.concatenate([[0.0], np.asarray(forces, dtype=float)])
    force, shift = [0.0], [0.0]
    q_r = d_r = direction = 0.0
    first = True
    for q0, q1 in zip(qs[:-1], qs[1:], strict=True):
        d = float(np.sign(q1 - q0))
        if d == 0.0:
            continue
        if direction and d != direction:
            q_r, d_r, first = q0, shift[-1], False
        direction = d
        for q in np.linspace(q0, q1, points + 1)[1:]:
            q = float(np.clip(q, -capacity, capacity))  # gross slip: the curve ends there
            if first:
                delta = float(np.copysign(virgin(abs(q)), q))
            else:
                delta = d_r + d * 2.0 * virgin(0.5 * abs(q - q_r))
            force.append(q)
            shift.append(delta)
            if abs(q) >= capacity:
                return np.array(shift), np.array(force)
    return np.array(shift), np.array(force)


def lubkin_moment(c, a, mu, p0):
    """Twisting moment that leaves a stick circle of radius c (Lubkin 1951), N m.

    M(c) = (8 mu p0 / 3) int_c^a t^2 E(sqrt(1 - t^2/a^2)) dt, with E the complete elliptic
    integral of the second kind (scipy's ``ellipe`` takes the parameter m = k^2).
    """
    if not 0.0 <= c <= a:
        raise InputError("c", "a stick radius in [0, a]", c)
    val, _ = quad(lambda t: t * t * ellipe(1.0 - (t / a) ** 2), c, a, epsabs=0.0, epsrel=1e-12)
    return 8.0 * mu * p0 / 3.0 * val


def lubkin_twist(c, a, mu, p0, body1: Material, body2: Material | None = None):
    """Rigid twist for a stick radius c, rad (Lubkin 1951; Johnson eq. 7.50).

    One body relative to the interface: beta = (mu p0 / (2 G)) [K(k') - E(k')],
    k' = sqrt(1 - c^2/a^2). With ``body2`` the relative twist of body 1 with respect to body 2,
    the sum of the two.
    """
    if not 0.0 < c <= a:
        raise InputError("c", "a stick radius in (0, a]", c)
    m = 1.0 - (c / a) ** 2
    return 0.5 * mu * p0 * _shear_compliance(body1, body2) * (ellipk(m) - ellipe(m))


def lubkin_stick_radius(moment, a, mu, p0):
    """Invert :func:`lubkin_moment`: the stick radius for a moment below gross slip, m."""
    M = check_positive("moment", moment, allow_zero=True)
    limit = lubkin_moment(0.0, a, mu, p0)
    if M >= limit:
        raise InputError("moment", f"below the gross-slip moment {limit:g} N m", M)
    if M == 0.0:
        return a
    return brentq(lambda c: lubkin_moment(c, a, mu, p0) - M, 0.0, a, xtol=1e-15 * a, rtol=1e-13)


def uniform_torsion_moment(c, a, mu, p):
    """Moment on a circle of radius a under uniform pressure p with stick radius c, N m.

    M = (4 mu p a / 3) [a^2 arccos(c/a) + c sqrt(a^2 - c^2)] (Johnson sec. 7.3, flat punch
    pressure replaced by a uniform one).
    """
    if not 0.0 <= c <= a:
        raise InputError("c", "a stick radius in [0, a]", c)
    return 4.0 * mu * p * a / 3.0 * (a * a * np.arccos(c / a) + c * np.sqrt(a * a - c * c))


def uniform_torsion_twist(c, a, mu, p, body1: Material, body2: Material | None = None):
    """Twist for uniform pressure and stick radius c: beta = (mu p / (2 G)) arccosh(a/c), rad.

    Per body relative to the interface; with ``body2`` the relative twist (sum of both).
    """
    if not 0.0 < c <= a:
        raise InputError("c", "a stick radius in (0, a]", c)
    return 0.5 * mu * p * _shear_compliance(body1, body2) * np.arccosh(a / c)


def uniform_torsion_stick_radius(moment, a, mu, p):
    """Invert :func:`uniform_torsion_moment` for the stick radius, m."""
    M = check_positive("moment", moment, allow_zero=True)
    limit = gross_slip_moment_uniform(mu, p, a)
    if M >= limit:
        raise InputError("moment", f"below the gross-slip moment {limit:g} N m", M)
    if M == 0.0:
        return a
    return brentq(lambda c: uniform_torsion_moment(c, a, mu, p) - M, 0.0, a, xtol=1e-15 * a)


def gross_slip_moment_hertz(mu, normal_load, a):
    """Gross-slip moment of a circular Hertz contact, 3 pi mu P a / 16, N m."""
    return 3.0 * np.pi * mu * normal_load * a / 16.0


def gross_slip_moment_ellipse(mu, p0, a, b):
    """Gross-slip moment of an elliptical Hertz contact about its centre, N m.

    int mu p |r| dA with x = a rho cos t, y = b rho sin t (a >= b):
    mu p0 a b int_0^1 rho^2 sqrt(1 - rho^2) d rho int_0^2pi sqrt(a^2 cos^2 + b^2 sin^2) dt
    = (pi / 4) mu p0 a^2 b E(1 - b^2/a^2); 3 pi mu P a / 16 for a circle. The centre is the
    minimiser by symmetry and convexity (REFERENCE.md, gross slip under a pure moment).
    """
    a, b = max(a, b), min(a, b)
    return 0.25 * math.pi * mu * p0 * a * a * b * ellipe(1.0 - (b / a) ** 2)


def rectangle_distance_integral(x1, x2, y1, y2):
    """int int sqrt(x^2 + y^2) dx dy over [x1, x2] x [y1, y2] in closed form, m^3.

    Antiderivative G = x y r / 3 + (x^3 / 6) ln(y + r) + (y^3 / 6) ln(x + r), r = |(x, y)|
    (d^2 G / dx dy = r), with ln(u + r) = ln(v^2 / (r - u)) for u < 0 to avoid cancellation.
    """
    def log_sum(u, v, r):
        if v == 0.0:
            return 0.0
        return math.log(u + r) if u >= 0 else math.log(v * v / (r - u))

    def G(xv, yv):
        r = math.hypot(xv, yv)
        return (xv * yv * r / 3.0 + xv**3 / 6.0 * log_sum(yv, xv, r)
                + yv**3 / 6.0 * log_sum(xv, yv, r))

    return G(x2, y2) - G(x1, y2) - G(x2, y1) + G(x1, y1)


def gross_slip_moment_rectangles(boxes, weights):
    """Gross-slip moment of uniformly loaded rectangles under a pure moment, N m.

    min over the centre of rotation c of sum_k w_k int_box_k |r - c| dA (a convex function;
    REFERENCE.md), with the exact rectangle integrals of :func:`rectangle_distance_integral`.

    Parameters
    ----------
    boxes : sequence of (x1, x2, y1, y2)
        The rectangles, m.
    weights : sequence of float
        mu p of each rectangle, Pa.

    Returns
    -------
    (float, ndarray)
        The moment and the centre of rotation (2,), m.
    """
    def moment(c):
        return sum(w * rectangle_distance_integral(b[0] - c[0], b[1] - c[0], b[2] - c[1],
                                                   b[3] - c[1])
                   for w, b in zip(weights, boxes, strict=True))

    start = np.average([[0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3])] for b in boxes], axis=0,
                       weights=weights)
    best = minimize(moment, start, method="Nelder-Mead",
                    options={"xatol": 1e-12 * (boxes[0][1] - boxes[0][0]), "fatol": 0.0,
                             "maxiter": 4000})
    return float(best.fun), best.x


def gross_slip_moment_uniform(mu, p, a):
    """Gross-slip moment of a uniformly loaded circle, (2 pi / 3) mu p a^3, N m."""
    return 2.0 * np.pi / 3.0 * mu * p * a**3
