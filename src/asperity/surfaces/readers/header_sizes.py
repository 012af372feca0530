"""Header sizes of text exports as the file writes numbers: a decimal comma in a header's
spacing or size (``Pixel size: 1,5 µm``) read as one, two numbers each with their unit
(``0.5 µm x 0.8 µm``) read as a pair, and a header spacing that is no grid's refused quoting
the header.

:func:`~.layout.interpret` reads a header's ``a, b`` as the x and y spacings; a European
export writes ``1,5`` for 1.5. :func:`text_layout` tells the two apart by the data: decimal
commas there (tab- or semicolon-separated values with a comma between digits) make the
header's a decimal too; without them the pair reading stands where it gives a grid's two
spacings, with a warning naming the decimal reading.
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import numpy as np

from ...errors import InputError
from .layout import SIZE_KEYS, Layout, interpret
from .text import TextTable, file_lines, read_table

__all__ = ["check_header_spacing", "header_factor", "length_text", "text_layout"]


#: The header keys of a spacing or a size (:mod:`.layout`): the entries a decimal
#: comma changes.
_SIZE_KEYS = SIZE_KEYS
_DIGIT_COMMA = re.compile(r"(?<=\d),(?=\d)")
_NUMBER_TEXT = r"[+-]?(?:\d+[.,]?\d*|[.,]\d+)(?:[eE][+-]?\d+)?"
#: Two numbers of a header value each with the same unit (``0,5 µm x 0,5 µm``).
_UNIT_EACH = re.compile(rf"^\s*({_NUMBER_TEXT})\s*([A-Za-zµμÅ]+)\s*(x|×|\*|by|;)\s*"
                        rf"({_NUMBER_TEXT})\s*\2\s*$")


def _one_unit(value: str) -> str:
    """A header value of two numbers each with the same unit written with the unit once
    (``0.5 µm x 0.5 µm`` -> ``0.5 x 0.5 µm``), as :mod:`.layout` reads two numbers: it
    took the first alone, in the file's x unit (metres without one)."""
    match = _UNIT_EACH.match(value)
    if match is None:
        return value
    return f"{match.group(1)} {match.group(3)} {match.group(4)} {match.group(2)}"


def _decimal_data(path: Path, first_line: int) -> bool:
    """Whether the data block (from line ``first_line`` on) is written with decimal commas: a
    line split on tabs or semicolons with a comma between digits, which
    :func:`~.text.read_table` reads as a decimal point."""
    return any(("\t" in line or ";" in line) and line.lstrip()[:1] not in ("#", "%", ";", "!")
               and _DIGIT_COMMA.search(line) for line in file_lines(path)[first_line - 1:])


def _with_header(table: TextTable, entries: dict[str, str]) -> TextTable:
    return replace(table, header={**table.header, **entries})


def length_text(value: float) -> str:
    """``"0.5 um"``: a length (m) in the first of um, mm, nm that writes it between 0.01 and
    1000 (metres else), as the user would give it."""
    for factor, name in ((1e-6, "um"), (1e-3, "mm"), (1e-9, "nm")):
        if 0.01 <= abs(value) / factor < 1000:
            return f"{value / factor:.4g} {name}"
    return f"{value:.4g} m"


def header_factor(lay: Layout, given_x: float | None) -> float:
    """Metres per unit of the header's spacing: its own unit, else the x unit given or the
    file's, else metres (as :func:`_read_text` reads it)."""
    x = given_x if given_x is not None else lay.x_factor
    return lay.spacing_factor or (1.0 if x is None else x)


def _comma_pair(lay: Layout | None, decimal: Layout) -> bool:
    """Whether ``lay`` reads a header's ``a,b`` as the x and y spacings of a grid: two values,
    both > 0, of a height matrix; a profile's, a zero, or a size's (whose first number alone is
    read) are no such reading."""
    return (lay is not None and lay.x is None and lay.z.ndim == 2 and lay.spacing is not None
            and len(lay.spacing) == 2 and min(lay.spacing) > 0
            and lay.spacing != decimal.spacing)


def _spacing_of(lay: Layout, given_x: float | None) -> str:
    """``"0.5 um"`` or ``"0.5 um x 0.8 um"``: a layout's header spacing in metres, as written."""
    factor = header_factor(lay, given_x)
    return " x ".join(length_text(v * factor) for v in lay.spacing)


