"""Case-file table ``[roughness]``: a generated, built-in or measured rough surface.

The surface is evaluated on the case's grid (cell centres) and its heights are subtracted from
the undeformed gap (peaks close the gap). Generated surfaces are periodic over the grid and
reproducible from ``seed``. A measured file (``kind = "file"``) is referred to its
least-squares mean line or plane (``form_degree``, default 1), its positions are taken from
its own start, and a grid longer than the file is refused (:func:`roughness_on_grid`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, ValidationError, field_validator, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from ..errors import InputError
from ..formatting import format_quantity
from ..surfaces.recipe import SurfaceRecipe, Waviness, build_surface, build_surface_record
from ..surfaces.topography import Profile
from ..surfaces.unit_advice import PLAUSIBLE_HEIGHT
from .fields import CaseModel, Integer, Number, Quantity, existing_file

__all__ = ["DEFAULT_FORM_DEGREE", "REFUSED_SLOPE", "FormKeys", "GridRoughness", "KIND_KEYS",
           "MeasuredFile",
           "RoughnessSpec", "SurfaceKeys", "WavinessSpec", "length_unit", "measured_file",
           "named_in_table", "refuse_implausible_file", "roughness_on_grid", "surface_heights",
           "surface_recipe", "undeformed_gap"]

#: Degree of the least-squares form removed from a measured file by default (its mean line or
#: plane: the offset and tilt of an unlevelled scan), as ``asperity surface stats`` does.
DEFAULT_FORM_DEGREE = 1


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


class FormKeys(CaseModel):
    """The form removed from a measured file before a contact or an EHL run uses it, shared by
    ``[roughness]`` and ``[surface1]``/``[surface2]`` (a surface analysis has its own,
    ``[evaluation] form_degree``)."""

    form_degree: Annotated[Integer, Field(ge=0, le=9)] | None = None
    """Degree of the least-squares form removed from a measured file before use (default 1: its
    mean line or plane, the offset and tilt of the scan; 0: the mean only; 2: also a
    curvature)."""


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
    hurst: Annotated[Number, Field(gt=0, lt=1)] | None = None
    """Hurst exponent H of a self-affine surface (0 < H < 1)."""
    rolloff_wavelength: Quantity("length", gt=0) | None = None
    """Wavelength above which the self-affine spectrum is flat."""
    short_cutoff: Quantity("length", gt=0) | None = None
    """Shortest wavelength of the self-affine spectrum."""
    run_in: Annotated[Number, Field(ge=0, lt=1)] | None = None
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
    seed: Annotated[Integer, Field(ge=0)] | None = None
    """Seed of the random generator (default 0; the same seed gives the same surface)."""

    _path = field_validator("path")(measured_file)

    def longest_lengths(self) -> dict:
        """The longest lengths of a surface generated on its grid, as keywords of
        :func:`asperity.diagnostics.roughness_extent`: a self-affine surface's
        ``rolloff_wavelength``, a Gaussian one's ``correlation_length``; none for the other
        kinds (a profile, a file, a built-in trace have their own length)."""
        if self.kind == "self-affine":
            return {"rolloff_wavelength": self.rolloff_wavelength}
        if self.kind == "gaussian":
            return {"correlation_length": self.correlation_length}
        return {}

    def check_kind(self, need: dict, uses: dict | None = None) -> None:
        """Refuse a missing key that ``need[kind]`` names, reading keys of a measured file for
        another kind, a key that ``uses[kind]`` (when given) does not list, and a self-affine
        surface without exactly one of rms or rms_slope."""
        for key in need.get(self.kind, ()):
            if getattr(self, key) is None:
                raise ValueError(f"expected {key} for kind = \"{self.kind}\"")
        if self.kind != "file":
            for key in (*MeasuredFile.model_fields, *FormKeys.model_fields):
                if getattr(self, key, None) is not None:
                    raise _key_error(key, f"expected no {key} for kind = \"{self.kind}\" (it is "
                                          "for a measured file)", getattr(self, key))
        if uses is not None:  # in declaration order: the first is reported
            for key in (*SurfaceKeys.model_fields, *FormKeys.model_fields):
                value = getattr(self, key, None)
                if key != "kind" and key not in uses[self.kind] and value is not None:
                    raise _key_error(key, f"expected no {key} for kind = \"{self.kind}\" "
                                          "(unused by that kind)", value)
        if self.kind == "self-affine" and (self.rms is None) == (self.rms_slope is None):
            raise ValueError("expected exactly one of rms or rms_slope for a self-affine surface")


def _key_error(key: str, message: str, value) -> ValidationError:
    """A validation error located at ``key`` of the table, so that its line names the key."""
    detail = InitErrorDetails(type=PydanticCustomError("value_error", message), loc=(key,),
                              input=value)
    return ValidationError.from_exception_data("case", [detail])


#: The surface keys each kind of ``[roughness]`` uses (``scale`` and ``waviness`` apply to all).
KIND_KEYS = {
    "gaussian": {"rms", "correlation_length", "correlation_length_y", "acf", "seed"},
    "self-affine": {"hurst", "rms", "rms_slope", "rolloff_wavelength", "short_cutoff", "seed"},
    "ground": {"ra", "correlation_length", "run_in", "seed"},
    "builtin": {"profile"},
    "file": {"path", "spacing", "form_degree", *MeasuredFile.model_fields},
}


class RoughnessSpec(FormKeys, SurfaceKeys):
    """Which surface: ``kind`` and its parameters (unused ones must be left out).

    - ``gaussian``: ``rms``, ``correlation_length`` (or ``correlation_length_y`` too), ``acf``
    - ``self-affine``: ``hurst``, ``rms`` or ``rms_slope``, ``rolloff_wavelength``,
      ``short_cutoff``
    - ``ground``: transverse-ground profile along x with ``ra``, ``correlation_length``,
      ``run_in`` (0 fresh .. <1 strongly run-in)
    - ``builtin``: ``profile`` "A", "B" or "C" (synthetic stand-ins of the mixed-EHL seed)
    - ``file``: ``path`` (text, npy, npz, or an instrument format; relative to the case file, or
      ``builtin:NAME`` for shipped data), ``spacing`` if the file has no coordinates (refused
      for one that has), ``form_degree`` (default 1: the file's least-squares mean line or
      plane is removed), and the reading keys of :class:`MeasuredFile` (``unit``, ``x_unit``,
      ``z_unit``, ``missing``, ``resample``)
    All kinds take ``scale`` (multiplies the heights) and an optional ``waviness``; a key the
    kind does not use is refused (:data:`KIND_KEYS`). The keys are those of
    :class:`SurfaceKeys` and :class:`FormKeys`.
    """

    kind: Literal["gaussian", "self-affine", "ground", "builtin", "file"]
    """Which surface: "gaussian", "self-affine", "ground", "builtin" or "file" (each takes its own
    keys)."""
    scale: Annotated[Number, Field(ge=0, le=1e3)] = 1.0
    """Factor on the heights."""
    waviness: WavinessSpec | None = None
    """A sinusoidal waviness added to the roughness."""

    @model_validator(mode="after")
    def _required(self):
        self.check_kind({"gaussian": ("rms", "correlation_length"), "self-affine": ("hurst",),
                         "ground": ("ra",), "builtin": ("profile",), "file": ("path",)},
                        KIND_KEYS)
        return self


def surface_recipe(spec: CaseModel, **changes) -> SurfaceRecipe:
    """The neutral recipe of a case table's surface (``[roughness]``, ``[surface1]``,
    ``[surface]``): its keys named as :class:`~asperity.surfaces.recipe.SurfaceRecipe` fields,
    the file reading keys of a :class:`MeasuredFile`, its waviness, then ``changes``.

    Keys left out (None) take the recipe's defaults, which are the generators' defaults; a
    measured file's ``form_degree`` defaults to :data:`DEFAULT_FORM_DEGREE`.
    """
    fields = type(spec).model_fields
    values = {name: getattr(spec, name) for name in SurfaceRecipe.__dataclass_fields__
              if name in fields and name != "waviness" and getattr(spec, name) is not None}
    if spec.kind == "file":
        values["file_spacing"] = spec.spacing
        values.setdefault("form_degree", DEFAULT_FORM_DEGREE)
        if isinstance(spec, MeasuredFile):
            values["read_options"] = spec.read_options()
    wavy = getattr(spec, "waviness", None)
    if wavy is not None:
        values["waviness"] = Waviness(wavy.wavelength, wavy.amplitude, wavy.direction)
    return SurfaceRecipe(**{**values, **changes})


@dataclass(frozen=True)
class GridRoughness:
    """A ``[roughness]`` table's heights on a case grid, with what a measured file needs said.

    Attributes
    ----------
    heights : ndarray
        Heights (m) at the cell centres, ``[ix, iy]``.
    file_spacing : tuple of float or None
        A measured file's own sampling interval along x (and y for a topography), m; None for
        the other kinds.
    notes : tuple of str
        What was done to a measured file: the form removed, where its positions start, what
        the reader assumed.
    warnings : tuple of str
        The reader's reasons to doubt the file (heights implausible in metres).
    file_slope : float or None
        A measured file's rms slope (Rdq or Sdq of its levelled heights times ``scale``,
        :func:`~asperity.surfaces.rms_gradient`), to set the grid's against; None for the
        other kinds.
    """

    heights: np.ndarray
    file_spacing: tuple[float, ...] | None = None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    file_slope: float | None = None

    def sampling_cells(self, x, y) -> tuple[int, int]:
        """The file's sampling interval in grid cells along x and y (at least 1; 1 for a
        surface not read from a file, and across y for a profile repeated across it)."""
        if self.file_spacing is None:
            return 1, 1
        cells = []
        for h, coord in zip((*self.file_spacing, None)[:2], (x, y), strict=True):
            d = float(coord[1] - coord[0]) if len(coord) > 1 else math.inf
            cells.append(1 if h is None else max(1, round(h / d)))
        return cells[0], cells[1]


def roughness_on_grid(spec: RoughnessSpec, x, y, label: str = "roughness") -> GridRoughness:
    """The specified surface at the cell centres ``x`` by ``y`` (m).

    A gaussian or self-affine surface is generated over the grid (periodic), a ground or
    built-in profile is sampled at ``x`` and repeated across ``y``. A measured file is read,
    referred to its least-squares form (``form_degree``), and sampled (cubic spline) at the
    cell centres measured from its start: the grid's lower edge lies a whole number of
    sampling intervals before its first point, less than one (a file starting at x = 12.5 mm
    is used from there); cells within half an interval past its last point take that point's
    height. A profile is repeated across ``y``. ``scale`` multiplies the heights with the
    waviness.

    Parameters
    ----------
    spec : RoughnessSpec
    x, y : array_like
        Cell-centre coordinates, m.
    label : str
        The table's place in the case (``"roughness"``, ``"pressure.roughness"``), which errors,
        notes and warnings name.

    Returns
    -------
    GridRoughness

    Raises
    ------
    InputError
        The file cannot be read as the keys say (naming ``label.path`` or the key), or the grid
        is longer than a non-periodic file (naming ``grid.x_extent`` or ``grid.y_extent``).
    """
    x, y = np.asarray(x, float), np.asarray(y, float)
    if spec.kind == "file":
        return _measured_on_grid(spec, x, y, label)
    dx = x[1] - x[0]
    dy = y[1] - y[0] if len(y) > 1 else dx
    length, spacing = len(x) * dx, (dx, dy)
    if spec.kind == "builtin":
        length, spacing = length + dx, min(dx, 0.5e-6)
    ys = y - y[0] + dy / 2
    try:
        surf = build_surface(surface_recipe(spec, scale=1.0), length, spacing,
                             width=len(y) * dy, y=ys)
    except InputError as exc:  # the generator's key, named in the case's table
        raise named_in_table(exc, label, spec) from None
    return GridRoughness(spec.scale * _on_grid(surf, x - x[0] + dx / 2, ys))


def named_in_table(exc: InputError, table: str, spec) -> InputError:
    """An error of a surface generator with its field named in the case's ``table``
    (``correlation_length`` -> ``surface2.correlation_length``) and, where it gave none, the
    value the table holds, in SI (``correlation_length = 40``, meant in um, is 40 m)."""
    field = exc.field if exc.field.startswith(table + ".") else f"{table}.{exc.field}"
    got = exc.got
    if got is None and isinstance(getattr(spec, exc.field, None), float):
        got = format_quantity(getattr(spec, exc.field), "m")
    return InputError(field, exc.expected, got, problem=exc.problem)


def surface_heights(spec: RoughnessSpec, x, y) -> np.ndarray:
    """Heights (m) of the specified surface at the cell centres ``x`` by ``y``: the heights of
    :func:`roughness_on_grid`."""
    return roughness_on_grid(spec, x, y).heights


def undeformed_gap(rx: float, ry: float, x, y, heights=None):
    """Gap (m) of an ellipsoid on a flat at the cell centres: ``x^2/(2 rx) + y^2/(2 ry)``
    (none for ``rx = inf``, a flat punch or a nominally flat interface) minus the roughness
    ``heights`` (m, ``[ix, iy]``; peaks close the gap)."""
    X, Y = np.meshgrid(np.asarray(x, float), np.asarray(y, float), indexing="ij")
    gap = np.zeros_like(X)
    if np.isfinite(rx):
        gap += X**2 / (2 * rx) + Y**2 / (2 * ry)
    if heights is not None:
        gap -= heights
    return gap


def _measured_on_grid(spec: RoughnessSpec, x, y, label: str) -> GridRoughness:
    """A measured file's heights on the grid, with its notes and warnings."""
    dx = x[1] - x[0]
    dy = y[1] - y[0] if len(y) > 1 else dx
    ys = y - y[0] + dy / 2
    try:
        built = build_surface_record(surface_recipe(spec, scale=1.0), 0.0, (dx, dy), y=ys)
    except InputError as exc:
        raise _file_error(exc, spec, label) from None
    name = Path(spec.path).name
    surf, read = built.surface, built.reading.surface
    refuse_implausible_file(built, f"{label}.path ({name})", label)
    xs = _from_start(surf.x, len(x), dx, surf.periodic, "x", f"{label}.path ({name})")
    notes, warnings = built.file_report(f"{label}.path", name)
    warnings = tuple(_in_case_keys(w, label) for w in warnings)
    notes = list(notes)
    origin = _file_origin(read.x)
    if origin != 0.0:
        notes.append(f"{label}.path ({name}): positions taken from the file's start: its x = "
                     f"{_length(origin)} lies at the grid's lower edge")
    if isinstance(surf, Profile):
        z = _on_grid(surf, xs, ys)
        if len(y) > 1:
            notes.append(f"{label}.path ({name}): a profile along x, repeated at every y: "
                         "ridges across the grid (a lay along y, as of a turned or ground "
                         "surface measured across it), not an isotropic surface")
    else:
        z = _on_grid(surf, xs, _from_start(surf.y, len(y), dy, surf.periodic, "y",
                                           f"{label}.path ({name})"))
    spacing = tuple(float(h) for h in np.atleast_1d(read.spacing))
    if not all(math.isclose(h, d, rel_tol=1e-6) for h, d in zip(spacing, (dx, dy),
                                                                strict=False)):
        apart = " by ".join(f"{h * 1e6:.4g} um" for h in spacing)
        cells = " by ".join(f"{d * 1e6:.4g} um" for d in (dx, dy)[:len(spacing)])
        notes.append(f"{label}.path ({name}): heights sampled by cubic spline at the grid's "
                     f"cell centres ({cells} apart) from the file's points ({apart} apart)")
    return GridRoughness(spec.scale * z, spacing, tuple(notes), warnings,
                         spec.scale * built.rms_slope[1])


