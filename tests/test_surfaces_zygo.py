"""Zygo MetroPro / Mx text exports, written by hand as the MetroPro Reference Guide lays them out.

The ASCII data file (Format 2) holds a fixed header, an intensity block and a phase block of
integer counts ten to a line; a count is a height of counts * S * O * wavelength / R (R = 32768
at phase resolution 1), and counts of 2147483640 mark invalid pixels. The generic text reader
took its phase block for a height matrix ten points wide with the invalid counts as heights;
the XYZ data file (Format 1: ``column row height_um`` or ``No Data``) was refused as unnamed
pixel indices although its header gives the pixel size.
"""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces.io import read_measured
from asperity.surfaces.parameters import residual_heights

NX, NY, PIXEL = 24, 16, 0.8e-6
WAVELENGTH, S, O, R = 632.8e-9, 0.5, 0.97, 32768
INVALID = [(3, 2), (10, 7), (11, 7)]  # (column, row)


def heights():
    """An asymmetric map, rows of constant y: a tilt along x, a bump at column 17, row 4."""
    col, row = np.meshgrid(np.arange(NX), np.arange(NY))
    return (2e-4 * col * PIXEL + 40e-9 * np.exp(-((col - 17) ** 2 + (row - 4) ** 2) / 4.0)
            + 5e-9 * np.sin(col))


def header(fmt: str, ox=0, oy=0, phase_res=1, sign=0, intensity=(0, 0, 0)):
    iw, ih, buckets = intensity
    return [f"Zygo {fmt} Data File - Format {2 if fmt == 'ASCII' else 1}",
            '1 8 6 0 "Tue Dec 01 23:50:00 2026       "', f"0 0 {iw} {ih} {buckets} 255",
            f"{ox} {oy} {NX} {NY}", '"lapped flat"', '"SN 1"', '"P-7"',
            f"0 {S} {WAVELENGTH} 0.3 {O} 10 {PIXEL} 1764633000", '640 480 5 0 0 0 "10X"',
            "0 0 0 0 0 0 0 0 0 0", f"{phase_res} 1 20 2 0 0 0 {sign} 1", '0 ""', "1 0"]


def write_ascii(path, sign=0, per_line=10, intensity=True):
    counts = np.round(heights() / (S * O * WAVELENGTH / R)).astype(np.int64)
    for col, row in INVALID:
        counts[row, col] = 2147483640
    lines = header("ASCII", sign=sign, intensity=(4, 2, 1) if intensity else (0, 0, 0))
    lines += ['"  1.0 "', "#"]
    if intensity:
        lines += ["100 101 102 103 104", "105 106 107"]
    lines.append("#")
    flat = counts.ravel()
    lines += [" ".join(map(str, flat[i:i + per_line])) for i in range(0, flat.size, per_line)]
    lines.append("#")
    path.write_text("\n".join(lines) + "\n")
    return counts * (S * O * WAVELENGTH / R)


def test_ascii_file_reads_the_counts_as_heights_on_the_phase_grid(tmp_path):
    expected = write_ascii(tmp_path / "flat.asc")
    reading = read_measured(tmp_path / "flat.asc", missing="mask")
    z = reading.surface.z
    assert z.shape == (NX, NY)  # [ix, iy]: the old reader made it (10, 39)
    assert np.allclose(reading.surface.spacing, PIXEL)
    lost = np.zeros((NX, NY), bool)
    for col, row in INVALID:
        lost[col, row] = True
    assert np.array_equal(reading.missing_points, lost)
    assert np.allclose(z[~lost], expected.T[~lost], rtol=0, atol=1e-15)
    assert np.unravel_index(np.argmax(residual_heights(z)), z.shape) == (17, 4)
    assert "R 32768" in reading.notes[0]


def test_inverted_data_sign_turns_the_heights_over(tmp_path):
    expected = write_ascii(tmp_path / "inv.asc", sign=1, per_line=7, intensity=False)
    z = read_measured(tmp_path / "inv.asc", missing="fill").surface.z
    assert np.allclose(z[17, 4], -expected[4, 17], rtol=0, atol=1e-15)


def test_xyz_file_reads_pixels_from_the_phase_origin_in_micrometres(tmp_path):
    z = heights()
    lines = header("XYZ", ox=100, oy=50) + ["#"]
    for row in range(NY):
        for col in range(NX):
            value = "No Data" if (col, row) in INVALID else f"{z[row, col] * 1e6:.7f}"
            lines.append(f"{col + 100} {row + 50} {value}")
    (tmp_path / "map.xyz").write_text("\n".join(lines + ["#"]) + "\n")
    reading = read_measured(tmp_path / "map.xyz", missing="mask")
    assert reading.surface.z.shape == (NX, NY)
    assert np.allclose(reading.surface.spacing, PIXEL)
    assert int(reading.missing_points.sum()) == len(INVALID)
    assert reading.missing_points[10, 7] and reading.missing_points[3, 2]
    good = ~reading.missing_points
    assert np.allclose(reading.surface.z[good], z.T[good], rtol=0, atol=1e-13)


def test_a_phase_block_of_another_size_is_refused_naming_it(tmp_path):
    write_ascii(tmp_path / "cut.asc")
    text = (tmp_path / "cut.asc").read_text().splitlines()
    del text[-3]  # one line of counts lost
    (tmp_path / "cut.asc").write_text("\n".join(text) + "\n")
    with pytest.raises(InputError, match=r"phase block: expected 24 x 16 = 384 values"):
        read_measured(tmp_path / "cut.asc", missing="fill")


def test_a_unit_given_for_a_zygo_file_is_ignored_with_a_warning(tmp_path):
    write_ascii(tmp_path / "u.asc")
    reading = read_measured(tmp_path / "u.asc", z_unit="nm", missing="fill")
    assert np.ptp(reading.surface.z) < 1e-6
    assert any("unit given is ignored" in w for w in reading.warnings)
