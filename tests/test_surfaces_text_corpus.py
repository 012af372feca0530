"""Text exports in many header styles (tests/data/text, described in tests/data/README.md).

Every file holds the same construction, written in its own units and layout:
profile f(x) = 0.5 um sin(2 pi x / 40 um) + 0.2 um cos(2 pi x / 13 um) at x = i * 0.5 um
(i = 0..63; the stylus export at x = i / 3 um), and topography f(x) + g(y) with
g(y) = 0.1 um cos(2 pi y / 3 um) on 64 x 8 points 0.5 um apart. Each is read back to SI
heights within the precision printed in the file; unreadable files are refused with one line.
"""

from pathlib import Path

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import Profile, Topography
from asperity.surfaces.io import read_measured

DATA = Path(__file__).parent / "data" / "text"


def f(x):
    return 0.5e-6 * np.sin(2 * np.pi * x / 40e-6) + 0.2e-6 * np.cos(2 * np.pi * x / 13e-6)


def g(y):
    return 0.1e-6 * np.cos(2 * np.pi * y / 3e-6)


#: file -> (spacing m, height tolerance m = the printed resolution in metres)
PROFILES = {
    "x_um_z_um.csv": (0.5e-6, 1e-11),
    "position_mm_height_nm.csv": (0.5e-6, 1e-12),
    "unit_line.txt": (0.5e-6, 1e-12),
    "dektak_meta_block.csv": (1e-6 / 3, 1e-12),
    "semicolon_decimal_comma.txt": (0.5e-6, 1e-12),
    "heights_spacing_key.txt": (0.5e-6, 1e-12),
    "tab_angstrom_missing.txt": (0.5e-6, 1e-12),
    "inch_microinch.csv": (0.5e-6, 2.54e-12),
    "plain_metres.txt": (0.5e-6, 1e-12),
    "nodata_value.txt": (0.5e-6, 1e-12),
    "unit_in_key.txt": (0.5e-6, 1e-12),
    "quoted_csv.csv": (0.5e-6, 1e-12),
    "point_numbers_pitch.csv": (0.5e-6, 1e-12),
}
#: file -> height tolerance (m)
TOPOGRAPHIES = {
    "gwyddion_matrix.txt": 1e-13,
    "matrix_height_scale.asc": 1e-11,
    "nova_scale.txt": 1e-12,
    "spip_bit2nm.asc": 1e-11,
    "gwyddion_xyz.xyz": 1e-12,
    "matrix_with_axes.csv": 1e-12,
    "matrix_with_axes_labelled.txt": 1e-12,
}
REFUSED = {
    "binary.dat": "expected a text file",
    "no_numbers.txt": "expected a block of numbers",
    "scattered.xyz": "expected x, y, z points on a rectangular grid",
    "uneven_x.csv": "expected uniformly spaced x",
    "ragged.csv": r"ragged\.csv:4: expected 2 columns like line 2",
}


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_profile_styles_read_to_si(name):
    spacing, tol = PROFILES[name]
    reading = read_measured(DATA / name, missing="fill")
    p = reading.surface
    assert isinstance(p, Profile) and p.z.size == 64
    assert p.spacing == pytest.approx(spacing, rel=1e-5)
    i = np.arange(64)
    measured = np.isfinite(p.z)
    if name.startswith("tab_angstrom"):  # three points are missing markers, filled linearly
        assert reading.filled == 3
        measured = ~np.isin(i, [10, 11, 40])
    if name.startswith("nodata"):  # two points hold the header's no-data value
        assert reading.filled == 2
        measured = ~np.isin(i, [5, 33])
        np.testing.assert_allclose(p.z[5], 0.5 * (p.z[4] + p.z[6]), rtol=1e-12)
    np.testing.assert_allclose(p.z[measured], f(i * spacing)[measured], rtol=0, atol=tol)
    assert not reading.warnings


@pytest.mark.parametrize("name", sorted(TOPOGRAPHIES))
def test_matrix_and_xyz_styles_read_to_si(name):
    reading = read_measured(DATA / name)
    t = reading.surface
    assert isinstance(t, Topography) and t.shape == (64, 8)
    assert t.spacing == pytest.approx((0.5e-6, 0.5e-6), rel=1e-9)
    i, j = np.arange(64), np.arange(8)
    expected = f(i * 0.5e-6)[:, None] + g(j * 0.5e-6)[None, :]
    np.testing.assert_allclose(t.z, expected, rtol=0, atol=TOPOGRAPHIES[name])
    assert not reading.warnings


def test_the_issue_cases_read_right():
    # Ra = 3.2e5 um of the issue: a CSV headed x_um,z_um read as metres.
    assert np.ptp(read_measured(DATA / "x_um_z_um.csv").surface.z) < 2e-6
    # Sq = 4.4 m of the issue: a matrix whose header gives a height scale.
    assert np.std(read_measured(DATA / "matrix_height_scale.asc").surface.z) < 1e-6


def test_rounded_x_is_accepted_with_a_note():
    reading = read_measured(DATA / "dektak_meta_block.csv")
    assert any("uniform to that precision" in note for note in reading.notes)
    assert "Raw Micrometer" in reading.style


def test_unlabelled_heights_warn_and_explicit_units_fix_them():
    reading = read_measured(DATA / "unlabelled_nm.txt", spacing=0.5e-6)
    assert len(reading.warnings) == 1 and "z-unit" in reading.warnings[0]
    fixed = read_measured(DATA / "unlabelled_nm.txt", spacing=0.5e-6, z_unit="nm")
    np.testing.assert_allclose(fixed.surface.z, f(np.arange(64) * 0.5e-6), atol=1e-12)
    assert not fixed.warnings
    both = read_measured(DATA / "x_um_z_um.csv", unit="nm")  # explicit units replace the file's
    assert np.ptp(both.surface.z) < 2e-9 and any("replaces" in n for n in both.notes)


