"""Text and CSV exports of profilometers: find the data block, its columns, units and scales.

A text export is a header (comment lines, ``key: value`` / ``key = value`` / ``key,value,unit``
lines, a line of column names) followed by a block of numbers. The reader

1. splits each line on tabs or semicolons if it has any, else on commas, else on white space
   (a decimal comma is accepted when the separator is not a comma), dropping a trailing empty
   field (``0.1,0.2,``) and the double quotes of spreadsheet-style CSV (``"X Unit","um"``; a
   comma inside quotes is part of the field);
2. takes as the data block the last run of lines whose fields are all numbers or missing-value
   markers (empty field, ``NaN``, ``BAD``, ``***``, ``-``, ``undefined``, ``inf``, Zygo's
   two-word ``No Data``, ...); every line before it is header; after it only lines of words or
   results written ``key,value[,unit]`` (a footer) may follow -- another line mixing numbers
   and words is an error naming the line, and so
   is the line just above the block when it starts with a number and has as many fields as a
   data line or more (a data line with a marker the reader does not know, which would
   otherwise cut the data in two and keep only the part after it);
3. reads ``key: value`` pairs from the header (:func:`header_pairs`) and the column names from
   the last header line with one name per column (or a corner label and one number per
   column after it: a matrix's x positions); when that line holds only length units
   (``mm,um``) and the line above it one name per column, the two make the names
   (``Distance [mm]``), and a line of units alone makes names of units (``[mm]``).

:func:`read_table` returns the numbers with NaN for missing values, the column names, the header
pairs and the printed resolution of each column (for rounded coordinates). Interpreting them
(which column is x, units, scale factors) is :mod:`asperity.surfaces.readers.layout`'s job.
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...errors import InputError
from .units import length_factor

__all__ = ["MISSING_TOKENS", "TextTable", "file_lines", "header_pairs", "normalise_key",
           "is_number", "printed_resolution", "read_table"]

#: Field values that instruments write for a point they could not measure (lower case).
MISSING_TOKENS = frozenset({"", "nan", "-nan", "+nan", "bad", "nd", "n/a", "na", "***", "*",
                            "-", "--", "undefined", "invalid", "void", "inf", "-inf", "+inf",
                            "infinity", "-infinity", "null", "none", "nodata", "no data"})
#: A missing-value marker of two words (Zygo's XYZ export), read as one field.
_TWO_WORD_MISSING = re.compile(r"\bno\s+data\b", re.IGNORECASE)
_COMMENT = re.compile(r"^\s*(#|%|//|;|!)\s*")
_KEY_VALUE = re.compile(r"^([^=:：]{1,60}?)\s*[=:：]\s*(.*)$")
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


@dataclass(frozen=True)
class TextTable:
    """What a text export holds, before interpretation.

    Attributes
    ----------
    data : ndarray, shape (rows, columns)
        The data block, NaN where a value is missing.
    names : list of str or None
        Column names from the header line above the block.
    header : dict of str to str
        Header pairs, keys normalised by :func:`normalise_key`.
    resolution : ndarray, shape (columns,)
        The coarsest printed resolution of each column (1e-3 for ``12.345``); 0 for a column
        of integers, taken as exact.
    first_line : int
        Line number (1-based) of the first data row.
    """

    data: np.ndarray
    names: list[str] | None
    header: dict[str, str]
    resolution: np.ndarray
    first_line: int


def normalise_key(key: str) -> str:
    """Lower case; runs of spaces, underscores, hyphens as one space (``X-Unit`` -> ``x unit``)."""
    return re.sub(r"[\s_\-]+", " ", key.strip().lower()).strip()


def _unquoted(field: str) -> str:
    """A field without the double quotes a spreadsheet-style CSV puts round it."""
    field = field.strip()
    return field[1:-1].strip() if len(field) > 1 and field[0] == field[-1] == '"' else field


def _split(text: str) -> list[str]:
    if "\t" in text or ";" in text:
        fields = re.split(r"[\t;]", text)
    elif "," in text:
        fields = next(csv.reader([text], skipinitialspace=True)) if '"' in text else \
            text.split(",")
    else:
        fields = _TWO_WORD_MISSING.sub("nodata", text).split()
    fields = [_unquoted(f) for f in fields]
    while fields and not fields[-1]:
        fields.pop()
    return fields


def _value(token: str, decimal_comma: bool) -> float | None:
    """The number a field holds, NaN for a missing-value marker, None for a word."""
    t = token.replace(",", ".") if decimal_comma else token
    if _NUMBER.match(t):
        return float(t)
    if token.lower() in MISSING_TOKENS:
        return np.nan
    return None


def is_number(token: str) -> bool:
    """Whether ``token`` is a plain decimal number (``12``, ``-0.5``, ``1.5e-6``)."""
    return bool(_NUMBER.match(token))


def printed_resolution(token: str) -> float:
    """The last printed digit's value: ``12.345`` -> 1e-3, ``1.5e-6`` -> 1e-7, ``7`` -> 1."""
    mantissa, _, exponent = token.lower().replace(",", ".").partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** (int(exponent or 0) - decimals)


