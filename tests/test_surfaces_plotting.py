"""Surface figures: the traces drawn are the data, in mm and um."""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.plotting.surfaces import plot_profiles, plot_surface, plot_turning_roughness
from asperity.surfaces import builtin_profile, roughness_along, turned_profile_dynamic


def test_profiles_are_stacked_in_um():
    profiles = {name: builtin_profile(name, length=0.2e-3, spacing=1e-6) for name in "ABC"}
    fig = plot_profiles(profiles, offset=2e-6)
    lines = fig.axes[0].get_lines()
    assert len(lines) == 3
    np.testing.assert_allclose(lines[1].get_xdata(), profiles["B"].x * 1e3)
    np.testing.assert_allclose(lines[1].get_ydata(), (profiles["B"].z - 2e-6) * 1e6)
    with pytest.raises(InputError, match="surface"):
        plot_surface(np.zeros(3))


def test_turning_roughness_figure():
    res = turned_profile_dynamic(0.127e-3, 0.794e-3, 0.305e-3, 61 / 60, 0.05, 5e-3, 1e-6, 28.0,
                                 mass=250.0)
    fig = plot_turning_roughness([res], 5 * 0.127e-3, labels=["28 Hz"])
    centres, rt = roughness_along(res.profile, 5 * 0.127e-3)
    line = fig.axes[0].get_lines()[0]
    np.testing.assert_allclose(line.get_ydata(), rt * 1e6)
    np.testing.assert_allclose(line.get_xdata(), centres * 1e3)


def test_material_ratio_figure_draws_the_curve_and_the_line():
    from asperity.plotting.surfaces import plot_material_ratio

    z = np.random.default_rng(0).permutation(np.linspace(1e-6, -1e-6, 1000))  # C = 1 - 2 mr
    ax = plot_material_ratio(z).axes[0]
    curve, line = ax.get_lines()[:2]
    np.testing.assert_allclose(curve.get_xdata(), (np.arange(1000) + 0.5) / 10)
    np.testing.assert_allclose(curve.get_ydata(), np.linspace(1, -1, 1000))
    # the equivalent line of a straight curve is the curve: 1 um at 0 %, -1 um at 100 %
    np.testing.assert_allclose(line.get_ydata(), [1.0, -1.0], atol=2e-3)


def test_texture_figure_of_a_profile_has_its_families():
    from asperity.plotting.surfaces import plot_texture
    from asperity.surfaces import evaluate_texture, gaussian_profile

    texture = evaluate_texture(gaussian_profile(4e-3, 1e-6, 0.4e-6, 10e-6, seed=1), 0.8e-3)
    fig = plot_texture(texture, title="t")
    assert len(fig.axes) == 4  # P with W, R, spectrum, material ratio
    np.testing.assert_allclose(fig.axes[1].get_lines()[0].get_ydata(),
                               texture.families.roughness.z * 1e6)


def _labels_overlap(fig, axis) -> bool:
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in axis.get_ticklabels(which="both")
             if t.get_visible() and t.get_text()]
    boxes.sort(key=lambda b: b.x0)
    return any(a.x1 > b.x0 for a, b in zip(boxes, boxes[1:], strict=False))


def test_texture_figure_of_a_small_map_is_in_um_with_its_colour_bar_beside_it():
    # a 60 x 64 um field of view: its axes read 0.00 ... 0.06 mm, the map sat at the right of
    # an empty half-row with the colour bar at the far edge, and the PSD's q labels (1.5
    # decades) were drawn over each other
    from asperity.plotting.surfaces import plot_texture
    from asperity.surfaces import Topography, evaluate_texture

    x, y = (np.arange(120) + 0.5) * 0.5e-6, (np.arange(80) + 0.5) * 0.8e-6
    z = 0.3e-6 * np.sin(2 * np.pi * x / 12e-6)[:, None] + 0.05e-6 * np.random.default_rng(
        3).standard_normal((120, 80))
    fig = plot_texture(evaluate_texture(Topography(x, y, z)), title="t")
    surface_ax = fig.axes[0]
    psd_ax = next(a for a in fig.axes if a.get_title().startswith("Power spectral"))
    assert surface_ax.get_xlabel() == "x (µm)" and surface_ax.get_ylabel() == "y (µm)"
    mesh = surface_ax.collections[0]
    assert mesh.get_coordinates()[0, 0, 0] == pytest.approx(0.0, abs=1e-9)
    assert mesh.get_coordinates()[-1, -1, 0] == pytest.approx(60.0)  # cell edges, um
    assert mesh.get_coordinates()[-1, -1, 1] == pytest.approx(64.0)
    fig.canvas.draw()
    colour_bar = mesh.colorbar.ax
    assert colour_bar.get_ylabel() == "height (µm)"
    gap = colour_bar.get_position().x0 - surface_ax.get_position().x1
    assert 0 < gap < 0.05  # figure fractions: against the map
    centre = 0.5 * (surface_ax.get_position().x0 + surface_ax.get_position().x1)
    assert centre == pytest.approx(0.5, abs=0.08)
    assert not _labels_overlap(fig, psd_ax.xaxis)


def test_the_spectrum_of_a_gaussian_map_is_drawn_down_to_twelve_decades_below_its_peak():
    """A Gaussian-correlated map's PSD falls as exp(-q^2 l^2 / 4) to the FFT's round-off
    (1e-57 m^4 against a peak of 1e-24 for Sq 0.3 um, l 10 um): drawn to the floor, the
    measured part filled the top tenth of the panel. It is drawn down to 1e-12 of its peak
    and its unit is written as a power."""
    from asperity.plotting.surfaces import PSD_DECADES, plot_texture
    from asperity.surfaces import evaluate_texture, gaussian_topography

    surface = gaussian_topography(200e-6, 1e-6, 0.3e-6, 10e-6, seed=1)
    fig = plot_texture(evaluate_texture(surface), title="t")
    psd_ax = next(a for a in fig.axes if a.get_title().startswith("Power spectral"))
    peak = max(line.get_ydata().max() for line in psd_ax.get_lines())
    low = psd_ax.get_ylim()[0]
    assert peak * 10.0**-PSD_DECADES / 3 < low < peak * 1e-9
    assert psd_ax.get_ylabel() == "C (q) (m⁴)"
