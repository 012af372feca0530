"""Reading and writing surfaces: round trips, formats, error messages; SurfaceTopography."""

import sys

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import (
    Profile,
    Topography,
    gaussian_profile,
    gaussian_topography,
    read_measured,
    read_surface,
    residual_heights,
    roughness_parameters,
    write_surface,
)


@pytest.fixture
def profile():
    return gaussian_profile(0.2e-3, 0.5e-6, 0.3e-6, 5e-6, seed=2)


@pytest.fixture
def topography():
    return gaussian_topography((60e-6, 40e-6), (1e-6, 2e-6), 0.3e-6, 8e-6, seed=2)


@pytest.mark.parametrize("suffix", [".txt", ".csv", ".dat", ".npz"])
def test_round_trip_keeps_everything(tmp_path, profile, topography, suffix):
    for surface in (profile, topography):
        path = write_surface(surface, tmp_path / f"s{suffix}")
        back = read_surface(path)
        assert type(back) is type(surface) and back.periodic == surface.periodic
        np.testing.assert_array_equal(back.z, surface.z)
        np.testing.assert_allclose(back.x, surface.x, rtol=1e-12)
        if isinstance(surface, Topography):
            np.testing.assert_allclose(back.y, surface.y, rtol=1e-12)


def test_npy_keeps_heights_and_needs_a_spacing(tmp_path, profile, topography):
    write_surface(profile, tmp_path / "p.npy")
    with pytest.raises(InputError, match="spacing: expected a grid spacing"):
        read_surface(tmp_path / "p.npy")
    matrix = tmp_path / "vk.csv"  # a spacing under a key the reader does not know
    matrix.write_text('"XY calibration","500.0","nm/pixel"\n"Height"\n1,2,3,4\n2,3,4,1\n')
    with pytest.raises(InputError, match=r'no spacing or size in a header .* --spacing "0.5 um"'):
        read_surface(matrix)  # was: "expected a grid spacing (m)", not saying how to give one
    back = read_surface(tmp_path / "p.npy", spacing=profile.spacing)
    np.testing.assert_allclose(back.x, profile.x, rtol=1e-12)
    write_surface(topography, tmp_path / "t.npy")
    back = read_surface(tmp_path / "t.npy", spacing=topography.spacing)
    assert back.spacing == pytest.approx(topography.spacing)


def test_text_variants(tmp_path):
    one = tmp_path / "z.txt"
    one.write_text("height\n1e-6\n2e-6\n-1e-6\n0.5e-6\n")
    p = read_surface(one, spacing=2e-6)
    assert isinstance(p, Profile) and p.z.tolist() == [1e-6, 2e-6, -1e-6, 0.5e-6]
    assert p.x.tolist() == pytest.approx([1e-6, 3e-6, 5e-6, 7e-6])
    two = tmp_path / "xz.csv"
    two.write_text("x;z\n0;1e-6\n1e-6;2e-6\n2e-6;0\n")
    assert read_surface(two).spacing == pytest.approx(1e-6)
    matrix = tmp_path / "m.asc"  # one line per y, as instruments write images
    matrix.write_text("1 2 3\n4 5 6\n7 8 9\n10 11 12\n")
    t = read_surface(matrix, spacing=(1e-6, 3e-6))
    assert isinstance(t, Topography) and t.shape == (3, 4) and t.z[2, 1] == 6


def test_text_errors_name_the_file_and_line(tmp_path):
    ragged = tmp_path / "ragged.txt"
    ragged.write_text("# a comment\n0 1\n1 2\n2 3 4\n")
    with pytest.raises(InputError, match=r"ragged\.txt:4: expected 2 columns like line 2"):
        read_surface(ragged)
    words = tmp_path / "words.csv"
    words.write_text("x,z\n0,1\n1,abc\n")
    with pytest.raises(InputError, match=r"words\.csv:3: expected numbers only, got 'abc'"):
        read_surface(words)
    nan = tmp_path / "nan.txt"
    nan.write_text("0 1\n1 nan\n")
    with pytest.raises(InputError, match=r"nan\.txt: expected no missing points.*1 of 2 points"):
        read_surface(nan)
    uneven = tmp_path / "uneven.txt"
    uneven.write_text("0 1\n1 2\n3 3\n")
    with pytest.raises(InputError, match="x: expected uniformly spaced"):
        read_surface(uneven)
    with pytest.raises(InputError, match="file: expected an existing file"):
        read_surface(tmp_path / "missing.txt")
    with pytest.raises(InputError, match="path"):
        write_surface(Profile(np.arange(3.0), np.zeros(3)), tmp_path / "p.abc")


