"""Zygo MetroPro / Mx text exports: the ASCII data file and the XYZ data file.

Both start with the same header of fixed lines (MetroPro Reference Guide, "ASCII data file
format"; the same fields as the binary ``.dat`` header that Gwyddion's ``metropro.c`` and
SurfaceTopography's ``MetroPro.py`` read):

====  ======================================================================================
line  fields
====  ======================================================================================
1     ``Zygo ASCII Data File - Format 2`` or ``Zygo XYZ Data File - Format 1``
3     intensity origin x, y, width, height, number of buckets, intensity range
4     phase origin x, y, width, height
8     source, interferometric scale factor S, wavelength (m), numerical aperture,
      obliquity factor O, magnification, camera resolution (m per pixel), time stamp
11    phase resolution (0, 1, 2), phase averages, ..., data sign (index 7), ...
====  ======================================================================================

followed by ``#``. The ASCII file then holds the intensity block (``buckets x width x height``
values, often none) and the phase block (``width x height`` integer counts, row by row, ten to
a line), each closed by ``#``. A count is a height of ``counts * S * O * wavelength / R``, with
R = 4096, 32768 or 131072 for phase resolution 0, 1 or 2; counts of 2147483640 and above are
invalid pixels. The XYZ file lists one pixel a line, ``column row height``, the column and
row counted in camera pixels from the phase origin and the height in micrometres or
``No Data``.

Read by the generic text reader, the ASCII file's phase block of ten counts a line became a
height matrix ten points wide with the invalid counts as heights of 2.1e9; the XYZ file was
refused as unnamed pixel indices.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...errors import InputError

__all__ = ["INVALID_PHASE", "PHASE_RESOLUTION", "ZygoData", "is_zygo", "read_zygo"]

_FIRST_LINE = re.compile(r"^\s*Zygo (ASCII|XYZ) Data File - Format (\d+)\s*$", re.IGNORECASE)
#: Phase resolution code -> counts per fringe R.
PHASE_RESOLUTION = {0: 4096, 1: 32768, 2: 131072}
#: Counts at and above this value mark a pixel without data.
INVALID_PHASE = 2147483640
#: Lines of the fixed header before the first ``#`` (the ASCII file's zoom line is the 14th).
_HEADER_LINES = 13


@dataclass(frozen=True)
class ZygoData:
    """Heights of a Zygo text export.

    Attributes
    ----------
    heights : ndarray, shape (nx, ny)
        Heights in metres, axis 0 along x (the file's columns), NaN at invalid pixels.
    pixel_size : float
        Camera resolution, metres per pixel; 0 when the file does not give it.
    style : str
        Which export, for the reader's notes (``"Zygo ASCII data file (Format 2), 40 x 30
        pixels"``).
    """

    heights: np.ndarray
    pixel_size: float
    style: str


def is_zygo(path: Path) -> bool:
    """Whether the file's first line is that of a Zygo ASCII or XYZ data file."""
    with open(path, encoding="latin-1") as f:
        return bool(_FIRST_LINE.match(f.readline()))


def _numbers(line: str, count: int, where: str, what: str) -> list[float]:
    try:
        values = [float(v) for v in line.split()[:count]]
    except ValueError:
        values = []
    if len(values) < count:
        raise InputError(where, f"{count} numbers ({what}) as a Zygo data file has them",
                         line.strip())
    return values


def read_zygo(path: Path) -> ZygoData:
    """Read a Zygo ASCII (Format 2) or XYZ (Format 1) data file (module docstring: layout).

    Parameters
    ----------
    path : Path

    Returns
    -------
    ZygoData

    Raises
    ------
    InputError
        A header line without its numbers, a block with another number of values than the
        header's width x height, a pixel outside the phase rectangle, no ``#`` separators.
    """
    lines = Path(path).read_text(encoding="latin-1").splitlines()
    kind = _FIRST_LINE.match(lines[0]).group(1).upper()
    where = f"{path}: line"
    if len(lines) < _HEADER_LINES + 1:
        raise InputError(str(path), f"the {_HEADER_LINES}-line header of a Zygo data file",
                         f"{len(lines)} lines")
    phase_rect = [int(v) for v in _numbers(lines[3], 4, f"{where} 4", "phase origin and size")]
    scale, wavelength, _, obliquity, _, camera_res = _numbers(
        lines[7], 7, f"{where} 8", "source, scale factor, wavelength, NA, obliquity, "
        "magnification, camera resolution")[1:]
    processing = _numbers(lines[10], 8, f"{where} 11", "phase resolution ... data sign")
    width, height = phase_rect[2], phase_rect[3]
    marks = [i for i in range(_HEADER_LINES, len(lines)) if lines[i].strip().startswith("#")]
    if kind == "XYZ":
        z = _xyz_block(lines, marks, phase_rect, str(path))
        style = f"Zygo XYZ data file, {width} x {height} pixels"
    else:
        # the intensity block, skipped, lies between the first two '#' lines
        if len(marks) < 3:
            raise InputError(str(path), "'#' lines closing the header, the intensity block "
                                        "and the phase block of a Zygo ASCII data file",
                             f"{len(marks)} of them")
        block = " ".join(lines[marks[1] + 1:marks[2]]).split()
        counts = np.array(block, dtype=float) if block else np.zeros(0)
        if counts.size != width * height:
            raise InputError(f"{path}: phase block", f"{width} x {height} = {width * height} "
                             "values (the header's phase width x height)", counts.size)
        resolution = PHASE_RESOLUTION.get(int(processing[0]))
        if resolution is None:
            raise InputError(f"{where} 11", "a phase resolution of 0, 1 or 2",
                             int(processing[0]))
        factor = scale * obliquity * wavelength / resolution * (-1 if processing[7] else 1)
        counts[counts >= INVALID_PHASE] = np.nan
        z = (counts * factor).reshape(height, width)
        style = (f"Zygo ASCII data file, {width} x {height} pixels, counts x {factor:.6g} m "
                 f"(S {scale:g}, O {obliquity:g}, wavelength {wavelength * 1e9:.6g} nm, "
                 f"R {resolution})")
    return ZygoData(np.ascontiguousarray(z.T), float(camera_res), style)


def _xyz_block(lines: list[str], marks: list[int], rect: list[int], where: str) -> np.ndarray:
    """The pixels of a Zygo XYZ file's block, ``column row height_um``, on the phase rectangle
    (rows of constant y), NaN where ``No Data`` or absent."""
    if len(marks) < 2:
        raise InputError(where, "'#' lines closing the header and the data of a Zygo XYZ "
                                "data file", f"{len(marks)} of them")
    z = np.full((rect[3], rect[2]), np.nan)
    for number in range(marks[0] + 1, marks[1]):
        fields = lines[number].split(None, 2)
        if not fields:
            continue
        try:
            col, row = int(fields[0]) - rect[0], int(fields[1]) - rect[1]
            value = np.nan if fields[2].strip().lower() == "no data" else float(fields[2])
        except (ValueError, IndexError):
            raise InputError(f"{where}: line {number + 1}", "'column row height' (height in "
                             "um or 'No Data')", lines[number].strip()) from None
        if not (0 <= row < rect[3] and 0 <= col < rect[2]):
            raise InputError(f"{where}: line {number + 1}", f"a pixel within the phase "
                             f"rectangle ({rect[2]} x {rect[3]} from {rect[0]}, {rect[1]})",
                             lines[number].strip())
        z[row, col] = value * 1e-6
    return z
