"""Case-file table ``[roughness]``: a generated, built-in or measured rough surface.

The surface is evaluated on the case's grid (cell centres) and its heights are subtracted from
the undeformed gap (peaks close the gap). Generated surfaces are periodic over the grid and
reproducible from ``seed``.
"""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, field_validator, model_validator

from ..surfaces.recipe import SurfaceRecipe, Waviness, build_surface
from .fields import CaseModel, Quantity, existing_file

__all__ = ["MeasuredFile", "RoughnessSpec", "SurfaceKeys", "WavinessSpec", "length_unit",
           "measured_file", "surface_heights", "surface_recipe", "undeformed_gap"]


def measured_file(cls, value, info):
    """Field validator of a measured surface's ``path``: ``builtin:NAME`` names a data file
    shipped with asperity (:func:`asperity.examples.builtin_data`); any other path must exist,
    a relative one relative to the case file's folder (:func:`~.fields.existing_file`)."""
    from ..errors import InputError
    from ..examples import BUILTIN_PREFIX, builtin_data

    if isinstance(value, str) and value.startswith(BUILTIN_PREFIX):
        try:
            return str(builtin_data(value))
        except InputError as err:
            raise ValueError(err.expected) from None
    return existing_file(cls, value, info)


def length_unit(cls, value):
    """Field validator of a unit name (``"um"``, ``"nm"``, ``"angstrom"``, ``"in"``)."""
    from ..errors import InputError
    from ..surfaces.readers.units import parse_length

    if value is not None:
        try:
            parse_length(value, "unit")
        except InputError as err:
            raise ValueError(f"expected {err.expected}") from None
    return value


class MeasuredFile(CaseModel):
    """The keys of a measured surface file, shared by ``[roughness]`` and ``[surface]``.

    ``unit`` (of both coordinates and heights), ``x_unit``, ``z_unit``: length units of the
    file's numbers when it does not say (they replace what it says); ``missing``: ``"refuse"``
    (default), ``"fill"`` missing points, or ``"mask"`` them (filled for the filters, left out
    of the surface analysis' height parameters; a contact sees them filled); ``resample``:
    resample non-uniform x by cubic spline.
    """

    unit: str | None = None
    """Length unit of the file's coordinates and heights when the file does not say (e.g. "um";
    replaces what it says)."""
    x_unit: str | None = None
    """Length unit of the file's coordinates only."""
    z_unit: str | None = None
    """Length unit of the file's heights only."""
    missing: Literal["refuse", "fill", "mask"] | None = None
    """Missing points: "refuse" (default, an error), "fill" them, or "mask" them (filled, but
    left out of a surface analysis' height parameters)."""
    resample: bool | None = None
    """Resample non-uniformly spaced x by cubic spline."""

    _units = field_validator("unit", "x_unit", "z_unit")(length_unit)

    def read_options(self) -> dict:
        """Keyword arguments of :func:`asperity.surfaces.io.read_measured`."""
        return {"unit": self.unit, "x_unit": self.x_unit, "z_unit": self.z_unit,
                "missing": self.missing or "refuse", "resample": bool(self.resample)}


class WavinessSpec(CaseModel):
    """A sinusoid of ``wavelength`` and ``amplitude`` varying along ``direction``."""

    wavelength: Quantity("length", gt=0)
    """Wavelength of the sinusoidal waviness."""
    amplitude: Quantity("length", ge=0)
    """Amplitude (half the peak-to-valley) of the waviness."""
    direction: Literal["x", "y"] = "y"
    """Direction along which the waviness varies."""


