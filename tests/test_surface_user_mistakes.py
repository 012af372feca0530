"""Mistakes a user trial made with ``asperity surface stats`` and ``analysis = "surface"``:
each gives one clear error, or a warning that says what to change, never a silent answer.

References: Rdq of a sine a sin(2 pi x / lam) is a (2 pi / lam) / sqrt 2 and its Ra 2 a / pi;
the ISO 16610-21 Gaussian weighting function has variance sigma^2 = (alpha lambda_c)^2 / (2 pi),
so the mean line of a parabola -x^2 / (2 rho) lies sigma^2 / (2 rho) below it; ISO 3274 Table 1
allows lambda_s = 2.5 um at lambda_c = 0.8 mm only for spacings up to 0.5 um; ISO 25178-2 Sal
is the lag at which the ACF falls to 0.2 (here along x, interpolated between grid lags).
"""

import json
import math
import re

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from asperity.cases import load_case
from asperity.cli.surface import surface_app
from asperity.errors import InputError
from asperity.runners import run_case
from asperity.surfaces import Topography, autocorrelation_length, read_measured
from asperity.surfaces.areal import areal_families, areal_parameters

app = typer.Typer()
app.add_typer(surface_app, name="surface")
runner = CliRunner()
ALPHA = math.sqrt(math.log(2) / math.pi)  # ISO 16610-21 eq. (1)
H = 0.5e-6


def _export(path, x_mm, z_um, header="X (mm)\tZ (um)"):
    """A Talysurf-like two-column export: x printed in mm, heights in um."""
    lines = [header] + [f"{x:.6f}\t{z:.5f}" for x, z in zip(x_mm, z_um, strict=True)]
    path.write_text("\n".join(lines) + "\n")
    return path


def _stats(*args):
    res = runner.invoke(app, ["surface", "stats", *map(str, args)])
    return res, [line.removeprefix("warning: ") for line in res.stderr.splitlines()
                 if line.startswith("warning: ")]


def _sine(n, a_um, lam_m, h=H):
    x = np.arange(n) * h
    return x, a_um * np.sin(2 * np.pi * x / lam_m)


def test_heights_in_nm_read_as_um_warn_on_the_slope(tmp_path):
    a, lam = 0.3e-6, 50e-6
    x, z = _sine(11200, a * 1e6, lam)
    path = _export(tmp_path / "nm_as_um.txt", x * 1e3, z * 1e3)  # nm under a 'Z (um)' header
    res, warnings = _stats(path, "--json")
    assert res.exit_code == 0, res.output
    slope = [w for w in warnings if w.startswith("Rdq: rms slope")]
    assert len(slope) == 1, warnings
    assert "--z-unit nm" in slope[0] and "the column name 'Z (um)'" in slope[0]
    res, warnings = _stats(path, "--json", "--z-unit", "nm")
    assert not any("rms slope" in w for w in warnings)
    rdq = json.loads(res.stdout)["parameters"]["R"]["Rdq"]
    assert rdq == pytest.approx(a * 2 * np.pi / lam / math.sqrt(2), rel=0.01)


def test_steep_topography_warns_on_sdq(tmp_path):
    h, lam, a = 1e-6, 16e-6, 5e-6  # Sdq = a (2 pi / lam) / sqrt 2 = 1.39
    x1 = (np.arange(64) + 0.5) * h
    z = np.repeat(a * np.sin(2 * np.pi * x1 / lam)[:, None], 48, axis=1)
    path = tmp_path / "steep.txt"
    np.savetxt(path, z.T * 1e6, fmt="%.6f", header="Value units: um\nWidth: 64 um")
    res, warnings = _stats(path, "--json")
    sdq = json.loads(res.stdout)["parameters"]["hybrid"]["Sdq"]
    assert sdq == pytest.approx(a * 2 * np.pi / lam / math.sqrt(2), rel=0.02)
    (line,) = [w for w in warnings if "rms slope" in w]
    assert line.startswith("Sdq: rms slope") and "--z-unit nm" in line
    assert "the header's 'value units' entry" in line


def test_x_in_um_under_a_mm_header_warns_about_the_length_not_the_trace(tmp_path):
    x, z = _sine(11200, 0.3, 50e-6)
    path = _export(tmp_path / "x_um.txt", x * 1e6, z)  # um written under 'X (mm)': 5.6 m
    res, warnings = _stats(path)
    assert res.exit_code == 0, res.output
    length = [w for w in warnings if w.startswith("x: length 5.6 m")]
    assert len(length) == 1 and "the column name 'X (mm)'" in length[0]
    assert "--x-unit um" in length[0]
    assert not any("longer trace" in w for w in warnings)
    cutoff = next(w for w in warnings if w.startswith("lambda_c"))
    assert "spacing (500 um) is too coarse" in cutoff


