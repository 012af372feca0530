"""Linear elastic bodies and the combinations of their constants used by contact theory.

References
----------
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, ch. 3 and 7.
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import InputError

__all__ = [
    "Material",
    "contact_modulus",
    "tangential_compliance",
    "coupling_compliance",
    "STEEL",
]


@dataclass(frozen=True)
class Material:
    """An isotropic linear elastic half-space.

    Parameters
    ----------
    youngs_modulus : float
        Young's modulus E in Pa; ``float("inf")`` makes a rigid body.
    poisson_ratio : float
        Poisson's ratio nu, -1 < nu <= 0.5.
    name : str, optional
        A label for reports.
    hardness : float, optional
        Indentation hardness in Pa. Not used by the elastic solvers; where a contact pressure
        exceeds it, the result carries a warning (the elastic answer is not physical there).
    """

    youngs_modulus: float
    poisson_ratio: float
    name: str = "material"
    hardness: float | None = None

    def __post_init__(self):
        e = float(self.youngs_modulus)
        if not (e > 0):
            raise InputError(f"{self.name}.youngs_modulus", "a number > 0 in Pa",
                             self.youngs_modulus)
        nu = float(self.poisson_ratio)
        if not (-1.0 < nu <= 0.5):
            raise InputError(f"{self.name}.poisson_ratio", "a number in (-1, 0.5]",
                             self.poisson_ratio)
        object.__setattr__(self, "youngs_modulus", e)
        object.__setattr__(self, "poisson_ratio", nu)
        if self.hardness is not None:
            h = float(self.hardness)
            if not (0 < h < float("inf")):
                raise InputError(f"{self.name}.hardness", "a finite number > 0 in Pa",
                                 self.hardness)
            object.__setattr__(self, "hardness", h)

    @property
    def shear_modulus(self) -> float:
        """G = E / (2 (1 + nu)) in Pa."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))

    @property
    def rigid(self) -> bool:
        """True for an infinitely stiff body."""
        return self.youngs_modulus == float("inf")


STEEL = Material(youngs_modulus=206e9, poisson_ratio=0.3, name="steel")


def contact_modulus(body1: Material, body2: Material) -> float:
    """Composite (plane-strain) modulus E* of two bodies in Pa.

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson 1985, eq. 3.38). EHL papers use E' = 2 E*.
    """
    c = (1 - body1.poisson_ratio**2) / body1.youngs_modulus
    c += (1 - body2.poisson_ratio**2) / body2.youngs_modulus
    if c <= 0:
        raise InputError("body1, body2", "at least one deformable body")
    return 1.0 / c


def tangential_compliance(body1: Material, body2: Material) -> float:
    """Composite tangential compliance (2 - nu1)/G1 + (2 - nu2)/G2 in 1/Pa (Mindlin 1949)."""
    return sum(
        0.0 if b.rigid else (2.0 - b.poisson_ratio) / b.shear_modulus for b in (body1, body2)
    )


def coupling_compliance(body1: Material, body2: Material) -> float:
    """Normal-tangential coupling (1 - 2 nu1)/G1 - (1 - 2 nu2)/G2 in 1/Pa.

    It vanishes for identical materials (and for nu = 0.5 against a rigid body); the normal and
    tangential contact problems then decouple exactly (Johnson 1985, sec. 7.1). Dundurs'
    constant is beta = E* coupling_compliance / 4 (for nu1 = nu2 = 0.5 or equal bodies, 0).
    """
    return sum(
        0.0 if b.rigid else sign * (1.0 - 2.0 * b.poisson_ratio) / b.shear_modulus
        for sign, b in ((1.0, body1), (-1.0, body2))
    )
