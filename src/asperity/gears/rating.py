"""ISO 6336-2 nominal contact stress at the pitch point, beside the Hertz pressure of the path.

Gear engineers rate the flank against the nominal contact stress of ISO 6336-2:2019, method B,

    sigma_H0 = Z_H Z_E Z_eps Z_beta sqrt(F_t / (d1 b) (u + 1) / u)

with the nominal tangential force ``F_t = 2 T1 / d1`` at the reference circle, the gear ratio
``u = z2 / z1`` and the factors

    Z_H    = sqrt(2 cos beta_b cos alpha_wt / (cos^2 alpha_t sin alpha_wt))   zone factor
    Z_E    = sqrt(1 / (pi ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)))                 elasticity
    Z_eps  = sqrt((4 - eps_alpha)/3 (1 - eps_beta) + eps_beta / eps_alpha)   (eps_beta < 1)
           = sqrt(1 / eps_alpha)                                           (eps_beta >= 1)
    Z_beta = 1 / sqrt(cos beta)                  helix angle factor (2019; 2006: sqrt(cos beta))

(the load factors K and the single pair contact factors Z_B, Z_D are not applied: this is the
nominal stress). For ``eps_beta >= 1`` the product without ``Z_beta`` is exactly the Hertz
pressure of the path at the pitch point (the normal-section radius ``rho_C / cos beta_b``
carrying ``F_bn cos beta_b / (eps_alpha b)``), so there ``sigma_H0`` is that pressure times
``Z_beta``, an empirical factor of the standard (5.0 % at beta = 25 deg). For spur pairs
``Z_eps`` is ISO's contact-ratio factor, not the load sharing of the path (docs/gears.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import check_positive
from ..materials import Material
from .geometry import GearPair

__all__ = ["NominalContactStress", "nominal_contact_stress"]


@dataclass(frozen=True)
class NominalContactStress:
    """ISO 6336-2 nominal contact stress sigma_H0 (Pa) and its factors (``elasticity`` Z_E in
    sqrt(Pa)); ``tangential_force`` F_t at the reference circle, N."""

    stress: float
    zone: float
    elasticity: float
    contact_ratio: float
    helix: float
    tangential_force: float


def nominal_contact_stress(pair: GearPair, torque: float, body1: Material,
                           body2: Material) -> NominalContactStress:
    """Nominal contact stress of ISO 6336-2:2019 at the pitch point (module notes).

    Parameters
    ----------
    pair : GearPair
        The gear pair.
    torque : float
        Pinion torque T1, N m.
    body1, body2 : Material
        Pinion and wheel materials (E, nu).

    Returns
    -------
    NominalContactStress
    """
    torque = check_positive("torque", torque)
    z1, z2 = pair.teeth
    d1 = pair.d[0]
    ratio = z2 / z1
    zone = math.sqrt(2.0 * math.cos(pair.beta_b) * math.cos(pair.alpha_wt)
                     / (math.cos(pair.alpha_t) ** 2 * math.sin(pair.alpha_wt)))
    compliance = sum((1.0 - m.poisson_ratio**2) / m.youngs_modulus for m in (body1, body2))
    elasticity = math.sqrt(1.0 / (math.pi * compliance))
    ea, eb = pair.contact_ratio, pair.overlap_ratio
    contact = math.sqrt(1.0 / ea) if eb >= 1.0 else math.sqrt(
        (4.0 - ea) / 3.0 * (1.0 - eb) + eb / ea)
    helix = 1.0 / math.sqrt(math.cos(pair.helix_angle))
    force = 2.0 * torque / d1
    stress = zone * elasticity * contact * helix * math.sqrt(
        force / (d1 * pair.face_width) * (ratio + 1.0) / ratio)
    return NominalContactStress(stress, zone, elasticity, contact, helix, force)