@pytest.mark.parametrize("rows, cols", [(192, 256), (4800, 1)])
def test_a_bare_spacing_of_one_is_refused_for_areas_as_for_profiles(tmp_path, rows, cols):
    path = tmp_path / "heights.txt"
    z = np.random.default_rng(0).normal(size=(rows, cols)) * 0.2
    np.savetxt(path, z, fmt="%.5f", header="Value units: um")
    res, _ = _stats(path, "--spacing", "1")
    assert res.exit_code == 2
    (line,) = res.stderr.splitlines()
    assert line.startswith("error: spacing: expected a grid spacing of at most 4 mm")
    assert line.endswith("got '1 m'") and '--spacing "1 um"' in line
    res, _ = _stats(path, "--spacing", "1 um", "--cutoff", "0.8 mm" if cols == 1 else "0.1 mm")
    assert res.exit_code == 0, res.output


def test_three_unnamed_columns_of_a_profile_export_are_refused_with_the_fix(tmp_path):
    x, z = _sine(4800, 0.3, 50e-6, h=1e-6)
    rows = [f"{a:.4f} {b:.4f} {0.9 * b:.4f}" for a, b in zip(x * 1e3, z, strict=True)]
    path = tmp_path / "three.txt"
    path.write_text("\n".join(rows) + "\n")
    res, _ = _stats(path, "--spacing", "1 um", "--unit", "um")  # the earlier hint
    assert res.exit_code == 2
    (line,) = res.stderr.splitlines()
    assert "profile export" in line and "'x_mm z_um z2_um'" in line
    path.write_text("x_mm z_um z2_um\n" + path.read_text())  # the fix the error names
    reading = read_measured(path)
    assert reading.surface.z.ndim == 1 and reading.surface.spacing == pytest.approx(1e-6)


def _cylinder(tmp_path, rho=5e-3, a=0.3e-6, lam=50e-6):
    """A 2.4 mm trace across a roller of radius rho, with sine roughness."""
    x = np.arange(4800) * H
    z = -((x - x.mean()) ** 2) / (2 * rho) + a * np.sin(2 * np.pi * x / lam)
    return _export(tmp_path / "cylinder.csv", x * 1e3, z * 1e6)


def test_form_left_in_warns_and_names_the_radius_and_the_fix(tmp_path):
    rho, a = 5e-3, 0.3e-6
    path = _cylinder(tmp_path, rho, a)
    res, warnings = _stats(path, "--json")
    form = [w for w in warnings if w.startswith("form:")]
    assert len(form) == 1 and warnings[0] == form[0]  # first, before the ISO 4288 length one
    assert "--form-degree 2" in form[0] and "evaluation.form_degree = 2" in form[0]
    sigma2 = (ALPHA * 0.8e-3) ** 2 / (2 * math.pi)
    mean = float(re.search(r"evaluation length is ([-\d.]+) um", form[0]).group(1)) * 1e-6
    assert mean == pytest.approx(sigma2 / (2 * rho), rel=0.02)  # 2.25 um
    radius = float(re.search(r"about ([\d.]+) mm radius", form[0]).group(1)) * 1e-3
    assert radius == pytest.approx(rho, rel=0.02)
    res, warnings = _stats(path, "--json", "--form-degree", "2")
    assert not any(w.startswith("form") for w in warnings)
    ra = json.loads(res.stdout)["parameters"]["R"]["Ra_m"]
    assert ra == pytest.approx(2 * a / math.pi, rel=0.02)


def test_form_degree_of_a_surface_case_removes_the_form(tmp_path):
    path = _cylinder(tmp_path)
    text = f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path}"\n'
    assert any(w.startswith("form:") for w in run_case(load_case(text)).warnings)
    out = run_case(load_case(text + "[evaluation]\nform_degree = 2\n"))
    assert not any(w.startswith("form:") for w in out.warnings)
    assert out.summary["ra_m"] == pytest.approx(2 * 0.3e-6 / math.pi, rel=0.02)


