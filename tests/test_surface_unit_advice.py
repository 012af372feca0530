"""Files without a unit: the unit advised is the one that makes the numbers plausible, not
always um; an evaluation refused for implausible units says so first; an x read as metres for
want of a unit has a note.

References: independent numpy numbers of the surfaces written -- the rms height about the
least-squares plane and the trace's known length -- and the ISO 4288 rule that a profile must
hold two 0.08 mm cut-offs. Before, nm heights with ``--spacing "1 um"`` were advised
``--z-unit um`` (Sq 49.76 um after it), a trace in mm ``--x-unit um`` (then refused as 7.2 um
long), and a bare x (um), z (nm) profile was refused for its cut-off ('got 2000 m') alone.
"""

import json

import numpy as np
import pytest
from scipy.ndimage import gaussian_filter
from typer.testing import CliRunner

from asperity.cases import load_case
from asperity.cli import app
from asperity.errors import InputError
from asperity.runners import run_case
from asperity.surfaces.io import read_measured


def _stats(*args):
    res = CliRunner().invoke(app, ["surface", "stats", *map(str, args)])
    warnings = [line[len("warning: "):] for line in res.stderr.splitlines()
                if line.startswith("warning: ")]
    return res, warnings


def _field(shape, sigma, seed):
    z = gaussian_filter(np.random.default_rng(seed).standard_normal(shape), sigma, mode="wrap")
    return z / z.std()


def _levelled_rms(z):
    """RMS about the least-squares plane of a matrix z[iy, ix] (numpy lstsq)."""
    iy, ix = np.mgrid[: z.shape[0], : z.shape[1]]
    a = np.c_[np.ones(z.size), ix.ravel(), iy.ravel()]
    c, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
    return float(np.sqrt(np.mean((z.ravel() - a @ c) ** 2)))


@pytest.fixture
def nm_matrix(tmp_path):
    """A bare matrix of heights in nm (Sq about 50 nm, correlation a few um at 1 um)."""
    z = 50.0 * _field((99, 150), 3.0, 4)
    path = tmp_path / "nm_matrix.txt"
    np.savetxt(path, z, fmt="%.3f")
    return path, z


def test_nm_heights_are_advised_nm_and_that_advice_is_right(nm_matrix):
    path, z = nm_matrix
    res, warnings = _stats(path, "--spacing", "1 um")
    assert res.exit_code == 0, res.output
    (doubt,) = [w for w in warnings if w.startswith("heights:")]
    assert "--z-unit nm" in doubt and 'z_unit = "nm"' in doubt
    assert "--z-unit um" not in doubt
    assert not any(w.startswith("Sdq: rms slope") for w in warnings)  # said once, not twice
    res, warnings = _stats(path, "--spacing", "1 um", "--z-unit", "nm", "--json")
    assert res.exit_code == 0 and not warnings, res.output
    sq = json.loads(res.stdout)["parameters"]["height"]["Sq_m"]
    assert sq == pytest.approx(_levelled_rms(z) * 1e-9, rel=1e-6)


def test_a_case_file_is_advised_the_same_unit(nm_matrix, tmp_path):
    path, _ = nm_matrix
    case = tmp_path / "case.toml"
    case.write_text(f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path.name}"\n'
                    'spacing = "1 um"\n')
    with pytest.raises(InputError, match=r"surface.path: expected heights in metres") as err:
        run_case(load_case(case))  # refused: 316 "m" peak-to-valley
    assert 'z_unit = "nm"' in str(err.value) and 'z_unit = "um"' not in str(err.value)
    case.write_text(case.read_text() + 'z_unit = "nm"\n')
    out = run_case(load_case(case))
    assert not any("unit" in w for w in out.warnings)


@pytest.fixture
def talysurf_trace(tmp_path):
    """A bare two-column trace, x in mm (7.2 mm at 0.5 um) and heights in um, with a tilt."""
    x = np.arange(14401) * 0.5e-3
    z = 0.35 * _field(x.size, 8.0, 5) + 0.4 * np.sin(2 * np.pi * x / 2.3) + 0.75 * x + 3.0
    path = tmp_path / "taly_bare.txt"
    np.savetxt(path, np.c_[x, z], fmt="%.5f")
    return path


