"""Quantities as people read them: ``1.0464e9`` Pa -> ``"1.046 GPa"``.

Everything inside asperity is SI; this module is the other edge of :mod:`asperity.units`. It
chooses a readable unit for a value (GPa, MPa, um, nm, %, 1/ms), prints a few significant
digits without float noise (``0.019100000000000002`` -> ``0.0191``; zero as ``0``), puts an
imperial value beside the SI one when the case was given in imperial units, and turns the
unit-suffixed keys of ``summary.json`` (``max_pressure_pa``) into words and a unit
(``maximum pressure``, Pa). Conversions go through the shared pint registry.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass

from .units import registry

__all__ = [
    "NOISE",
    "STANDARD_ERROR",
    "SummaryRow",
    "cf_units",
    "coordinate_unit",
    "display_unit",
    "format_axis_value",
    "format_duration",
    "describe_key",
    "format_number",
    "format_quantity",
    "format_summary_value",
    "given_in_imperial",
    "result_unit",
    "summary_rows",
    "unit_label",
    "units_from_cf",
    "with_standard_error",
]

def format_duration(seconds: float) -> str:
    """A wall time in words: ``40 s``, ``12 min``, ``3.1 h``."""
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.2g} min"
    return f"{seconds / 3600:.2g} h"


#: SI unit (pint expression) -> readable units to choose from, largest first: (pint, label[,
#: smallest magnitude shown in it, default 1]).
_SI_CHOICES = {
    "Pa": (("GPa", "GPa"), ("MPa", "MPa"), ("kPa", "kPa"), ("Pa", "Pa")),
    "m": (("m", "m"), ("mm", "mm"), ("um", "µm"), ("nm", "nm")),
    "m^2": (("m^2", "m²", 0.01), ("mm^2", "mm²", 0.01), ("um^2", "µm²")),
    "N": (("MN", "MN"), ("kN", "kN"), ("N", "N"), ("mN", "mN")),
    "N/m": (("MN/m", "MN/m"), ("kN/m", "kN/m"), ("N/m", "N/m")),
    "N*m": (("kN*m", "kN m"), ("N*m", "N m"), ("N*mm", "N mm")),
    "J": (("kJ", "kJ"), ("J", "J"), ("mJ", "mJ"), ("uJ", "µJ")),
    "s": (("s", "s"), ("ms", "ms"), ("us", "µs"), ("ns", "ns")),
    "m/s": (("m/s", "m/s"), ("mm/s", "mm/s")),
    "rad": (("rad", "rad"), ("mrad", "mrad"), ("urad", "µrad")),
    "Pa*s": (("Pa*s", "Pa s"), ("mPa*s", "mPa s")),
    "1/Pa": (("1/GPa", "1/GPa"),),
    "Hz": (("MHz", "MHz"), ("kHz", "kHz"), ("Hz", "Hz")),
    "kg/m^3": (("kg/m^3", "kg/m³"),),
    "kg": (("kg", "kg"), ("g", "g")),
    "1/ms": (("1/ms", "1/ms"),),
    "%": (("percent", "%"),),
}

#: SI unit -> imperial units to choose from, largest first.
_IMPERIAL_CHOICES = {
    "Pa": (("psi", "psi"),),
    # inches from a thou on (a Hertz semi-axis of 0.0089 in, not 8915 µin), microinches below
    # (roughness, films, approaches: 16 µin)
    "m": (("in", "in", 0.001), ("microinch", "µin")),
    "m^2": (("in^2", "in²"),),
    "N": (("lbf", "lbf"),),
    "N/m": (("lbf/in", "lbf/in"),),
    "N*m": (("lbf*in", "in lbf"),),  # as Seireg writes moments
    "J": (("lbf*in", "in lbf"),),
    "m/s": (("ft/s", "ft/s"),),
}

#: Unit suffixes of summary keys, longest first.
_SUFFIXES = (("_deg", "deg"), ("_per_ms", "1/ms"), ("_percent", "%"), ("_m_s", "m/s"),
             ("_pa_s", "Pa*s"), ("_k", "K"), ("_c", "°C"),
             ("_m3_per_m2", "m"), ("_m2", "m^2"), ("_nm", "N*m"), ("_pa", "Pa"),
             ("_rad", "rad"), ("_hz", "Hz"),
             ("_j", "J"), ("_n", "N"), ("_m", "m"), ("_s", "s"))

#: Words of summary keys written out (whole words only).
_WORDS = {"max": "maximum", "min": "minimum", "hertz": "Hertz", "moes": "Moes",
          "nijenbanning": "Nijenbanning", "dowson": "Dowson", "higginson": "Higginson",
          "hamrock": "Hamrock", "chittenden": "Chittenden", "roelands": "Roelands",
          "greenwood": "Greenwood", "tripp": "Tripp", "brewe": "Brewe", "taylor": "Taylor",
          "eyring": "Eyring", "cattaneo": "Cattaneo", "mindlin": "Mindlin",
          "lubkin": "Lubkin", "martin": "Martin", "iso": "ISO",
          "centreline": "centre line", "center": "centre", "rms": "rms", "u1": "u1", "u2": "u2",
          "a": "a", "b": "b", "x": "x", "y": "y", "rsm": "RSm"}

#: Authors of a formula: written side by side in a key, joined by a hyphen in its label
#: (``hamrock_dowson_central_film`` -> "Hamrock-Dowson central film").
_AUTHORS = frozenset({"Hamrock", "Dowson", "Higginson", "Greenwood", "Tripp", "Brewe", "Taylor",
                      "Nijenbanning", "Moes", "Chittenden", "Cattaneo", "Mindlin"})

#: ISO 4287 / 13565 / 25178 parameter names as they appear (lower case) in summary keys.
_ISO_PARAMETER = re.compile(r"[prws](a|q|sk|ku|p|v|t|z|dq|dc|k|pk|vk|dr|al|tr|td)|[rs]?mr[12]?"
                            r"|v(mp|mc|vc|vv)")

#: Labels of summary keys that words alone would not make clear (key without its suffix).
_LABELS = {
    "iso_zone_factor": "ISO 6336-2 zone factor Z_H",
    "iso_elasticity_factor_sqrt_mpa": "ISO 6336-2 elasticity factor Z_E (√MPa)",
    "iso_contact_ratio_factor": "ISO 6336-2 contact ratio factor Z_eps",
    "iso_helix_angle_factor": "ISO 6336-2 helix angle factor Z_beta",
    "iso_nominal_contact_stress": "ISO 6336-2 nominal contact stress sigma_H0",
    "iso_nominal_tangential_force": "ISO 6336-2 nominal tangential force F_t",
    "hertz_a": "Hertz semi-axis a (along x)",
    "hertz_b": "Hertz semi-axis b (along y)",
    "minimum_film_thickness_centreline": "minimum film thickness on the centre line",
    "load_error": "load error (relative)",
    "moment": "twisting moment",
    "u1": "surface speed u1",
    "u2": "surface speed u2",
    "residual": "residual (relative)",
    "steps_converged_fraction": "steps converged",
    "contact_time_fraction": "contact time",
    "mean_hertz_contact_count_rate": "mean contact count rate over the Hertz contact",
    "friction_coefficient": "friction coefficient",
    "slide_roll_ratio": "slide/roll ratio",
    # the gear path's count below gears.path.BOUNDARY_LUBRICATION_LAMBDA, not below the
    # friction rule's boundary_lambda = 1 (a user read "0 boundary points" at lambda 0.49)
    "boundary_lubrication_points": "points in boundary lubrication (lambda < 0.1)",
    # the transient's fixed-point check (ehl.stepper.check_fixed_point): its last step relaxed
    # on to a hundredth of the tolerance, how far the fields moved
    "fixed_point_distance_pressure_fraction": "last step's pressure change, relaxed further",
    "fixed_point_distance_film_fraction": "last step's film change, relaxed further",
    "load_capacity": "gross-slip load / applied load",
    "gross_slip": "gross slip at the applied load",
    "path_gross_slip": "gross slip on the load path",
    "path_gross_slip_step": "load-path step of gross slip",
    "load_median_spot_cells": "cells per spot at the load's median",
    "largest_spot_cells": "cells of the largest spot",
    "kinematic_rt": "kinematic Rt, parabola f^2/(8 r) (Seireg eq. 4.1)",
    "kinematic_ra": "kinematic Ra, parabola f^2/(18 sqrt(3) r)",
    "kinematic_rt_arc": "kinematic Rt of the nose arcs, r - sqrt(r^2 - f^2/4)",
}

#: Relative size below which a value is round-off of zero (see :func:`summary_rows`).
NOISE = 1e-9

_IMPERIAL_WORDS = {"inch", "microinch", "foot", "yard", "mile", "pound", "kip", "thou", "mil",
                   "ounce", "fahrenheit", "poundal", "slug"}


def format_number(value, digits: int = 4) -> str:
    """A number with ``digits`` significant digits and no float noise.

    Integers print whole; zero prints as ``0``; numbers below 1e-3 or from 1e6 on print as
    ``1.235×10⁻⁸``; trailing zeros are dropped (``962.0`` -> ``962``); NaN and infinity print
    as ``n/a``.

    Parameters
    ----------
    value : float or int
    digits : int
        Significant digits kept.

    Returns
    -------
    str
    """
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    value = float(value)
    if not math.isfinite(value):
        return "n/a"
    if value == 0.0:
        return "0"
    rounded = float(f"{value:.{digits}g}")
    exponent = math.floor(math.log10(abs(rounded)))
    if -3 <= exponent < 6:
        text = f"{rounded:.{max(digits - 1 - exponent, 0)}f}"
        return _strip(text) if "." in text else text
    mantissa = _strip(f"{rounded / 10.0**exponent:.{digits - 1}f}")
    power = str(exponent).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"10{power}" if mantissa == "1" else f"{mantissa}×10{power}"


def _strip(text: str) -> str:
    return text.rstrip("0").rstrip(".") if "." in text else text


#: asperity unit spellings -> CF/UDUNITS strings (for netCDF attributes). A rate per
#: millisecond stays "1/ms" (UDUNITS and pint read it as 1000 s-1): "ms-1", written before,
#: reads to a person as metres per second, and pint cannot parse it.
_CF = {"": "1", "m^2": "m2", "N*m": "N m", "m/s": "m s-1", "Pa*s": "Pa s", "1/Pa": "Pa-1",
       "%": "percent", "kg/m^3": "kg m-3", "N/m": "N m-1", "N*s/m": "N s m-1"}
_FROM_CF = {v: k for k, v in _CF.items()} | {"ms-1": "1/ms"}  # files written before


def cf_units(unit: str) -> str:
    """An asperity unit (``"m^2"``, ``"N*m"``, ``"m/s"``, ``"%"``, ``""``) as a CF/UDUNITS
    string (``"m2"``, ``"N m"``, ``"m s-1"``, ``"percent"``, ``"1"``)."""
    return _CF.get(unit, unit)


def units_from_cf(cf: str) -> str:
    """The inverse of :func:`cf_units`: ``"m2"`` -> ``"m^2"``, ``"1"`` -> ``""``."""
    return _FROM_CF.get(cf, cf)


def unit_label(unit: str) -> str:
    """A unit as printed: ``"m^2"`` -> ``"m²"``, ``"N*m"`` -> ``"N m"``, ``"ms-1"`` ->
    ``"1/ms"``, ``"1"`` -> ``""``."""
    unit = units_from_cf(unit)
    if unit in ("", "1"):
        return ""
    return unit.replace("^2", "²").replace("^3", "³").replace("*", " ")


def _convert(value: float, si_unit: str, choices, digits: int = 4) -> tuple[float, str]:
    """``value`` (in ``si_unit``) in the first of ``choices`` where it reads, rounded to
    ``digits`` significant digits, at least the choice's smallest magnitude (0.9999999999 N
    is 1 N, not 1000 mN); zero in the SI unit itself where it is a choice."""
    base = registry().Quantity(value, "percent" if si_unit == "%" else si_unit)
    if value == 0:
        choices = [c for c in choices if c[0] == si_unit] or choices[:1]
    for pint_unit, label, *smallest in choices:
        converted = float(base.to(pint_unit).magnitude)
        if float(f"{abs(converted):.{digits}g}") >= (smallest[0] if smallest else 1.0):
            return converted, label
    return converted, label


def display_unit(magnitude: float, unit: str) -> tuple[float, str]:
    """The readable unit for values up to ``magnitude`` (in SI ``unit``), for an axis or column.

    Parameters
    ----------
    magnitude : float
        The largest absolute value to show, in ``unit``.
    unit : str
        SI unit as in :func:`format_quantity`.

    Returns
    -------
    (float, str)
        The factor from SI to the chosen unit and its label: ``(1e-9, "GPa")`` for 1.4e10 Pa.
    """
    unit = units_from_cf(unit)
    choices = _SI_CHOICES.get(unit)
    if choices is None or not math.isfinite(magnitude) or magnitude == 0:
        return 1.0, unit_label(unit)
    converted, label = _convert(abs(magnitude), unit, choices)
    return converted / abs(magnitude), label


def result_unit(key: str, magnitude: float) -> tuple[float, str]:
    """The one unit of a summary key's values up to ``magnitude`` (SI), for a study's figure
    panel and its table column alike: the factor from SI and its label (:func:`display_unit`;
    ``(1e6, "mm²")`` for areas up to 1.05e-8 m²), a fraction in percent (``(100.0, "%")``).
    A ``_standard_error`` key has its quantity's unit."""
    unit = describe_key(key)[1]
    if unit == "%" and key.removesuffix(STANDARD_ERROR).endswith("fraction"):
        return 100.0, "%"
    return display_unit(magnitude, unit)


