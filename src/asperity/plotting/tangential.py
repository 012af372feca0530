"""Figures of frictional contact in the style of Seireg ch. 3 (Figs. 3.19-3.33).

Each function returns a matplotlib Figure; lengths are shown in mm, tractions in MPa.
"""

from __future__ import annotations

import numpy as np

from .style import new_figure

__all__ = ["traction_map", "slip_progression", "compliance_curves", "center_of_rotation_curve"]

MM, MPA = 1e3, 1e-6


def _border(ax, x, y, mask, **kwargs):
    """Dashed outline of a boolean cell mask (the stick/slip border)."""
    if mask.any() and not mask.all():
        ax.contour(x * MM, y * MM, mask.T.astype(float), levels=[0.5], **kwargs)


def traction_map(result, x, y, title="Tangential traction", arrows=16):
    """Traction magnitude contours, direction field, and the stick/slip border dashed.

    (Figs. 3.25-3.30: magnitude and direction of the traction, border of the no-slip region.)
    """
    fig, ax = new_figure(6.4, 5.0)
    q = np.hypot(*result.traction) * MPA
    contact = result.labels > 0
    cs = ax.contourf(x * MM, y * MM, np.where(contact, q, np.nan).T, levels=12, cmap="viridis")
    fig.colorbar(cs, ax=ax, label="|q| (MPa)")
    step_x, step_y = max(len(x) // arrows, 1), max(len(y) // arrows, 1)
    sub = (slice(None, None, step_x), slice(None, None, step_y))
    qx, qy = result.traction[0][sub], result.traction[1][sub]
    norm = np.hypot(qx, qy)
    ok = contact[sub] & (norm > 0)
    X, Y = np.meshgrid(x[sub[0]], y[sub[1]], indexing="ij")
    ax.quiver(X[ok] * MM, Y[ok] * MM, qx[ok] / norm[ok], qy[ok] / norm[ok], color="w",
              scale=arrows * 1.5, width=0.004)
    _border(ax, x, y, result.stick, colors="k", linestyles="--", linewidths=1.2)
    if np.all(np.isfinite(result.center_of_rotation)):
        ax.plot(*(result.center_of_rotation * MM), "r+", ms=10, label="centre of rotation")
        ax.legend(loc="upper right")
    ax.set(xlabel="x (mm)", ylabel="y (mm)", title=title, aspect="equal")
    return fig


def slip_progression(path, x, y, title="Progression of slip"):
    """Stick-zone borders at successive loads (Figs. 3.20, 3.32)."""
    fig, ax = new_figure(6.4, 5.0)
    contact = path.final.labels > 0
    _border(ax, x, y, contact, colors="k", linewidths=1.5)
    colors = _colors(len(path.loads))
    for k, stick in enumerate(path.stick):
        _border(ax, x, y, stick, colors=[colors[k]], linestyles="--", linewidths=1.0)
    sm = _scalar_mappable(path.loads)
    fig.colorbar(sm, ax=ax, label="load step")
    ax.set(xlabel="x (mm)", ylabel="y (mm)", title=title, aspect="equal")
    return fig


def _colors(n):
    from matplotlib import colormaps

    return colormaps["plasma"](np.linspace(0.0, 0.9, max(n, 1)))


def _scalar_mappable(loads):
    from matplotlib import cm, colors

    return cm.ScalarMappable(norm=colors.Normalize(1, len(loads)), cmap="plasma")


def compliance_curves(path, title="Compliance"):
    """Force vs rigid shift and moment vs twist along a load path (Figs. 3.21, 3.33)."""
    fig, (a1, a2) = new_figure(9.6, 4.0, ncols=2)
    force = np.hypot(path.loads[:, 0], path.loads[:, 1])
    sign = np.sign(path.loads[:, 0] + path.loads[:, 1])
    a1.plot(np.hypot(*path.shift.T) * np.where(sign == 0, 1, sign) * 1e6,
            force * np.where(sign == 0, 1, sign), "o-")
    a1.set(xlabel="rigid shift (um)", ylabel="tangential force (N)")
    a2.plot(path.rotation * 1e3, path.loads[:, 2], "o-")
    a2.set(xlabel="twist (mrad)", ylabel="twisting moment (N m)")
    fig.suptitle(title)
    return fig


def center_of_rotation_curve(path, reference=(0.0, 0.0), title="Centre of rotation"):
    """Distance of the centre of rotation from a reference point vs moment (Fig. 3.31)."""
    fig, ax = new_figure()
    d = path.center_of_rotation - np.asarray(reference)[None, :]
    ax.plot(path.loads[:, 2], d[:, 0] * MM, "o-", label="x")
    ax.plot(path.loads[:, 2], d[:, 1] * MM, "s--", label="y")
    ax.set(xlabel="twisting moment (N m)", ylabel="offset from reference (mm)", title=title)
    ax.legend()
    return fig