_UNIT_IN_KEY = re.compile(r"^(.*?)\s*[\[(]\s*([^\])]+?)\s*[\])]$")


def _pair(key: str, value: str) -> tuple[str, str]:
    """A header pair with a length unit written in the key moved to its numbers:
    ``X spacing (um), 0.5`` -> ``("x spacing", "0.5 um")``, as ``X spacing: 0.5 um`` reads."""
    key, value = normalise_key(key), value.strip()
    match = _UNIT_IN_KEY.match(key)
    if (match is not None and length_factor(match.group(2)) is not None
            and all(_NUMBER.match(v) for v in value.split())):
        return match.group(1), f"{value} {match.group(2)}"
    return key, value


def header_pairs(lines: list[str]) -> dict[str, str]:
    """``key: value``, ``key = value`` or ``key,value[,unit]`` header lines as a dict.

    Keys are normalised (:func:`normalise_key`), values are the fields joined by spaces; a
    length unit in brackets at the end of a key whose value is numbers goes with the numbers
    (:func:`_pair`); the first occurrence of a key wins; other lines are ignored.
    """
    pairs = {}
    for line in lines:
        text = _COMMENT.sub("", line).strip()
        match = _KEY_VALUE.match(text)
        if match is not None and match.group(2).strip():
            pairs.setdefault(*_pair(match.group(1), match.group(2)))
            continue
        fields = _split(text)
        if len(fields) >= 2 and not _NUMBER.match(fields[0]) and fields[1]:
            pairs.setdefault(*_pair(fields[0], " ".join(fields[1:])))
    return pairs


def file_lines(path: Path) -> list[str]:
    """The lines of a text file, decoded as :func:`read_table` decodes it (refused when
    binary)."""
    raw = path.read_bytes()
    if b"\x00" in raw[:4096] and not raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise InputError(str(path), "a text file (this one is binary; a binary format needs "
                                    "its own suffix, e.g. .x3p, .sdf, .sur)")
    for encoding in ("utf-8-sig", "utf-16") if raw[:2] in (b"\xff\xfe", b"\xfe\xff") else (
            "utf-8-sig", "latin-1"):
        try:
            return raw.decode(encoding).splitlines()
        except UnicodeDecodeError:
            continue
    raise InputError(str(path), "a text file in UTF-8, UTF-16 or Latin-1")


def _row(text: str) -> tuple[list[float], list[str]] | None:
    """The values of a data line, or None when it is not one."""
    fields = _split(text)
    if not fields:
        return None
    decimal_comma = ("\t" in text or ";" in text) and "," in text
    values = [_value(f, decimal_comma) for f in fields]
    if any(v is None for v in values) or all(f.lower() in MISSING_TOKENS for f in fields):
        return None
    return values, fields


