"""Case file of a dry normal contact: an ellipsoid (or sphere) on a flat, smooth or rough."""

from __future__ import annotations

from typing import Literal

from pydantic import model_validator

from ..errors import InputError
from ..formatting import format_quantity
from .bodies import GridSpec, MaterialSpec
from .doubts import CurvedBody
from .fields import CaseHeader, CaseModel, Quantity
from .roughness import RoughnessSpec

__all__ = ["NormalCase", "GeometrySpec", "NormalLoading"]


class GeometrySpec(CurvedBody):
    """Undeformed shape: radii of relative curvature ``rx``, ``ry`` (m); a sphere when equal.

    ``shape = "flat"`` gives a nominally flat contact (use with a rough surface and a periodic
    grid).
    """

    shape: Literal["sphere", "ellipsoid", "flat"] = "sphere"
    """"sphere" (rx only), "ellipsoid" (rx and ry) or "flat" (a nominally flat contact; use with
    roughness and a periodic grid)."""
    rx: Quantity("length", gt=0) | None = None
    """Radius of relative curvature along x, 1/rx = 1/rx1 + 1/rx2."""
    ry: Quantity("length", gt=0) | None = None
    """Radius of relative curvature along y (an ellipsoid)."""

    @model_validator(mode="after")
    def _radii(self):
        """Each shape takes its own radii: a flat none, a sphere ``rx`` alone (an ``ry``
        beside it would silently make the gap an ellipsoid's, ``x^2/(2 rx) + y^2/(2 ry)``,
        under the name of a sphere), an ellipsoid both."""
        if self.shape == "flat":
            given = [k for k in ("rx", "ry") if getattr(self, k) is not None]
            if given:
                raise InputError(f"geometry.{given[0]}", "", problem=(
                    f'expected no {" or ".join(given)} for shape = "flat" (a nominally flat '
                    'contact has no curvature); give shape = "sphere" or "ellipsoid" for a '
                    "curved body, or leave the radii out"))
            return self
        if (self.shape == "sphere" and self.rx is not None and self.ry is not None
                and abs(self.ry - self.rx) > 1e-12 * self.rx):
            raise InputError("geometry.ry", "", problem=(
                f"expected no ry for a sphere (one radius, rx = {format_quantity(self.rx, 'm')})"
                f", got ry = {format_quantity(self.ry, 'm')}; for two radii give shape = "
                '"ellipsoid"'))
        if self.rx is None:
            raise ValueError("expected rx (radius of curvature along x) for a "
                             f"{self.shape}")
        if self.shape == "ellipsoid" and self.ry is None:
            raise ValueError("expected ry (radius of curvature along y) for an ellipsoid")
        return self

    def radii(self) -> tuple[float, float]:
        """(rx, ry) in m; a sphere uses rx for both."""
        if self.shape == "flat":
            return float("inf"), float("inf")
        return self.rx, self.ry if self.ry is not None else self.rx


class NormalLoading(CaseModel):
    """Exactly one of ``load`` (N) or ``approach`` (m)."""

    load: Quantity("force", gt=0) | None = None
    """Normal load (give this or approach)."""
    approach: Quantity("length") | None = None
    """Rigid-body approach of the two bodies (give this or load): without roughness from first
    contact (> 0); with roughness from the roughness's mean plane through the apex, not from
    first contact, so negative where the rough surfaces touch before that plane is reached
    (a rough flat in partial contact). It must exceed the approach of first contact and, on a
    periodic grid, stay below the mean undeformed gap (full contact needs ``load``)."""

    @model_validator(mode="after")
    def _one(self):
        if (self.load is None) == (self.approach is None):
            raise ValueError("expected exactly one of load or approach")
        return self


class NormalCase(CaseHeader):
    """``analysis = "normal"``: frictionless contact of two elastic bodies."""

    analysis: Literal["normal"]
    """Selects the dry normal-contact analysis."""
    title: str = "Dry normal contact"
    body1: MaterialSpec
    """First elastic body."""
    body2: MaterialSpec
    """Second elastic body."""
    geometry: GeometrySpec
    """Undeformed shape of the gap."""
    loading: NormalLoading
    """Load or approach."""
    grid: GridSpec
    """Computational grid (cells and extents)."""
    roughness: RoughnessSpec | None = None
    """Rough surface added to the gap (absent: smooth)."""
    tolerance: Quantity("dimensionless", gt=0, lt=1) = 1e-8
    """Relative convergence tolerance of the conjugate-gradient solver."""
