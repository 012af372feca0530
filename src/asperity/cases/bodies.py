"""Case-file tables shared by every analysis: materials and the numerical grid."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, field_validator, model_validator

from ..formatting import format_quantity
from ..materials import Material
from ..units import is_bare, to_si
from .doubts import BareNumbers
from .fields import CaseModel, Integer, Number, Quantity

__all__ = ["MaterialSpec", "GridSpec", "STIFFEST_SOLID", "PSI_AMBIGUOUS",
           "SOFTEST_BARE_MODULUS"]

#: Young's modulus of diamond, the stiffest solid (about 1.05-1.2 TPa), Pa: no body is stiffer,
#: so a larger modulus is a unit mistake ("30e6 GPa" for "30e6 psi").
STIFFEST_SOLID = 1.2e12

#: Bare moduli (TOML numbers, read in Pa) in this range are a soft solid's in Pa (0.1-200 MPa:
#: rubbers, soft polymers) or an engineering solid's in psi (1e5 psi a soft polymer, 1e7-3e7 psi
#: the metals, 1.7e8 psi diamond): the number alone does not say which.
PSI_AMBIGUOUS = (1e5, 2e8)

#: Bare moduli below the ambiguous range, under 0.1 MPa (a bare ``206`` is 206 Pa), are
#: refused: no solid of a contact case is that soft without the user saying so with the
#: unit (a hydrogel's "20 kPa"), and the number is most often GPa or MPa meant.
SOFTEST_BARE_MODULUS = PSI_AMBIGUOUS[0]


class MaterialSpec(BareNumbers):
    """An elastic body: ``youngs_modulus`` (e.g. ``"30e6 psi"``) and ``poisson_ratio``.

    ``hardness`` (optional, e.g. ``"6 GPa"``): contact pressures above it make the run warn
    that the elastic answer is not physical there.
    """

    youngs_modulus: Quantity("pressure", gt=0)
    """Young's modulus E of the body."""
    poisson_ratio: Annotated[Number, Field(gt=-1.0, le=0.5)] = 0.3
    """Poisson's ratio nu of the body."""
    name: str = "material"
    """Name of the material, shown in reports (not implied by the moduli: a glass disc left
    unnamed is not called steel)."""
    hardness: Quantity("pressure", gt=0) | None = None
    """Indentation hardness; contact pressures above it make the run warn that the elastic answer is
    not physical there, and in a dry contact a Hertz peak above 0.57 of it that the body yields
    beneath the surface (p0 = 1.6 Y with H = 2.8 Y)."""

    @field_validator("youngs_modulus", mode="before")
    @classmethod
    def _bare_too_soft(cls, value):
        """Refuse a bare modulus (read in Pa) below :data:`SOFTEST_BARE_MODULUS`:
        ``youngs_modulus = 206`` meant as GPa was 206 Pa, a contact a thousand times wider
        (a gear case ran to exit 3 with a lambda of -986, a tangential one to exit 0); the
        line gives the readings to write."""
        if not is_bare(value) or not 0 < float(value) < SOFTEST_BARE_MODULUS:
            return value
        number = f"{float(value):.6g}".replace("e+0", "e").replace("e+", "e")
        readings = [f'"{number} {unit}"' for unit, scale in (("GPa", 1e9), ("MPa", 1e6))
                    if SOFTEST_BARE_MODULUS <= float(value) * scale <= STIFFEST_SOLID]
        raise ValueError(
            f"expected a Young's modulus with its unit: the bare number {number} is read in "
            f"Pa, {format_quantity(float(value), 'Pa')}, softer than "
            f"{format_quantity(SOFTEST_BARE_MODULUS, 'Pa')} (the softest rubbers); write "
            f"{' or '.join(readings) or 'the unit'} (steel is \"206 GPa\"), or \"{number} Pa\" "
            "for a gel that soft")

    @field_validator("youngs_modulus")
    @classmethod
    def _solid(cls, value):
        """No solid is stiffer than diamond (:data:`STIFFEST_SOLID`)."""
        if value > STIFFEST_SOLID:
            raise ValueError(
                f"expected at most {format_quantity(STIFFEST_SOLID, 'Pa')} (diamond's, the "
                f"stiffest solid; this is {format_quantity(value, 'Pa')}): check the unit "
                '(steel is "210 GPa" or "30e6 psi")')
        return value

    def unit_doubts(self, key: str) -> list[str]:
        """A warning when the modulus was a bare number in :data:`PSI_AMBIGUOUS`.

        A bare number is read in Pa, so ``youngs_modulus = 30e6`` is 30 MPa, a rubber's
        modulus, and the steel meant as 30e6 psi (206.8 GPa) becomes 6900 times softer: the
        contact grows and its pressure falls, each by about the cube root of that. The line
        says both readings and what to write for each.

        Parameters
        ----------
        key : str
            The body's table, ``"body1"`` or ``"body2"``.

        Returns
        -------
        list of str
            One line, or none.
        """
        raw = self.bare("youngs_modulus")
        if raw is None or not PSI_AMBIGUOUS[0] <= raw <= PSI_AMBIGUOUS[1]:
            return []
        as_psi = to_si(f"{raw!r} psi", "pressure", "")
        number = f"{raw:.6g}".replace("e+0", "e").replace("e+", "e")
        # 210000 is steel's modulus in MPa, as a data sheet gives it, as often as anything
        in_mpa = 1e8 <= raw * 1e6 <= STIFFEST_SOLID
        mpa = (f", in MPa {format_quantity(raw * 1e6, 'Pa')}" if in_mpa else "")
        mpa_advice = f'"{number} MPa" for a modulus given in MPa, ' if in_mpa else ""
        return [f"{key}.youngs_modulus: the bare number {number} is read in Pa, "
                f"{format_quantity(raw, 'Pa')} (a rubber's or a soft polymer's modulus); read "
                f"in psi it would be {format_quantity(as_psi, 'Pa')}{mpa}; write the unit: "
                f'"{number} psi" for a modulus given in psi, {mpa_advice}'
                f'"{format_quantity(raw, "Pa")}" to confirm the soft body']

    @model_validator(mode="before")
    @classmethod
    def _homogeneous(cls, data):
        """A coating or layer key is refused as what it is, not as a misspelling: every
        solver's influence coefficients are those of a homogeneous half-space (Love,
        Cerruti), so no key could give a layered body."""
        layered = [k for k in data if isinstance(k, str) and any(
            w in k.lower() for w in ("coat", "layer", "substrate"))] if isinstance(data, dict) \
            else []
        if layered:
            raise ValueError(
                f"expected a homogeneous body, got {', '.join(layered)}: asperity's bodies "
                "are homogeneous elastic half-spaces, with no coating or layer; give the "
                "coating's modulus when it is several contact radii thick, the substrate's "
                "when it is a small fraction of one; between them a run with each bounds "
                "the contact's size and pressure")
        return data

    def material(self) -> Material:
        """The :class:`asperity.Material` this table describes."""
        return Material(self.youngs_modulus, self.poisson_ratio, self.name, self.hardness)