@pytest.mark.parametrize("spacing, coarse", [(2e-6, True), (0.5e-6, False)])
def test_sampling_coarser_than_iso_3274_warns(tmp_path, spacing, coarse):
    n = int(5.6e-3 / spacing)
    x, z = _sine(n, 0.6, 200e-6, h=spacing)  # Ra = 0.38 um: lambda_c 0.8 mm
    res, warnings = _stats(_export(tmp_path / "p.txt", x * 1e3, z), "--json")
    assert json.loads(res.stdout)["filters"]["cutoff_m"] == pytest.approx(0.8e-3)
    sampling = [w for w in warnings if w.startswith("sampling:")]
    assert bool(sampling) == coarse
    if coarse:
        assert "0.5 um ISO 3274 allows" in sampling[0] and "--spacing" in sampling[0]
        assert "Rdq" in sampling[0] and "RSm" in sampling[0]


def test_sal_is_interpolated_between_lags():
    rng = np.random.default_rng(5)
    n, h = 128, 2e-6
    k = np.fft.rfftfreq(n, h)
    f = np.fft.irfft(np.exp(-(np.pi * k * 8e-6) ** 2 / 4)
                     * (rng.normal(size=k.size) + 1j * rng.normal(size=k.size)), n)
    x1 = (np.arange(n) + 0.5) * h
    y1 = (np.arange(48) + 0.5) * h
    # grooves along y, periodic: the circular ACF is acf_x(tx) at every ty, so the fastest
    # decay is along x
    surface = Topography(x1, y1, np.repeat(f[:, None], 48, axis=1), periodic=True)
    r = f - f.mean()
    acf = np.array([np.sum(r * np.roll(r, -j)) for j in range(n // 2)]) / np.sum(r * r)
    k0 = int(np.argmax(acf <= 0.2))
    expected = h * (k0 - 1 + (acf[k0 - 1] - 0.2) / (acf[k0 - 1] - acf[k0]))
    assert autocorrelation_length(surface) == pytest.approx(expected, rel=1e-6)
    sal = areal_parameters(areal_families(surface))["spatial"]["Sal"]
    assert sal == pytest.approx(expected, rel=1e-6)
    assert abs(sal / h - round(sal / h)) > 0.01  # not a whole lag


def test_a_surface_case_headlines_the_iso_ra_as_surface_stats_does(tmp_path):
    a = 0.5e-6
    x = np.arange(11200) * H
    z = a * np.sin(2 * np.pi * x / 50e-6) + 1e-6 * np.sin(2 * np.pi * x / 8e-3)  # + waviness
    path = _export(tmp_path / "wavy.txt", x * 1e3, z * 1e6)
    out = run_case(load_case(f'analysis = "surface"\n[surface]\nkind = "file"\n'
                             f'path = "{path}"\n'))
    stats = json.loads(_stats(path, "--json")[0].stdout)
    assert out.summary["ra_m"] == stats["parameters"]["R"]["Ra_m"] == out.summary["iso_ra_m"]
    assert out.summary["ra_m"] == pytest.approx(2 * a / math.pi, rel=0.02)
    assert any("as asperity surface stats gives them" in n for n in out.notes)


def test_small_messages_show_units_and_plain_numbers(tmp_path):
    x, z = _sine(11200, 0.6, 200e-6)
    path = _export(tmp_path / "p.txt", x * 1e3, z)
    res, _ = _stats(path, "--cutoff", "0.8")
    (line,) = res.stderr.splitlines()
    assert line.endswith("got '0.8 m'") and "a plain number is metres" in line
    heights = tmp_path / "h.txt"
    heights.write_text("1\n2\n3\n")
    with pytest.raises(InputError, match=r"spacing: expected a finite number > 0, got -1e-06$"):
        read_measured(heights, -1e-6)
    stats = json.loads(_stats(path, "--json")[0].stdout)
    chosen = next(n for n in stats["notes"] if "chosen by ISO 4288" in n)
    ra = float(re.search(r"Ra = ([\d.]+) um", chosen).group(1))
    assert ra == float(f"{stats['parameters']['R']['Ra_m'] * 1e6:.4g}")


def test_a_spacing_the_file_does_not_use_is_said(tmp_path):
    x, z = _sine(4000, 0.3, 50e-6)
    path = _export(tmp_path / "p.txt", x * 1e3, z)
    reading = read_measured(path, 2e-6)
    assert reading.surface.spacing == pytest.approx(H)
    assert any(w.startswith("spacing: the spacing given (2e-06 m) is not used")
               for w in reading.warnings)
    assert not read_measured(path, H).warnings
