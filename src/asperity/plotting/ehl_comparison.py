"""Point against line contact on the centre line, in the layout of the seed's Fig. 10
(Holmes, Evans & Snidle, J. Tribol. 127 (2005) 61)."""

from __future__ import annotations

from .ehl_transient import surfaces_below
from .style import new_figure

__all__ = ["plot_line_vs_point"]


def plot_line_vs_point(comparison, index=-1, offset=None):
    """Centre-line pressure and film of the point contact (solid) and the equivalent line
    contact (dotted) at one common step, the two surfaces drawn below, offset for clarity
    (seed Fig. 10: pressure heavy, line-contact results dotted).

    Parameters
    ----------
    comparison : CentreLineComparison
        From :func:`asperity.ehl.compare_centre_lines`.
    index : int
        Which of ``comparison.steps``.
    offset : float, optional
        Vertical offset between the film and each surface, um; default 1.5 times the larger
        of the surface relief and the film inside the Hertz width.

    Returns
    -------
    matplotlib.figure.Figure
    """
    c = comparison
    fig, ax = new_figure()
    x = c.x / c.a
    ax.plot(x, c.point_pressure[index] / 1e9, color="black", lw=2.0, label="p, point")
    ax.plot(x, c.line_pressure[index] / 1e9, color="black", lw=2.0, ls=":", label="p, line")
    ax.set_xlabel("x / a")
    ax.set_ylabel("pressure (GPa)")
    ax2 = ax.twinx()
    h_point = c.point_film[index] * 1e6
    ax2.plot(x, h_point, color="tab:blue", lw=1.0, label="h, point")
    ax2.plot(x, c.line_film[index] * 1e6, color="tab:blue", lw=1.0, ls=":", label="h, line")
    surfaces_below(ax2, x, h_point, c.surface1[index], c.surface2[index], offset)
    lines = ax.get_lines() + ax2.get_lines()[:2]
    ax.legend(lines, [line.get_label() for line in lines], loc="upper right", fontsize=8)
    ax.set_title(f"step {int(c.steps[index])}: point (solid) and line (dotted) contact")
    return fig