def _in_case_keys(text: str, table: str) -> str:
    """``text`` (a surface reader's advice) with its options as the case file's keys of
    ``table``: ``give --z-unit nm (case file: z_unit = "nm")`` reads ``give roughness.z_unit
    = "nm"``, ``(--x-unit, --z-unit; case file: x_unit, z_unit)`` reads
    ``(roughness.x_unit, roughness.z_unit)``, ``--spacing "1 um"`` reads
    ``roughness.spacing = "1 um"``. The reader's advice
    names the command line's options, which a case file does not have."""
    def keys(match):
        return ", ".join(f"{table}.{item.strip()}" for item in match.group(1).split(", "))

    text = re.sub(r"--[xz]-unit \S+(?: and --[xz]-unit \S+)? \(case file: ([^)]*)\)", keys,
                  text)
    text = re.sub(r"\(--[^;()]*; case file: ([^)]*)\)", lambda m: f"({keys(m)})", text)
    text = re.sub(r"\(--([xz])-unit\)", rf"({table}.\1_unit)", text)
    return re.sub(r'--spacing ("[^"]*")', rf"{table}.spacing = \1", text)


#: RMS slope (Sdq, Rdq) above which a measured file is refused in a case: ten times the
#: reader's :data:`~asperity.surfaces.unit_advice.PLAUSIBLE_SLOPE`, a mean slope angle of 84
#: degrees, which no measured roughness has (heights in um read as nm: Sdq 13.7; a .npy in um
#: read as metres: 1.4e4); between 1 and 10 the reader's warning stands.
REFUSED_SLOPE = 10.0


