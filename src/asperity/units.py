"""Quantities with units at the edge of asperity: ``"2160 lbf"`` -> 9608.1 (N).

Everything inside asperity is SI. Case files may give a quantity as a plain number (taken as SI)
or as a string with a unit that pint understands; :func:`to_si` converts once, checking that the
dimension is the one the field needs.
"""

from __future__ import annotations

import math
from functools import lru_cache

from .errors import InputError

__all__ = ["DIMENSIONS", "is_bare", "registry", "to_si"]

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


def _parse(text: str, si_unit: str, field: str) -> float:
    import pint

    ureg = registry()
    try:
        q = ureg.Quantity(text.strip())
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
        raise InputError(field, f"a quantity convertible to {si_unit or 'a pure number'}", text)
    try:
        return float(q.to(want.units).magnitude)
    except (pint.errors.PintError, TypeError, ValueError):
        raise InputError(field, f"a quantity convertible to {si_unit}", text) from None