def coordinate_unit(values, cf_unit: str) -> tuple[float, str]:
    """The one unit of a study axis's numeric ``values`` in CF unit ``cf_unit``, for its
    figure axis and its table column alike: angles in degrees, as they are written, else
    :func:`display_unit` of the largest finite magnitude."""
    if cf_unit == "rad":
        return math.degrees(1.0), "deg"
    magnitudes = [abs(float(v)) for v in values if math.isfinite(float(v))]
    return display_unit(max(magnitudes, default=0.0), units_from_cf(cf_unit))


def format_quantity(value, unit: str = "", *, imperial: bool = False, digits: int = 4) -> str:
    """A value in SI ``unit`` as a readable string in a well-chosen unit.

    Parameters
    ----------
    value : float or int
        The value in the SI unit ``unit``.
    unit : str
        Its SI unit as written in asperity: ``"Pa"``, ``"m"``, ``"m^2"`` (or ``"m2"``),
        ``"N"``, ``"N*m"`` (or ``"N m"``), ``"1/ms"`` (or ``"ms-1"``), ``"%"``, ``""`` ...
    imperial : bool
        Add the imperial value in parentheses where one exists (``"9.608 kN (2160 lbf)"``).
    digits : int
        Significant digits.

    Returns
    -------
    str
        E.g. ``"1.046 GPa"``, ``"336.4 µm"``, ``"0 N"``, ``"38.54 %"``.

    Examples
    --------
    >>> format_quantity(1.0464e9, "Pa")
    '1.046 GPa'
    >>> format_quantity(9608.1, "N", imperial=True)
    '9.608 kN (2160 lbf)'
    """
    unit = units_from_cf(unit)
    if isinstance(value, bool) or not isinstance(value, int | float) or (
            isinstance(value, float) and not math.isfinite(value)):
        return format_number(value) if isinstance(value, int | float) else str(value)
    choices = _SI_CHOICES.get(unit)
    if choices is None:
        number = format_number(value, digits)
        label = unit_label(unit)
        return f"{number} {label}" if label else number
    converted, label = _convert(value, unit, choices, digits)
    text = f"{format_number(converted, digits)} {label}"
    if imperial and unit in _IMPERIAL_CHOICES:
        converted, label = _convert(value, unit, _IMPERIAL_CHOICES[unit], digits)
        text += f" ({format_number(converted, digits)} {label})"
    return text


