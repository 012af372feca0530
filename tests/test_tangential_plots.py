"""Frictional-contact figures render from solver results (headless)."""

import numpy as np

from asperity.contact import hertz_point
from asperity.contact.load_path import proportional_path, tangential_load_path
from asperity.materials import Material
from asperity.plotting import tangential as tplot

STEEL = Material(206e9, 0.3, "steel")


def test_figures_render(tmp_path):
    hz = hertz_point(1000.0, 0.01, 0.01, STEEL, STEEL)
    x = np.linspace(-1.1 * hz.a, 1.1 * hz.a, 24)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = hz.pressure(X, Y)
    m = 0.6 * 3 * np.pi * 0.3 * 1000.0 * hz.a / 16
    path = tangential_load_path(p, x, x, 0.3, STEEL, STEEL,
                                proportional_path((50.0, 0.0), m, steps=3))
    figs = [tplot.traction_map(path.final, x, x), tplot.slip_progression(path, x, x),
            tplot.compliance_curves(path), tplot.centre_of_rotation_curve(path)]
    for k, fig in enumerate(figs):
        out = tmp_path / f"fig{k}.png"
        fig.savefig(out)
        assert out.stat().st_size > 5000
