"""Units of the steady EHL figures (asperity.plotting.ehl)."""

import numpy as np
import pytest

from asperity.plotting.ehl import centre_line_profiles, contour_maps, transverse_section


def _soft_contact():
    """A Hertzian pressure of 255.2 kPa and a 1.01 um film: a PDMS ball on glass."""
    x = np.linspace(-2.5e-3, 1.5e-3, 81)
    y = np.linspace(-2e-3, 2e-3, 41)
    r2 = (x[:, None] / 1e-3) ** 2 + (y[None, :] / 1e-3) ** 2
    p = 255.2e3 * np.sqrt(np.clip(1 - r2, 0, None))
    h = 1.01e-6 + np.clip(r2 - 1, 0, None) * 5e-5
    return x, y, p, h


def test_a_soft_contact_is_drawn_in_kpa_and_um():
    """Its 255 kPa was drawn on a GPa axis (0.00025); the film keeps um although the gap at
    the domain's edge is 0.4 mm."""
    x, y, p, h = _soft_contact()
    mid = y.size // 2
    fig = centre_line_profiles(x, p[:, mid], h[:, mid], 1e-3, p[:, mid])
    ax_p, ax_h = fig.axes[:2]
    assert ax_p.get_ylabel() == "pressure (kPa)" and ax_h.get_ylabel() == "film (µm)"
    assert ax_p.get_lines()[0].get_ydata().max() == pytest.approx(255.2, rel=1e-3)
    assert ax_p.get_lines()[1].get_ydata().max() == pytest.approx(255.2, rel=1e-3)
    assert ax_h.get_lines()[0].get_ydata().min() == pytest.approx(1.01, rel=1e-3)
    fig = contour_maps(x, y, p, h, 1e-3, 1e-3, 1.01e-6)
    assert [ax.get_title() for ax in fig.axes[:2]] == ["pressure (kPa)", "film thickness (µm)"]
    fig = transverse_section(y, p[40], h[40], 1e-3)
    assert fig.axes[0].get_ylabel() == "pressure (kPa)"
    assert fig.axes[1].get_ylabel() == "film (µm)"


def test_a_film_collapsed_over_most_of_the_hertz_width_keeps_its_centre_on_the_axis():
    """Probe case 04: the film at x = 0 sat on a 0.0004 nm floor over |y| = 0.35-0.95 b and
    was 19 nm in the middle; scaled on its median over the Hertz width, the axis ran to
    0.0012 nm and the central film was drawn off it. The centre's film now sets the scale
    where it is above the median."""
    import matplotlib.pyplot as plt

    b = 1e-4
    y = np.linspace(-3.2 * b, 3.2 * b, 81)
    p = 2.5e9 * np.sqrt(np.clip(1 - (y / b) ** 2, 0, None))
    h = np.where(np.abs(y) < 0.3 * b, 19e-9, 4e-13) + np.clip(np.abs(y) / b - 1, 0, None) * 1e-6
    fig = transverse_section(y, p, h, b)
    try:
        ax_h = fig.axes[1]
        assert ax_h.get_ylabel() == "film (nm)"
        assert ax_h.get_ylim()[1] == pytest.approx(3 * 19.0)
    finally:
        plt.close(fig)


def _histogram(counts):
    import types

    edges = np.linspace(0.0, 1e-6, 11)
    return types.SimpleNamespace(film_edges=edges, film_counts=np.asarray(counts))


def test_film_histogram_names_its_overflow_bin_only_when_it_holds_films():
    """An empty overflow bin had its "overflow: h >= ..." legend entry all the same."""
    import matplotlib.pyplot as plt

    from asperity.plotting.ehl_transient import plot_film_histogram

    empty = plot_film_histogram(_histogram([5, 4, 3, 2, 1, 1, 1, 1, 1, 0]))
    full = plot_film_histogram(_histogram([5, 4, 3, 2, 1, 1, 1, 1, 1, 2]))
    try:
        names = [[t.get_text() for t in fig.axes[0].get_legend().texts] for fig in (empty, full)]
        assert names[0] == ["film thickness"]
        assert names[1] == ["film thickness", "overflow: h >= 0.9 µm"]
    finally:
        plt.close(empty)
        plt.close(full)


def test_a_nearly_rigid_contacts_pressure_keeps_its_own_scale():
    """A glass ball in glycerol: its EHL pressure peaks at 0.71 MPa against the dry Hertz
    109 MPa; drawn on Hertz's scale it was a flat line at zero. The axis now follows the EHL
    pressure and the Hertz curve is marked off scale; a deforming contact keeps both."""
    a = 46.7e-6
    x = np.linspace(-100 * a, 10 * a, 401)
    hertz = 109e6 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))
    rigid = 0.71e6 * np.exp(-(((x + 4 * a) / (6 * a)) ** 2))
    film = 8e-6 + x**2 / (2 * 10e-3)
    fig = centre_line_profiles(x, rigid, film, a, hertz)
    ax_p = fig.axes[0]
    assert ax_p.get_ylim()[1] == pytest.approx(1.15 * rigid.max() / 1e3)  # kPa
    assert any("off scale" in t.get_text() for t in ax_p.get_legend().get_texts())
    fig = centre_line_profiles(x, 0.9 * hertz, film, a, hertz)
    assert not any("off scale" in t.get_text() for t in fig.axes[0].get_legend().get_texts())
    assert fig.axes[0].get_ylim()[1] > 100.0  # MPa: Hertz's peak drawn whole