def test_decimal_commas_with_a_comma_separator_are_refused(tmp_path):
    """A European export whose separator is the comma too: the header names 2 columns and each
    line has 4 fields. Read as a 4-column height matrix it came out as a surface with Sa of
    14.8 km; it is refused, saying why and how to export instead. The same numbers with ';'
    read."""
    bad = tmp_path / "euro.csv"
    bad.write_text("x_mm,z_um\n0,0000,2,90296\n0,0005,2,86233\n0,0010,2,82629\n")
    with pytest.raises(InputError, match=r"euro\.csv: expected one field per column.*"
                                         r"2 names.*4 fields.*decimal commas.*';'"):
        read_surface(bad)
    good = tmp_path / "euro-semicolon.csv"
    good.write_text("x_mm;z_um\n0,0000;2,90296\n0,0005;2,86233\n0,0010;2,82629\n")
    p = read_surface(good)
    assert p.z == pytest.approx([2.90296e-6, 2.86233e-6, 2.82629e-6])
    assert p.spacing == pytest.approx(0.5e-6)


def test_instrument_formats_need_surface_topography(tmp_path, monkeypatch):
    (tmp_path / "scan.x3p").write_bytes(b"PK")
    monkeypatch.setitem(sys.modules, "SurfaceTopography", None)  # import fails
    with pytest.raises(InputError, match=r"SurfaceTopography reader: pip install "
                                         r"'asperity\[instruments\]'"):
        read_surface(tmp_path / "scan.x3p")


# --- cross-check against SurfaceTopography (optional peer) ---------------------------------


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # SurfaceTopography's own aliases
def test_parameters_agree_with_surface_topography(profile, topography):
    st = pytest.importorskip("SurfaceTopography")
    # Same data: the heights after asperity's mean-line/plane removal, non-periodic; and the
    # periodic surfaces as generated.
    r = residual_heights(profile.z)
    mine = roughness_parameters(r, profile.x)
    line = st.UniformLineScan(r, profile.length, periodic=False)
    assert mine["Rq"] == pytest.approx(line.rms_height_from_profile(), rel=1e-6)
    assert mine["Rdq"] == pytest.approx(line.rms_slope_from_profile(), rel=1e-6)
    periodic_line = st.UniformLineScan(profile.z, profile.length, periodic=True)
    assert roughness_parameters(profile)["Rdq"] == pytest.approx(
        periodic_line.rms_slope_from_profile(), rel=1e-6)
    (nx, ny), (dx, dy) = topography.shape, topography.spacing
    rz = residual_heights(topography.z)
    mine2 = roughness_parameters(rz, topography.x, topography.y)
    area = st.Topography(rz, (nx * dx, ny * dy), periodic=False)
    assert mine2["Sq"] == pytest.approx(area.rms_height_from_area(), rel=1e-6)
    assert mine2["Sdq"] == pytest.approx(area.rms_gradient(), rel=1e-6)
    periodic_area = st.Topography(topography.z, (nx * dx, ny * dy), periodic=True)
    assert roughness_parameters(topography)["Sdq"] == pytest.approx(
        periodic_area.rms_gradient(), rel=1e-6)


def test_reads_x3p_through_surface_topography(tmp_path, topography):
    st = pytest.importorskip("SurfaceTopography")
    (nx, ny), (dx, dy) = topography.shape, topography.spacing
    st.Topography(topography.z, (nx * dx, ny * dy), unit="m").to_x3p(tmp_path / "scan.x3p")
    back = read_surface(tmp_path / "scan.x3p")
    assert isinstance(back, Topography) and back.shape == topography.shape
    np.testing.assert_allclose(back.z, topography.z, rtol=1e-6, atol=1e-6 * 0.3e-6)
    assert back.spacing == pytest.approx(topography.spacing, rel=1e-9)


