"""XYZ point lists and data lines with markers, as optical instruments export them.

A Keyence- or Zygo-style export lists one point per line, x y z, often not in raster order,
with coordinates printed to a fixed number of decimals, points the instrument lost either
marked (``No Data``) or left out. The construction is h(x, y) = 0.4 um sin(2 pi x / 5 um) +
0.15 um cos(2 pi y / 4 um) + 0.05 um * x / 10 um on 30 x 20 points 1/3 um (x) and 0.5 um (y)
apart; each file is read back to it within the printed precision (1e-4 um laterally, 1e-3 nm
in height), or refused with one line that names what to do.
"""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces.io import read_measured

NX, NY, DX, DY = 30, 20, 1e-6 / 3, 0.5e-6


def h(x, y):
    return 0.4e-6 * np.sin(2 * np.pi * x / 5e-6) + 0.15e-6 * np.cos(2 * np.pi * y / 4e-6) \
        + 0.05e-6 * x / 10e-6


def points():
    x, y = np.meshgrid(np.arange(NX) * DX, np.arange(NY) * DY, indexing="ij")
    return np.column_stack([x.ravel(), y.ravel(), h(x, y).ravel()])


def write(path, rows, head="X(um),Y(um),Z(nm)", fmt="{:.4f},{:.4f},{}"):
    lines = [head] if head else []
    lines += [fmt.format(x * 1e6, y * 1e6, z if isinstance(z, str) else f"{z * 1e9:.3f}")
              for x, y, z in rows]
    path.write_text("\n".join(lines) + "\n")
    return path


def expected():
    x, y = np.meshgrid(np.arange(NX) * DX, np.arange(NY) * DY, indexing="ij")
    return h(x, y)


def test_shuffled_points_with_rounded_coordinates_are_read(tmp_path):
    # x printed to 1e-4 um at a 1/3 um pitch: not uniform to the last digit; was refused as
    # "more than the printed precision", with --resample (a profile's option) as the advice
    rows = points()[np.random.default_rng(1).permutation(NX * NY)]
    reading = read_measured(write(tmp_path / "cloud.csv", rows))
    t = reading.surface
    assert t.shape == (NX, NY)
    assert t.spacing == pytest.approx((DX, DY), rel=3e-4)  # 0.5e-4 um of 1/3 um
    np.testing.assert_allclose(t.z, expected(), rtol=0, atol=1e-12)
    assert not reading.warnings


def test_points_left_out_of_the_list_are_missing_points(tmp_path):
    rows = points()
    gone = np.random.default_rng(2).choice(NX * NY, 9, replace=False)
    path = write(tmp_path / "holes.csv", np.delete(rows, gone, axis=0))
    with pytest.raises(InputError, match=r"9 of 600 points \(1.5 %\) missing"):
        read_measured(path)  # was: "expected x, y, z points on a full rectangular grid"
    reading = read_measured(path, missing="mask")
    lost = np.zeros(NX * NY, bool)
    lost[gone] = True
    lost = lost.reshape(NX, NY)
    np.testing.assert_array_equal(reading.missing_points, lost)
    np.testing.assert_allclose(reading.surface.z[~lost], expected()[~lost], rtol=0, atol=1e-12)
    assert "9 of the 600 grid positions absent" in reading.style


def test_a_whole_row_left_out_is_found_on_the_lattice(tmp_path):
    rows = points()
    keep = ~np.isclose(rows[:, 0], 7 * DX)  # x = 7/3 um absent altogether
    reading = read_measured(write(tmp_path / "row.csv", rows[keep]), missing="mask")
    assert reading.surface.shape == (NX, NY) and reading.missing_points[7].all()
    assert reading.missing_points.sum() == NY


def test_a_repeated_position_is_refused(tmp_path):
    rows = points()
    rows[5] = rows[6]
    with pytest.raises(InputError, match="each \\(x, y\\) position once, got '1 repeated"):
        read_measured(write(tmp_path / "twice.csv", rows))
    rows = [list(r) for r in points()]
    rows[7][0] = np.nan
    path = write(tmp_path / "nox.csv", rows, fmt="{},{:.4f},{}")
    with pytest.raises(InputError, match="an x and a y position on every line.*got '1 lines"):
        read_measured(path, missing="fill")


