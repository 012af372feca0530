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


#: Share of the contact cells that filled contours must colour; below it (a rough contact's
#: spots of a cell or two, which contourf leaves blank) the map colours each cell instead.
CONTOUR_SHARE = 0.9


def _contoured_share(contact) -> float:
    """Share of the contact cells inside a 2 x 2 block of contact cells: the cells that
    filled contours (matplotlib's contourf, which needs four corners) can colour."""
    c = np.asarray(contact, dtype=bool)
    if not c.any() or min(c.shape) < 2:
        return 1.0
    block = c[:-1, :-1] & c[1:, :-1] & c[:-1, 1:] & c[1:, 1:]
    covered = np.zeros_like(c)
    for i in (0, 1):
        for j in (0, 1):
            covered[i:c.shape[0] - 1 + i, j:c.shape[1] - 1 + j] |= block
    return float(covered[c].mean())


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
    field = np.where(contact, q, np.nan).T
    if _contoured_share(contact) < CONTOUR_SHARE:  # spots of a cell or two: colour each cell
        cs = ax.pcolormesh(x * MM, y * MM, np.ma.masked_invalid(field), shading="nearest",
                           cmap="viridis")
    else:
        cs = ax.contourf(x * MM, y * MM, field, levels=12, cmap="viridis")
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
    if result.gross_slip:
        ax.text(0.02, 0.02, "gross slip: the contact slides as a whole\n(full-slip traction, "
                f"load {1.0 / result.load_capacity:.3g} x capacity)"
                if result.load_capacity > 0 else "gross slip", transform=ax.transAxes,
                fontsize=9, color="r", va="bottom",
                bbox={"facecolor": "w", "edgecolor": "r", "alpha": 0.85})
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=4,
               fontsize=8, frameon=False)
    ax.set(xlabel="x (mm)", ylabel="y (mm)", aspect="equal")
    ax.set_title(title + (" (gross slip)" if result.gross_slip else ""), fontsize=10)
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
        # round-off of a coordinate that is zero (-1.9e-14 mm beside 0.228 mm) is shown as 0
        size = max(np.ptp(x), np.ptp(y), abs(centre[0]), abs(centre[1])) * MM
        cx, cy = (0.0 if abs(v) <= 1e-9 * size else v for v in (cx, cy))
        ax.text(0.02, 0.98, f"centre of rotation off the map: ({cx:.3g}, {cy:.3g}) mm",
                transform=ax.transAxes, va="top", fontsize=8, color="r")


#: Most stick-zone borders drawn by :func:`slip_progression` (more are unreadable).
MAX_BORDERS = 10


def _loading_branch(values) -> np.ndarray:
    """Indices of the first loading: the leading steps while ``values`` rises."""
    v = np.asarray(values, dtype=float)
    n = 1
    while n < len(v) and v[n] > v[n - 1]:
        n += 1
    return np.arange(n)


def slip_progression(path, x, y, title="Progression of slip", *, load_fraction=None,
                     fraction_label=None):
    """Stick-zone borders along the first loading of a path (Figs. 3.20, 3.32).

    Parameters
    ----------
    path : asperity.contact.load_path.LoadPathResult
    x, y : ndarray
        Cell-centre coordinates, m.
    title : str
    load_fraction : array_like, optional
        Each step's load over the gross-slip load (``Q / (mu P)`` for a force), which colours
        the borders; omitted, the step number does.
    fraction_label : str, optional
        The colour bar's label for ``load_fraction``.

    Notes
    -----
    Only the first loading is drawn (unloading and reversed loading grow new slip annuli
    that the borders of the loading would hide), at most :data:`MAX_BORDERS` of its steps,
    evenly spread, the last one included.
    """
    from matplotlib import cm, colormaps, colors

    fig, ax = _figure_for(x, y)
    contact = path.final.labels > 0
    _border(ax, x, y, contact, colors="k", linewidths=1.5)
    scale = (np.asarray(load_fraction, dtype=float) if load_fraction is not None
             else np.linalg.norm(path.loads, axis=1))
    branch = _loading_branch(scale)
    if len(branch) > MAX_BORDERS:
        branch = branch[np.unique(np.round(np.linspace(0, len(branch) - 1, MAX_BORDERS))
                                  .astype(int))]
    if load_fraction is not None:
        value, label = scale, fraction_label or "load / gross-slip load"
        norm = colors.Normalize(0.0, max(1.0, float(value[branch].max())))
    else:
        value, label = np.arange(1, len(path.loads) + 1, dtype=float), "load step"
        norm = colors.Normalize(1, max(len(path.loads), 2))
    cmap = colormaps["plasma"]
    for k in branch:
        _border(ax, x, y, path.stick[k], colors=[cmap(0.9 * norm(value[k]))],
                linestyles="--", linewidths=1.0)
    sm = cm.ScalarMappable(norm=norm, cmap=colors.ListedColormap(cmap(np.linspace(0, 0.9,
                                                                                  256))))
    fig.colorbar(sm, ax=ax, label=label, shrink=0.9)
    ax.plot([], [], "k-", lw=1.5, label="contact outline")
    ax.plot([], [], "--", color=cmap(0.45), lw=1.0, label="stick border, coloured by the load")
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=2,
               fontsize=8, frameon=False)
    shown = (f"first loading, steps 1-{int(branch[-1]) + 1} of {len(path.loads)}"
             if branch[-1] + 1 < len(path.loads) or len(branch) < branch[-1] + 1 else "")
    if shown and len(branch) < branch[-1] + 1:
        shown += f" ({len(branch)} shown)"
    ax.set(xlabel="x (mm)", ylabel="y (mm)", aspect="equal")
    ax.set_title(title + (f"\n{shown}" if shown else ""), fontsize=10)
    return fig