def format_axis_value(value, cf_unit: str) -> str:
    """A swept value of a study as shown in its table and figure: quantities in readable
    units, angles in degrees, labels as they are.

    Parameters
    ----------
    value : float or str
        The coordinate value (SI).
    cf_unit : str
        Its ``units`` attribute in ``study.nc`` (CF spelling).

    Returns
    -------
    str
    """
    if not isinstance(value, int | float) or isinstance(value, bool):
        return str(value)
    if cf_unit == "rad":
        return f"{format_number(math.degrees(value))} deg"
    return format_quantity(value, units_from_cf(cf_unit))


#: Ending of a summary key that holds the standard error of the key before it
#: (``contact_time_fraction_standard_error``): shown in the other's unit, beside its value.
STANDARD_ERROR = "_standard_error"


def describe_key(key: str) -> tuple[str, str]:
    """Words and SI unit of a summary key: ``"max_pressure_pa"`` -> ``("maximum pressure",
    "Pa")``; a key ending in ``fraction`` is shown in percent.

    Parameters
    ----------
    key : str
        A key of ``summary.json`` (its unit, if any, is the suffix: ``_pa``, ``_m``, ``_m2``,
        ``_n``, ``_nm`` (N m), ``_m_s``, ``_s``, ``_rad``, ``_deg``, ``_j``, ``_percent``,
        ``_per_ms``, ``_m3_per_m2`` (a volume per area, ISO 25178-2 Vmp ...: a length); ``_k``
        and ``_c`` after ``temperature``: kelvin and degrees Celsius).

    Returns
    -------
    (str, str)
        The label and the unit (``""`` when dimensionless); a key ending in
        ``_standard_error`` (:data:`STANDARD_ERROR`) has the unit of the key before it, and
        its label with ", standard error".
    """
    if key.endswith(STANDARD_ERROR) and len(key) > len(STANDARD_ERROR):
        label, unit = describe_key(key[: -len(STANDARD_ERROR)])
        return f"{label}, standard error", unit
    stem, unit = key, ""
    for suffix, si in _SUFFIXES:
        if key.endswith(suffix) and len(key) > len(suffix):
            stem, unit = key[: -len(suffix)], si
            break
    if unit in ("K", "°C") and not stem.endswith("temperature"):
        stem, unit = key, ""  # _k and _c are temperatures only
    if not unit and stem.endswith("fraction"):
        unit = "%"
    return _LABELS.get(stem) or _words(stem.split("_")), unit


