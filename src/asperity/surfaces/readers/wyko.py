"""Wyko / Veeco / Bruker Vision ASCII exports (``Wyko ASCII Data File Format 0``).

The file starts with ``Wyko ASCII Data File Format 0<TAB>r<TAB>1``, then ``X Size<TAB>nx``,
``Y Size<TAB>ny`` and a table of blocks, ``name<TAB>type<TAB>length<TAB>value``:
``Pixel_size`` (mm), ``Wavelength`` (nm), ``Mult``, ``Aspect`` (the y pixel over the x pixel).
A data block (``RAW_DATA``, ``OPD``, ``SAMPLE_DATA``) has an empty value and is followed by nx
lines of ny values each: one line per x, its values along y from the largest y down, as
Gwyddion's ``opd.c`` reads them; ``Bad`` marks a pixel without data. The flag r is 1 when the
values are nanometres and 0 when they are in units of the wavelength over ``Mult`` (Gwyddion
reads the latter; SurfaceTopography's text reader both). Intensity blocks (``Intensity``,
``Image``, ``SecArr_0``) are skipped.

Read by the generic text reader, the block table's ``Pixel_size 7 4 0.00164`` was taken for a
spacing of three numbers, which refused the file naming ``spacing`` and, with ``--spacing``
given, ended in a traceback.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...errors import InputError

__all__ = ["WykoData", "is_wyko", "read_wyko"]

_FIRST_LINE = re.compile(r"^\s*Wyko ASCII Data File Format\s+\d+\s+(\d+)", re.IGNORECASE)
_DATA_BLOCKS = ("raw_data", "raw data", "opd", "sample_data")
_IMAGE_BLOCKS = ("intensity", "image", "secarr_0")


@dataclass(frozen=True)
class WykoData:
    """Heights of a Wyko ASCII export.

    Attributes
    ----------
    heights : ndarray, shape (nx, ny)
        Heights in metres, axis 0 along x, y increasing with the index; NaN at ``Bad`` pixels.
    spacing : tuple of float
        Pixel size along x and y (m): ``Pixel_size`` and ``Aspect`` times it.
    style : str
        Which export and how its values were scaled, for the reader's notes.
    """

    heights: np.ndarray
    spacing: tuple[float, float]
    style: str


def is_wyko(path: Path) -> bool:
    """Whether the file's first line is that of a Wyko ASCII data file."""
    with open(path, encoding="latin-1") as f:
        return bool(_FIRST_LINE.match(f.readline()))


def _value(blocks: dict, key: str, where: str, default: float | None = None) -> float:
    if key not in blocks:
        if default is None:
            raise InputError(where, f"a {key!r} entry in the block table of a Wyko ASCII file")
        return default
    try:
        return float(blocks[key])
    except ValueError:
        raise InputError(where, f"a number as the value of {key!r}", blocks[key]) from None


def read_wyko(path: Path) -> WykoData:
    """Read a Wyko ASCII data file (module docstring: layout).

    Parameters
    ----------
    path : Path

    Returns
    -------
    WykoData

    Raises
    ------
    InputError
        No ``X Size``, ``Y Size``, ``Pixel_size`` or ``Wavelength``; no data block; a data
        line with another number of values than ``Y Size``, or fewer lines than ``X Size``.
    """
    lines = Path(path).read_text(encoding="latin-1").splitlines()
    where = str(path)
    in_nm = _FIRST_LINE.match(lines[0]).group(1) == "1"
    sizes: dict[str, int] = {}
    blocks: dict[str, str] = {}
    number, start = 1, None
    while number < len(lines):
        fields = lines[number].split("\t")
        name = fields[0].strip().lower()
        if name in ("x size", "y size") and len(fields) > 1:
            sizes[name] = int(float(fields[1]))
        elif name in _DATA_BLOCKS:
            start = number
            break
        elif name in _IMAGE_BLOCKS:
            number += sizes.get("x size", 0)  # its lines of values
        elif len(fields) >= 4 and name != "block name":
            blocks[name] = fields[3].strip()
        number += 1
    if start is None:
        raise InputError(where, "a RAW_DATA (or OPD) block in a Wyko ASCII file")
    if "x size" not in sizes or "y size" not in sizes:
        raise InputError(where, "'X Size' and 'Y Size' lines in a Wyko ASCII file")
    nx, ny = sizes["x size"], sizes["y size"]
    pixel = _value(blocks, "pixel_size", where) * 1e-3
    aspect = _value(blocks, "aspect", where, 1.0)
    wavelength = _value(blocks, "wavelength", where) * 1e-9
    mult = _value(blocks, "mult", where, 1.0)
    factor = 1e-9 if in_nm else wavelength / mult
    rows = lines[start + 1:start + 1 + nx]
    if len(rows) < nx:
        raise InputError(f"{where}: {lines[start].split(chr(9))[0]} block",
                         f"X Size = {nx} lines of values", f"{len(rows)} lines")
    z = np.empty((nx, ny))
    for i, row in enumerate(rows):
        values = [v for v in row.replace("\t", " ").split(" ") if v]
        if len(values) != ny:
            raise InputError(f"{where}: line {start + 2 + i}", f"Y Size = {ny} values",
                             f"{len(values)} values")
        z[i] = [np.nan if v.lower() == "bad" else float(v) for v in values]
    scale = "nm" if in_nm else f"waves x {wavelength * 1e9:.6g} nm / Mult {mult:g}"
    style = f"Wyko ASCII data file, {nx} x {ny} pixels, values in {scale}"
    return WykoData(z[:, ::-1] * factor, (pixel, pixel * aspect), style)
