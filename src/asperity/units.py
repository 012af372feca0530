"""Quantities with units at the edge of asperity: ``"2160 lbf"`` -> 9608.1 (N).

Everything inside asperity is SI. Case files may give a quantity as a plain number (taken as SI)
or as a string with a unit that pint understands; :func:`to_si` converts once, checking that the
dimension is the one the field needs. Three of pint's readings are not what people write: it
drops commas and multiplies numbers written side by side ("12,5 mm" is 125 mm), so a quantity
must be one number with a decimal point; and its turns are 2 pi radians each ("1500 rpm" is
157 Hz, "0.127 mm/rev" 0.0202 mm), so outside an angle a turn, revolution or cycle counts one;
and outside an angle a mil is the engineer's thousandth of an inch, not pint's angular mil.
"""

from __future__ import annotations

import math
import re
from functools import lru_cache

from .errors import InputError

__all__ = ["DIMENSIONS", "is_bare", "registry", "to_si", "unit_of"]

#: What a case-file field measures -> its SI unit (a pint unit string; "" for pure numbers).
DIMENSIONS = {
    "length": "m",
    "force": "N",
    "force_per_length": "N/m",
    "pressure": "Pa",
    "moment": "N*m",
    "speed": "m/s",
    "viscosity": "Pa*s",
    "inverse_pressure": "1/Pa",
    "density": "kg/m^3",
    "frequency": "Hz",
    "time": "s",
    "mass": "kg",
    "angle": "rad",
    "dimensionless": "",
    "stiffness": "N/m",
    "damping": "N*s/m",
}


@lru_cache(maxsize=1)
def registry():
    """The shared pint UnitRegistry."""
    import pint

    return pint.UnitRegistry()


def to_si(value, dimension: str, field: str) -> float:
    """Convert a case-file quantity to an SI float.

    Parameters
    ----------
    value : float, int or str
        A number (already SI) or a string "number unit", e.g. ``"30e6 psi"``, ``"0.6 in"``,
        ``"11.1 1/GPa"``, ``"25 m/s"``.
    dimension : str
        A key of :data:`DIMENSIONS` saying what the field measures.
    field : str
        The field's name, used in the error message.

    Returns
    -------
    float
        The value in SI units.

    Raises
    ------
    InputError
        For a non-number, an unknown unit, a unit of the wrong dimension, or NaN/infinity.
    """
    si_unit = DIMENSIONS[dimension]
    if isinstance(value, bool):
        raise InputError(field, f"a number or a quantity in {si_unit or 'no unit'}", value)
    if isinstance(value, int | float):
        result = float(value)
    elif isinstance(value, str):
        result = _parse(value, si_unit, field)
    else:
        raise InputError(field, f"a number or a string like '1.0 {si_unit}'", value)
    if not math.isfinite(result):
        raise InputError(field, "a finite number", value)
    if dimension == "angle" and abs(result) > 2.0 * math.pi and is_bare(value):
        # a bare 90 meant in degrees would be 90 rad = 116.6 deg, silently
        raise InputError(field, "an angle with its unit ('90 deg') or at most 2 pi radians as a "
                         "bare number", value)
    return result


def is_bare(value) -> bool:
    """Whether a case-file value is a number without a unit (``90``, ``"90"``; not a bool)."""
    if isinstance(value, bool):
        return False
    if isinstance(value, int | float):
        return True
    try:
        float(value)
    except (TypeError, ValueError):
        return False
    return True


def unit_of(value) -> str | None:
    """The unit a case-file quantity is written in (``"9.525 mm"``: ``"mm"``), or None for a
    bare number or a value that does not start with a number."""
    if not isinstance(value, str):
        return None
    match = _LEADING_NUMBER.match(value)
    unit = value[match.end():].strip() if match else ""
    return unit or None


def _kinematic_hint(q, written: str) -> str:
    dynamic = q.to("m**2/s").magnitude * 850.0 * 1e3  # mPa s at a mineral oil's 850 kg/m^3
    return ("this is a kinematic viscosity: the dynamic viscosity is it times the density, "
            f"{written} x 850 kg/m^3 (a mineral oil's) = {dynamic:.4g} mPa s")


def _mass_hint(q, written: str) -> str:
    unit = unit_of(written) or ""
    return (f"a mass: its weight is '{q.magnitude:g} {unit}f' or {written} x 9.81 m/s^2 = "
            f"{q.to('kg').magnitude * 9.80665:.4g} N")