def test_a_column_of_point_numbers_is_not_read_as_x(tmp_path):
    """A stylus export's ``"No.","Profile(um)"`` columns (point numbers 1..N, the pitch in the
    header) were read as x in metres: 64 points at 0.5 um a 64 m profile. Unnamed point
    numbers 0..N-1 need the spacing, as heights alone do; integer positions with an x unit
    in the header stay positions."""
    named = read_measured(DATA / "point_numbers_pitch.csv")
    assert "point numbers named 'No.'" in named.style
    with pytest.raises(InputError, match="expected a grid spacing for .*point_numbers_unnamed"
                                         r"\.txt \(a column of point numbers and heights\)"):
        read_measured(DATA / "point_numbers_unnamed.txt")
    unnamed = read_measured(DATA / "point_numbers_unnamed.txt", spacing=0.5e-6, z_unit="um")
    np.testing.assert_allclose(unnamed.surface.z, f(np.arange(64) * 0.5e-6), atol=1e-12)
    positions = tmp_path / "integer_um.txt"
    positions.write_text("# X unit: um\n# Z unit: um\n" + "".join(
        f"{i} {v * 1e6:.6f}\n" for i, v in enumerate(f(np.arange(64) * 1e-6))))
    stays = read_measured(positions).surface
    assert stays.spacing == pytest.approx(1e-6)
    np.testing.assert_allclose(stays.z, f(np.arange(64) * 1e-6), atol=1e-12)


def test_a_matrix_with_a_number_in_its_corner_reads_its_axes_unless_it_is_a_plane(tmp_path):
    """The corner cell of a matrix with axes may hold a number (here 0): the first row and
    column are still its x and y where the heights beside them are not evenly spaced. A
    tilted plane's matrix, every row and column on a line, stays a matrix of heights."""
    x, y = np.arange(64) * 0.5, np.arange(8) * 0.5
    z = (f(x * 1e-6)[None, :] + g(y * 1e-6)[:, None]) * 1e6
    corner = tmp_path / "corner.csv"
    lines = [f"{yj:.1f}," + ",".join(f"{v:.6f}" for v in row)
             for yj, row in zip(y, z, strict=True)]
    corner.write_text("Unit,um\n0," + ",".join(f"{v:.1f}" for v in x) + "\n"
                      + "\n".join(lines) + "\n")
    reading = read_measured(corner)
    assert "corner's 0 not read" in reading.style and reading.surface.shape == (64, 8)
    np.testing.assert_allclose(reading.surface.z, z.T * 1e-6, atol=1e-12)
    plane = tmp_path / "plane.csv"
    rows = 1e-3 * np.arange(8)[:, None] + 2e-3 * np.arange(64)[None, :]
    plane.write_text("# Spacing: 0.5 um\n# Unit: um\n" + "".join(
        ",".join(f"{v:.4f}" for v in row) + "\n" for row in rows))
    flat = read_measured(plane)
    assert flat.surface.shape == (64, 8) and "one line per y" in flat.style


def test_missing_points_refused_unless_filled():
    with pytest.raises(InputError, match=r"3 of 64 points \(4.69 %\) missing"):
        read_measured(DATA / "tab_angstrom_missing.txt")


@pytest.mark.parametrize("name", sorted(REFUSED))
def test_unreadable_files_refused_with_one_line(name):
    with pytest.raises(InputError, match=REFUSED[name]) as err:
        read_measured(DATA / name)
    assert "\n" not in str(err.value)


def test_non_uniform_x_resampled_on_request():
    reading = read_measured(DATA / "uneven_x.csv", resample=True)
    p = reading.surface
    assert p.z.size == 5 and p.spacing == pytest.approx(7e-6 / 4)
    assert p.z[0] == pytest.approx(1e-6) and p.z[-1] == pytest.approx(0.0, abs=1e-15)
    assert any("cubic spline" in n for n in reading.notes)


def test_bad_unit_names_the_field():
    with pytest.raises(InputError, match="z_unit: expected a length unit"):
        read_measured(DATA / "plain_metres.txt", z_unit="furlongs per fortnight")
    with pytest.raises(InputError, match="unit: expected a length unit"):
        read_measured(DATA / "plain_metres.txt", unit="px")  # pint's px: 1/96 inch


def test_decreasing_x_is_turned_round_with_its_heights(tmp_path):
    lines = (DATA / "x_um_z_um.csv").read_text().splitlines()
    (tmp_path / "reversed.csv").write_text("\n".join([lines[0], *lines[:0:-1]]) + "\n")
    p = read_measured(tmp_path / "reversed.csv").surface
    np.testing.assert_allclose(p.z, f(np.arange(64) * 0.5e-6), atol=1e-11)
    assert p.x[0] == pytest.approx(0.0, abs=1e-12)


def test_pixel_size_of_two_numbers_gives_both_spacings(tmp_path):
    # 'Pixel size: 0.5 x 0.8 um' was read as 0.5 x 0.5 um (the second number dropped)
    i, j = np.arange(64), np.arange(8)
    z = f(i * 0.5e-6)[:, None] + g(j * 0.8e-6)[None, :]
    path = tmp_path / "pixels.txt"
    path.write_text("# X-Unit: um\n# Z-Unit: nm\n# Pixel size: 0.5 x 0.8 um\n"
                    + "\n".join(" ".join(f"{v * 1e9:.3f}" for v in row) for row in z.T) + "\n")
    t = read_measured(path).surface
    assert t.spacing == pytest.approx((0.5e-6, 0.8e-6), rel=1e-12)
    np.testing.assert_allclose(t.z, z, rtol=0, atol=1e-12)