class SurfaceKeys(MeasuredFile):
    """The keys of a surface shared by every table that names one: ``[roughness]``,
    ``[surface1]``/``[surface2]`` (transient EHL, gears) and ``[surface]`` (surface analysis).

    Each key is declared once here (type, unit, bounds, meaning); the tables add the kinds and
    keys of their own (``scale``, ``waviness``, ``lowpass``, features, the turning models) and
    which keys each kind needs. Keys left out take the defaults of
    :class:`~asperity.surfaces.recipe.SurfaceRecipe` (:func:`surface_recipe`).
    """

    kind: str
    """Which surface (each table names the kinds it takes)."""
    rms: Quantity("length", ge=1e-12, le=1e-2) | None = None
    """Root-mean-square height Sq (gaussian; self-affine instead of rms_slope)."""
    rms_slope: Quantity("dimensionless", gt=0, le=100) | None = None
    """Root-mean-square slope (self-affine, instead of rms)."""
    ra: Quantity("length", ge=1e-12, le=1e-2) | None = None
    """Arithmetic mean height Ra of a ground profile."""
    correlation_length: Quantity("length", gt=0) | None = None
    """Lag where the autocorrelation falls to 0.2 (gaussian; ground, default 15 um)."""
    correlation_length_y: Quantity("length", gt=0) | None = None
    """Correlation length along y of a gaussian topography (default: correlation_length)."""
    acf: Literal["gaussian", "exponential"] | None = None
    """Autocorrelation function of a gaussian surface ("gaussian", the default, or
    "exponential")."""
    hurst: Annotated[float, Field(gt=0, lt=1)] | None = None
    """Hurst exponent H of a self-affine surface (0 < H < 1)."""
    rolloff_wavelength: Quantity("length", gt=0) | None = None
    """Wavelength above which the self-affine spectrum is flat."""
    short_cutoff: Quantity("length", gt=0) | None = None
    """Shortest wavelength of the self-affine spectrum."""
    run_in: Annotated[float, Field(ge=0, lt=1)] | None = None
    """Degree of running-in of a ground profile, 0 fresh (the default) to < 1 strongly run-in
    (peaks truncated)."""
    profile: Literal["A", "B", "C"] | None = None
    """Built-in profile "A", "B" or "C" (synthetic stand-ins of the mixed-EHL seed's Fig. 1)."""
    path: str | None = None
    """Measured surface file (text, npy, npz or an instrument format), relative to the case file,
    or builtin:NAME for data shipped with asperity."""
    spacing: Quantity("length", gt=0) | None = None
    """Sampling interval of a file without coordinates (surface analysis: also of a generated
    surface)."""
    seed: Annotated[int, Field(ge=0)] | None = None
    """Seed of the random generator (default 0; the same seed gives the same surface)."""

    _path = field_validator("path")(measured_file)

    def check_kind(self, need: dict) -> None:
        """Refuse a missing key that ``need[kind]`` names, reading keys of a measured file for
        another kind, and a self-affine surface without exactly one of rms or rms_slope."""
        for key in need.get(self.kind, ()):
            if getattr(self, key) is None:
                raise ValueError(f"expected {key} for kind = \"{self.kind}\"")
        if self.kind != "file":
            for key in MeasuredFile.model_fields:
                if getattr(self, key) is not None:
                    raise ValueError(f"expected no {key} for kind = \"{self.kind}\" (it is "
                                     "for a measured file)")
        if self.kind == "self-affine" and (self.rms is None) == (self.rms_slope is None):
            raise ValueError("expected exactly one of rms or rms_slope for a self-affine surface")


class RoughnessSpec(SurfaceKeys):
    """Which surface: ``kind`` and its parameters (unused ones must be left out).

    - ``gaussian``: ``rms``, ``correlation_length`` (or ``correlation_length_y`` too), ``acf``
    - ``self-affine``: ``hurst``, ``rms`` or ``rms_slope``, ``rolloff_wavelength``,
      ``short_cutoff``
    - ``ground``: transverse-ground profile along x with ``ra``, ``correlation_length``,
      ``run_in`` (0 fresh .. <1 strongly run-in)
    - ``builtin``: ``profile`` "A", "B" or "C" (synthetic stand-ins of the mixed-EHL seed)
    - ``file``: ``path`` (text, npy, npz, or an instrument format; relative to the case file, or
      ``builtin:NAME`` for shipped data), ``spacing`` if the file has no coordinates, and the
      reading keys of :class:`MeasuredFile` (``unit``, ``x_unit``, ``z_unit``, ``missing``,
      ``resample``)
    All kinds take ``scale`` (multiplies the heights), ``seed`` and an optional ``waviness``.
    The keys are those of :class:`SurfaceKeys`.
    """

    kind: Literal["gaussian", "self-affine", "ground", "builtin", "file"]
    """Which surface: "gaussian", "self-affine", "ground", "builtin" or "file" (each takes its own
    keys)."""
    scale: Annotated[float, Field(ge=0, le=1e3)] = 1.0
    """Factor on the heights."""
    waviness: WavinessSpec | None = None
    """A sinusoidal waviness added to the roughness."""

    @model_validator(mode="after")
    def _required(self):
        self.check_kind({"gaussian": ("rms", "correlation_length"), "self-affine": ("hurst",),
                         "ground": ("ra",), "builtin": ("profile",), "file": ("path",)})
        return self