def test_no_data_markers_are_missing_points(tmp_path):
    # Zygo writes "No Data" (two words); the whitespace split made them two fields, and the
    # data block was taken from the last such line on: 600 points read as the 195 after it
    rows = [list(r) for r in points()]
    for k in (40, 404):
        rows[k][2] = "No Data"
    path = write(tmp_path / "zygo.xyz", rows, head="x_um y_um z_nm", fmt="{:.4f} {:.4f} {}")
    reading = read_measured(path, missing="mask")
    assert reading.surface.shape == (NX, NY) and reading.filled == 2
    lost = reading.missing_points
    np.testing.assert_allclose(reading.surface.z[~lost], expected()[~lost], rtol=0, atol=1e-12)


def test_an_unknown_marker_in_a_data_line_is_refused_not_cut(tmp_path):
    rows = [list(r) for r in points()]
    rows[404][2] = "NoValue"
    path = write(tmp_path / "marker.xyz", rows, head="x_um y_um z_nm", fmt="{:.4f} {:.4f} {}")
    with pytest.raises(InputError, match=r"marker\.xyz:406: expected numbers or a "
                                         r"missing-value marker .* got 'NoValue'"):
        read_measured(path)
    profile = tmp_path / "profile.txt"  # a two-column trace cut the same way
    profile.write_text("x_um z_um\n0 0.1\n0.5 0.2\n1.0 n.m.\n1.5 0.1\n2.0 0.3\n2.5 0.2\n")
    with pytest.raises(InputError, match=r"profile\.txt:4: .* got 'n\.m\.'"):
        read_measured(profile)


def test_a_header_line_starting_with_a_number_is_still_header(tmp_path):
    path = tmp_path / "count.txt"
    path.write_text("Talysurf export\n6 points\n0 0.1\n0.5 0.2\n1.0 0.3\n1.5 0.1\n2.0 0.3\n"
                    "2.5 0.2\n")
    assert read_measured(path).surface.z.size == 6


def test_three_unnamed_columns_of_points_are_refused(tmp_path):
    # pixel indices and heights, as Zygo's XYZ export: read as a height matrix 3 points wide
    # (3 x 600) once a spacing was given
    i, j = np.meshgrid(np.arange(NX), np.arange(NY), indexing="ij")
    lines = [f"{a} {b} {h(a * DX, b * DY) * 1e6:.6f}" for a, b in zip(i.ravel(), j.ravel(),
                                                                        strict=True)]
    path = tmp_path / "indices.xyz"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"these 3 columns are points \(30 x by 20 y values"):
        read_measured(path, spacing=0.5e-6)


@pytest.mark.parametrize("along", ["x", "y"])
def test_a_line_profile_exported_as_points_is_a_profile(tmp_path, along):
    # a line scan written as x, y, z with y (or x) the same on every line was refused as
    # "2000 points over 2000 x and 1 y values"
    s = np.arange(200) * 0.5e-6
    rows = [(a, 12.5e-6, h(a, 0.0)) if along == "x" else (3e-3, a, h(a, 0.0)) for a in s]
    head = "X(um),Y(um),Z(nm)" if along == "x" else "X(mm),Y(um),Z(nm)"  # x's unit not y's
    reading = read_measured(write(tmp_path / "line.csv", rows, head, fmt="{:.3f},{:.3f},{}"))
    p = reading.surface
    assert p.z.ndim == 1 and p.spacing == pytest.approx(0.5e-6, rel=1e-9)
    np.testing.assert_allclose(p.z, h(s, 0.0), rtol=0, atol=1e-12)
    assert f"a profile along '{along.upper()}(um)'" in reading.style


def test_named_pixel_indices_are_not_told_to_give_a_unit(tmp_path):
    # "X Y Z" columns of pixel indices read as a 30 m field: the warning said --x-unit um,
    # which would make them 1 um pixels whatever the pixel size
    i, j = np.meshgrid(np.arange(NX), np.arange(NY), indexing="ij")
    lines = ["X Y Z"] + [f"{a} {b} {h(a * DX, b * DY) * 1e6:.6f}"
                         for a, b in zip(i.ravel(), j.ravel(), strict=True)]
    path = tmp_path / "indices.xyz"
    path.write_text("\n".join(lines) + "\n")
    warnings = read_measured(path).warnings
    assert any("pixel indices?" in w and "x_um y_um z_um" in w for w in warnings)
    assert not any("--x-unit um" in w for w in warnings)
