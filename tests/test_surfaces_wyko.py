"""Wyko / Veeco / Bruker Vision ASCII exports, written by hand in the layout Gwyddion's opd.c
reads: ``X Size`` lines of ``Y Size`` values, one line per x, its values from the largest y
down; ``Pixel_size`` in mm, ``Wavelength`` in nm; values in nm (flag 1) or in waves over
``Mult`` (flag 0); ``Bad`` pixels.

The generic text reader took the block table's ``Pixel_size 7 4 0.00164`` for three spacings:
refused naming ``spacing`` (which the user had not given), and with ``--spacing`` a traceback.
"""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces.io import read_measured

NX, NY, PIXEL_MM, ASPECT = 7, 5, 0.00164, 1.25


def values():
    """Line i (x index i), value k: an asymmetric ramp, 10 i + k (+ a bump at line 2, value 1)."""
    v = 10.0 * np.arange(NX)[:, None] + np.arange(NY)[None, :]
    v[2, 1] += 100.0
    return v


def write(path, in_nm=1, mult=2.0, intensity=False, bad=(4, 3)):
    v = values()
    lines = [f"Wyko ASCII Data File Format 0\t{in_nm}\t1", f"X Size\t{NX}", f"Y Size\t{NY}",
             "Block Name\tType\tLength\tValue", "Title\t5\t10\tbore",
             f"Pixel_size\t7\t4\t{PIXEL_MM}", "Wavelength\t7\t4\t632.8", f"Mult\t7\t4\t{mult}",
             f"Aspect\t7\t4\t{ASPECT}"]
    if intensity:
        lines.append(f"Intensity\t3\t{2 * NX * NY}\t")
        lines += ["\t".join(["999"] * NY) for _ in range(NX)]
    lines.append(f"RAW_DATA\t3\t{4 * NX * NY}\t")
    for i in range(NX):
        lines.append("\t".join("Bad" if (i, k) == bad else f"{v[i, k]:g}" for k in range(NY)))
    path.write_text("\n".join(lines) + "\n")
    return v


@pytest.mark.parametrize("in_nm, factor", [(1, 1e-9), (0, 632.8e-9 / 2.0)])
def test_values_are_read_per_line_along_x_from_the_largest_y(tmp_path, in_nm, factor):
    v = write(tmp_path / "scan.asc", in_nm=in_nm, intensity=True)
    reading = read_measured(tmp_path / "scan.asc", missing="mask")
    z, lost = reading.surface.z, reading.missing_points
    assert z.shape == (NX, NY)
    assert np.allclose(reading.surface.spacing, (PIXEL_MM * 1e-3, PIXEL_MM * 1e-3 * ASPECT))
    expected = v[:, ::-1] * factor  # value k of a line lies at y index NY - 1 - k
    assert lost[4, NY - 1 - 3] and int(lost.sum()) == 1
    assert np.allclose(z[~lost], expected[~lost], rtol=1e-12, atol=0)
    assert np.unravel_index(np.argmax(z - 10 * factor * np.arange(NX)[:, None]), z.shape) == (
        2, NY - 1 - 1)


def test_a_spacing_given_replaces_the_pixel_size_with_a_warning(tmp_path):
    write(tmp_path / "scan.asc")
    reading = read_measured(tmp_path / "scan.asc", spacing=2e-6, missing="fill")
    assert np.allclose(reading.surface.spacing, 2e-6)
    assert any("replaces the header's" in w for w in reading.warnings)


def test_a_short_data_line_is_refused_naming_it(tmp_path):
    write(tmp_path / "scan.asc")
    text = (tmp_path / "scan.asc").read_text().replace("\t34\n", "\n")
    (tmp_path / "scan.asc").write_text(text)
    with pytest.raises(InputError, match=r"scan.asc: line 14: expected Y Size = 5 values"):
        read_measured(tmp_path / "scan.asc", missing="fill")


@pytest.mark.parametrize("spacing", [None, 1e-6])
def test_a_header_spacing_of_three_numbers_is_one_line_naming_it(tmp_path, spacing):
    (tmp_path / "m.txt").write_text("# Pixel size: 7 4 0.00164 mm\n1 2 3 4\n5 6 7 8\n9 10 11 12\n")
    with pytest.raises(InputError, match=r"^.*m.txt: header 'pixel size': expected one "
                                         r"spacing, or two"):
        read_measured(tmp_path / "m.txt", spacing=spacing)


def test_heights_agree_with_surfacetopography(tmp_path):
    st = pytest.importorskip("SurfaceTopography")
    write(tmp_path / "scan.asc", in_nm=0, bad=(-1, -1))
    ours = read_measured(tmp_path / "scan.asc").surface
    theirs = st.read_topography(str(tmp_path / "scan.asc"))
    factor = st.Support.UnitConversion.get_unit_conversion_factor(theirs.unit, "m")
    assert np.allclose(np.sort(ours.z.ravel()), np.sort(np.ravel(theirs.heights()) * factor),
                       rtol=1e-12, atol=0)
    assert np.isclose(ours.x[1] - ours.x[0], theirs.physical_sizes[1] * factor / NX)