def _words(words: list[str]) -> str:
    """Key words as text: abbreviations written out, ISO roughness parameters as ISO spells
    them (``ra`` -> ``Ra``), a profile's letter after its parameter in parentheses, the authors
    of one formula joined by hyphens (``Hamrock-Dowson``)."""
    out = []
    for i, word in enumerate(words):
        if _ISO_PARAMETER.fullmatch(word):
            out.append(word[0].upper() + word[1:])
        elif i and len(word) == 1 and _ISO_PARAMETER.fullmatch(words[i - 1]):
            out.append(f"({word.upper()})")
        else:
            out.append(_WORDS.get(word, word))
    text = out[:1]
    for before, word in itertools.pairwise(out):
        joined = before.rsplit("-", 1)[-1] in _AUTHORS and word in _AUTHORS
        text.append(("-" if joined else " ") + word)
    return "".join(text)


@dataclass(frozen=True)
class SummaryRow:
    """One line of a key-results table: the key, its label, unit and formatted value."""

    key: str
    label: str
    unit: str
    text: str


def summary_rows(summary: dict, *, imperial: bool = False) -> list[SummaryRow]:
    """The scalars of a summary as labelled, formatted rows (lists and tables are skipped).

    Values of keys ending in ``fraction`` are shown in percent. A key with a standard error
    beside it (the same key ending in ``_standard_error``, :data:`STANDARD_ERROR`) is shown as
    ``value ± standard error`` in one row. A value whose magnitude is at
    most :data:`NOISE` times the largest of the summary's values in the same unit is round-off
    and shown as zero (``3.3e-13 N`` beside a load of 48 kN). A second key that reads the same
    (label and value: ``contact_time_fraction`` beside ``contact_time_percent``) is shown once.

    Parameters
    ----------
    summary : dict
        ``Outcome.summary``.
    imperial : bool
        Put imperial values beside SI.

    Returns
    -------
    list of SummaryRow
    """
    scalars = {k: v for k, v in summary.items()
               if isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)}
    scale: dict[str, float] = {}
    for key, value in scalars.items():
        unit = describe_key(key)[1]
        scale[unit] = max(scale.get(unit, 0.0), abs(value))
    rows = []
    shown = set()
    for key, value in summary.items():
        if isinstance(value, dict | list | tuple) or value is None:
            continue
        base = key.removesuffix(STANDARD_ERROR)
        if base != key and base in summary:
            continue  # shown with its value
        label, unit = describe_key(key)
        text = format_summary_value(key, value, scale=scale.get(unit, 0.0), imperial=imperial)
        if not isinstance(value, bool):
            text = with_standard_error(key, text, scalars.get(key + STANDARD_ERROR),
                                       imperial=imperial)
        if (label, text) not in shown:
            shown.add((label, text))
            rows.append(SummaryRow(key, label, unit_label(unit), text))
    return rows


