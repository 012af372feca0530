"""Case file of a frictional contact: pressure, friction, tangential force and twisting moment.

``analysis = "tangential"`` (Seireg, *Friction and Lubrication in Mechanical Design*, ch. 3).
The normal pressure is given or computed first, then held fixed while the tangential load is
applied (Goodman's approximation, exact for identical materials)::

    analysis = "tangential"
    mu = 0.12
    [body1]
    youngs_modulus = "30e6 psi"
    [body2]
    youngs_modulus = "30e6 psi"
    [pressure]
    source = "uniform"          # or "hertz" (load, rx[, ry | aspect_ratio]) or "normal"
    spacing = "1 in"            # two regions on the x axis, centroids this far apart
    [[pressure.regions]]
    size = ["0.6 in", "0.6 in"]
    pressure = "20000 psi"
    [[pressure.regions]]
    size = ["0.6 in", "0.6 in"]
    pressure = "10000 psi"
    [loading]
    moment = "700 in lbf"       # about loading.center (the centre of the normal load by default)
    force = "0 lbf"             # magnitude, acting along loading.direction
    rotation = "free"           # or "fixed": twist prevented, the fixture's moment reported
    [grid]
    nx = 64                     # cells across the contact's bounding box (default domain)
    ny = 24
    [load_path]                 # optional: the load applied in steps (compliance, slip growth)
    steps = 10
    history = "load"            # "unload" returns to zero, "cycle" adds a fretting cycle
    [reference]                 # optional: published numbers, shown beside asperity's
    source = "Seireg Fig. 3.32"
    gross_slip_moment = "770 in lbf"
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, ValidationInfo, field_validator, model_validator

from ..contact.hertz import radius_ratio
from .bodies import MaterialSpec
from .doubts import CurvedBody
from .fields import CaseHeader, CaseModel, Integer, Number, Quantity
from .roughness import RoughnessSpec

__all__ = [
    "LoadPathSpec",
    "PressureSpec",
    "RegionSpec",
    "TangentialCase",
    "TangentialGridSpec",
    "TangentialLoading",
    "TangentialReference",
]

Length = Quantity("length")
PositiveLength = Quantity("length", gt=0)

#: Largest grid of the LP method (dense influence matrices between contact cells).
LP_MAX_CELLS = 40 * 40


class RegionSpec(CaseModel):
    """``[[pressure.regions]]``: a rectangle (``size``) or circle (``radius``) under a uniform
    ``pressure``, centred at ``center`` (omitted when ``pressure.spacing`` places the regions),
    with its own ``mu`` if given."""

    shape: Literal["rectangle", "circle"] = "rectangle"
    """"rectangle" (size) or "circle" (radius)."""
    center: tuple[Length, Length] | None = None
    """Centre (x, y) of the region (omit when pressure.spacing places the regions)."""
    size: tuple[PositiveLength, PositiveLength] | None = None
    """Side lengths (along x, along y) of a rectangle."""
    radius: PositiveLength | None = None
    """Radius of a circle."""
    pressure: Quantity("pressure", gt=0)
    """Uniform pressure on the region."""
    mu: Quantity("dimensionless", gt=0, le=10) | None = None
    """Friction coefficient of this region (default the case's mu)."""
    name: str = ""
    """Name of the region in reports."""

    @model_validator(mode="after")
    def _dimensions(self):
        if self.shape == "rectangle" and (self.size is None or self.radius is not None):
            raise ValueError("expected size = [width, height] (and no radius) for a rectangle")
        if self.shape == "circle" and (self.radius is None or self.size is not None):
            raise ValueError("expected radius (and no size) for a circle")
        return self

    def half_extents(self) -> tuple[float, float]:
        """Half width and half height of the region's bounding box, m."""
        if self.shape == "circle":
            return self.radius, self.radius
        return 0.5 * self.size[0], 0.5 * self.size[1]

    def area(self) -> float:
        """Area of the region, m^2."""
        if self.shape == "circle":
            return math.pi * self.radius**2
        return self.size[0] * self.size[1]

    def mask(self, X, Y, center) -> np.ndarray:
        """Cells whose centres lie inside the region centred at ``center``."""
        dx, dy = X - center[0], Y - center[1]
        if self.shape == "circle":
            return np.hypot(dx, dy) < self.radius
        hx, hy = self.half_extents()
        return (np.abs(dx) < hx) & (np.abs(dy) < hy)


def _overlap(r1: RegionSpec, c1, r2: RegionSpec, c2) -> bool:
    """Whether two regions share area (touching edges do not count)."""
    d = np.subtract(c2, c1)
    if r1.shape == r2.shape == "circle":
        return math.hypot(*d) < r1.radius + r2.radius
    if r1.shape == r2.shape == "rectangle":
        (h1x, h1y), (h2x, h2y) = r1.half_extents(), r2.half_extents()
        return abs(d[0]) < h1x + h2x and abs(d[1]) < h1y + h2y
    rect, circle, d = (r1, r2, d) if r1.shape == "rectangle" else (r2, r1, -d)
    hx, hy = rect.half_extents()
    gap = math.hypot(max(abs(d[0]) - hx, 0.0), max(abs(d[1]) - hy, 0.0))
    return gap < circle.radius


class PressureSpec(CurvedBody):
    """``[pressure]``: where the normal pressure comes from.

    - ``source = "hertz"``: ``load`` and the relative radii of curvature ``rx`` (``ry``
      defaults to ``rx``: a sphere); or ``rx`` the mean radius sqrt(Rx Ry) with an
      ``aspect_ratio`` a/b of the contact ellipse.
    - ``source = "uniform"``: ``[[pressure.regions]]``; ``spacing`` places two regions on the x
      axis, their centroids ``spacing`` apart and symmetric about the origin.
    - ``source = "normal"``: the same geometry keys as Hertz, solved by ``solve_normal`` first,
      with an optional ``[pressure.roughness]``.
    """

    source: Literal["hertz", "uniform", "normal"]
    """Where the normal pressure comes from: "hertz", "uniform" (regions) or "normal" (a normal
    solve first)."""
    load: Quantity("force", gt=0) | None = None
    """Normal load (hertz, normal)."""
    rx: PositiveLength | None = None
    """Radius of relative curvature along x (or the mean radius sqrt(Rx Ry) with aspect_ratio)."""
    ry: PositiveLength | None = None
    """Radius of relative curvature along y (default rx: a sphere)."""
    aspect_ratio: Annotated[Number, Field(gt=0, le=20)] | None = None
    """Aspect ratio a/b of the contact ellipse (with rx the mean radius)."""
    regions: list[RegionSpec] | None = None
    """Regions of uniform pressure (source = "uniform")."""
    spacing: PositiveLength | None = None
    """Places two regions on the x axis, their centroids this far apart, symmetric about the origin.
    """
    roughness: RoughnessSpec | None = None
    """Rough surface of the normal solve (source = "normal")."""
    normal_tolerance: Quantity("dimensionless", gt=0, lt=1) = 1e-8
    """Convergence tolerance of the normal solve."""

    @model_validator(mode="after")
    def _complete(self):
        geometric = ("load", "rx", "ry", "aspect_ratio")
        if self.source == "uniform":
            if not self.regions:
                raise ValueError('expected [[pressure.regions]] for source = "uniform"')
            for key in (*geometric, "roughness"):
                if getattr(self, key) is not None:
                    raise ValueError(f'expected no {key} for source = "uniform"')
            self._check_regions()
            return self
        for key in ("load", "rx"):
            if getattr(self, key) is None:
                raise ValueError(f'expected {key} for source = "{self.source}"')
        if self.ry is not None and self.aspect_ratio is not None:
            raise ValueError("expected ry or aspect_ratio, not both")
        for key in ("regions", "spacing"):
            if getattr(self, key) is not None:
                raise ValueError(f'expected no {key} for source = "{self.source}"')
        if self.source == "hertz" and self.roughness is not None:
            raise ValueError('expected no roughness for source = "hertz" (use "normal")')
        return self

    def _check_regions(self):
        if self.spacing is not None:
            if len(self.regions) != 2 or any(r.center is not None for r in self.regions):
                raise ValueError("expected two regions without center with spacing")
            hx = [r.half_extents()[0] for r in self.regions]
            if self.spacing < sum(hx):
                raise ValueError(f"expected spacing >= {sum(hx):g} m (the regions overlap)")
        elif any(r.center is None for r in self.regions):
            raise ValueError("expected a center for every region (or pressure.spacing)")
        centers = self.centers()
        for i, ri in enumerate(self.regions):
            for j in range(i):
                if _overlap(ri, centers[i], self.regions[j], centers[j]):
                    raise ValueError(f"expected non-overlapping regions ({j + 1} and {i + 1} "
                                     "overlap)")

    def centers(self) -> list[tuple[float, float]]:
        """Region centres, m."""
        if self.spacing is not None:
            return [(-0.5 * self.spacing, 0.0), (0.5 * self.spacing, 0.0)]
        return [tuple(r.center) for r in self.regions]

    def radii(self) -> tuple[float, float]:
        """Relative radii of curvature (Rx, Ry), m; from ``aspect_ratio`` when given.

        With an aspect ratio k = a/b the radii are Rx = R sqrt(l), Ry = R / sqrt(l) with
        R = ``rx`` and l = Rx/Ry the closed form of :func:`asperity.contact.hertz.radius_ratio`
        (exact elliptic integrals).
        """
        if self.aspect_ratio is None:
            return self.rx, self.ry if self.ry is not None else self.rx
        root_l = math.sqrt(radius_ratio(self.aspect_ratio))
        return self.rx * root_l, self.rx / root_l

    def bounding_box(self) -> tuple[float, float, float, float]:
        """(x0, x1, y0, y1) of the regions, m (uniform pressure only)."""
        boxes = [(c[0] - h[0], c[0] + h[0], c[1] - h[1], c[1] + h[1])
                 for r, c in zip(self.regions, self.centers(), strict=True)
                 for h in [r.half_extents()]]
        b = np.array(boxes)
        return b[:, 0].min(), b[:, 1].max(), b[:, 2].min(), b[:, 3].max()


class TangentialLoading(CaseModel):
    """``[loading]``: tangential ``force`` (N) along ``direction`` (angle from +x,
    counter-clockwise), twisting ``moment`` about ``center`` (counter-clockwise positive), and
    whether body 1 may twist (``rotation = "free"``) or is guided (``"fixed"``).

    ``center`` (two lengths) is the reference point of the moment; omitted, it is the centre
    of the normal load (the pressure centroid), so that a force alone causes no twist wherever
    the grid lies. The point used is in the summary (``moment_center_x_m``, ``_y_m``)."""

    force: Quantity("force") = 0.0
    """Tangential force."""
    direction: Quantity("angle") = 0.0
    """Direction of the force, angle from +x, counter-clockwise."""
    moment: Quantity("moment") = 0.0
    """Twisting moment, counter-clockwise positive."""
    center: tuple[Length, Length] | None = None
    """Reference point (x, y) of the moment (default the centre of the normal load)."""
    rotation: Literal["free", "fixed"] = "free"
    """"free": body 1 may twist; "fixed": it is guided (no rotation)."""

    @model_validator(mode="after")
    def _some_load(self):
        if self.force == 0.0 and (self.moment == 0.0 or self.rotation == "fixed"):
            raise ValueError("expected a non-zero force (or a moment with rotation free)")
        return self

    def vector(self) -> tuple[float, float]:
        """(Fx, Fy), N."""
        return self.force * math.cos(self.direction), self.force * math.sin(self.direction)

    def moment_about_origin(self) -> float:
        """The twisting moment about the origin, the centre of a Hertz contact, N m:
        ``moment + cx Fy - cy Fx`` with (cx, cy) = ``center`` (omitted: the centre of the
        normal load, the origin for a Hertz pressure, and the moment as given). A force whose
        line of action misses the contact's centre twists it: 30 N along x about
        ``center = ["0 mm", "0.1 mm"]`` is 30 N with -3 N mm about the centre."""
        if self.center is None:
            return self.moment
        fx, fy = self.vector()
        return self.moment + self.center[0] * fy - self.center[1] * fx


class TangentialGridSpec(CaseModel):
    """``[grid]``: ``nx`` by ``ny`` cells over the domain.

    The domain defaults to the contact's bounding box: exactly the regions' box for uniform
    pressure (so that rectangles aligned with the axes are whole cells), 1.05 times the Hertz
    ellipse's for ``hertz``, 1.5 times for ``normal``. ``x_extent``, ``y_extent`` (full lengths,
    centred on the origin unless ``x_start``/``y_start``) override it.
    """

    nx: Annotated[Integer, Field(ge=4, le=1024)] = 64
    """Cells along x."""
    ny: Annotated[Integer, Field(ge=4, le=1024)] = 64
    """Cells along y."""
    x_extent: PositiveLength | None = None
    """Full length of the domain along x (default from the contact's bounding box)."""
    y_extent: PositiveLength | None = None
    """Full length of the domain along y (default from the contact's bounding box)."""
    x_start: Length | None = None
    """x of the domain's lower edge (default: centred on the origin)."""
    y_start: Length | None = None
    """y of the domain's lower edge (default: centred on the origin)."""

    def coordinates(self, box) -> tuple[np.ndarray, np.ndarray]:
        """Cell-centre coordinates (m) over the given domain box or the explicit extents."""
        x0, x1, y0, y1 = box
        xe = self.x_extent if self.x_extent is not None else x1 - x0
        ye = self.y_extent if self.y_extent is not None else y1 - y0
        xs = self.x_start if self.x_start is not None else (
            -0.5 * xe if self.x_extent is not None else x0)
        ys = self.y_start if self.y_start is not None else (
            -0.5 * ye if self.y_extent is not None else y0)
        dx, dy = xe / self.nx, ye / self.ny
        return xs + dx * (np.arange(self.nx) + 0.5), ys + dy * (np.arange(self.ny) + 0.5)


class LoadPathSpec(CaseModel):
    """``[load_path]``: apply the load in ``steps`` equal increments from zero; ``history``
    ``"unload"`` returns to zero, ``"cycle"`` continues to the reversed load and back (a
    fretting cycle; its dissipated energy is reported). ``scale`` sets the peak as a multiple of
    the applied load. The path stops at gross slip."""

    steps: Annotated[Integer, Field(ge=1, le=100)] = 10
    """Equal load increments from zero."""
    history: Literal["load", "unload", "cycle"] = "load"
    """"load", "unload" (back to zero) or "cycle" (to the reversed load and back: a fretting cycle).
    """
    scale: Annotated[Number, Field(gt=0, le=100)] = 1.0
    """The path's peak is ``scale`` times the applied load (> 1: continue towards gross slip)."""


class TangentialReference(CaseModel):
    """``[reference]``: published numbers for this case (book values, per body where the book
    reports one body's motion). Rows without ``tolerance`` are shown, not checked."""

    source: str
    """Where the published numbers come from."""
    shift_per_body: Length | None = None
    """Published rigid shift of one body."""
    rotation_per_body: Quantity("angle") | None = None
    """Published rotation of one body."""
    closed_form_rotation_per_body: Quantity("angle") | None = None
    """Rotation of one body by a closed form."""
    gross_slip_moment: Quantity("moment", gt=0) | None = None
    """Published moment at gross slip."""
    gross_slip_force: Quantity("force", gt=0) | None = None
    """Published force at gross slip."""
    tolerance: Annotated[Number, Field(gt=0, lt=1)] | None = None
    """Relative tolerance of the comparison (absent: the rows are shown, not checked)."""
    note: str = ""
    """Remark shown with the reference rows."""


class TangentialCase(CaseHeader):
    """``analysis = "tangential"``: partial slip under a tangential force and a twisting moment."""

    analysis: Literal["tangential"]
    """Selects the frictional (tangential) contact analysis."""
    title: str = "Frictional contact"
    long_running: bool = False
    """Marks a case that runs for many minutes (listed as such by asperity examples)."""
    body1: MaterialSpec
    """First elastic body."""
    body2: MaterialSpec
    """Second elastic body."""
    mu: Quantity("dimensionless", gt=0, le=10)
    """Coefficient of friction."""
    pressure: PressureSpec
    """Where the normal pressure comes from."""
    loading: TangentialLoading
    """Tangential force and twisting moment."""
    grid: TangentialGridSpec = TangentialGridSpec()
    """Computational grid."""
    method: Literal["fft", "lp"] = "fft"
    """Solver: "fft" (FISTA on the FFT operator) or "lp" (the seed's linear programming, small
    grids)."""
    tolerance: Quantity("dimensionless", gt=0, lt=1) = 1e-8
    """Relative convergence tolerance."""
    load_path: LoadPathSpec | None = None
    """Apply the load in increments (slip progression, compliance, fretting cycle)."""
    reference: TangentialReference | None = None
    """Published numbers to compare with."""

    @field_validator("grid")
    @classmethod
    def _regions_inside(cls, grid, info: ValidationInfo):
        pressure = info.data.get("pressure")
        if (pressure is None or pressure.source != "uniform"
                or (grid.x_extent is None and grid.y_extent is None)):
            return grid
        box = pressure.bounding_box()
        x, y = grid.coordinates(box)
        dx, dy = x[1] - x[0], y[1] - y[0]
        slack = 1e-9 * max(dx, dy)
        if (box[0] < x[0] - 0.5 * dx - slack or box[1] > x[-1] + 0.5 * dx + slack
                or box[2] < y[0] - 0.5 * dy - slack or box[3] > y[-1] + 0.5 * dy + slack):
            raise ValueError("expected the pressure regions inside the grid (extend x_extent "
                             "/ y_extent or leave them out)")
        return grid

    @field_validator("method")
    @classmethod
    def _lp_size(cls, method, info: ValidationInfo):
        grid = info.data.get("grid")
        if method == "lp" and grid is not None and grid.nx * grid.ny > LP_MAX_CELLS:
            raise ValueError(f'expected "fft" for more than {LP_MAX_CELLS} cells (nx * ny): '
                             '"lp" builds dense matrices')
        return method

    @field_validator("load_path")
    @classmethod
    def _fft_path(cls, path, info: ValidationInfo):
        if path is not None and info.data.get("method") == "lp":
            raise ValueError('expected no [load_path] with method = "lp" (virgin loading only)')
        return path
