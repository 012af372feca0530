"""Reading and writing measured or generated profiles and topographies.

Formats (chosen by the file's suffix):

- Text (``.txt``, ``.csv``, ``.dat``, ``.asc``, ``.xyz``): instrument text exports and plain
  columns, read by :mod:`asperity.surfaces.readers` -- the data block found after any metadata
  block, columns and units from column names (``x_um``, ``Height [nm]``) and header keys
  (``Unit: um``, ``Value units``, ``Width``, ``Z scale``), missing-value markers (``NaN``,
  ``BAD``, ``***``). Without a unit, numbers are metres (with a note), with a warning naming
  the units that make the surface plausible when it is not so
  (:mod:`asperity.surfaces.unit_advice`); a surface longer than :data:`PLAUSIBLE_LENGTH` is
  warned about whatever its unit came from, naming where (:attr:`Reading.units`). An x column
  rounded to its printed precision is taken as uniform (with a note); a non-uniform one is
  resampled by cubic spline on request.
- Zygo MetroPro/Mx ASCII and XYZ data files and Wyko/Vision ASCII files (text suffixes,
  recognised by their first line): read by their fixed headers
  (:mod:`asperity.surfaces.readers.zygo`, :mod:`asperity.surfaces.readers.wyko`), in metres.
- ``.npy``: a 1-D array of real heights or a 2-D height matrix (needs a spacing).
- ``.npz``: arrays ``z`` and optionally ``x``, ``y``, ``periodic`` (what :func:`write_surface`
  writes), in metres unless ``x_unit`` / ``z_unit`` are given; without ``x`` a spacing is
  needed.
- Any other suffix (``.x3p``, ``.sdf``, ``.sur``, ``.opd``, ``.plu``, ``.datx``, ...) is read by
  ``SurfaceTopography.read_topography`` when that optional package is installed
  (``pip install 'asperity[instruments]'``), converted to metres.

Missing points are refused, or filled on request (:mod:`asperity.surfaces.missing`). Without
coordinates in the file, positions are the cell centres ``(i + 1/2) * spacing``; a spacing given
coarser than :data:`MAX_SPACING` is refused (a plain number is metres: ``--spacing 1`` is a
metre), and one that makes the surface implausible is named with the spacing that would not
(:func:`~asperity.surfaces.unit_advice.suggested_spacing`). A header spacing with a comma
between digits is a decimal comma in a file whose data use them
(:func:`~.readers.header_sizes.text_layout`). The rules are written out for users in
docs/surfaces.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

from ..errors import InputError, check_positive
from ..formatting import format_quantity
from .missing import fill_missing
from .parameters import residual_heights
from .readers.header_sizes import check_header_spacing, header_factor, length_text, text_layout
from .readers.units import parse_length
from .readers.wyko import is_wyko, read_wyko
from .readers.zygo import ZygoData, is_zygo, read_zygo
from .topography import Profile, Topography
from .unit_advice import (
    FLAT_HEIGHT,
    FLAT_SLOPE,
    PLAUSIBLE_HEIGHT,
    PLAUSIBLE_LENGTH,
    PLAUSIBLE_SLOPE,
    X_UNITS,
    Scales,
    doubts,
    suggested_spacing,
    suggested_units,
    unit_option,
)

__all__ = ["MAX_SPACING", "PLAUSIBLE_HEIGHT", "PLAUSIBLE_LENGTH", "PLAUSIBLE_SLOPE",
           "TEXT_SUFFIXES", "Reading", "read_measured", "read_surface", "unit_name",
           "write_surface"]

TEXT_SUFFIXES = (".txt", ".csv", ".dat", ".asc", ".xyz")
#: Coarsest grid spacing (m) accepted from the user: two spacings per cut-off of ISO 4288's
#: longest, 8 mm (the coarsest sampling a profile can be filtered at).
MAX_SPACING = 4e-3
#: Metres per unit -> the unit's name, and the unit 1000 times smaller.
_UNIT_NAMES = {1.0: "m", 1e-3: "mm", 1e-6: "um", 1e-9: "nm", 1e-10: "angstrom", 0.0254: "in",
               2.54e-5: "mil", 2.54e-8: "uin"}
_SMALLER = {1.0: "mm", 1e-3: "um", 1e-6: "nm"}
_METRES = {name: factor for factor, name in X_UNITS}
_NO_UNIT = ("no length unit makes the numbers plausible: check the file and give its units "
            "(--x-unit, --z-unit; case file: x_unit, z_unit)")


def _named(factor: float, names: dict) -> str | None:
    return next((name for f, name in names.items() if np.isclose(f, factor, rtol=1e-9)), None)


def unit_name(factor: float) -> str:
    """The name of a length unit from its metres per unit (``1e-6`` -> ``"um"``)."""
    return _named(factor, _UNIT_NAMES) or f"{factor:g} m"


def _spacings(spacing, ndim: int, source: str) -> tuple[float, ...]:
    if spacing is None:
        raise InputError("spacing", f"a grid spacing for {source}, which has no coordinates "
                                    "and no spacing or size in a header the reader knows "
                                    "(Spacing, Pixel size, Scale X, Width, ...): give it with "
                                    "its unit, --spacing \"0.5 um\" (case file: spacing = "
                                    "\"0.5 um\")")
    s = np.atleast_1d(np.asarray(spacing, dtype=float))
    if s.size == 1:
        s = np.repeat(s, ndim)
    if s.size != ndim:
        raise InputError("spacing", f"one spacing, or {ndim} (dx, dy)", spacing)
    return tuple(check_positive("spacing", float(v)) for v in s)


def _from_heights(z, spacing, source, origin=None, periodic=False):
    z = np.asarray(z, dtype=float)
    if z.ndim not in (1, 2) or min(z.shape) < 2:
        raise InputError(source, "a 1-D array of heights or a 2-D height matrix", z.shape)
    h = _spacings(spacing, z.ndim, source)
    start = [0.5 * d for d in h] if origin is None else list(np.atleast_1d(origin))
    if len(start) != z.ndim:
        raise InputError("origin", f"{z.ndim} coordinates", origin)
    coords = [s + d * np.arange(n) for s, d, n in zip(start, h, z.shape, strict=True)]
    if z.ndim == 1:
        return Profile(coords[0], z, periodic)
    return Topography(coords[0], coords[1], z, periodic)


@dataclass(frozen=True)
class Reading:
    """A surface read from a file, with what the reader did to it.

    Attributes
    ----------
    surface : Profile or Topography
        Heights and coordinates in metres.
    style : str
        The format or text layout recognised (``"two columns, x and z named 'x_um', 'z_um'"``).
    notes : tuple of str
        What was assumed or changed: units taken from the file, rounded coordinates accepted,
        points filled, data resampled.
    warnings : tuple of str
        Reasons to doubt the result (heights implausible in metres without a unit, a length
        beyond :data:`PLAUSIBLE_LENGTH`).
    filled : int
        Number of missing points filled (or masked).
    missing_points : ndarray of bool or None
        Where they were, on the grid of ``surface``; None when none were missing.
    masked : bool
        True when they are to be left out of the parameters (``missing="mask"``).
    units : str
        The units read and where they came from (``"x in mm from the column name 'X (mm)';
        heights in um from the column name 'Z (um)'"``), for warnings that doubt them.
    height_unit : float or None
        Metres per unit of the file's heights; None when they were read as metres for want of
        a unit.
    unit_advice : str
        When they were, and are implausible so: the units that make the surface plausible and
        how to give them (:func:`~asperity.surfaces.unit_advice.suggested_units`); '' else.
    x_unit : float or None
        Metres per unit of the file's coordinates (or of the spacing); None when they were read
        as metres for want of a unit, or are the format's own.
    spacing_given : bool
        Whether the grid spacing is the one the user gave (a file without positions): the
        warnings that doubt the units then name it too (:func:`_spacing_advice`).
    """

    surface: Profile | Topography
    style: str
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    filled: int = 0
    missing_points: np.ndarray | None = None
    masked: bool = False
    units: str = ""
    height_unit: float | None = None
    unit_advice: str = ""
    x_unit: float | None = None
    spacing_given: bool = False

    @property
    def excluded(self) -> np.ndarray | None:
        """The points to leave out of the parameters: the missing ones when masked."""
        return self.missing_points if self.masked else None

    def slope_warnings(self, name: str, value: float) -> tuple[str, ...]:
        """A warning when the rms slope ``value`` of parameter ``name`` (Rdq, Sdq) is above
        :data:`PLAUSIBLE_SLOPE`: the units read (:attr:`units`) are then likely wrong -- heights
        in nm read as um give slopes 1000 times too steep; or when it is below
        :data:`FLAT_SLOPE` while the heights' rms is below :data:`FLAT_HEIGHT`: heights in um
        read as nm give a surface 1000 times too flat. None when the reader has doubted the
        units already (:attr:`unit_advice`: its warnings name the units to give)."""
        if self.unit_advice:
            return ()
        rms = float(np.sqrt(np.nanmean(residual_heights(np.nan_to_num(self.surface.z),
                                                        self.surface.periodic) ** 2)))
        if value < FLAT_SLOPE and rms < FLAT_HEIGHT:
            return (f"{name}: rms slope {value:.3g} and rms height {rms * 1e9:.3g} nm are "
                    f"below {FLAT_SLOPE:g} and {FLAT_HEIGHT * 1e9:g} nm: flatter than machined "
                    "surfaces are (an optical flat), so the units read are likely wrong "
                    f"({self.units}): check the heights' unit in the file's header and give it "
                    "as the file has it (--z-unit; case file: z_unit; a .npy or .npz holds "
                    "metres: leave z_unit out)",)
        if not value > PLAUSIBLE_SLOPE:
            return ()
        smaller = None if self.height_unit is None else _named(self.height_unit, _SMALLER)
        give = (f"if they are in {smaller}, give --z-unit {smaller} (case file: z_unit = "
                f"\"{smaller}\")" if smaller else "give their unit: --z-unit (case file: z_unit)")
        heights = f"check the heights' unit in the file's header; {give}"
        lateral = "or check the x unit (--x-unit)"
        if self.spacing_given:
            scales = Scales.of(self.surface)
            lateral = ("or " + _spacing_advice(scales, self.surface) if suggested_spacing(scales)
                       else "or check the spacing given (--spacing)")
            if _spacing_doubted(scales):
                heights, lateral = lateral[3:], "or " + heights
        return (f"{name}: rms slope {value:.4g} is above {PLAUSIBLE_SLOPE:g} (a mean slope "
                "angle over 45 deg): steeper than any machined surface and outside the "
                "small-slope assumption of the contact models, so the units read are likely "
                f"wrong ({self.units}): {heights}; {lateral}",)

    def explained(self, error: InputError) -> InputError:
        """``error`` (of evaluating the surface: a profile too short for any cut-off) with the
        doubt on the units first when the surface is implausible in the units read
        (:func:`~asperity.surfaces.unit_advice.doubts`), naming those that make it plausible:
        a bare x (um), z (nm) profile read as a 2000 m trace was refused for its cut-off
        without a word on the units. ``error`` itself when the units are not in doubt."""
        scales = Scales.of(self.surface)
        found = doubts(scales, self.x_unit is None)
        if not found or (self.x_unit is not None and not doubts(scales, False, short=False)):
            # only short, in an x unit the user gave: a short trace, not a unit slip (a 100 um
            # AFM line read in um and nm was told to give mm and um)
            return error
        lateral = any(d.startswith(("length", "spacing")) for d in found)
        advice = _unit_advice(scales, None if self.spacing_given else self.x_unit or 1.0,
                              self.height_unit or 1.0)
        if self.spacing_given:  # an x unit would not change it: the spacing given might
            advice = _or_spacing(advice, scales, self.surface)
        if not advice:  # no units make it plausible: they are not what is wrong
            return error
        return InputError("x" if lateral else "heights", "", problem=(
            f"{_listed(found)} with the units read ({self.units}): implausible, the units are "
            "likely wrong; "
            f"{advice}; that is likely why it is refused: {error}"))


@dataclass
class _Units:
    """Explicit units (metres per file unit) given by the user, None where not given."""

    x: float | None
    z: float | None
    #: The x unit as given alone (``x_unit``), for the note that ignores it.
    x_named: str | None = None

    @classmethod
    def of(cls, unit, x_unit, z_unit):
        both = None if unit is None else parse_length(unit, "unit")
        return cls(both if x_unit is None else parse_length(x_unit, "x_unit"),
                   both if z_unit is None else parse_length(z_unit, "z_unit"), x_unit)

    def ignored_x(self, what: str, notes: list) -> None:
        """Note that the x unit given alone is not used for ``what`` (a file without positions
        whose spacing is given): the spacing given carries its own unit. It was dropped
        without a word (``--x-unit mm`` with ``--spacing`` on a .npy)."""
        if self.x_named is not None:
            notes.append(f"x_unit {self.x_named!r} ignored: {what} has no positions for it to "
                         "apply to, and the spacing given has its own unit (a plain number is "
                         f"metres): give it there, e.g. --spacing \"0.5 {self.x_named}\" (case "
                         f"file: spacing = \"0.5 {self.x_named}\")")


def _missing(z: np.ndarray, missing: str, where: str, notes: list):
    """Heights with missing points filled, their number, and where they were (or None)."""
    lost = ~np.isfinite(z)
    count = int(lost.sum())
    if count == 0:
        return z, 0, None
    share = f"{count} of {z.size} points ({100 * count / z.size:.3g} %)"
    if missing == "refuse":
        raise InputError(where, "no missing points, or missing points filled or masked on "
                                "request (--missing fill|mask; case file: missing = \"fill\")",
                         f"{share} missing")
    z, count = fill_missing(z)
    method = "linear interpolation" if z.ndim == 1 else "harmonic interpolation"
    if missing == "fill":
        notes.append(f"filled {share} missing in the file, by {method} from the "
                     "measured neighbours")
    else:
        notes.append(f"masked {share} missing in the file: left out of the height, "
                     f"material-ratio and volume parameters (and out of the form's fit); "
                     f"filled by {method} only for the filters, slopes, spatial parameters "
                     "and spectra")
    return z, count, lost


def _uniform_x(x: np.ndarray, resolution: float, resample: bool, where: str, notes: list,
               unit: float) -> tuple[np.ndarray, bool]:
    """Uniform positions for ``x`` (file units): the fitted grid, or a request to resample."""
    if not np.all(np.isfinite(x)):
        raise InputError(where, "a position on every line (an x value is missing)")
    steps = np.diff(x)
    if np.any(steps <= 0):
        raise InputError(where, "strictly increasing x positions")
    i = np.arange(x.size)
    slope, intercept = np.polyfit(i, x, 1)
    deviation = float(np.max(np.abs(x - (intercept + slope * i))))
    exact = 1e-9 * slope
    if deviation <= exact:
        return intercept + slope * i, False
    if deviation <= resolution * (1 + 1e-6) + exact:
        notes.append(f"x is printed to {resolution * unit:.3g} m: uniform to that precision "
                     f"(largest deviation {deviation * unit:.3g} m from a straight-line fit), "
                     f"taken as uniform with spacing {slope * unit:.6g} m")
        return intercept + slope * i, False
    if not resample:
        raise InputError(where, "uniformly spaced x (the spacing varies from "
                         f"{steps.min() * unit:.4g} to {steps.max() * unit:.4g} m, more than the "
                         "printed precision); resample on request: --resample (case file: "
                         "resample = true)")
    return x, True


def _mask_on(lost: np.ndarray, x: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """A mask of missing points carried to a resampled grid: the nearest original point's."""
    nearest = np.clip(np.searchsorted(x, grid), 1, x.size - 1)
    nearest -= (grid - x[nearest - 1]) < (x[nearest] - grid)
    return lost[nearest]


def _resampled(x, z, notes) -> tuple[np.ndarray, np.ndarray]:
    grid = np.linspace(x[0], x[-1], x.size)
    notes.append(f"non-uniform x resampled onto {x.size} uniform points by a cubic spline "
                 f"(spacing {grid[1] - grid[0]:.4g} m; the file's spacing ranged "
                 f"{np.diff(x).min():.4g} to {np.diff(x).max():.4g} m)")
    return grid, CubicSpline(x, z)(grid)


def _extent(surface) -> float:
    """The longest side (m) of a profile or topography, ``n * spacing``."""
    if isinstance(surface, Profile):
        return surface.length
    return max(n * h for n, h in zip(surface.shape, surface.spacing, strict=True))


#: What to give when an instrument file's own pixel size makes it implausibly long (the unit of
#: its numbers is the format's).
_CHECK_PIXEL = ("the pixel size written in the file is likely in another unit than its "
                "format's (an exporter that wrote um where metres belong): give the right one, "
                "--spacing \"0.5 um\" (case file: spacing = \"0.5 um\"), which replaces it")


def _pixel_indices(surface) -> bool:
    """Whether a surface's positions are pixel indices: whole numbers a step of 1 apart."""
    coords = [surface.x] if isinstance(surface, Profile) else [surface.x, surface.y]
    return all(np.allclose(c, np.round(c[0]) + np.arange(c.size), rtol=0, atol=1e-9)
               for c in coords)


def _plausible(surface, known: tuple[bool, bool], units: str, warnings: list,
               check: str | None = None, x_factor: float = 1.0,
               spacing_given: bool = False) -> str:
    """Warn when a surface read without a unit (``known``: whether the x and height units
    were given or found) is implausible in metres (:func:`~.unit_advice.doubts`), naming the
    units that make it plausible (:func:`~.unit_advice.suggested_units`), or when it is longer
    than :data:`PLAUSIBLE_LENGTH` whatever its unit came from (``units`` says where;
    ``check`` what to do then, by default the x unit that makes it plausible; ``x_factor``:
    metres per unit of the x read). With ``spacing_given`` (the user's spacing, of a file
    without positions) the spacing is doubted instead of an x unit, which it would not change
    (:func:`_spacing_advice`). Returns the advice ('' when none)."""
    if all(known) and _extent(surface) <= PLAUSIBLE_LENGTH:
        return ""  # the slopes are judged later (:meth:`Reading.slope_warnings`)
    scales = Scales.of(surface)
    found = doubts(scales, not known[0], short=False)
    if not found:
        return ""
    lateral = [d for d in found if d.startswith(("length", "spacing"))]
    vertical = [d for d in found if d not in lateral]
    too_long = scales.length > PLAUSIBLE_LENGTH
    indices = not known[0] and _pixel_indices(surface)  # which no unit makes lengths
    doubted_x = (not known[0] or too_long) and not indices and not spacing_given
    advice = _unit_advice(scales, (x_factor if known[0] else 1.0) if doubted_x else None,
                          None if known[1] else 1.0)
    if spacing_given:
        advice = _or_spacing(advice, scales, surface)
    advice = advice or _NO_UNIT
    if not known[1] and vertical:
        given = (f" and the spacing as given ({_spacing_given_text(surface)})"
                 if spacing_given else "")
        warnings.append(f"heights: {_listed(vertical)} with the heights read as metres (the "
                        f"file gives no unit){given}: implausible; {advice}")
    if indices and lateral:
        warnings.append(f"x: length {scales.length:.4g} m read as metres (the file gives no "
                        "unit): its positions are whole steps of 1 from a whole number (pixel "
                        "indices?), which no unit turns into lengths: write the positions as "
                        "lengths (indices times the pixel size) with their unit in the column "
                        "names, e.g. 'x_um y_um z_um'")
    elif not known[0] and lateral:
        warnings.append(f"x: {_listed(lateral)} with the positions read as metres (the file "
                        f"gives no unit): implausible; {advice}")
    elif known[0] and too_long:
        warnings.append(f"x: length {scales.length:.4g} m exceeds {PLAUSIBLE_LENGTH:g} m, "
                        f"longer than a profilometer traces ({units}): "
                        + (check or f"check that unit and give the right one or the right "
                                    f"spacing; {advice}"))
    return advice if not known[1] else ""


def _spacing_given_text(surface) -> str:
    """``"0.5 nm"`` or ``"0.5 nm x 0.8 nm"``: a surface's grid spacing, as the user gives it."""
    dx, dy = np.broadcast_to(np.atleast_1d(surface.spacing), 2).tolist()
    return length_text(dx) if np.isclose(dx, dy) else f"{length_text(dx)} x {length_text(dy)}"


def _spacing_doubted(scales: Scales) -> bool:
    """Whether a spacing given is itself outside what instruments sample at
    (:data:`~.unit_advice.FINEST_SPACING` to :data:`~.unit_advice.COARSEST_SPACING`): it is then
    named first among the suspects."""
    return any(d.startswith("spacing") for d in doubts(scales, True, short=False))


def _spacing_advice(scales: Scales, surface) -> str:
    """The spacing to give that makes the surface plausible, its heights kept
    (:func:`~.unit_advice.suggested_spacing`), with the sizes it gives; '' when none does."""
    factor = suggested_spacing(scales)
    if factor is None:
        return ""
    after = scales.scaled(factor, 1.0)
    dx, dy = (np.broadcast_to(np.atleast_1d(surface.spacing), 2) * factor).tolist()
    option = f"--spacing \"{length_text(dx)}\"" + (
        f" --spacing-y \"{length_text(dy)}\"" if not np.isclose(dx, dy) else "")
    return (f"the spacing given ({_spacing_given_text(surface)}) may be wrong: the surface is "
            f"plausible with {option} ({factor:g} times it: length "
            f"{format_quantity(after.length, 'm')}, spacing {format_quantity(after.spacing, 'm')}"
            f", rms height {format_quantity(after.rms, 'm')}, rms slope {after.slope:.3g}) "
            f"(case file: spacing = \"{length_text(dx)}\")")


def _or_spacing(advice: str, scales: Scales, surface) -> str:
    """``advice`` on the units and the spacing advice (:func:`_spacing_advice`), the spacing
    first when it is itself implausible (:func:`_spacing_doubted`): a given 0.5 nm pixel for
    0.5 um was advised --z-unit mm alone, which made heights of Sq 0.3 um 0.3 nm."""
    spacing = _spacing_advice(scales, surface)
    if not (advice and spacing):
        return advice or spacing
    return (f"{spacing}; or {advice}" if _spacing_doubted(scales) else
            f"{advice}; or {spacing}")


def _listed(items: list[str]) -> str:
    """``"a, b and c"``."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _unit_advice(scales: Scales, x_factor: float | None, z_factor: float | None) -> str:
    """What to give for the axes in doubt (``x_factor``, ``z_factor``: metres per unit read,
    None for an axis not in doubt): the units that make the surface plausible, with the sizes
    they give it; '' when no units do."""
    pair = suggested_units(scales, x_factor, z_factor)
    if pair is None or pair == (None, None):
        return ""
    x_name, z_name = pair
    after = scales.scaled(1.0 if x_name is None else _METRES[x_name] / x_factor,
                          1.0 if z_name is None else _METRES[z_name] / z_factor)
    said = [f"x in {x_name}" if x_name else "", f"heights in {z_name}" if z_name else ""]
    return (f"they are plausible with {' and '.join(w for w in said if w)} (length "
            f"{format_quantity(after.length, 'm')}, spacing "
            f"{format_quantity(after.spacing, 'm')}, rms height "
            f"{format_quantity(after.rms, 'm')}, rms slope {after.slope:.3g}): give "
            + unit_option(x_name, z_name))


def _unit_text(what: str, given: float | None, found: float | None, source: str | None) -> str:
    """``"heights in um from the column name 'Z (um)'"``: a unit read and where it came from."""
    if given is not None:
        return f"{what} in {unit_name(given)} as given"
    if found is not None:
        return f"{what} in {unit_name(found)} from {source}"
    return f"{what} read as metres, no unit given or in the file"


def _spacing_text(lay, given_spacing, given_x: float | None) -> str:
    """Where the spacing of a file without coordinates came from, for :attr:`Reading.units`."""
    if given_spacing is not None:
        return "spacing as given"
    if lay.spacing_factor is not None:
        return f"spacing in {unit_name(lay.spacing_factor)} from the header's spacing or size"
    return _unit_text("the header's spacing", given_x, lay.x_factor, lay.x_unit_source)


def _replaced_spacing(given, header, warnings: list) -> None:
    """Warn when a spacing given for a file whose header gives its own differs from it: the
    given one is used, and one of the two is wrong (a user's 2 um over a header's 1 um pixel
    size made the real contact area 3.1 % instead of 1.8 % without a word). One value given
    against a header's dx, dy (``Pixel size: 0.5 x 0.8 um``) is compared with both; it ended
    in a traceback."""
    wanted, have = np.broadcast_arrays(np.atleast_1d(np.asarray(given, dtype=float)),
                                       np.atleast_1d(np.asarray(header, dtype=float)))
    if not np.allclose(wanted, have, rtol=1e-3):
        warnings.append("spacing: the spacing given ("
                        + ", ".join(f"{v * 1e6:.4g} um" for v in wanted) + ") replaces the "
                        "header's (" + ", ".join(f"{v * 1e6:.4g} um" for v in have) + "); "
                        "leave the spacing out to use the header's, if it is right")


def _ignored_spacing(given, surface, warnings: list) -> None:
    """Warn when a spacing given for a file with coordinates differs from theirs (it is not
    used: the positions in the file are)."""
    if given is None:
        return
    wanted = np.atleast_1d(np.asarray(given, dtype=float))
    have = np.atleast_1d(surface.spacing)
    if wanted.size > have.size or not np.allclose(wanted, have[:wanted.size], rtol=1e-3):
        warnings.append("spacing: the spacing given ("
                        + ", ".join(f"{v:.4g} m" for v in wanted) + ") is not used: the file "
                        "gives positions " + " x ".join(f"{v:.4g} m" for v in have) + " apart; "
                        "leave the spacing out, or give the x unit (--x-unit; case file: "
                        "x_unit) if the positions are read in the wrong one")


def _read_text(path: Path, spacing, units: _Units, missing: str, resample: bool) -> Reading:
    given_spacing = spacing
    notes: list[str] = []
    warnings: list[str] = []
    lay, sizes = text_layout(path, units.x, spacing, notes, warnings)
    xf = units.x if units.x is not None else lay.x_factor
    zf = units.z if units.z is not None else lay.z_factor
    for name, given, found in (("x", units.x, lay.x_factor), ("z", units.z, lay.z_factor)):
        if given is not None and found is not None and not np.isclose(given, found):
            notes.append(f"{name} unit given ({given:g} m) replaces the file's ({found:g} m)")
    z = lay.z * (1.0 if zf is None else zf)
    z, filled, lost = _missing(z, missing, str(path), notes)
    if lay.x is not None and lay.y is None:
        unit = 1.0 if xf is None else xf
        order = slice(None, None, -1) if lay.x[-1] < lay.x[0] else slice(None)
        z = z[order]
        lost = None if lost is None else lost[order]
        x, uneven = _uniform_x(lay.x[order], lay.resolution, resample, f"{path}: x", notes,
                               unit)
        x = x * unit
        if uneven:
            x, z = _resampled(lay.x[order] * unit, z, notes)
            lost = None if lost is None else _mask_on(lost, lay.x[order] * unit, x)
        surface = Profile(x, z, lay.periodic)
    elif lay.x is not None:
        unit = 1.0 if xf is None else xf
        xs, ys = [_uniform_x(c, 0.0, False, f"{path}: {n}", notes, unit)[0] * unit
                  for c, n in ((lay.x, "x"), (lay.y, "y"))]
        surface = Topography(xs, ys, z, lay.periodic)
    else:
        if lay.spacing is not None:
            header = [v * header_factor(lay, units.x) for v in lay.spacing]
            if spacing is None:
                check_header_spacing(header, z.ndim, sizes, path)
                spacing = header
                xf = xf or lay.spacing_factor
            else:
                _replaced_spacing(spacing, header, warnings)
        surface = _from_heights(z, spacing, f"{path} ({lay.style})", lay.origin, lay.periodic)
    described = "; ".join((
        _unit_text("x", units.x, lay.x_factor, lay.x_unit_source) if lay.x is not None
        else _spacing_text(lay, given_spacing, units.x),
        _unit_text("heights", units.z, lay.z_factor, lay.z_unit_source)))
    known = (xf is not None or lay.x is None and spacing is not None, zf is not None)
    if zf is not None and units.z is None:
        notes.append(f"heights in {unit_name(zf)}, from {lay.z_unit_source}")
    if lay.x is not None and lay.x_factor is not None and units.x is None:
        notes.append(f"x in {unit_name(lay.x_factor)}, from {lay.x_unit_source}")
    if lay.x is not None and xf is None:
        notes.append("x read as metres: the file gives no unit for its positions (give it: "
                     "--x-unit; case file: x_unit)")
    if zf is None:
        notes.append("heights read as metres: the file gives no unit for them (give it: "
                     "--z-unit; case file: z_unit)")
    if lay.x is not None:
        _ignored_spacing(given_spacing, surface, warnings)
    used = lay.x is None and given_spacing is not None
    if used:
        units.ignored_x("this file", notes)
    advice = _plausible(surface, known, described, warnings, x_factor=xf or 1.0,
                        spacing_given=used)
    return Reading(surface, f"text: {lay.style}", tuple(notes), tuple(warnings), filled, lost,
                   missing == "mask", described, zf, advice,
                   xf if xf is not None else 1.0 if known[0] else None, used)


def _read_header_format(path: Path, spacing, units: _Units, missing: str) -> Reading:
    """A Zygo ASCII or XYZ data file (:mod:`asperity.surfaces.readers.zygo`) or a Wyko ASCII
    file (:mod:`asperity.surfaces.readers.wyko`): heights in metres from the header's
    wavelength and factors, the pixel size from its camera resolution or ``Pixel_size``."""
    data = read_zygo(path) if is_zygo(path) else read_wyko(path)
    name = data.style.split(",")[0]
    header_spacing = (data.pixel_size,) * 2 if isinstance(data, ZygoData) else data.spacing
    notes: list[str] = [f"heights and pixel size from the header: {data.style}"]
    warnings: list[str] = []
    if units.x is not None or units.z is not None:
        warnings.append(f"units: the {name}'s own (metres, from its header) are used and the "
                        "unit given is ignored: leave unit, x_unit and z_unit out for this "
                        "file; a wrong pixel size is replaced by giving the spacing "
                        "(--spacing; case file: spacing)")
    heights, filled, lost = _missing(data.heights, missing, str(path), notes)
    from_header = spacing is None
    if from_header:
        if min(header_spacing) <= 0:
            raise InputError("spacing", f"a grid spacing for {path}, whose header gives no "
                             "pixel size: give it with its unit, --spacing \"0.5 um\" (case "
                             "file: spacing = \"0.5 um\")")
        spacing = header_spacing
    elif min(header_spacing) > 0:
        _replaced_spacing(spacing, header_spacing, warnings)
    surface = _from_heights(heights, spacing, str(path))
    described = f"x and heights in metres from the {name}'s header"
    if from_header:
        _plausible(surface, (True, True), described, warnings, _CHECK_PIXEL)
    return Reading(surface, data.style, tuple(notes), tuple(warnings), filled, lost,
                   missing == "mask", described, 1.0, x_unit=1.0)


def _read_npz(path: Path, spacing, units: _Units, missing: str) -> Reading:
    """A .npz of arrays ``z`` and optionally ``x``, ``y``, ``periodic``, in metres as
    :func:`write_surface` writes them, or in the units given (``x_unit``, ``z_unit``, ``unit``;
    they were ignored without a word)."""
    with np.load(path, allow_pickle=False) as f:
        arrays = {k: f[k] for k in f.files}
    if "z" not in arrays:
        raise InputError(str(path), "an array named 'z' (and optionally 'x', 'y')",
                         sorted(arrays))
    notes: list[str] = []
    zf = 1.0 if units.z is None else units.z
    xf = 1.0 if units.x is None else units.x
    z, filled, lost = _missing(np.asarray(arrays["z"], float) * zf, missing, str(path), notes)
    periodic = bool(arrays.get("periodic", False))
    if "x" not in arrays:
        surface = _from_heights(z, spacing, str(path), periodic=periodic)
        units.ignored_x("a .npz without x", notes)
    elif z.ndim == 1:
        surface = Profile(np.asarray(arrays["x"], float) * xf, z, periodic)
    elif "y" not in arrays:
        raise InputError(str(path), "an array 'y' with the 2-D heights 'z'")
    else:
        surface = Topography(np.asarray(arrays["x"], float) * xf,
                             np.asarray(arrays["y"], float) * xf, z, periodic)
    given = [name for name, factor in (("x", units.x), ("heights", units.z))
             if factor is not None]
    described = (f"{' and '.join(given)} in the units given, the rest in m" if given else
                 "x and heights in m, as .npz files hold them")
    warnings: list[str] = []
    advice = _plausible(surface, (units.x is not None, units.z is not None), described,
                        warnings)
    return Reading(surface, "numpy .npz" + ("" if given else " (metres)"), tuple(notes),
                   tuple(warnings), filled, lost, missing == "mask", described, zf, advice,
                   x_unit=xf)


def _third_party_topography(reader, path: Path):
    """``reader.read_topography`` of ``path``; a NetCDF file from an open stream, closed
    after: scipy memory-maps a NetCDF file opened by name and warned 'Cannot close a
    netcdf_file opened with mmap=True' when SurfaceTopography let it go (a stream is read
    without mmap; the topography holds a copy of the heights)."""
    if path.suffix.lower() != ".nc":
        return reader.read_topography(str(path))
    with open(path, "rb") as stream:
        return reader.read_topography(stream)


def _read_instrument(path: Path, spacing, units: _Units, missing: str,
                     resample: bool) -> Reading:
    try:
        import SurfaceTopography
    except ImportError:
        raise InputError(str(path), f"a text, .npy or .npz file; {path.suffix or 'this'} files "
                                    "need the optional SurfaceTopography reader: pip install "
                                    "'asperity[instruments]'") from None
    notes: list[str] = []
    warnings: list[str] = []
    try:
        topo = _third_party_topography(SurfaceTopography, path)
    except Exception as err:  # any failure of the third-party reader
        raise InputError(str(path), "a file SurfaceTopography can read", str(err)) from err
    if getattr(topo, "unit", None) is None:
        if units.x is None and units.z is None:
            raise InputError(str(path), "a unit: the file gives none (--unit um; case file: "
                                        "unit = \"um\")")
        factor = units.x if units.x is not None else units.z
        height_factor = units.z if units.z is not None else factor
    else:
        factor = height_factor = (
            SurfaceTopography.Support.UnitConversion.get_unit_conversion_factor(topo.unit, "m"))
        if units.x is not None or units.z is not None:
            warnings.append(f"units: the file's own unit ({topo.unit}, of its format) is "
                            "used and the unit given is ignored: leave unit, x_unit and z_unit "
                            "out for this file; a wrong pixel size is replaced by giving the "
                            "spacing (--spacing; case file: spacing)")
    heights = np.ma.filled(np.ma.asarray(topo.heights(), dtype=float), np.nan) * height_factor
    heights, filled, lost = _missing(heights, missing, str(path), notes)
    if not topo.is_uniform:
        x = np.asarray(topo.positions(), float) * factor
        if not resample:
            raise InputError(str(path), "uniformly sampled data; resample on request: "
                                        "--resample (case file: resample = true)")
        grid, heights = _resampled(x, heights, notes)
        lost = None if lost is None else _mask_on(lost, x, grid)
        surface = Profile(grid, heights)
        _ignored_spacing(spacing, surface, warnings)
    else:
        h = tuple(np.atleast_1d(topo.pixel_size) * factor)
        if spacing is not None:
            _replaced_spacing(spacing, h, warnings)
            h = tuple(np.broadcast_to(np.atleast_1d(np.asarray(spacing, float)), len(h)))
        surface = _from_heights(heights, h, str(path), periodic=bool(topo.is_periodic))
    described = (f"x and heights in {topo.unit} from the file" if getattr(topo, "unit", None)
                 else f"x in {unit_name(factor)}, heights in {unit_name(height_factor)} as given")
    if spacing is None:
        _plausible(surface, (True, True), described, warnings, _CHECK_PIXEL)
    return Reading(surface, f"{path.suffix} through SurfaceTopography", tuple(notes),
                   tuple(warnings), filled, lost, missing == "mask", described, height_factor,
                   x_unit=factor)


def _check_coarse(spacing) -> None:
    """Refuse a given spacing coarser than :data:`MAX_SPACING`: a plain number is metres, so
    ``--spacing 1`` meant as 1 um reads as 1 m pixels -- for a topography as for a profile."""
    if spacing is None:
        return
    try:
        values = np.atleast_1d(np.asarray(spacing, dtype=float))
    except (TypeError, ValueError):
        raise InputError("spacing", "a grid spacing (m), or two (dx, dy)", spacing) from None
    coarse = values[values > MAX_SPACING]
    if coarse.size:
        raise InputError("spacing", f"a grid spacing of at most {MAX_SPACING * 1e3:g} mm (two "
                         "spacings per 8 mm, ISO 4288's longest cut-off); a plain number is "
                         "metres: give the unit, e.g. --spacing \"1 um\" (case file: spacing = "
                         "\"1 um\")", f"{float(coarse[0]):g} m")


def read_measured(path, spacing=None, *, unit=None, x_unit=None, z_unit=None,
                  missing="refuse", resample=False) -> Reading:
    """Read a profile or topography with the reader's notes (module docstring: formats, rules).

    Parameters
    ----------
    path : str or Path
    spacing : float or (float, float), optional
        Grid spacing (m) for files without coordinates; replaces a spacing from the header or
        an instrument file's pixel size (with a warning when they differ). At most
        :data:`MAX_SPACING`.
    unit, x_unit, z_unit : str, optional
        Length unit of the file's numbers (``"um"``): of both, of the coordinates, of the
        heights. They replace units found in a text file (with a note); an instrument
        file keeps its format's unit (with a warning; ``spacing`` replaces its pixel size).
    missing : {"refuse", "fill", "mask"}
        What to do with missing points: refuse the file (naming how many); fill them by
        linear (profile) or harmonic (topography) interpolation
        (:func:`asperity.surfaces.missing.fill_missing`); or mask them: filled the same way for
        filters and slopes, but left out of the height and material-ratio parameters
        (:attr:`Reading.excluded`, used by :func:`~asperity.surfaces.texture.evaluate_texture`).
    resample : bool
        Resample non-uniform x onto a uniform grid by a cubic spline instead of refusing.

    Returns
    -------
    Reading

    Raises
    ------
    InputError
        Missing file, unknown format, ragged or non-numeric text (naming file and line),
        missing spacing or points, a spacing coarser than :data:`MAX_SPACING`, non-uniform x,
        three unnamed columns of a profile export, a format that needs an extra.
    """
    if missing not in ("refuse", "fill", "mask"):
        raise InputError("missing", '"refuse", "fill" or "mask"', missing)
    _check_coarse(spacing)
    units = _Units.of(unit, x_unit, z_unit)
    path = Path(path)
    if not path.is_file():
        raise InputError("file", "an existing file", str(path))
    suffix = path.suffix.lower()
    if suffix in TEXT_SUFFIXES:
        if is_zygo(path) or is_wyko(path):
            return _read_header_format(path, spacing, units, missing)
        return _read_text(path, spacing, units, missing, resample)
    if suffix == ".npz":
        return _read_npz(path, spacing, units, missing)
    if suffix == ".npy":
        z = _npy_heights(path)
        notes: list[str] = []
        z = z * (1.0 if units.z is None else units.z)
        z, filled, lost = _missing(z, missing, str(path), notes)
        surface = _from_heights(z, spacing, str(path))
        units.ignored_x("a .npy", notes)
        warnings: list[str] = []
        described = "spacing as given; " + _unit_text("heights", units.z, None, None)
        advice = _plausible(surface, (True, units.z is not None), described, warnings,
                            spacing_given=True)
        return Reading(surface, "numpy .npy heights", tuple(notes), tuple(warnings), filled,
                       lost, missing == "mask", described, units.z, advice, 1.0, True)
    return _read_instrument(path, spacing, units, missing, resample)


def _npy_heights(path: Path) -> np.ndarray:
    """The real heights of a .npy file as floats; a complex, boolean, text or object array
    refused (a complex one was taken with numpy's 'Casting complex values to real discards
    the imaginary part' warning)."""
    try:
        z = np.load(path, allow_pickle=False)
    except ValueError as err:
        raise InputError(str(path), "a numeric .npy array", str(err)) from err
    if np.iscomplexobj(z):
        raise InputError(str(path), "real heights (a .npy of floats or integers)",
                         f"a complex array ({z.dtype})")
    if z.dtype.kind not in "iuf":
        raise InputError(str(path), "a numeric .npy array of heights (floats or integers)",
                         f"an array of dtype {z.dtype}")
    return z.astype(float)


def read_surface(path, spacing=None, **options):
    """Read a profile or topography: :func:`read_measured`'s surface alone.

    Parameters
    ----------
    path : str or Path
    spacing : float or (float, float), optional
        Grid spacing (m), needed when the file holds heights without coordinates.
    **options
        ``unit``, ``x_unit``, ``z_unit``, ``missing``, ``resample`` of :func:`read_measured`.

    Returns
    -------
    Profile or Topography
    """
    return read_measured(path, spacing, **options).surface

def write_surface(surface, path) -> Path:
    """Write a Profile or Topography; the suffix picks the format.

    ``.npz`` keeps everything (x, y, z, periodic); text keeps everything too (a profile as
    x, z columns, a topography as the height matrix with ``# spacing`` and ``# origin``
    metadata), with 17 significant digits; ``.npy`` keeps only the heights (reading it back
    needs the spacing). ``.csv`` is comma-separated, other text suffixes space-separated.
    """
    if not isinstance(surface, Profile | Topography):
        raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".npy":
        np.save(path, surface.z)
    elif suffix == ".npz":
        extra = {"y": surface.y} if isinstance(surface, Topography) else {}
        np.savez(path, x=surface.x, z=surface.z, periodic=surface.periodic, **extra)
    elif suffix in TEXT_SUFFIXES:
        sep = "," if suffix == ".csv" else " "
        head = ["unit: m", f"periodic: {str(surface.periodic).lower()}"]
        if isinstance(surface, Profile):
            data = np.column_stack([surface.x, surface.z])
            head = ["asperity profile, columns x z (m)", *head]
        else:
            data = surface.z
            dx, dy = surface.spacing
            head = ["asperity topography, heights z[ix, iy] (m), rows along x",
                    f"spacing: {dx!r} {dy!r}",
                    f"origin: {float(surface.x[0])!r} {float(surface.y[0])!r}",
                    *head]
        np.savetxt(path, data, fmt="%.17g", delimiter=sep, header="\n".join(head),
                   comments="# ")
    else:
        raise InputError("path", f"a file name ending in one of {', '.join(TEXT_SUFFIXES)}, "
                                 ".npy, .npz", str(path))
    return path