def refuse_implausible_file(built, where: str, table: str) -> None:
    """Refuse a measured file whose heights cannot be in the units read: a peak-to-valley
    above :data:`~asperity.surfaces.unit_advice.PLAUSIBLE_HEIGHT` (no roughness is that high)
    or an rms slope above :data:`REFUSED_SLOPE`. A contact or EHL run on it means nothing
    (heights in nm read as metres gave a sphere on a 2182 m map 8738 GPa, exit 0; a transient
    run on heights in um read as nm diverged at step 3 with advice on the time step). The
    reader's advice, when it has one, names the units that make the heights plausible, as the
    case file's keys of ``table``.

    Parameters
    ----------
    built : asperity.surfaces.recipe.SurfaceBuild
        The surface built from the file (with its reading).
    where : str
        The key and file, ``"roughness.path (map.npy)"``.
    table : str
        The case's table of the file (``"roughness"``, ``"surface1"``).
    """
    reading = built.reading
    z = reading.surface.z
    height = float(np.nanmax(z) - np.nanmin(z))
    name, slope = built.rms_slope
    if height > PLAUSIBLE_HEIGHT:
        found = (f"a peak-to-valley of {format_quantity(height, 'm')} in the units read "
                 f"({reading.units}), above {format_quantity(PLAUSIBLE_HEIGHT, 'm')}")
    elif slope > REFUSED_SLOPE:
        found = (f"an rms slope {name} = {slope:.4g} in the units read ({reading.units}), above "
                 f"{REFUSED_SLOPE:g}")
    else:
        return
    advice = reading.unit_advice or next(iter(reading.slope_warnings(name, slope)),
                                         "give the heights' unit (z_unit)")
    advice = _in_case_keys(advice, table)
    raise InputError(where, "", problem=(
        f"heights with {found}: no measured roughness is like that, so the units are wrong; "
        f"{advice}"))