def with_standard_error(key: str, text: str, error, *, imperial: bool = False) -> str:
    """``text``, the formatted value of summary key ``key``, with its standard error
    ``error`` (in the key's SI unit) beside it: ``"65.5 ± 7.2 %"`` (the unit once when both
    are shown in it), ``"4.3 GPa ± 30 MPa"``; ``text`` alone when ``error`` is None or not
    finite."""
    if error is None or not math.isfinite(error):
        return text
    error_text = format_summary_value(key + STANDARD_ERROR, error, imperial=imperial, digits=2)
    number, _, shown_unit = text.partition(" ")
    if shown_unit and error_text.endswith(" " + shown_unit):
        return f"{number} ± {error_text}"
    return f"{text} ± {error_text}"


def format_summary_value(key: str, value, *, scale: float = 0.0, imperial: bool = False,
                         digits: int = 4) -> str:
    """One value of a summary key as shown in a report (a run's key results, a study's cases).

    A value with a unit whose magnitude is at most :data:`NOISE` times ``scale`` is round-off
    of zero and shown as ``0`` (a force along an unloaded axis); a key ending in ``fraction``
    is shown in percent; text is shown as it is.

    Parameters
    ----------
    key : str
        The summary key (its suffix gives the unit, :func:`describe_key`).
    value : float, int, bool or str
    scale : float
        The largest magnitude it is compared with (of the same unit, or of the same key).
    imperial : bool
        Put the imperial value beside SI.
    digits : int
        Significant digits.

    Returns
    -------
    str
    """
    if isinstance(value, str):
        return value
    unit = describe_key(key)[1]
    if not isinstance(value, bool):
        if unit and math.isfinite(value) and abs(value) <= NOISE * scale:
            value = 0.0  # round-off of a quantity that is zero
        if unit == "%" and key.removesuffix(STANDARD_ERROR).endswith("fraction"):
            value = 100.0 * value
    return format_quantity(value, unit, imperial=imperial, digits=digits)


def given_in_imperial(data) -> bool:
    """Whether a raw case (parsed TOML) gives any quantity in imperial or US units.

    Parameters
    ----------
    data : dict, list or str
        The case as read from its file, before validation.

    Returns
    -------
    bool
        True when some string value parses as a quantity in inches, feet, pounds, psi, ...
    """
    if isinstance(data, dict):
        return any(given_in_imperial(v) for v in data.values())
    if isinstance(data, list):
        return any(given_in_imperial(v) for v in data)
    if not isinstance(data, str) or not re.match(r"\s*[-+]?\.?\d", data):
        return False
    try:
        quantity = registry().Quantity(data.strip())
    except Exception:  # pint raises many kinds on text that is not a quantity
        return False
    if not hasattr(quantity, "unit_items"):  # a bare number
        return False
    words = {w for name, _power in quantity.unit_items() for w in name.lower().split("_")}
    return bool(words & _IMPERIAL_WORDS)
