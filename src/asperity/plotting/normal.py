"""Figures of a dry normal contact: pressure map and centre-line profiles."""

from __future__ import annotations

import numpy as np

from .style import new_figure

__all__ = ["pressure_map", "centre_line"]


def pressure_map(x, y, pressure, contact=None, title="Contact pressure"):
    """Pressure (GPa) over x, y (mm) on equal axes, with the contact boundary; the figure is
    sized to the domain's shape."""
    tall = float(np.ptp(y) / max(np.ptp(x), 1e-300)) if len(y) > 1 else 1.0
    height = float(np.clip(3.2 * tall, 2.4, 4.5))
    fig, ax = new_figure(float(np.clip(height / tall, 2.4, 6.0)) + 1.8, height + 1.0)
    X, Y = np.meshgrid(np.asarray(x) * 1e3, np.asarray(y) * 1e3, indexing="ij")
    m = ax.pcolormesh(X, Y, pressure / 1e9, shading="auto", cmap="magma")
    if contact is not None and contact.any() and not contact.all():
        ax.contour(X, Y, contact.astype(float), levels=[0.5], colors="cyan", linewidths=0.8)
        ax.plot([], [], color="cyan", lw=0.8, label="contact boundary")
        fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize=8,
                   frameon=False)
    fig.colorbar(m, ax=ax, label="pressure (GPa)")
    ax.set(xlabel="x (mm)", ylabel="y (mm)", title=title, aspect="equal")
    return fig


def centre_line(x, pressure_line, gap_line, reference=None, title="Centre line y = 0"):
    """Pressure and deformed gap along x at the row nearest y = 0; Hertz dashed if given."""
    fig, ax = new_figure()
    xm = np.asarray(x) * 1e3
    ax.plot(xm, pressure_line / 1e9, "k-", lw=1.6, label="pressure")
    if reference is not None:
        ax.plot(xm, reference / 1e9, "r--", lw=1.0, label="Hertz")
    ax.set(xlabel="x (mm)", ylabel="pressure (GPa)", title=title)
    ax2 = ax.twinx()
    ax2.plot(xm, gap_line * 1e6, "b-", lw=1.0, label="gap")
    ax2.set_ylabel("gap (µm)", color="b")
    lines = ax.get_lines() + ax2.get_lines()
    fig.legend(lines, [ln.get_label() for ln in lines], loc="outside lower center", ncols=3,
               fontsize=8, frameon=False)
    return fig