def _along_largest_force(loads) -> np.ndarray:
    """Unit vector of the path's largest force (zero when it applies none): a reversed
    cycle's forces keep their sign along it, which their magnitudes would fold."""
    force = np.hypot(loads[:, 0], loads[:, 1])
    return loads[np.argmax(force), :2] / max(force.max(), np.finfo(float).tiny)


def compliance_curves(path, title="Compliance", *, closed_form=None):
    """Force vs rigid shift and moment vs twist along a load path (Figs. 3.21, 3.33).

    One panel per load component the path applies (both when it applies neither).

    Parameters
    ----------
    path : asperity.contact.load_path.LoadPathResult
    title : str
    closed_form : (ndarray, ndarray, str), optional
        A closed-form curve of the force panel: relative shift (m) and force (N) along the
        path's largest force, and its name (Cattaneo-Mindlin, Mindlin-Deresiewicz), drawn
        dashed.

    Notes
    -----
    A path that ends in gross slip has no shift at its last step; the gross-slip load there
    is drawn as a dotted line, labelled with its step (counted from 1).
    """
    force = np.hypot(path.loads[:, 0], path.loads[:, 1])
    has_force, has_moment = bool(np.any(force > 0)), bool(np.any(path.loads[:, 2] != 0))
    panels = [k for k, on in (("force", has_force), ("moment", has_moment)) if on] or [
        "force", "moment"]
    fig, axes = new_figure(4.8 * len(panels), 4.0, ncols=len(panels), squeeze=False)
    k_gs = int(path.gross_slip_step)
    t_gs = float(path.final.load_capacity) if k_gs >= 0 else float("nan")
    e = _along_largest_force(path.loads)
    for ax, panel in zip(axes[0], panels, strict=True):
        if panel == "force":
            # components along the largest force: a reversed cycle's shift and force change
            # sign at different steps, which signs taken from the force alone would mirror
            ax.plot(path.shift @ e * 1e6, path.loads[:, :2] @ e, "o-", label="load steps")
            if closed_form is not None:
                shift, along, name = closed_form
                ax.plot(np.asarray(shift) * 1e6, along, "k--", lw=1.0, label=name)
            gross = t_gs * float(path.loads[k_gs, :2] @ e) if k_gs >= 0 else None
            unit = "N"
            # with a twist the shift depends on the point: the solver's is the moment's
            # reference point (a twisting pair of pads moved it against the force)
            where = " of the moment's reference point" if has_moment else ""
            ax.set(xlabel=f"rigid shift{where} along the largest force (µm)",
                   ylabel="tangential force along it (N)")
        else:
            ax.plot(path.rotation * 1e3, path.loads[:, 2], "o-", label="load steps")
            gross = t_gs * float(path.loads[k_gs, 2]) if k_gs >= 0 else None
            unit = "N m"
            ax.set(xlabel="twist (mrad)", ylabel="twisting moment (N m)")
        if gross is not None and np.isfinite(gross):
            ax.axhline(gross, color="r", ls=":", lw=1.2,
                       label=f"gross slip at step {k_gs + 1} ({gross:.3g} {unit})")
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


#: Line-of-action offsets below this fraction of the contact's size are round-off (drawn 0).
OFFSET_NOISE = 1e-6


def load_sharing(path, title="Load sharing between regions"):
    """Force and moment carried by each contact region along a load path (Fig. 3.19).

    Left: each region's force along the path's largest force, signed (or its moment, for a
    pure moment) against the applied load along it. Right: with a force, the offset of the
    resultant traction's line of action from the moment's reference point, M_traction / F
    (Fig. 3.19b), rounded to :data:`OFFSET_NOISE` times the contact's equivalent radius; for a
    pure moment, each region's share of the moment. Steps before gross slip only.
    """
    fig, (a1, a2) = new_figure(9.6, 4.0, ncols=2)
    n = path.gross_slip_step if path.gross_slip_step >= 0 else len(path.loads)
    loads, region_force, region_moment = (path.loads[:n], path.region_force[:n],
                                          path.region_moment[:n])
    k = region_moment.shape[1]
    e = _along_largest_force(path.loads)
    applied = loads[:, :2] @ e
    if np.any(applied != 0):
        along = region_force @ e
        for r in range(k):
            a1.plot(applied, along[:, r], "o-", label=f"region {r + 1}")
        a1.set(xlabel="applied force along the largest force (N)",
               ylabel="force carried along it (N)")
        carried = region_moment.sum(axis=1)
        ok = applied != 0
        offset = carried[ok] / applied[ok]
        # round-off is not drawn: offsets to OFFSET_NOISE of the contact's radius (a pair of
        # pads' constant 50 mm was drawn as +-4e-10 mm about "5e1"), and no offset text
        quantum = OFFSET_NOISE * _contact_size(path)
        if quantum > 0:
            offset = np.round(offset / quantum) * quantum
        a2.plot(applied[ok], offset * MM, "o-", color="k", label="resultant traction")
        a2.ticklabel_format(axis="y", useOffset=False)
        a2.set(xlabel="applied force along the largest force (N)",
               ylabel="line of action offset (mm)")
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


def _contact_size(path) -> float:
    """Equivalent radius sqrt(A / pi) of the final contact, m (0 without its grid)."""
    final = path.final
    if final.x is None or final.y is None or len(final.x) < 2 or len(final.y) < 2:
        return 0.0
    cell = (final.x[1] - final.x[0]) * (final.y[1] - final.y[0])
    return float(np.sqrt((final.labels > 0).sum() * cell / np.pi))
