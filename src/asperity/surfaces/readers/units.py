"""Length units as instruments spell them: ``um``, ``µm``, ``Micrometer``, ``[nm]``, ``Å``.

Instrument exports write units in many ways (a micro sign or a Greek mu, plurals, British or
American spelling, ``A`` for angstrom, which pint would read as ampere). :func:`length_factor`
normalises the spelling and asks pint (:func:`asperity.units.registry`) for the factor to metres,
accepting only lengths. :func:`unit_of_name` finds the unit in a column name such as
``x_um``, ``Height [nm]``, ``Position (mm)`` or ``Raw Micrometer``.
"""

from __future__ import annotations

import re

from ...errors import InputError
from ...units import registry

__all__ = ["length_factor", "parse_length", "unit_of_name"]

#: Spellings pint does not know, or would misread, -> a pint unit.
_ALIASES = {
    "a": "angstrom", "å": "angstrom", "ang": "angstrom", "angstroms": "angstrom",
    "micron": "micrometer", "microns": "micrometer", "mu": "micrometer",
    "micrometre": "micrometer", "micrometres": "micrometer", "micrometers": "micrometer",
    "nanometre": "nanometer", "nanometres": "nanometer", "nanometers": "nanometer",
    "millimetre": "millimeter", "millimetres": "millimeter", "millimeters": "millimeter",
    "metre": "meter", "metres": "meter", "meters": "meter",
    "mil": "thou", "mils": "thou", "uinch": "microinch", "in": "inch", "inches": "inch",
}
_UNIT_IN_NAME = (
    re.compile(r"[\[(]\s*([^\])]+?)\s*[\])]"),  # Height [nm], Position (mm)
    re.compile(r"[_\s/-]([A-Za-zµμÅ]+)\s*$"),  # x_um, Raw Micrometer, z/nm
)


def _normalise(text: str) -> str:
    text = text.strip().replace("µ", "u").replace("μ", "u").replace("Å", "angstrom").lower()
    return _ALIASES.get(text, text)


#: Lengths pint knows that no instrument measures in: typographic pixels and points (pint's
#: ``px`` is 1/96 inch, so ``--unit px`` read heights as 0.26 mm each).
_NOT_INSTRUMENT_UNITS = frozenset({"px", "pixel", "pixels", "pt", "point", "points", "pica",
                                   "dot", "dots"})


def length_factor(text: str | None) -> float | None:
    """Metres per unit of a length unit spelt ``text``; None when it is not a length unit (or
    is one of :data:`_NOT_INSTRUMENT_UNITS`)."""
    if text is None or not text.strip() or re.search(r"\d", text):
        return None
    if _normalise(text) in _NOT_INSTRUMENT_UNITS:
        return None
    try:
        quantity = registry().Quantity(1.0, _normalise(text))
        if not quantity.check("[length]"):
            return None
        return float(quantity.to("m").magnitude)
    except Exception:  # pint raises many types for names it does not know
        return None


def parse_length(text: str, field: str) -> float:
    """A unit name as given by the user (``--unit um``); InputError naming ``field`` if not one."""
    factor = length_factor(text)
    if factor is None:
        raise InputError(field, "a length unit such as m, mm, um, nm, angstrom, in, mil", text)
    return factor


def unit_of_name(name: str) -> tuple[str, float] | None:
    """The unit written in a column name and its factor to metres, or None."""
    for pattern in _UNIT_IN_NAME:
        match = pattern.search(name.strip())
        if match is not None:
            factor = length_factor(match.group(1))
            if factor is not None:
                return match.group(1), factor
    return None
