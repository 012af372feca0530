"""asperity's readers and parameters against SurfaceTopography on small instrument files.

The files are written here by SurfaceTopography's own writers (x3p, Gwyddion .gwy, NetCDF, its
text matrix) from a Gaussian surface with 18 of 3072 pixels (0.6 %) undefined, and a NetCDF
line scan with 7 of 200 points undefined, then read by both packages. Missing pixels: both
fill them by the same harmonic interpolation (Laplace's equation with the measured pixels as
boundary values), so the filled heights must agree to solver precision; parameters are
compared on the filled, plane-levelled surface. A headerless height matrix is read in the
same orientation (one line per y).
Skipped when SurfaceTopography is not installed.
"""

import warnings

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import Topography, gaussian_topography, roughness_parameters
from asperity.surfaces.io import read_measured

st = pytest.importorskip("SurfaceTopography")
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

SIZE = (64e-6, 48e-6)


@pytest.fixture(scope="module")
def holed(tmp_path_factory):
    t = gaussian_topography(SIZE, 1e-6, 0.3e-6, 6e-6, seed=4)
    mask = np.zeros(t.z.shape, bool)
    mask.flat[np.random.default_rng(0).choice(t.z.size, 15, replace=False)] = True
    mask[10, 10:13] = True  # a small hole of three neighbours too
    topo = st.Topography(np.ma.masked_array(t.z, mask=mask), SIZE, unit="m", periodic=False)
    folder = tmp_path_factory.mktemp("instrument")
    files = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for suffix, write in ((".x3p", topo.to_x3p), (".gwy", topo.to_gwy),
                              (".nc", topo.to_netcdf), (".txt", topo.to_matrix)):
            files[suffix] = folder / f"holed{suffix}"
            write(str(files[suffix]))
    return topo, mask, files


@pytest.mark.parametrize("suffix", [".x3p", ".gwy", ".nc", ".txt"])
def test_missing_pixels_filled_as_surface_topography_fills_them(holed, suffix):
    topo, mask, files = holed
    with pytest.raises(InputError, match=rf"{mask.sum()} of 3072 points .* missing"):
        read_measured(files[suffix])
    reading = read_measured(files[suffix], missing="fill")
    assert reading.filled == mask.sum()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = st.read_topography(str(files[suffix])).interpolate_undefined_data()
        reference = np.asarray(theirs.heights())
    mine = reading.surface
    assert isinstance(mine, Topography) and mine.shape == reference.shape
    assert mine.spacing == pytest.approx(theirs.pixel_size, rel=1e-9)
    np.testing.assert_allclose(mine.z, reference, rtol=0, atol=1e-9 * np.ptp(reference))


def test_parameters_of_the_filled_surface_agree(holed):
    _, _, files = holed
    mine = read_measured(files[".x3p"], missing="fill").surface
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = st.read_topography(str(files[".x3p"])).interpolate_undefined_data().detrend(
            "height")
        sq, sdq = theirs.rms_height_from_area(), theirs.rms_gradient()
    params = roughness_parameters(mine)
    assert params["Sq"] == pytest.approx(sq, rel=1e-9)
    assert params["Sdq"] == pytest.approx(sdq, rel=1e-9)


def test_profile_with_missing_points(tmp_path):
    # In 1-D the harmonic fill is linear interpolation (constant past the ends): asperity's
    # linear fill must equal SurfaceTopography's, and Rq, Rdq of the levelled profiles agree.
    x = np.arange(200)
    mask = np.zeros(200, bool)
    mask[[0, 1, 50, 51, 52, 120, 199]] = True
    heights = np.ma.masked_array(1e-6 * np.sin(x / 7.0) + 0.2e-6 * np.cos(x / 2.3), mask=mask)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st.UniformLineScan(heights, 200e-6, unit="m", periodic=False).to_netcdf(
            str(tmp_path / "line.nc"))
        theirs = st.read_topography(str(tmp_path / "line.nc")).interpolate_undefined_data()
        reference = np.asarray(theirs.heights())
        levelled = theirs.detrend("height")
        rq, rdq = levelled.rms_height_from_profile(), levelled.rms_slope_from_profile()
    reading = read_measured(tmp_path / "line.nc", missing="fill")
    assert reading.filled == 7
    np.testing.assert_allclose(reading.surface.z, reference, rtol=0, atol=1e-15)
    params = roughness_parameters(reading.surface)
    assert params["Rq"] == pytest.approx(rq, rel=1e-9)
    assert params["Rdq"] == pytest.approx(rdq, rel=1e-9)


def test_headerless_matrix_has_the_orientation_surface_topography_gives_it(tmp_path):
    matrix = tmp_path / "m.asc"
    matrix.write_text("1 2 3 13\n4 5 6 14\n7 8 9 15\n")
    mine = read_measured(matrix, spacing=1e-6, z_unit="um").surface
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = st.read_topography(str(matrix), physical_sizes=(4.0, 3.0), unit="um")
    np.testing.assert_array_equal(mine.z, 1e-6 * np.asarray(theirs.heights()))