def test_a_trace_in_mm_and_um_is_advised_mm_and_um(talysurf_trace):
    res, warnings = _stats(talysurf_trace)
    assert res.exit_code == 0, res.output
    (x_doubt,) = [w for w in warnings if w.startswith("x:")]
    assert "length 7.2 m (limit 1 m)" in x_doubt
    assert "--x-unit mm and --z-unit um" in x_doubt and "--x-unit um" not in x_doubt
    res, warnings = _stats(talysurf_trace, "--x-unit", "mm", "--z-unit", "um", "--json")
    assert res.exit_code == 0, res.output
    assert not any(w.startswith(("x:", "heights:", "Rdq")) for w in warnings)
    # 14400 steps of 0.5 um
    assert json.loads(res.stdout)["spacing_m"] == [pytest.approx(0.5e-6, rel=1e-9)]


def test_units_given_wrong_are_named_before_the_cutoff_error(talysurf_trace):
    res, _ = _stats(talysurf_trace, "--x-unit", "um", "--z-unit", "um")
    assert res.exit_code == 2
    line = res.stderr.strip()
    assert line.startswith("error: x: length 7.2 µm (limit: at least 0.16 mm")
    assert line.index("--x-unit mm and --z-unit um") < line.index("profile: expected")


def test_a_bare_um_nm_profile_is_refused_naming_the_units_first(tmp_path):
    x = np.arange(4001) * 0.5  # um
    z = 20.0 * _field(x.size, 6.0, 2)  # nm
    path = tmp_path / "nm_profile.txt"
    np.savetxt(path, np.c_[x, z], fmt="%.4f")
    res, _ = _stats(path)
    assert res.exit_code == 2
    (line,) = res.stderr.strip().splitlines()
    assert line.startswith("error: x: length 2000 m (limit 1 m)")
    assert line.index("--x-unit um and --z-unit nm") < line.index("profile: expected")
    assert "got '2000 m'" in line
    res, warnings = _stats(path, "--x-unit", "um", "--z-unit", "nm", "--json")
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["spacing_m"] == [pytest.approx(0.5e-6, rel=1e-9)]


def test_a_matrix_with_axes_in_mm_and_no_x_unit_has_a_note_and_advice(tmp_path):
    nx, ny, d = 241, 181, 0.8e-3  # mm
    x, y = (np.arange(nx) - nx // 2) * d, np.arange(ny) * d
    z = 0.25 * _field((ny, nx), 4.0, 9)  # um
    path = tmp_path / "axes_mm.csv"
    with open(path, "w") as f:
        f.write("Height unit,um\n")
        f.write("y\\x," + ",".join(f"{v:.5f}" for v in x) + "\n")
        for yy, row in zip(y, z, strict=True):
            f.write(f"{yy:.5f}," + ",".join(f"{v:.5f}" for v in row) + "\n")
    reading = read_measured(path)
    assert reading.surface.spacing == pytest.approx((0.8e-3, 0.8e-3))  # as read: metres
    assert any(n.startswith("x read as metres: the file gives no unit") for n in reading.notes)
    (doubt,) = [w for w in reading.warnings if w.startswith("x:")]
    assert "spacing 800 µm (limit 50 um)" in doubt and "--x-unit mm" in doubt
    fixed = read_measured(path, x_unit="mm")
    assert fixed.surface.spacing == pytest.approx((0.8e-6, 0.8e-6))
    assert not fixed.warnings
    assert not any(n.startswith("x read as metres") for n in fixed.notes)


def test_a_short_trace_in_units_the_user_gave_is_not_advised_other_units(tmp_path):
    """A 100 um AFM trace at 10 nm steps, read with --x-unit um --z-unit nm as the user
    says: too short for the shortest ISO 4288 cut-off (0.16 mm), which the error says; it
    was told its units were "likely wrong" and to give --x-unit mm --z-unit um, 1000 times
    off on both axes."""
    x = np.arange(10000) * 0.01
    z = 20 * np.sin(2 * np.pi * x / 7) + np.random.default_rng(1).normal(0, 5, x.size)
    path = tmp_path / "afm.txt"
    np.savetxt(path, np.c_[x, z])
    result = CliRunner().invoke(app, ["surface", "stats", str(path), "--x-unit", "um",
                                      "--z-unit", "nm"])
    assert result.exit_code == 2
    assert "0.16 mm" in result.output and "--cutoff" in result.output
    assert "likely wrong" not in result.output and "--x-unit mm" not in result.output
