"""Reading files lets no library warning through, and refuses what it cannot read as heights.

A NetCDF file read through SurfaceTopography printed scipy's 'Cannot close a netcdf_file opened
with mmap=True' as a warning line; a complex .npy was read with numpy's 'Casting complex values
to real discards the imaginary part' and evaluated. References: the heights written.
"""

import gc
import warnings

import numpy as np
import pytest
from typer.testing import CliRunner

from asperity.cli import app
from asperity.errors import InputError
from asperity.surfaces.io import read_measured


def test_a_netcdf_file_is_read_without_a_warning(tmp_path):
    st = pytest.importorskip("SurfaceTopography")
    z = np.random.default_rng(1).normal(size=(40, 30)) * 0.2  # um
    path = tmp_path / "map.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st.Topography(z, (20.0, 15.0), unit="um").to_netcdf(str(path))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        reading = read_measured(path)
        gc.collect()  # scipy warned when the memory-mapped file was let go
    assert not [w for w in caught if "netcdf" in str(w.message).lower()]
    np.testing.assert_allclose(reading.surface.z, z * 1e-6, rtol=1e-12)
    res = CliRunner().invoke(app, ["surface", "stats", str(path)])
    assert res.exit_code == 0, res.output
    assert "mmap" not in res.stderr


def test_a_complex_npy_is_refused_in_one_line(tmp_path):
    path = tmp_path / "complex.npy"
    np.save(path, np.random.default_rng(1).normal(size=(50, 50)) + 1j)
    with pytest.raises(InputError, match=r"expected real heights.*complex128"):
        read_measured(path, 0.5e-6)
    res = CliRunner().invoke(app, ["surface", "stats", str(path), "--spacing", "0.5 um"])
    assert res.exit_code == 2
    (line,) = res.stderr.strip().splitlines()
    assert line.startswith(f"error: {path}: expected real heights")
    assert "casting" not in res.output.lower()


def test_a_real_npy_is_still_read(tmp_path):
    path = tmp_path / "real.npy"
    z = np.random.default_rng(2).normal(size=(20, 20)).astype(np.float32) * 1e-7
    np.save(path, z)
    np.testing.assert_allclose(read_measured(path, 1e-6).surface.z, z.astype(float))