def surface_recipe(spec: CaseModel, **changes) -> SurfaceRecipe:
    """The neutral recipe of a case table's surface (``[roughness]``, ``[surface1]``,
    ``[surface]``): its keys named as :class:`~asperity.surfaces.recipe.SurfaceRecipe` fields,
    the file reading keys of a :class:`MeasuredFile`, its waviness, then ``changes``.

    Keys left out (None) take the recipe's defaults, which are the generators' defaults.
    """
    fields = type(spec).model_fields
    values = {name: getattr(spec, name) for name in SurfaceRecipe.__dataclass_fields__
              if name in fields and name != "waviness" and getattr(spec, name) is not None}
    if spec.kind == "file":
        values["file_spacing"] = spec.spacing
        if isinstance(spec, MeasuredFile):
            values["read_options"] = spec.read_options()
    wavy = getattr(spec, "waviness", None)
    if wavy is not None:
        values["waviness"] = Waviness(wavy.wavelength, wavy.amplitude, wavy.direction)
    return SurfaceRecipe(**{**values, **changes})


def surface_heights(spec: RoughnessSpec, x, y) -> np.ndarray:
    """Heights (m) of the specified surface at the cell centres ``x`` by ``y``.

    A gaussian or self-affine surface is generated over the grid (periodic), a ground, built-in
    or measured profile is sampled at ``x`` and repeated across ``y``; ``scale`` multiplies the
    heights with the waviness.
    """
    from .. import surfaces as s

    x, y = np.asarray(x, float), np.asarray(y, float)
    dx = x[1] - x[0]
    dy = y[1] - y[0] if len(y) > 1 else dx
    length, spacing = len(x) * dx, (dx, dy)
    if spec.kind == "builtin":
        length, spacing = length + dx, min(dx, 0.5e-6)
    ys = y - y[0] + dy / 2
    surf = build_surface(surface_recipe(spec, scale=1.0), length, spacing, width=len(y) * dy,
                         y=ys)
    z = _on_grid(surf, x - x[0] + dx / 2, ys, s)
    return spec.scale * z


def undeformed_gap(rx: float, ry: float, x, y, roughness: RoughnessSpec | None = None):
    """Gap (m) of an ellipsoid on a flat at the cell centres: ``x^2/(2 rx) + y^2/(2 ry)``
    (none for ``rx = inf``, a flat punch or a nominally flat interface) minus the heights of
    ``roughness`` (peaks close the gap)."""
    X, Y = np.meshgrid(np.asarray(x, float), np.asarray(y, float), indexing="ij")
    gap = np.zeros_like(X)
    if np.isfinite(rx):
        gap += X**2 / (2 * rx) + Y**2 / (2 * ry)
    if roughness is not None:
        gap -= surface_heights(roughness, x, y)
    return gap


def _on_grid(surf, xs, ys, s) -> np.ndarray:
    """Heights on the grid, sampled by spline unless the surface already has its shape."""
    if isinstance(surf, s.Profile):
        line = surf.z if surf.z.shape == xs.shape else surf.sample(xs)
        return np.repeat(line[:, None], len(ys), axis=1)
    if surf.z.shape == (len(xs), len(ys)):
        return np.array(surf.z)
    return surf.sample(xs, ys)