class GridSpec(CaseModel):
    """Cells of the computational grid: counts and extents (m) along x and y.

    ``x_extent`` and ``y_extent`` are the full lengths of the domain, centred on the origin
    unless ``x_start``/``y_start`` are given.
    """

    nx: Annotated[Integer, Field(ge=4, le=8192)] = 128
    """Cells along x."""
    ny: Annotated[Integer, Field(ge=1, le=8192)] = 128
    """Cells along y."""
    x_extent: Quantity("length", gt=0)
    """Full length of the domain along x."""
    y_extent: Quantity("length", gt=0)
    """Full length of the domain along y."""
    x_start: Quantity("length") | None = None
    """x of the domain's lower edge (default: the domain is centred on the origin)."""
    y_start: Quantity("length") | None = None
    """y of the domain's lower edge (default: the domain is centred on the origin)."""
    periodic: bool = False
    """Periodic domain (a nominally flat rough interface) instead of an isolated contact."""

    def coordinates(self):
        """Cell-centre coordinates ``(x, y)`` as numpy arrays, m."""
        import numpy as np

        dx, dy = self.x_extent / self.nx, self.y_extent / self.ny
        x0 = -0.5 * self.x_extent if self.x_start is None else self.x_start
        y0 = -0.5 * self.y_extent if self.y_start is None else self.y_start
        return x0 + dx * (np.arange(self.nx) + 0.5), y0 + dy * (np.arange(self.ny) + 0.5)
