"""Maps too small for a parameter to mean anything: Sal, Str, Std and the material-ratio and
volume parameters are left out (n/a) with a warning, and the figure says why its panels are
thin; the height parameters stay, with the standard errors of Ssk and Sku named.

References: numpy's rms about the least-squares plane (Sq) and the standard errors
sqrt(6 / n), sqrt(24 / n) of the sample skewness and kurtosis of n Gaussian values. A 5 x 5
map was given Sal 0.29 um, Str 82 %, Std 0 deg and a full Sk table without a word; the PSD
panel of a 3 x 50 map (one wavevector) was empty.
"""

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from asperity.cli import app
from asperity.plotting.surfaces import plot_texture
from asperity.surfaces import Topography
from asperity.surfaces.texture import evaluate_texture


def _write(path, z, d=0.5):
    """A Gwyddion-style matrix of heights in nm, z[iy, ix]."""
    ny, nx = z.shape
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"# Width: {nx * d:g} µm\n# Height: {ny * d:g} µm\n# Value units: nm\n")
        for row in z:
            f.write(" ".join(f"{v:.4f}" for v in row) + "\n")
    return path


def _levelled_rms(z):
    iy, ix = np.mgrid[: z.shape[0], : z.shape[1]]
    a = np.c_[np.ones(z.size), ix.ravel(), iy.ravel()]
    c, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
    return float(np.sqrt(np.mean((z.ravel() - a @ c) ** 2)))


@pytest.mark.parametrize("nx, ny", [(5, 5), (3, 50), (50, 3)])
def test_a_tiny_map_leaves_the_spatial_and_material_ratio_parameters_out(tmp_path, nx, ny):
    z = np.random.default_rng(2).normal(size=(ny, nx)) * 100  # nm
    res = CliRunner().invoke(app, ["surface", "stats", str(_write(tmp_path / "m.txt", z)),
                                   "--json"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.stdout)
    groups = out["parameters"]
    assert all(groups["spatial"][k] is None for k in ("Sal_m", "Str", "Std_deg"))
    assert all(v is None for k, v in groups["functional"].items() if k != "title")
    assert all(v is None for k, v in groups["volume"].items() if k != "title")
    assert groups["height"]["Sq_m"] == pytest.approx(_levelled_rms(z) * 1e-9, rel=1e-9)
    (grid,) = [w for w in out["warnings"] if w.startswith("grid:")]
    n = nx * ny
    assert f"the {nx} x {ny} map ({n} points evaluated) is too small" in grid
    assert f"{math.sqrt(6 / n):.2g} and {math.sqrt(24 / n):.2g}" in grid


def test_a_map_large_enough_has_them_and_no_warning():
    h = 0.5e-6
    x = (np.arange(16) + 0.5) * h
    z = 0.1e-6 * np.random.default_rng(3).normal(size=(16, 16))
    texture = evaluate_texture(Topography(x, x, z))
    assert not any(w.startswith("grid:") for w in texture.warnings)
    assert np.isfinite(texture.groups["spatial"]["Std"])
    assert np.isfinite(texture.groups["volume"]["Vmc"])


def test_the_figure_of_a_thin_map_draws_its_spectrum_and_keeps_its_colour_bar_clear():
    h = 0.5e-6
    x, y = (np.arange(3) + 0.5) * h, (np.arange(50) + 0.5) * h
    z = 0.1e-6 * np.random.default_rng(4).normal(size=(3, 50))
    fig = plot_texture(evaluate_texture(Topography(x, y, z)), title="thin")
    surface_ax = fig.axes[0]
    psd_ax = next(a for a in fig.axes if a.get_title().startswith("Power spectral"))
    (line,) = psd_ax.get_lines()
    assert line.get_xdata().size == 1 and line.get_marker() == "o"  # a point, not an empty line
    assert any("too small for a spectrum" in t.get_text() for t in psd_ax.texts)
    # 25 um tall, 1.5 um wide: drawn at most 5 times taller than wide, and says so
    assert "compressed 3.3 times" in surface_ax.get_ylabel()
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    map_box = surface_ax.get_window_extent(renderer)
    bar = surface_ax.collections[0].colorbar.ax
    label = bar.yaxis.label.get_window_extent(renderer)
    assert label.x0 > map_box.x1 and bar.get_window_extent(renderer).x0 >= map_box.x1
    titles = [a.get_title() for a in fig.axes]
    assert any(t.startswith("S-F: 150 points, too few for the Sk construction") for t in titles)


def test_the_figure_of_a_wide_strip_is_stretched_and_says_so():
    """50 x 3 points of 0.5 um: 25 um wide, 1.5 um tall, 16.7 times wider than tall; drawn to
    scale the strip was a line. Drawn 5 times wider than tall: y stretched 16.7 / 5 = 3.3
    times, its page aspect (y unit over x unit) 3.33."""
    h = 0.5e-6
    x, y = (np.arange(50) + 0.5) * h, (np.arange(3) + 0.5) * h
    z = 0.1e-6 * np.random.default_rng(5).normal(size=(50, 3))
    fig = plot_texture(evaluate_texture(Topography(x, y, z)), title="strip")
    surface_ax = fig.axes[0]
    assert "stretched 3.3 times" in surface_ax.get_ylabel()
    assert surface_ax.get_aspect() == pytest.approx(25.0 / 1.5 / 5.0, rel=1e-9)