_INTEGER = re.compile(r"^[+-]?\d+$")
_DIGITS = re.compile(r"^\d+([eE][+-]?\d+)?$")


def _footer(fields: list[str]) -> bool:
    """Whether a line after the data block is a footer: words only, or a result as
    ``key,value[,unit]`` (``"Ra","0.0376","um"``, as stylus exports append their results) --
    a word first and one number. Such a result line was refused as a data line with a word."""
    numbers = sum(bool(_NUMBER.match(f)) for f in fields)
    return numbers == 0 or (numbers == 1 and len(fields) <= 3
                            and _value(fields[0], False) is None)


def _unit_row(fields: list[str]) -> bool:
    """Whether every field is a length unit (``mm``, ``[um]``, ``(nm)``): a line of units."""
    return all(length_factor(f.strip().strip("[]()")) is not None for f in fields)


def _names_over_units(units: list[str], header_lines: list[str], width: int):
    """Column names for a line of units under a line of names (``Distance,Height`` then
    ``mm,um``, as spreadsheets and several instruments export): ``Distance [mm]``; a line of
    units alone gives ``[mm]``. The units line was taken for the names and its units lost: the
    numbers were read as metres. Returns the names and the header lines left."""
    bare = [u.strip().strip("[]()") for u in units]
    plain = [line for line in header_lines
             if line.strip() and _split(_COMMENT.sub("", line).strip()) != units]
    above = _split(_COMMENT.sub("", plain[-1])) if plain else []
    if (len(above) == width and not _unit_row(above)
            and all(_value(f, False) is None for f in above)):
        return ([f"{n} [{u}]" for n, u in zip(above, bare, strict=True)],
                [h for h in header_lines if h is not plain[-1]])
    return [f"[{u}]" for u in bare], header_lines


def _axis_row(fields: list[str]) -> bool:
    """Whether a header line is a corner label and one number per column after it
    (``y\\x,0.0,0.5,...`` over a height matrix whose first column is y): kept as the names,
    whose numbers :mod:`asperity.surfaces.readers.layout` reads as x."""
    return (len(fields) >= 3 and _value(fields[0], False) is None
            and all(is_number(f) for f in fields[1:]))


def _decimal_commas(names: list[str], line: str, rows: list[list[str]]) -> bool:
    """Whether comma-separated column ``names`` over data lines of twice as many fields read
    as numbers written with decimal commas and a comma separator (``x_mm,z_um`` over
    ``0,0005,2,86233``): every pair of fields an integer part and its digits."""
    if (len(names) < 2 or "," not in line or "\t" in line or ";" in line
            or any(_value(f, False) is not None for f in names)):
        return False
    return all(len(row) == 2 * len(names)
               and all(_INTEGER.match(row[k]) and _DIGITS.match(row[k + 1])
                       for k in range(0, len(row), 2)) for row in rows)


def _refuse_cut_block(path: Path, lines: list[str], parsed: list, start: int) -> None:
    """Refuse a file whose data block is cut by a data line with an unknown word.

    The line just above the block (``start``), blank lines skipped, is taken for a data line
    -- a point the instrument marked with a word the reader does not know (``12 7 NoValue``)
    -- when it is not a comment, its first field is a number, it has the block's number of
    fields or one more (a marker of two words) and a word among them; for a block of fewer than
    three columns also only when its first number continues the block's first column by one
    step (so that a header line ``8000 points`` above x, z columns is not one). Taking the block
    after such a line would silently drop every line before it (a Zygo XYZ export's
    ``No Data`` points once read as the 642 lines after the last one).
    """
    width = len(parsed[start][0])
    above = start - 1
    while above >= 0 and not lines[above].strip():
        above -= 1
    if above < 0 or _COMMENT.match(lines[above]):
        return
    text = lines[above].strip()
    decimal_comma = ("\t" in text or ";" in text) and "," in text
    fields = _split(text)
    values = [_value(f, decimal_comma) for f in fields]
    if (len(fields) not in (width, width + 1) or values[0] is None or np.isnan(values[0])
            or all(v is not None for v in values)):
        return
    if width < 3:
        following = parsed[start + 1] if start + 1 < len(parsed) else None
        if following is None:
            return
        first, second = parsed[start][0][0], following[0][0]
        if not abs(values[0] - (2 * first - second)) <= 0.5 * abs(second - first):
            return
    word = next(f for f, v in zip(fields, values, strict=True) if v is None)
    raise InputError(f"{path}:{above + 1}", "numbers or a missing-value marker (NaN, BAD, "
                     "***, No Data, ...) in each field of a data line; the lines from "
                     f"{start + 1} on would be read alone", word)