def _rotation_hint(q, written: str) -> str:
    return ("a rotational speed: the surface speed is it times the radius, "
            f"{written} on a 50 mm radius = {q.to('1/s').magnitude * 2 * math.pi * 0.05:.4g} "
            "m/s")


#: (SI unit wanted, dimension given) -> what the given quantity probably is, and what to write
#: (from the quantity as read and as written).
_MISTAKEN = {
    ("Pa*s", "[length] ** 2 / [time]"): _kinematic_hint,
    ("N", "[mass]"): _mass_hint,
    ("m/s", "1 / [time]"): _rotation_hint,
}

#: Units that count whole turns. pint makes each 2 pi radians, so that "1500 rpm" is 157 Hz and a
#: feed of "0.127 mm/revolution" 0.0202 mm; outside an angle they are counts.
_TURNS = re.compile(r"\b(?:rev|revs|revolutions?|turns?|cycles?)\b")
_PER_TURN = {"rpm": "1/min", "rps": "1/s"}

#: The number that starts a quantity: digits with a decimal point, an optional exponent.
_LEADING_NUMBER = re.compile(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*")


def _check_one_number(text: str, field: str) -> None:
    """Refuse what pint would read as another number than the one written.

    pint drops commas and multiplies numbers written side by side, so a decimal comma
    (``"12,5 mm"``) is read as 125 mm, a thousands space (``"1 000 N"``) as 0 N and
    ``"12, 5 mm"`` as 60 mm. A quantity is one number with a decimal point, then its unit,
    which may start with ``1/`` (``"20 1/GPa"``).
    """
    match = _LEADING_NUMBER.match(text)
    rest = text[match.end():] if match else text
    if "," in text or (match and rest[:1].isdigit() and not re.match(r"1\s*/", rest)):
        raise InputError(field, "one number with a decimal point (no comma or thousands "
                         "separator), then its unit (e.g. '12.5 mm')", text)


#: Viscosity units as people write them without the space pint needs (lower case, dots
#: dropped) -> as pint reads them: "30 mPas" (pint: an error), "30 cp" (pint: candlepower).
_VISCOSITY_SPELLINGS = {"pas": "Pa*s", "mpas": "mPa*s", "cp": "cP", "cps": "cP"}


def _parse(text: str, si_unit: str, field: str) -> float:
    import pint

    ureg = registry()
    _check_one_number(text, field)
    read = text.strip()
    unit = unit_of(read)
    if si_unit == "Pa*s" and unit and unit.lower().replace(".", "") in _VISCOSITY_SPELLINGS:
        read = read[:-len(unit)] + _VISCOSITY_SPELLINGS[unit.lower().replace(".", "")]
    if si_unit != "rad":  # turns are counts: "0.127 mm/rev" is 0.127 mm, "1500 rpm" 25 Hz;
        read = _TURNS.sub("1", re.sub(r"\b(rpm|rps)\b", lambda m: _PER_TURN[m[1]], read))
        read = re.sub(r"\bmils?\b", "thou", read)  # and a mil is a thousandth of an inch
    try:
        q = ureg.Quantity(read)
    except pint.errors.OffsetUnitCalculusError:  # "73 degC": a known unit, a temperature
        raise InputError(field, f"a quantity convertible to {si_unit or 'a pure number'} (this "
                         "is a temperature)", text) from None
    except Exception:  # pint's parser raises many kinds (even AssertionError) on odd text
        raise InputError(field, f"a number with a known unit (e.g. '1.0 {si_unit or '1'}')",
                         text) from None
    if not isinstance(q, pint.Quantity):  # a bare number in a string
        try:
            return float(q)
        except (TypeError, ValueError):
            raise InputError(field, "a number", text) from None
    want = ureg.Quantity(1, si_unit) if si_unit else ureg.Quantity(1)
    if q.dimensionality != want.dimensionality:
        hint = _MISTAKEN.get((si_unit, str(q.dimensionality)))
        raise InputError(field, f"a quantity convertible to {si_unit or 'a pure number'}"
                         + (f" ({hint(q, text.strip())})" if hint else ""), text)
    try:
        return float(q.to(want.units).magnitude)
    except (pint.errors.PintError, TypeError, ValueError):
        raise InputError(field, f"a quantity convertible to {si_unit}", text) from None
