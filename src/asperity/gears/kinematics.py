"""Rolling and sliding speeds and radii of curvature along the path of contact.

At a point of the line of action at distance ``rho1`` from T1 the flanks have the transverse
radii of curvature ``rho1`` and ``rho2 = T1T2 - rho1`` (ISO 21771, clause 5; a ring gear's
concave flank ``rho2 = -(rho1 + T1T2)``, negative, and it turns the same way as the pinion,
``omega2 = omega1 z1 / z2 < 0`` with ``z2 < 0``, so that its speed ``omega2 rho2`` has the
pinion's sign and the reduced radius ``r1 r2 / (r1 + r2)`` is ``r1 |r2| / (|r2| - r1)``), and
each flank
moves across the line of action at its rolling speed ``omega_i rho_i``. In a helical pair
the flank velocity at the contact is ``omega_i (rho_i`` across the plane of action, ``+ r_bi``
within it``)``: the part within the plane splits into the normal approach ``omega_i r_bi cos
beta_b`` (equal for both flanks) and a part along the contact line, which entrains nothing, so
the entraining speeds across the contact line are the transverse ``omega_i rho_i``; the radii
in the section perpendicular to the contact line are ``rho_i / cos beta_b``.

Sliding: ``u1 - u2 = (omega1 + omega2) s`` with ``s = rho1 - rho1(C)`` the signed distance
from the pitch point, since ``omega1 rho1(C) = omega2 rho2(C)`` there (an internal pair has
``omega1 + omega2 = omega1 (1 - z1/|z2|)`` where an external one of the same pinion and teeth
has ``omega1 (1 + z1/z2)``: it slides less at the same distance from C).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import check_positive
from .geometry import GearPair

__all__ = ["Kinematics", "kinematics"]


@dataclass(frozen=True)
class Kinematics:
    """Radii and speeds at positions ``rho1`` of the path of contact (arrays, SI).

    Attributes
    ----------
    rho1, rho2 : ndarray
        Transverse radii of curvature of pinion and wheel flank, m (``rho2 < 0``: a ring
        gear's concave flank).
    roll_angle : ndarray
        Pinion roll angle rho1 / r_b1, rad.
    distance : ndarray
        Signed distance from the pitch point along the line of action, m (positive towards E).
    radius1, radius2, reduced_radius : ndarray
        Normal-section radii rho_i / cos beta_b (signed as ``rho_i``) and
        R = r1 r2 / (r1 + r2) > 0, m.
    u1, u2 : ndarray
        Rolling speeds of pinion and wheel flank normal to the contact line, m/s.
    sliding_speed : ndarray
        u1 - u2 in the transverse plane (the full sliding speed), m/s.
    """

    rho1: np.ndarray
    rho2: np.ndarray
    roll_angle: np.ndarray
    distance: np.ndarray
    radius1: np.ndarray
    radius2: np.ndarray
    reduced_radius: np.ndarray
    u1: np.ndarray
    u2: np.ndarray
    sliding_speed: np.ndarray

    @property
    def sum_speed(self) -> np.ndarray:
        """u1 + u2 (twice the entrainment speed), m/s."""
        return self.u1 + self.u2

    @property
    def mean_speed(self) -> np.ndarray:
        """Entrainment speed (u1 + u2) / 2, m/s."""
        return 0.5 * (self.u1 + self.u2)

    @property
    def slide_roll_ratio(self) -> np.ndarray:
        """xi = (u1 - u2) / ((u1 + u2)/2), the seed's convention (u1 = u (1 + xi/2))."""
        return (self.u1 - self.u2) / self.mean_speed


def kinematics(pair: GearPair, rho1, pinion_speed: float) -> Kinematics:
    """Radii and speeds at the positions ``rho1`` (m) for a pinion speed in rad/s.

    Parameters
    ----------
    pair : GearPair
    rho1 : array_like
        Positions on the line of action, distance from T1, m.
    pinion_speed : float
        Angular speed omega1 of the pinion, rad/s (the wheel turns at omega1 z1 / z2, the
        other way for an external pair; a ring gear's speed is relative to the carrier of a
        planetary stage when the pinion's is).

    Returns
    -------
    Kinematics
    """
    omega1 = check_positive("pinion_speed", pinion_speed)
    omega2 = omega1 / pair.ratio
    rho1 = np.asarray(rho1, dtype=float)
    rho2 = pair.rho2(rho1)
    cos_bb = math.cos(pair.beta_b)
    r1, r2 = rho1 / cos_bb, rho2 / cos_bb
    return Kinematics(
        rho1=rho1, rho2=rho2, roll_angle=pair.roll_angle(rho1),
        distance=rho1 - pair.points["C"], radius1=r1, radius2=r2,
        reduced_radius=r1 * r2 / (r1 + r2),
        u1=omega1 * rho1, u2=omega2 * rho2,
        sliding_speed=omega1 * rho1 - omega2 * rho2,
    )
