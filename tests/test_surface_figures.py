"""Figures draw what the numbers are of: masked points marked, not drawn as measured; the P and
W profiles and height map of a surface case levelled as its pq, wq, sq are.

References: numpy's least-squares line and plane (polyfit, lstsq) of the data written, and the
summary's own numbers. Before, a masked dropout was drawn as a smooth measured disc, and a
trace's 5.4 um tilt was drawn in P and W while pq_m and wq_m were of the levelled profiles.
"""

import numpy as np
import pytest
from scipy.ndimage import gaussian_filter

from asperity.cases import load_case
from asperity.plotting.surfaces import plot_texture
from asperity.runners import run_case
from asperity.surfaces import Profile, Topography
from asperity.surfaces.texture import evaluate_texture

H = 0.5e-6


def _map(nx=80, ny=60, seed=7):
    z = gaussian_filter(np.random.default_rng(seed).standard_normal((nx, ny)), 3.0)
    return (np.arange(nx) + 0.5) * H, (np.arange(ny) + 0.5) * H, 0.2e-6 * z / z.std()


def test_masked_pixels_are_grey_and_out_of_the_material_ratio_curve():
    x, y, z = _map()
    ix, iy = np.meshgrid(np.arange(x.size), np.arange(y.size), indexing="ij")
    blob = (ix - 20) ** 2 + (iy - 20) ** 2 < 10**2
    texture = evaluate_texture(Topography(x, y, z), exclude=blob)
    fig = plot_texture(texture, title="blob")
    mesh = fig.axes[0].collections[0]
    drawn = np.ma.getmaskarray(mesh.get_array()).reshape(y.size, x.size)
    np.testing.assert_array_equal(drawn, blob.T)  # the map is drawn z.T: rows along y
    assert f"grey: {blob.sum()} masked points" in fig.axes[0].get_title()
    curve = next(a for a in fig.axes if a.get_xlabel() == "material ratio (%)").get_lines()[0]
    assert curve.get_xdata().size == (~blob).sum()


def test_masked_stretches_of_a_profile_are_shaded():
    x = (np.arange(4000) + 0.5) * 1e-6
    z = 0.3e-6 * np.sin(2 * np.pi * x / 90e-6)
    lost = np.zeros(x.size, bool)
    lost[1000:1100] = lost[2500:2520] = True
    fig = plot_texture(evaluate_texture(Profile(x, z), 0.8e-3, exclude=lost), title="p")
    spans = [p for p in fig.axes[0].patches if p.get_label().startswith("masked")]
    assert len(spans) == 1  # labelled once; both stretches drawn
    assert len(fig.axes[0].patches) >= 2
    xs = spans[0].get_patch_transform().transform(spans[0].get_path().vertices)[:, 0]
    assert xs.min() == pytest.approx(x[1000] * 1e3) and xs.max() == pytest.approx(x[1099] * 1e3)


def _case(tmp_path, body):
    path = tmp_path / "case.toml"
    path.write_text('analysis = "surface"\n[surface]\nkind = "file"\n' + body)
    return run_case(load_case(path))


def test_a_surface_case_draws_p_and_w_levelled_as_its_numbers(tmp_path):
    x = np.arange(7201) * 1e-3  # mm, 1 um apart
    rng = np.random.default_rng(5)
    r = gaussian_filter(rng.standard_normal(x.size), 4.0)
    z = 0.35 * r / r.std() + 0.4 * np.sin(2 * np.pi * x / 2.3) + 0.75 * x + 3.0  # um
    np.savetxt(tmp_path / "trace.csv", np.c_[x, z], fmt="%.6f", delimiter=",",
               header="x_mm,z_um", comments="")
    out = _case(tmp_path, 'path = "trace.csv"\n[evaluation]\ncutoff = "0.8 mm"\n')
    levelled = z - np.polyval(np.polyfit(x, z, 1), x)
    assert out.summary["pq_m"] == pytest.approx(np.sqrt(np.mean(levelled**2)) * 1e-6, rel=1e-6)
    fig = out.figures["waviness"][0]()
    primary, waviness = fig.axes[0].get_lines()[:2]
    p = primary.get_ydata() * 1e-6
    assert np.std(p) == pytest.approx(out.summary["pq_m"], rel=1e-6)  # not the 5.4 um ramp
    assert np.ptp(waviness.get_ydata()) * 1e-6 == pytest.approx(out.summary["wt_m"], rel=1e-6)
    assert "least-squares line removed" in fig.axes[0].texts[0].get_text()
    profile = out.figures["profiles"][0]()
    assert np.std(profile.axes[0].get_lines()[0].get_ydata()) * 1e-6 == pytest.approx(
        out.summary["pq_m"], rel=1e-6)


def test_a_surface_case_draws_its_map_levelled(tmp_path):
    x, y, z = _map()
    tilt = z + 2e-3 * x[:, None] - 1e-3 * y[None, :]
    np.savez(tmp_path / "map.npz", x=x, y=y, z=tilt)
    out = _case(tmp_path, 'path = "map.npz"\n')
    ax = out.figures["topography"][0]().axes[0]
    drawn = np.asarray(ax.collections[0].get_array()) * 1e-6
    X, Y = np.meshgrid(x, y, indexing="ij")
    a = np.c_[np.ones(X.size), X.ravel(), Y.ravel()]
    coef, *_ = np.linalg.lstsq(a, tilt.ravel(), rcond=None)
    reference = tilt.ravel() - a @ coef
    assert np.sqrt(np.mean(drawn**2)) == pytest.approx(np.sqrt(np.mean(reference**2)),
                                                       rel=1e-9)
    assert np.sqrt(np.mean(drawn**2)) == pytest.approx(out.summary["sq_m"], rel=1e-9)
    assert "least-squares plane removed" in ax.get_title()


def test_a_masked_surface_case_draws_its_map_levelled_on_the_measured_points(tmp_path):
    """With a dropout masked, the map was drawn less the filled map's plane while sq_m is of
    the measured points' plane (rms 2.002098e-7 drawn against 2.002056e-7): the drawn
    measured pixels are now those heights, against numpy's lstsq on the measured points."""
    x, y, z = _map()
    tilt = z + 2e-3 * x[:, None] - 1e-3 * y[None, :]
    ix, iy = np.meshgrid(np.arange(x.size), np.arange(y.size), indexing="ij")
    blob = (ix - 20) ** 2 + (iy - 20) ** 2 < 12**2
    np.savez(tmp_path / "map.npz", x=x, y=y, z=np.where(blob, np.nan, tilt))
    out = _case(tmp_path, 'path = "map.npz"\nmissing = "mask"\n')
    drawn = np.ma.compressed(out.figures["topography"][0]().axes[0].collections[0].get_array())
    X, Y = np.meshgrid(x, y, indexing="ij")
    keep = ~blob
    a = np.c_[np.ones(keep.sum()), X[keep], Y[keep]]
    coef, *_ = np.linalg.lstsq(a, tilt[keep], rcond=None)
    reference = tilt[keep] - a @ coef
    rms = np.sqrt(np.mean((drawn * 1e-6) ** 2))
    assert drawn.size == keep.sum()
    assert rms == pytest.approx(np.sqrt(np.mean(reference**2)), rel=1e-9)
    assert rms == pytest.approx(out.summary["sq_m"], rel=1e-9)
