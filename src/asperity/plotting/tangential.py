"""Figures of frictional contact in the style of Seireg ch. 3 (Figs. 3.19-3.33).

Each function returns a matplotlib Figure; lengths are shown in mm, tractions in MPa.
"""

from __future__ import annotations

import numpy as np

from .style import new_figure

__all__ = ["traction_map", "slip_progression", "compliance_curves", "centre_of_rotation_curve",
           "load_sharing"]

MM, MPA = 1e3, 1e-6


def _border(ax, x, y, mask, **kwargs):
    """Dashed outline of a boolean cell mask (the stick/slip border)."""
    if mask.any():  # padded with a ring of cells outside, so that edges on the domain show
        xp = np.concatenate([[2 * x[0] - x[1]], x, [2 * x[-1] - x[-2]]])
        yp = np.concatenate([[2 * y[0] - y[1]], y, [2 * y[-1] - y[-2]]])
        ax.contour(xp * MM, yp * MM, np.pad(mask, 1).T.astype(float), levels=[0.5], **kwargs)


def _figure_for(x, y, width=7.0):
    """A figure whose height follows the domain's aspect ratio (room for the colour bar)."""
    lx, ly = np.ptp(x) + (x[1] - x[0]), np.ptp(y) + (y[1] - y[0])
    return new_figure(width, float(np.clip(0.8 * width * ly / lx + 1.2, 2.6, 6.0)))


def traction_map(result, x, y, title="Tangential traction", arrows=16):
    """Traction magnitude contours, direction field, and the stick/slip border dashed.

    (Figs. 3.25-3.30: magnitude and direction of the traction, border of the no-slip region.)
    Arrows (unit length: directions only) are spaced evenly in space, about ``arrows`` along
    the longer side; the contact outline is drawn solid.
    """
    fig, ax = _figure_for(x, y)
    q = np.hypot(*result.traction) * MPA
    contact = result.labels > 0
    cs = ax.contourf(x * MM, y * MM, np.where(contact, q, np.nan).T, levels=12, cmap="viridis")
    fig.colorbar(cs, ax=ax, label="|q| (MPa)", shrink=0.9)
    dx, dy = x[1] - x[0], y[1] - y[0]
    spacing = max(np.ptp(x) + dx, np.ptp(y) + dy) / arrows
    step_x, step_y = max(int(round(spacing / dx)), 1), max(int(round(spacing / dy)), 1)
    sub = (slice(step_x // 2, None, step_x), slice(step_y // 2, None, step_y))
    qx, qy = result.traction[0][sub], result.traction[1][sub]
    norm = np.hypot(qx, qy)
    ok = contact[sub] & (norm > 0)
    X, Y = np.meshgrid(x[sub[0]], y[sub[1]], indexing="ij")
    ax.quiver(X[ok] * MM, Y[ok] * MM, qx[ok] / norm[ok], qy[ok] / norm[ok], color="w",
              angles="xy", scale_units="xy", scale=1.0 / (0.75 * spacing * MM), width=0.003,
              pivot="middle")
    _border(ax, x, y, contact, colors="k", linewidths=1.0)
    _border(ax, x, y, result.stick, colors="k", linestyles="--", linewidths=1.2)
    ax.plot([], [], "k-", lw=1.0, label="contact outline")
    if result.stick.any():
        ax.plot([], [], "k--", lw=1.2, label="stick/slip border")
    ax.plot([], [], marker=r"$\rightarrow$", ls="none", color="0.3", ms=10,
            label="traction direction")
    _mark_centre(ax, result.centre_of_rotation, x, y)
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=4,
               fontsize=8, frameon=False)
    ax.set(xlabel="x (mm)", ylabel="y (mm)", aspect="equal")
    ax.set_title(title, fontsize=10)
    return fig


def _mark_centre(ax, centre, x, y):
    """The centre of rotation as a cross where it lies on the map, else named in a corner
    (a centre far away, nearly a translation, would otherwise set the axis limits)."""
    if not np.all(np.isfinite(centre)):
        return
    cx, cy = centre * MM
    if x[0] * MM <= cx <= x[-1] * MM and y[0] * MM <= cy <= y[-1] * MM:
        ax.plot(cx, cy, "r+", ms=10, mew=2, label="centre of rotation")
    else:
        ax.text(0.02, 0.98, f"centre of rotation off the map: ({cx:.3g}, {cy:.3g}) mm",
                transform=ax.transAxes, va="top", fontsize=8, color="r")


def slip_progression(path, x, y, title="Progression of slip"):
    """Stick-zone borders at successive loads (Figs. 3.20, 3.32)."""
    fig, ax = _figure_for(x, y)
    contact = path.final.labels > 0
    _border(ax, x, y, contact, colors="k", linewidths=1.5)
    colors = _colors(len(path.loads))
    for k, stick in enumerate(path.stick):
        _border(ax, x, y, stick, colors=[colors[k]], linestyles="--", linewidths=1.0)
    sm = _scalar_mappable(path.loads)
    fig.colorbar(sm, ax=ax, label="load step")
    ax.plot([], [], "k-", lw=1.5, label="contact outline")
    ax.plot([], [], "--", color=colors[-1], lw=1.0, label="stick border at a load step")
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=2,
               fontsize=8, frameon=False)
    ax.set(xlabel="x (mm)", ylabel="y (mm)", title=title, aspect="equal")
    return fig