def read_table(path: Path) -> TextTable:
    """Read a text export's header and data block (see the module docstring).

    Raises
    ------
    InputError
        No data block, a data line with another number of columns than the first (naming the
        file and line), words after the data block or in a data line just above it
        (:func:`_refuse_cut_block`), a binary file.
    """
    lines = file_lines(path)
    parsed = [None if _COMMENT.match(line) else _row(line) for line in lines]
    last = max((i for i, p in enumerate(parsed) if p is not None), default=None)
    if last is None:
        raise InputError(str(path), "a block of numbers (one column of heights, x and z "
                                    "columns, or a height matrix)")
    start = last
    while start > 0 and (parsed[start - 1] is not None or not lines[start - 1].strip()):
        start -= 1
    while parsed[start] is None:  # blank lines at the top of the block
        start += 1
    _refuse_cut_block(path, lines, parsed, start)
    width = len(parsed[start][0])
    rows, tokens = [], []
    for i in range(start, len(lines)):
        if parsed[i] is None:
            text = lines[i].strip()
            fields = _split(text)
            if not text or _COMMENT.match(lines[i]) or (i > last and _footer(fields)):
                continue  # blank, comment, or a footer after the data block
            bad = next((f for f in _split(text) if _value(f, False) is None), text)
            raise InputError(f"{path}:{i + 1}", "numbers only", bad)
        values, fields = parsed[i]
        if len(values) != width:
            raise InputError(f"{path}:{i + 1}", f"{width} columns like line {start + 1}",
                             f"{len(values)} columns")
        rows.append(values)
        tokens.append(fields)
    if len(rows) < 2:
        raise InputError(str(path), "at least 2 rows of numbers")
    data = np.array(rows, dtype=float)
    resolution = np.zeros(width)
    for j in range(width):
        column = [row[j] for row in tokens if _NUMBER.match(row[j].replace(",", "."))]
        fractional = [t for t in column if "." in t or "," in t or "e" in t.lower()]
        resolution[j] = max((printed_resolution(t) for t in fractional), default=0.0)
    header_lines = lines[:start]
    names = None
    plain = [line for line in header_lines if line.strip() and not _COMMENT.match(line)]
    candidates = plain[-1:] or [_COMMENT.sub("", line) for line in header_lines[-1:]
                                if not _KEY_VALUE.match(_COMMENT.sub("", line).strip())]
    for line in candidates:
        fields = _split(line) if width > 1 else [line.strip()]
        if len(fields) == width and (all(_value(f, False) is None for f in fields)
                                     or _axis_row(fields)):
            names = fields
            header_lines = [h for h in header_lines if h is not line]
            if _unit_row(fields):
                names, header_lines = _names_over_units(fields, header_lines, width)
        elif _decimal_commas(fields, line, tokens):
            raise InputError(str(path), f"one field per column named in the header line "
                             f"{line.strip()!r}: its {len(fields)} names are separated by "
                             f"commas and each data line has {width} fields, as decimal "
                             "commas with a comma separator give (line "
                             f"{start + 1}: {lines[start].strip()!r}); export with ';' or "
                             "tab separators, or with decimal points")
    pairs = header_pairs([line for line in header_lines if line.strip()])
    return TextTable(data, names, pairs, resolution, start + 1)
