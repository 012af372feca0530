"""A header's spacing with a decimal comma, and doubts on a spacing the user gave."""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces.io import read_measured

HEIGHTS = np.random.default_rng(5).normal(size=(12, 10)) * 0.3  # um, [ix, iy]


def _matrix(path, header, sep=";", decimal=".", heights=HEIGHTS):
    """A height matrix, one line per y, with ``header`` lines above it."""
    lines = [sep.join(f"{v:.5f}".replace(".", decimal) for v in heights[:, j])
             for j in range(heights.shape[1])]
    path.write_text("".join(f"{h}\n" for h in header) + "\n".join(lines) + "\n",
                    encoding="utf-8")
    return path


def _rms_slope(z, dx, dy):
    """RMS slope of ``z[ix, iy]`` less its least-squares plane, by forward differences."""
    i, j = np.meshgrid(np.arange(z.shape[0]), np.arange(z.shape[1]), indexing="ij")
    design = np.column_stack([np.ones(z.size), i.ravel(), j.ravel()])
    level = z - (design @ np.linalg.lstsq(design, z.ravel(), rcond=None)[0]).reshape(z.shape)
    gx, gy = np.diff(level, axis=0) / dx, np.diff(level, axis=1) / dy
    return float(np.sqrt(np.mean(gx**2) + np.mean(gy**2)))


@pytest.mark.parametrize(("written", "spacing"), [("1,5 µm", 1.5e-6), ("2,25 µm", 2.25e-6),
                                                  ("0,5 µm", 0.5e-6),
                                                  ("0,5 µm x 0,5 µm", 0.5e-6)])
def test_a_decimal_comma_in_the_header_of_decimal_comma_data_is_a_decimal(tmp_path, written,
                                                                         spacing):
    path = _matrix(tmp_path / "eu.csv", [f"Pixel size: {written}", "Z unit: µm"],
                   decimal=",")
    reading = read_measured(path)
    np.testing.assert_allclose(reading.surface.spacing, (spacing, spacing), rtol=1e-12)
    np.testing.assert_allclose(reading.surface.z, HEIGHTS * 1e-6, rtol=0, atol=5.1e-12)
    assert any("decimal comma" in n and written in n for n in reading.notes)
    assert not any("spacing" in w for w in reading.warnings)


def test_the_same_map_reads_alike_with_decimal_points(tmp_path):
    comma = read_measured(_matrix(tmp_path / "eu.csv", ["Pixel size: 1,5 µm", "Z unit: µm"],
                                  decimal=","))
    point = read_measured(_matrix(tmp_path / "pt.csv", ["Pixel size: 1.5 µm", "Z unit: µm"]))
    np.testing.assert_array_equal(comma.surface.x, point.surface.x)
    np.testing.assert_array_equal(comma.surface.y, point.surface.y)
    np.testing.assert_array_equal(comma.surface.z, point.surface.z)


def test_a_tab_matrix_with_missing_points_reads_its_decimal_comma_spacing(tmp_path):
    heights = HEIGHTS.copy()
    heights[3, 4] = np.nan
    path = tmp_path / "tab.txt"
    lines = ["\t".join("NaN" if np.isnan(v) else f"{v:.5f}".replace(".", ",")
                       for v in heights[:, j]) for j in range(heights.shape[1])]
    path.write_text("# Spacing: 0,5 um\n# Z unit: µm\n" + "\n".join(lines) + "\n",
                    encoding="utf-8")
    reading = read_measured(path, missing="mask")
    np.testing.assert_allclose(reading.surface.spacing, (0.5e-6, 0.5e-6), rtol=1e-12)
    assert reading.excluded[3, 4] and reading.excluded.sum() == 1


def test_a_comma_pair_over_decimal_point_data_is_x_and_y_with_a_warning(tmp_path):
    path = _matrix(tmp_path / "pt.csv", ["Pixel size: 1,5 µm", "Z unit: µm"])
    reading = read_measured(path)
    np.testing.assert_allclose(reading.surface.spacing, (1e-6, 5e-6), rtol=1e-12)
    (warning,) = [w for w in reading.warnings if w.startswith("spacing")]
    assert "'pixel size' (1,5 µm)" in warning and "x 1 um, y 5 um" in warning
    assert '--spacing "1.5 um"' in warning


def test_a_spacing_given_as_the_decimal_reading_is_not_warned(tmp_path):
    path = _matrix(tmp_path / "pt.csv", ["Pixel size: 1,5 µm", "Z unit: µm"])
    reading = read_measured(path, 1.5e-6)
    np.testing.assert_allclose(reading.surface.spacing, (1.5e-6, 1.5e-6), rtol=1e-12)
    assert not any("spacing" in w for w in reading.warnings)
    assert any("decimal comma (1.5 um)" in n for n in reading.notes)


