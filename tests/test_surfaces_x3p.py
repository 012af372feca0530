"""An ISO 25178-72 .x3p built by hand, as an instrument's exporter writes one.

The file is a zip of main.xml and bindata/data.bin (int32 counts, x fastest, with the z axis's
Increment and Offset) and bindata/valid.bin (one bit per point, least significant first,
1 = valid), 120 x 80 points 0.5 um (x) by 0.8 um (y) apart, of an asymmetric surface: grooves
across x, a bump at (45 um, 10 um) and a tilt along x, with 7 points invalid. Read through
SurfaceTopography, its heights must be the counts times the increment plus the offset, at the
right [ix, iy], and the invalid points exactly the ones marked. An exporter that wrote the
increments in um where the format has metres (a 64 m field of 0.5 m pixels) was read without
a word; it warns now, naming --spacing, which replaces the pixel size.
Skipped when SurfaceTopography is not installed.
"""

import hashlib
import zipfile

import numpy as np
import pytest

from asperity.surfaces.io import read_measured

pytest.importorskip("SurfaceTopography")
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

NX, NY, DX, DY = 120, 80, 0.5e-6, 0.8e-6
INCREMENT, OFFSET = 1e-9, 5e-6


def surface():
    x, y = np.meshgrid(np.arange(NX) * DX, np.arange(NY) * DY, indexing="ij")
    return (0.3e-6 * np.sin(2 * np.pi * x / 12e-6)
            + 1e-6 * np.exp(-((x - 45e-6) ** 2 + (y - 10e-6) ** 2) / (3e-6) ** 2) + 2e-3 * x)


def write_x3p(path, dx=DX, dy=DY):
    counts = np.round((surface() - OFFSET) / INCREMENT).astype("<i4")
    invalid = np.zeros((NX, NY), bool)
    invalid[10:13, 50] = True
    invalid[100, 5:9] = True
    data = counts.T.tobytes()  # ISO 5436-2: x varies fastest
    valid = np.packbits((~invalid).T.reshape(-1), bitorder="little").tobytes()
    axis = "<AxisType>I</AxisType><DataType>D</DataType><Increment>{:.15e}</Increment>"
    xml = ('<?xml version="1.0" encoding="UTF-8"?>'
           '<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2"><Record1>'
           '<Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>'
           f'<CX>{axis.format(dx)}</CX><CY>{axis.format(dy)}</CY>'
           '<CZ><AxisType>A</AxisType><DataType>L</DataType>'
           f'<Increment>{INCREMENT:.15e}</Increment><Offset>{OFFSET:.15e}</Offset></CZ>'
           '</Axes></Record1><Record3><MatrixDimension>'
           f'<SizeX>{NX}</SizeX><SizeY>{NY}</SizeY><SizeZ>1</SizeZ></MatrixDimension>'
           '<DataLink><PointDataLink>bindata/data.bin</PointDataLink>'
           f'<MD5ChecksumPointData>{hashlib.md5(data).hexdigest()}</MD5ChecksumPointData>'
           '<ValidPointsLink>bindata/valid.bin</ValidPointsLink></DataLink></Record3>'
           '</p:ISO5436_2>')
    with zipfile.ZipFile(path, "w") as zf:
        zf.writestr("main.xml", xml)
        zf.writestr("bindata/data.bin", data)
        zf.writestr("bindata/valid.bin", valid)
    return counts * INCREMENT + OFFSET, invalid


def test_hand_built_x3p_reads_in_place_with_its_invalid_points(tmp_path):
    heights, invalid = write_x3p(tmp_path / "map.x3p")
    reading = read_measured(tmp_path / "map.x3p", missing="mask")
    t = reading.surface
    assert t.shape == (NX, NY) and t.spacing == pytest.approx((DX, DY), rel=1e-12)
    np.testing.assert_array_equal(reading.missing_points, invalid)
    np.testing.assert_allclose(t.z[~invalid], heights[~invalid], rtol=0, atol=1e-18)
    bump = np.unravel_index(np.argmax(t.z - 2e-3 * t.x[:, None]), t.shape)
    assert (t.x[bump[0]], t.y[bump[1]]) == pytest.approx((45.25e-6, 10.4e-6), abs=0.5e-6)
    assert not reading.warnings


def test_pixel_size_in_the_wrong_unit_warns_and_spacing_replaces_it(tmp_path):
    write_x3p(tmp_path / "um.x3p", dx=DX * 1e6, dy=DY * 1e6)  # "0.5" meant as um
    reading = read_measured(tmp_path / "um.x3p", missing="fill")
    assert reading.surface.spacing == pytest.approx((0.5, 0.8))
    assert len(reading.warnings) == 1
    assert "length 64 m exceeds 1 m" in reading.warnings[0]
    assert '--spacing "0.5 um"' in reading.warnings[0]
    fixed = read_measured(tmp_path / "um.x3p", (DX, DY), missing="fill")
    assert fixed.surface.spacing == pytest.approx((DX, DY), rel=1e-12)
    assert not any("exceeds" in w for w in fixed.warnings)
    assert any("replaces the header's" in w for w in fixed.warnings)


def test_a_unit_given_for_an_x3p_is_ignored_with_a_warning(tmp_path):
    heights, invalid = write_x3p(tmp_path / "map.x3p")
    reading = read_measured(tmp_path / "map.x3p", z_unit="nm", missing="fill")
    np.testing.assert_allclose(reading.surface.z[~invalid], heights[~invalid], atol=1e-18)
    assert any(w.startswith("units: the file's own unit (m") for w in reading.warnings)