def _map_file(tmp_path, z_um, name="map.txt"):
    """A profiler's areal export: pixel size and height unit in the header, a line per y."""
    path = tmp_path / name
    np.savetxt(path, z_um.T, header="Pixel size: 1 um\nZ unit: um", comments="# ")
    return path


def test_heights_read_1000_times_too_small_are_doubted(tmp_path):
    """A map in um (Sq 0.3 um, rms slope about 0.05) given z_unit = nm: Sq 0.3 nm and a slope
    a thousand times too small, flatter than any machined surface, so the reading doubts the
    unit; read as it says, the same map is not doubted, nor is a superfinished one (Sq 20 nm,
    slope about 0.004)."""
    from asperity.surfaces import read_measured, rms_gradient

    rough = gaussian_topography((64e-6, 64e-6), (1e-6, 1e-6), 0.3e-6, 8e-6, seed=3)
    path = _map_file(tmp_path, rough.z * 1e6)
    wrong = read_measured(path, z_unit="nm")
    name, slope = rms_gradient(wrong.surface)
    assert slope == pytest.approx(rms_gradient(rough)[1] * 1e-3, rel=1e-3) and slope < 1e-3
    doubt = wrong.slope_warnings(name, slope)
    assert len(doubt) == 1 and "flatter than machined surfaces" in doubt[0]
    assert "z_unit" in doubt[0]
    right = read_measured(path)
    assert right.slope_warnings(*rms_gradient(right.surface)) == ()
    fine = gaussian_topography((64e-6, 64e-6), (1e-6, 1e-6), 20e-9, 8e-6, seed=3)
    smooth = read_measured(_map_file(tmp_path, fine.z * 1e6, "fine.txt"))
    assert rms_gradient(smooth.surface)[1] > 1e-3
    assert smooth.slope_warnings(*rms_gradient(smooth.surface)) == ()


def test_a_spacing_given_over_the_headers_is_warned(tmp_path):
    """A spacing given for a file whose header has its own pixel size replaces it, with a
    warning naming both (a user's 2 um over 1 um doubled the map's size in silence); the
    same spacing as the header's is quiet."""
    from asperity.surfaces import read_measured

    rough = gaussian_topography((32e-6, 32e-6), (1e-6, 1e-6), 0.3e-6, 8e-6, seed=3)
    path = _map_file(tmp_path, rough.z * 1e6)
    given = read_measured(path, spacing=2e-6)
    assert given.surface.spacing == pytest.approx((2e-6, 2e-6))
    assert [w for w in given.warnings if w.startswith(
        "spacing: the spacing given (2 um) replaces the header's (1 um)")]
    assert not [w for w in read_measured(path, spacing=1e-6).warnings
                if w.startswith("spacing")]


def test_one_spacing_given_over_a_headers_dx_and_dy_is_warned(tmp_path):
    """One spacing given for a file whose header gives dx and dy (``Pixel size: 0.5 x 0.8
    um``) replaces both, with the warning naming the header's two; it was a traceback."""
    from asperity.surfaces import read_measured

    path = tmp_path / "map.txt"
    path.write_text("# Pixel size: 0.5 x 0.8 um\n# Z unit: um\n"
                    + "\n".join(" ".join(f"{0.1 * np.sin(i + 2 * j):.4f}" for i in range(6))
                                for j in range(5)) + "\n")
    given = read_measured(path, spacing=0.6e-6)
    assert given.surface.spacing == pytest.approx((0.6e-6, 0.6e-6))
    assert [w for w in given.warnings if w.startswith(
        "spacing: the spacing given (0.6 um, 0.6 um) replaces the header's (0.5 um, 0.8 um)")]
    assert read_measured(path).surface.spacing == pytest.approx((0.5e-6, 0.8e-6))


@pytest.mark.parametrize("head", ["Distance,Height\nmm,um\n", "Distance,Height\n[mm],(um)\n",
                                  "mm,um\n", "# probe: 2 um tip\n# Distance Height\n# mm um\n"])
