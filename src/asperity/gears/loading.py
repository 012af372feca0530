"""Load sharing between tooth pairs, load per unit length of contact line and Hertz pressure.

Load sharing factor X (the share of the normal force a tooth pair carries), in the simple form
of ISO/TR 13989-1 (the flash-temperature method of scuffing load capacity) for spur gears:
linear in the position along the path between the values

    X(A) = 1/3, X(B) = 2/3, X(B..D) = 1, X(D) = 2/3, X(E) = 1/3      (no tip relief)

and with tip relief on the wheel (acting at A) or the pinion (at E) the share at that end
falls to 0 (and that at D or B rises to 1), so that the two pairs in contact, a base pitch
apart, always carry X(rho) + X(rho + p_bt) = 1. Helical pairs with an overlap ratio
eps_beta >= 1 share uniformly, X = 1/eps_alpha; for eps_beta < 1 the spur and helical values are
interpolated linearly in eps_beta.

The normal force is F_bn = T1 / (r_b1 cos beta_b) (ISO 6336-1); the normal load per unit
length of contact line is w' = X F_bn cos beta_b / b (for a spur pair X F_bn / b; for a helical
pair with X = 1/eps_alpha the force over the mean total length of contact lines
eps_alpha b / cos beta_b).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..contact.hertz import hertz_line, hertz_point
from ..errors import check_positive
from ..materials import Material
from .geometry import GearPair

__all__ = ["LoadJump", "hertz_along_path", "load_jumps", "load_per_length", "load_sharing",
           "normal_force"]


def load_sharing(pair: GearPair, rho1) -> np.ndarray:
    """Load sharing factor X at positions ``rho1`` (m) on the path A-E (see module notes)."""
    rho = np.asarray(rho1, dtype=float)
    pts = pair.points
    x_a = 0.0 if pair.tip_relief[1] > 0 else 1.0 / 3.0
    x_e = 0.0 if pair.tip_relief[0] > 0 else 1.0 / 3.0
    if pair.contact_ratio >= 2.0:
        spur = np.full(rho.shape, 0.5)
    else:
        rise = (rho - pts["A"]) / (pts["B"] - pts["A"])
        fall = (pts["E"] - rho) / (pts["E"] - pts["D"])
        # single-pair contact on the closed interval B..D: at B and D themselves the pair
        # carries the whole load (the design points of ISO 6336-2), not the two-pair limit
        spur = np.where(rho < pts["B"], x_a + (1.0 - x_e - x_a) * rise,
                        np.where(rho > pts["D"], x_e + (1.0 - x_a - x_e) * fall, 1.0))
    weight = min(pair.overlap_ratio, 1.0)
    return (1.0 - weight) * spur + weight / pair.contact_ratio


class LoadJump(NamedTuple):
    """A jump of the load sharing at B or D where a path position lies on it."""

    #: Index of the position on B or D.
    index: int
    #: Side of the two-pair values: -1 before B, +1 after D.
    side: float
    #: X at the position (single-pair contact, B and D included).
    share: float
    #: X on the two-pair side of the jump.
    outside: float
    #: A position (m from T1) on the two-pair side, 1e-12 base pitches from B or D: its
    #: radii and speeds are those of B or D, its load the two-pair one.
    rho: float


def load_jumps(pair: GearPair, rho1) -> list[LoadJump]:
    """The jumps of :func:`load_sharing` at B and D where a position of ``rho1`` (m) lies on
    them (as :meth:`GearPair.path` places them), B's first; none where X does not jump (a
    helical pair with ``eps_beta >= 1``, a contact ratio of 2 or more)."""
    rho = np.atleast_1d(np.asarray(rho1, dtype=float))
    pts, jumps = pair.points, []
    for key, side in (("B", -1.0), ("D", 1.0)):
        hits = np.flatnonzero(np.abs(rho - pts[key]) <= 1e-12 * pair.t1t2)
        if not hits.size:
            continue
        outside_rho = pts[key] + side * 1e-12 * pair.pbt
        at, outside = load_sharing(pair, np.array([pts[key], outside_rho]))
        if at > 0 and abs(outside - at) > 1e-9 * at:
            jumps.append(LoadJump(int(hits[0]), side, float(at), float(outside),
                                  float(outside_rho)))
    return jumps


def normal_force(pair: GearPair, torque: float) -> float:
    """F_bn = T1 / (r_b1 cos beta_b), N, for a pinion torque T1 (N m)."""
    torque = check_positive("torque", torque)
    return torque / (pair.rb[0] * math.cos(pair.beta_b))


def load_per_length(pair: GearPair, rho1, torque: float) -> np.ndarray:
    """Normal load per unit length of contact line, w' = X F_bn cos beta_b / b, N/m."""
    share = load_sharing(pair, rho1)
    return share * normal_force(pair, torque) * math.cos(pair.beta_b) / pair.face_width


def hertz_along_path(pair: GearPair, rho1, torque: float, reduced_radius, body1: Material,
                     body2: Material):
    """Hertz semi-width (along the motion) and maximum pressure at each position.

    A pair without crowning is a line contact of radius R and load w' (Johnson 1985,
    eqs. 4.43-4.45); a crowned pair is an elliptical contact with ``rx = R``,
    ``ry = 1 / (1/R_c1 + 1/R_c2)`` (crowning radii) carrying X F_bn.

    Returns
    -------
    (a, b, p_max, load) : tuple of ndarray
        ``b`` is NaN for a line contact; ``load`` is w' (N/m) or the point load (N); an
        unloaded position (the end of a relieved tip) has a = p_max = 0.
    """
    rho = np.atleast_1d(np.asarray(rho1, dtype=float))
    radius = np.broadcast_to(np.asarray(reduced_radius, dtype=float), rho.shape)
    a = np.zeros(rho.shape)
    b = np.full(rho.shape, np.nan)
    p = np.zeros(rho.shape)
    if pair.crowned:
        ry = pair.crowning_radius
        load = load_sharing(pair, rho) * normal_force(pair, torque)
        for i in np.flatnonzero(load > 0):
            hz = hertz_point(load[i], radius[i], ry, body1, body2)
            a[i], b[i], p[i] = hz.a, hz.b, hz.p_max
    else:
        load = load_per_length(pair, rho, torque)
        for i in np.flatnonzero(load > 0):
            hz = hertz_line(load[i], radius[i], body1, body2)
            a[i], p[i] = hz.a, hz.p_max
    return a, b, p, load