def _colors(n):
    from matplotlib import colormaps

    return colormaps["plasma"](np.linspace(0.0, 0.9, max(n, 1)))


def _scalar_mappable(loads):
    from matplotlib import cm, colors

    return cm.ScalarMappable(norm=colors.Normalize(1, len(loads)), cmap="plasma")


def compliance_curves(path, title="Compliance"):
    """Force vs rigid shift and moment vs twist along a load path (Figs. 3.21, 3.33).

    One panel per load component the path applies (both when it applies neither).
    """
    force = np.hypot(path.loads[:, 0], path.loads[:, 1])
    has_force, has_moment = bool(np.any(force > 0)), bool(np.any(path.loads[:, 2] != 0))
    panels = [k for k, on in (("force", has_force), ("moment", has_moment)) if on] or [
        "force", "moment"]
    fig, axes = new_figure(4.8 * len(panels), 4.0, ncols=len(panels), squeeze=False)
    for ax, panel in zip(axes[0], panels, strict=True):
        if panel == "force":
            # components along the largest force: a reversed cycle's shift and force change
            # sign at different steps, which signs taken from the force alone would mirror
            e = path.loads[np.argmax(force), :2] / max(force.max(), np.finfo(float).tiny)
            ax.plot(path.shift @ e * 1e6, path.loads[:, :2] @ e, "o-", label="load steps")
            ax.set(xlabel="rigid shift along the largest force (um)",
                   ylabel="tangential force along it (N)")
        else:
            ax.plot(path.rotation * 1e3, path.loads[:, 2], "o-", label="load steps")
            ax.set(xlabel="twist (mrad)", ylabel="twisting moment (N m)")
        ax.legend(loc="lower right", fontsize=8)
    fig.suptitle(title)
    return fig


def centre_of_rotation_curve(path, reference=(0.0, 0.0), title="Centre of rotation"):
    """Distance of the centre of rotation from a reference point vs moment (Fig. 3.31)."""
    fig, ax = new_figure()
    d = path.centre_of_rotation - np.asarray(reference)[None, :]
    ax.plot(path.loads[:, 2], d[:, 0] * MM, "o-", label="x")
    ax.plot(path.loads[:, 2], d[:, 1] * MM, "s--", label="y")
    ax.set(xlabel="twisting moment (N m)", ylabel="offset from reference (mm)", title=title)
    ax.legend()
    return fig


def load_sharing(path, title="Load sharing between regions"):
    """Force and moment carried by each contact region along a load path (Fig. 3.19).

    Left: each region's force along the applied force (or its moment, for a pure moment)
    against the applied load. Right: with a force, the offset of the resultant traction's line
    of action from the moment's reference point, M_traction / |F| (Fig. 3.19b); for a pure
    moment, each region's share of the moment. Steps before gross slip only.
    """
    fig, (a1, a2) = new_figure(9.6, 4.0, ncols=2)
    n = path.gross_slip_step if path.gross_slip_step >= 0 else len(path.loads)
    loads, region_force, region_moment = (path.loads[:n], path.region_force[:n],
                                          path.region_moment[:n])
    force = np.hypot(loads[:, 0], loads[:, 1])
    k = region_moment.shape[1]
    if np.any(force > 0):
        unit = loads[:, :2] / np.where(force > 0, force, 1.0)[:, None]
        along = np.einsum("krc,kc->kr", region_force, unit)
        for r in range(k):
            a1.plot(force, along[:, r], "o-", label=f"region {r + 1}")
        a1.set(xlabel="applied force (N)", ylabel="force carried (N)")
        carried = region_moment.sum(axis=1)
        ok = force > 0
        a2.plot(force[ok], carried[ok] / force[ok] * MM, "o-", color="k",
                label="resultant traction")
        a2.set(xlabel="applied force (N)", ylabel="line of action offset (mm)")
        a2.legend(fontsize=8)
    else:
        m = loads[:, 2]
        for r in range(k):
            a1.plot(m, region_moment[:, r], "o-", label=f"region {r + 1}")
            a2.plot(m, region_moment[:, r] / np.where(m != 0, m, 1.0), "o-",
                    label=f"region {r + 1}")
        a1.set(xlabel="applied moment (N m)", ylabel="moment carried (N m)")
        a2.set(xlabel="applied moment (N m)", ylabel="share of the moment")
        a2.legend(fontsize=8)
    a1.legend(fontsize=8)
    fig.suptitle(title)
    return fig