def _same_spacing(given, lay: Layout, given_x: float | None) -> bool:
    """Whether a spacing given (m) is the header's of ``lay``."""
    header = [v * header_factor(lay, given_x) for v in lay.spacing]
    wanted, have = np.broadcast_arrays(np.atleast_1d(np.asarray(given, dtype=float)),
                                       np.atleast_1d(np.asarray(header, dtype=float)))
    return bool(np.allclose(wanted, have, rtol=1e-3))


def text_layout(path: Path, given_x: float | None, given, notes: list,
                 warnings: list) -> tuple[Layout, dict[str, str]]:
    """The layout of a text export (:func:`~.layout.interpret`) with its header's
    spacing and size entries read as the file writes numbers, and those entries as written.

    A comma between digits in them (``Pixel size: 1,5 µm``) is a decimal comma when the data are
    written with decimal commas (with a note). Else it is read as :mod:`.layout` reads
    ``a, b``, the x and y spacings, where that makes a grid's spacings, with a warning naming the
    decimal reading and how to give it; and as a decimal comma, with a note, where it does not
    (a profile's spacing, a size, a zero: ``0,5 um`` read 0 and 5 um, refused as a spacing of 0).
    Read as two numbers, the decimal-comma header of a semicolon matrix made it 1 x 5 um
    without a word.
    """
    table = read_table(path)
    sizes = {k: v for k, v in table.header.items() if k in _SIZE_KEYS}
    merged = {k: _one_unit(v) for k, v in sizes.items()}
    commas = {k: v for k, v in merged.items() if _DIGIT_COMMA.search(v)}
    if not commas:
        return interpret(_with_header(table, merged), str(path)), sizes
    points = _with_header(table, {**merged, **{k: _DIGIT_COMMA.sub(".", v)
                                               for k, v in commas.items()}})
    shown = ", ".join(f"{k!r} ({sizes[k]})" for k in commas)
    if _decimal_data(path, table.first_line):
        lay = interpret(points, str(path))
        value = "" if lay.spacing is None else f" ({_spacing_of(lay, given_x)})"
        notes.append(f"header {shown} read with a decimal comma{value}, as the data are "
                     "written")
        return lay, sizes
    try:
        lay = interpret(_with_header(table, merged), str(path))
    except InputError:  # more than two numbers: ``0,5 x 0,5 um`` as four
        lay = None
    decimal = interpret(points, str(path))
    if lay is not None and (lay.x is not None or (lay.spacing, lay.spacing_factor)
                            == (decimal.spacing, decimal.spacing_factor)):
        return lay, sizes  # the header's spacing is not used, or the comma is not in it
    one = _spacing_of(decimal, given_x)
    if _comma_pair(lay, decimal) and (given is None or not _same_spacing(given, decimal,
                                                                          given_x)):
        if given is None:
            dx, dy = _spacing_of(lay, given_x).split(" x ")
            warnings.append(f"spacing: header {shown} read as x {dx}, y {dy} (two numbers "
                            "between a comma); the data show no decimal commas to tell, and if "
                            f"it is the decimal {one} give --spacing \"{one}\" (case file: "
                            f"spacing = \"{one}\")")
        return lay, sizes
    why = ("the spacing given is that" if _comma_pair(lay, decimal) else
           "read as two numbers, x and y, it is no spacing of this file")
    notes.append(f"header {shown} read with a decimal comma ({one}): the data show no decimal "
                 f"commas, but {why}")
    return decimal, sizes


def check_header_spacing(values: list[float], ndim: int, sizes: dict[str, str], path: Path) -> None:
    """Refuse a spacing from the header that is no grid's spacing (a value not > 0, or two for
    a profile), quoting the header lines it was read from: ``spacing: expected a finite number
    > 0, got 0.0`` did not say that it came from the file."""
    if len(values) in (1, ndim) and all(np.isfinite(v) and v > 0 for v in values):
        return
    lines = "; ".join(f"{k}: {v}" for k, v in sizes.items())
    raise InputError(f"{path}: header", "a grid spacing > 0 with its unit ("
                     + ("one, or dx and dy" if ndim == 2 else "one value, for a profile")
                     + "): correct that header line, or give the spacing, --spacing \"0.5 um\" "
                     "(case file: spacing = \"0.5 um\")", lines or values)
