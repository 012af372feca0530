"""Masked missing points: the height parameters are of the measured points, from their own mean
plane (ISO 25178-2), not of the filled map's.

Reference: an independent numpy computation -- the least-squares plane (line) fitted to the
measured points only by ``numpy.linalg.lstsq`` (``numpy.polyfit``), subtracted, and the moments
of the measured residuals about their mean. The fill (harmonic over a blob) is smooth and tilts
the filled map's plane; taken with it, Ssk of this map was 0.4812 and Sp 0.6547 um against
0.4585 and 0.6521 um.
"""

import json

import numpy as np
import pytest
from scipy.ndimage import gaussian_filter
from typer.testing import CliRunner

from asperity.cli import app
from asperity.surfaces import Profile
from asperity.surfaces.io import read_measured
from asperity.surfaces.profiles import profile_families
from asperity.surfaces.texture import evaluate_texture

NX, NY, D = 120, 100, 0.5e-6


def _map_with_blob():
    """Heights z[iy, ix] (rows along y, as a Gwyddion export writes them), a tilt, and a
    dropout blob of 8 % of the points."""
    rng = np.random.default_rng(7)
    z = gaussian_filter(rng.standard_normal((NY, NX)), 3.0, mode="wrap")
    z = 0.2e-6 * z / z.std()
    iy, ix = np.mgrid[:NY, :NX]
    z += 2e-9 * ix - 1e-9 * iy  # a tilt of a few nm a pixel
    blob = (ix - 30) ** 2 + (iy - 30) ** 2 < 18**2
    return z, blob


def _reference(z, blob):
    """Sa, Sq, Ssk, Sku, Sp, Sv of the measured points about their own plane."""
    iy, ix = np.mgrid[:NY, :NX]
    m = ~blob
    a = np.c_[np.ones(m.sum()), (ix[m] + 0.5) * D, (iy[m] + 0.5) * D]
    c, *_ = np.linalg.lstsq(a, z[m], rcond=None)
    r = z[m] - a @ c
    r = r - r.mean()
    sq = np.sqrt(np.mean(r**2))
    return {"Sa": np.mean(np.abs(r)), "Sq": sq, "Ssk": np.mean(r**3) / sq**3,
            "Sku": np.mean(r**4) / sq**4, "Sp": r.max(), "Sv": -r.min()}


def _write(path, z, blob):
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"# Channel: Height\n# Width: {NX * D * 1e6:.3f} µm\n"
                f"# Height: {NY * D * 1e6:.3f} µm\n# Value units: m\n")
        for row, lost in zip(z, blob, strict=True):
            f.write("\t".join("nan" if k else f"{v:.9e}" for v, k in zip(row, lost,
                                                                          strict=True)) + "\n")
    return path


def test_masked_map_heights_are_of_the_measured_points_plane(tmp_path):
    z, blob = _map_with_blob()
    path = _write(tmp_path / "blob.txt", z, blob)
    ref = _reference(z, blob)
    result = CliRunner().invoke(app, ["surface", "stats", str(path), "--missing", "mask",
                                      "--json"])
    assert result.exit_code == 0, result.output
    height = json.loads(result.stdout)["parameters"]["height"]
    for key, value in ref.items():
        got = height[key + "_m"] if key in ("Sa", "Sq", "Sp", "Sv") else height[key]
        assert got == pytest.approx(value, rel=1e-6, abs=1e-15), key
    # the filled map's plane is a different reference: the test tells the two apart
    filled = read_measured(path, missing="fill").surface
    old = evaluate_texture(filled).groups["height"]
    assert abs(old["Ssk"] - ref["Ssk"]) > 100 * 1e-6 * abs(ref["Ssk"])


def test_masked_map_says_which_parameters_use_the_filled_map(tmp_path):
    z, blob = _map_with_blob()
    reading = read_measured(_write(tmp_path / "blob.txt", z, blob), missing="mask")
    texture = evaluate_texture(reading.surface, exclude=reading.excluded)
    assert any("fitted to the 10995 measured points" in n for n in texture.notes)
    assert any(n.startswith("Sdq, Sdr, Sal, Str and Std need the whole grid") and
               "1005 masked points filled" in n for n in texture.notes)


def test_masked_profile_mean_line_is_fitted_to_the_measured_points():
    x = (np.arange(2000) + 0.5) * 1e-6
    rng = np.random.default_rng(3)
    z = 0.3e-6 * gaussian_filter(rng.standard_normal(x.size), 4.0) / 0.1 + 2e-4 * x
    lost = np.zeros(x.size, bool)
    lost[100:400] = True
    z[lost] = z[lost] + 1e-6  # what a fill might put there: it must not move the mean line
    fam = profile_families(Profile(x, z), 0.25e-3, lambda_s=None, exclude=lost)
    line = np.polyval(np.polyfit(x[~lost], z[~lost], 1), x)
    assert np.allclose(fam.primary.z, z - line, rtol=0, atol=1e-15)


def test_a_masked_surface_runs_headline_heights_are_of_the_measured_points(tmp_path):
    """An ``analysis = "surface"`` case of the map: its sa_m ... sv_m keys were of the filled
    map (Ssk 0.4812); they are now those of the measured points, as the iso_* keys are."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    z, blob = _map_with_blob()
    path = _write(tmp_path / "blob.txt", z, blob)
    ref = _reference(z, blob)
    case = load_case(f'analysis = "surface"\ntitle = "blob"\n[surface]\nkind = "file"\n'
                     f'path = "{path}"\nmissing = "mask"\n')
    summary = run_case(case, workdir=tmp_path / "out").summary
    for key, value in ref.items():
        got = summary[key.lower() + "_m"] if key in ("Sa", "Sq", "Sp", "Sv") \
            else summary[key.lower()]
        assert got == pytest.approx(value, rel=1e-6, abs=1e-15), key