def test_a_line_of_units_under_the_names_gives_the_units(tmp_path, head):
    """A line of units under (or instead of) the column names, as spreadsheets and several
    instruments export them: the x in mm and the heights in um were read as metres (a
    0.3 um sine as 0.3 m, with warnings naming --x-unit um)."""
    from asperity.surfaces import read_measured

    x = np.arange(400) * 0.5e-6
    z = 0.3e-6 * np.sin(2 * np.pi * x / 40e-6)
    sep = " " if head.startswith("#") else ","
    lines = [f"{a * 1e3:.4f}{sep}{b * 1e6:.5f}" for a, b in zip(x, z, strict=True)]
    path = tmp_path / "trace.csv"
    path.write_text(head + "\n".join(lines) + "\n")
    reading = read_measured(path)
    assert not reading.warnings
    assert reading.surface.spacing == pytest.approx(0.5e-6, rel=1e-6)
    np.testing.assert_allclose(reading.surface.z, z, rtol=0, atol=1e-11)


def test_a_line_of_units_under_xyz_names_gives_each_its_unit(tmp_path):
    """``X Y Z`` then ``um um nm``: a point list with nm heights (it was refused as unnamed
    points, the units line taken for the names)."""
    from asperity.surfaces import read_measured

    col, row = np.meshgrid(np.arange(12), np.arange(8), indexing="ij")
    z = 20.0 * np.sin(col + 2 * row)  # nm
    lines = [f"{0.5 * i:.2f}\t{0.5 * j:.2f}\t{v:.4f}"
             for i, j, v in zip(col.ravel(), row.ravel(), z.ravel(), strict=True)]
    path = tmp_path / "map.txt"
    path.write_text("X\tY\tZ\nµm\tµm\tnm\n" + "\n".join(lines) + "\n")
    reading = read_measured(path)
    assert reading.surface.spacing == pytest.approx((0.5e-6, 0.5e-6))
    np.testing.assert_allclose(reading.surface.z, z * 1e-9, rtol=0, atol=1e-13)


def test_results_after_the_data_are_a_footer(tmp_path):
    """Results appended after the data (``"Ra","0.0376","um"``), as stylus exports write them,
    are a footer; they were refused as a data line with a word. A data line with a word is
    still refused, naming its line."""
    from asperity.surfaces import read_measured

    x = np.arange(200) * 0.5
    z = 0.2 * np.sin(2 * np.pi * x / 30.0)
    body = "".join(f'"{a:.2f}","{b:.5f}"\n' for a, b in zip(x, z, strict=True))
    path = tmp_path / "sj.csv"
    path.write_text('"X(um)","Z(um)"\n' + body + '"Ra","0.127","um"\n"Rz","0.62","um"\n'
                    '"Judgement","OK"\n')
    reading = read_measured(path)
    np.testing.assert_allclose(reading.surface.z, z * 1e-6, rtol=0, atol=1e-11)
    path.write_text('"X(um)","Z(um)"\n' + body + '"100.00","NoValue"\n')
    with pytest.raises(InputError, match=r"sj\.csv:202: expected numbers only, got 'NoValue'"):
        read_measured(path)


def test_a_users_npz_in_um_takes_the_units_given_and_is_doubted_without_them(tmp_path):
    """A user's own .npz (x, y, z in um, as their numpy wrote it): x_unit and z_unit were
    ignored without a word, and read as metres the 50 um map was 50 m long with 0.6 m
    heights, silently. The units given apply; without them the units are doubted, with the
    units that make it plausible."""
    x, y = np.arange(100) * 0.5, np.arange(80) * 0.5
    z = 0.3 * np.sin(x[:, None] / 3) * np.cos(y[None, :] / 4)
    np.savez(tmp_path / "um.npz", x=x, y=y, z=z)
    read = read_measured(tmp_path / "um.npz", x_unit="um", z_unit="um")
    assert read.surface.spacing == pytest.approx((0.5e-6, 0.5e-6), rel=1e-12)
    assert np.ptp(read.surface.z) == pytest.approx(np.ptp(z) * 1e-6, rel=1e-12)
    assert read.warnings == ()
    doubted = read_measured(tmp_path / "um.npz")
    assert doubted.warnings and "--x-unit um and --z-unit um" in doubted.warnings[0]