def test_a_comma_that_makes_no_pair_is_a_decimal_with_a_note(tmp_path):
    matrix = read_measured(_matrix(tmp_path / "pt.csv", ["Pixel size: 0,5 µm", "Z unit: µm"]))
    np.testing.assert_allclose(matrix.surface.spacing, (0.5e-6, 0.5e-6), rtol=1e-12)
    assert any("decimal comma (0.5 um)" in n for n in matrix.notes)
    path = tmp_path / "profile.txt"
    path.write_text("# Spacing: 2,5 um\n# Z unit: um\n"
                    + "\n".join(f"{v:.4f}" for v in HEIGHTS.ravel()) + "\n", encoding="utf-8")
    profile = read_measured(path)
    assert profile.surface.spacing == pytest.approx(2.5e-6, rel=1e-12)
    assert any("decimal comma (2.5 um)" in n for n in profile.notes)


def test_a_comma_and_space_pair_and_a_unit_on_each_number_are_x_and_y(tmp_path):
    pair = read_measured(_matrix(tmp_path / "a.csv", ["Pixel size: 0.5, 0.8 um", "Z unit: um"]))
    each = read_measured(_matrix(tmp_path / "b.csv", ["Pixel size: 0.5 µm x 0.8 µm",
                                                     "Z unit: um"]))
    for reading in (pair, each):
        np.testing.assert_allclose(reading.surface.spacing, (0.5e-6, 0.8e-6), rtol=1e-12)
        assert not any("spacing" in w for w in reading.warnings)


def test_a_spacing_error_from_the_header_quotes_its_line(tmp_path):
    path = _matrix(tmp_path / "zero.csv", ["Pixel size: 0 µm", "Z unit: µm"])
    with pytest.raises(InputError, match="pixel size: 0 µm"):
        read_measured(path)


@pytest.fixture
def nm_pixels(tmp_path):
    """A map of Sq 0.3 um in metres, saved without its spacing (0.5 um, read as 0.5 nm)."""
    i, j = np.meshgrid(np.arange(64), np.arange(48), indexing="ij")
    z = 0.3e-6 * (np.sin(2 * np.pi * i / 32) + np.cos(2 * np.pi * j / 24 + 0.3))
    z += 2e-3 * 0.5e-6 * i
    np.save(tmp_path / "map.npy", z)
    return tmp_path / "map.npy", z


def test_an_implausible_given_spacing_is_named_with_the_one_that_fits(nm_pixels):
    path, z = nm_pixels
    assert _rms_slope(z, 0.5e-9, 0.5e-9) > 1 > _rms_slope(z, 0.5e-6, 0.5e-6)
    reading = read_measured(path, 0.5e-9)
    (warning,) = reading.warnings
    assert "spacing as given (0.5 nm)" in warning
    assert warning.index('--spacing "0.5 um"') < warning.index("--z-unit mm")
    assert reading.unit_advice.startswith("the spacing given (0.5 nm) may be wrong")


def test_the_slope_warning_names_the_given_spacing_too(nm_pixels):
    path, z = nm_pixels
    reading = read_measured(path, 0.5e-9, z_unit="m")
    assert reading.warnings == () and reading.unit_advice == ""
    (warning,) = reading.slope_warnings("Sdq", _rms_slope(z, 0.5e-9, 0.5e-9))
    assert '--spacing "0.5 um"' in warning and "--x-unit" not in warning
    assert read_measured(path, 0.5e-6, z_unit="m").slope_warnings(
        "Sdq", _rms_slope(z, 0.5e-6, 0.5e-6)) == ()


def test_an_x_unit_with_a_given_spacing_is_noted_as_ignored(nm_pixels, tmp_path):
    path, _ = nm_pixels
    reading = read_measured(path, 0.5e-6, x_unit="mm")
    np.testing.assert_allclose(reading.surface.spacing, (0.5e-6, 0.5e-6), rtol=1e-12)
    assert any(n.startswith("x_unit 'mm' ignored") for n in reading.notes)
    text = read_measured(_matrix(tmp_path / "m.csv", ["Z unit: um"]), 0.5e-6, x_unit="mm")
    np.testing.assert_allclose(text.surface.spacing, (0.5e-6, 0.5e-6), rtol=1e-12)
    assert any(n.startswith("x_unit 'mm' ignored") for n in text.notes)
    assert not any("x_unit" in n for n in read_measured(path, 0.5e-6).notes)