def _length(value: float) -> str:
    """A length in um below a millimetre, else in mm."""
    return f"{value * 1e6:.4g} um" if abs(value) < 1e-3 else f"{value * 1e3:.4g} mm"


def _file_origin(coord: np.ndarray) -> float:
    """Where the grid's lower edge lies on the file's axis: a whole number of sampling
    intervals, so that the file's first point lies within the grid's first interval (a file
    whose positions start at 0, or at half an interval as those of a file without positions
    do, is used from 0)."""
    h = coord[1] - coord[0]
    return float(h * np.floor(coord[0] / h + 1e-6))


def _from_start(coord: np.ndarray, n: int, d: float, periodic: bool, axis: str,
                source: str) -> np.ndarray:
    """Cell centres of ``n`` cells of ``d`` from :func:`_file_origin`. Unless the file is
    periodic, a centre before its first point (by less than one sampling interval) or within
    half an interval past its last point takes that point's height; one further is refused."""
    h = coord[1] - coord[0]
    origin = _file_origin(coord)
    centres = origin + d * (np.arange(n) + 0.5)
    if periodic:
        return centres
    end = coord[-1] + h / 2
    if centres[-1] > end + 1e-9 * h:
        most = (end - origin) / (1.0 - 0.5 / n)
        raise InputError(f"grid.{axis}_extent", f"at most {_length(most)}, so that the grid "
                         f"lies within {source}: the file is {_length(coord.size * h)} long "
                         f"along {axis} ({coord.size} points {_length(h)} apart), the grid "
                         f"{_length(n * d)}; shorten grid.{axis}_extent or use a longer file")
    return np.clip(centres, coord[0], coord[-1])


def _file_error(exc: InputError, spec: RoughnessSpec, label: str) -> InputError:
    """A reading error located at the table's key, or at its path (naming where in the file)."""
    if exc.field in type(spec).model_fields:
        return InputError(f"{label}.{exc.field}", exc.expected, exc.got)
    where = exc.field.removeprefix(str(spec.path)).lstrip(":").strip()
    return InputError(f"{label}.path", exc.expected + (f" (at {where})" if where else ""),
                      exc.got)


def _same(coord: np.ndarray, points: np.ndarray) -> bool:
    """True when ``points`` are the surface's own positions (no interpolation needed)."""
    return coord.shape == points.shape and np.allclose(
        coord, points, rtol=0.0, atol=1e-6 * abs(points[1] - points[0]) if points.size > 1 else 0)


def _on_grid(surf, xs, ys) -> np.ndarray:
    """Heights on the grid, sampled by spline unless the surface has its points there."""
    if isinstance(surf, Profile):
        line = surf.z if _same(surf.x, xs) else surf.sample(xs)
        return np.repeat(np.asarray(line)[:, None], len(ys), axis=1)
    if _same(surf.x, xs) and _same(surf.y, ys):
        return np.array(surf.z)
    return surf.sample(xs, ys)
