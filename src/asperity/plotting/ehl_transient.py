"""Figures of a transient mixed-EHL run in the style of the seed (Holmes et al. 2005, Figs 3-14)."""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import MaxNLocator

from .style import hertz_outline, map_aspect, map_ylabel, new_figure

__all__ = ["plot_centre_line", "plot_contact_rate", "plot_contact_rate_line",
           "plot_film_histogram", "plot_film_snapshots", "plot_flow_vectors",
           "surfaces_below"]


def plot_contact_rate(result, problem):
    """Contours of the contact count rate Q/ms over x/a, y/a with the Hertz ellipse heavy
    (Figs. 4-8); without contact in the counting period, the words as the title instead of
    an empty scale (a title, not a box on the map, which a long narrow contact's map is too
    narrow to hold)."""
    xa, ya = result.x / problem.a, result.y / problem.a
    fig, ax, aspect = _map_figure(xa, ya)
    X, Y = np.meshgrid(xa, ya, indexing="ij")
    q = result.contact_count_rate
    if q.max() > 0.0:
        levels = MaxNLocator(10).tick_values(0.0, q.max())
        cs = ax.contourf(X, Y, q, levels=levels, cmap="Greys")
        fig.colorbar(cs, ax=ax, label="contact count rate Q (1/ms)", shrink=0.9)
    else:
        ax.set_xlim(xa[0], xa[-1])
        ax.set_ylim(ya[0], ya[-1])
        ax.set_title("no contact in the\ncounting period", fontsize=9)
    hertz_outline(ax, getattr(problem, "b", problem.a) / problem.a, label="Hertz contact")
    ax.set_xlabel("x / a  (entrainment ->)")
    ax.set_ylabel(map_ylabel(aspect))
    ax.set_aspect(aspect)
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize=8,
               frameon=False)
    return fig


def plot_contact_rate_line(result, problem):
    """Contact count rate Q/ms along x/a for a line contact, the Hertz width shaded; without
    contact in the counting period, the words as the title and a scale from 0 (not one
    centred on a flat zero line)."""
    fig, ax = new_figure()
    ax.axvspan(-1.0, 1.0, color="0.92", label="Hertz contact")
    q = result.contact_count_rate[:, 0]
    ax.plot(result.x / problem.a, q, color="black", lw=1.5)
    if not q.max() > 0.0:
        ax.set_ylim(0.0, 1.0)
        ax.set_title("no contact in the counting period", fontsize=9)
    ax.set_xlabel("x / a")
    ax.set_ylabel("contact count rate Q (1/ms)")
    ax.legend(loc="upper left", fontsize=8)
    return fig


def plot_centre_line(result, problem, index=-1, offset=None):
    """Pressure (heavy) and film on y = 0 at one recorded step, the two surfaces drawn below,
    offset for clarity (Figs. 3 and 10)."""
    fig, ax = new_figure()
    x = result.x / problem.a
    ax.plot(x, result.centre_pressure[index] / 1e9, color="black", lw=2.0, label="p (GPa)")
    ax.set_xlabel("x / a")
    ax.set_ylabel("pressure (GPa)")
    ax2 = ax.twinx()
    h = result.centre_film[index] * 1e6
    ax2.plot(x, h, color="tab:blue", lw=1.0, label="film h (µm)")
    surfaces_below(ax2, x, h, result.centre_surface1[index], result.centre_surface2[index],
                   offset)
    band = ax.axvspan(-1.0, 1.0, color="0.92", zorder=0)
    film_line, surface_line = ax2.get_lines()[:2]
    fig.legend([ax.get_lines()[0], film_line, surface_line, band],
               ["pressure p", "film h", "surfaces (offset)", "Hertz width"],
               loc="outside lower center", ncols=4, fontsize=8, frameon=False)
    ax.set_title(f"step {int(result.snapshot_steps[index])}")
    return fig


def plot_film_snapshots(result, problem, feature_positions):
    """The film change on y = 0 at every recorded step, against the smooth steady film,
    stacked upwards in time, with each step's feature centre marked on its baseline: where
    the film change a dent or bump makes travels against the feature itself (with sliding, at
    the mean speed rather than the feature's; Venner & Lubrecht 1994, Kaneta et al. 1993), as
    such runs are drawn in the literature.

    ``feature_positions`` maps a label (``"surface1"``) to the feature centre's x (m) at each
    recorded step (``result.snapshot_steps``). Films in nm; the steps are set apart by the
    largest change, so that they do not overlap.
    """
    fig, ax = new_figure()
    x = result.x / problem.a
    j = int(np.argmin(np.abs(result.y)))
    change = (result.centre_film - result.steady_film[:, j]) * 1e9
    shown = np.isfinite(change).all(axis=1)
    spread = float(np.max(np.abs(change[shown]))) if shown.any() else 1.0
    gap = 1.1 * max(spread, 1e-3)
    ax.axvspan(-1.0, 1.0, color="0.92", zorder=0, label="Hertz width")
    markers, marked = ["v", "^"], set()
    for n, step in enumerate(result.snapshot_steps):
        if not shown[n]:
            continue
        level = n * gap
        ax.axhline(level, color="0.75", lw=0.5, zorder=1)
        ax.plot(x, change[n] + level, color="tab:blue", lw=1.2, zorder=2)
        ax.text(x[-1], level, f" step {int(step)}", fontsize=7, va="center")
        for k, (label, centres) in enumerate(feature_positions.items()):
            xc = centres[n] / problem.a
            if x[0] <= xc <= x[-1]:
                ax.plot([xc], [level], marker=markers[k % 2], color="tab:red", ms=6,
                        ls="none", zorder=3,
                        label=None if label in marked else f"{label}: feature centre")
                marked.add(label)
    ax.set_xlim(x[0], x[-1] + 0.14 * (x[-1] - x[0]))
    ax.set_xlabel("x / a")
    ax.set_ylabel(f"film change on y = 0 (nm), steps {gap:.3g} nm apart")
    ax.set_yticks([])
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncols=3,
               fontsize=8, frameon=False)
    ax.set_title("film h - smooth steady film, at the recorded steps (time upwards)", fontsize=9)
    return fig


def surfaces_below(ax, x, film_um, z1, z2, offset=None):
    """Draw surfaces 1 and 2 (heights in m) below the film on ``ax``, offset for clarity.

    In their contact configuration, offset for clarity (the seed's Figs. 3 and 10): surface 1
    above, mirrored at ``-gap - z1`` so that its asperities point down, surface 2 below at
    ``-2 gap + z2``, its asperities pointing up at surface 1; ``gap`` (um) 1.5 times the
    larger relief unless given. The y limits leave room for the film over ``|x| <= 1`` (x in
    units of a).
    """
    inside = np.abs(x) <= 1.0
    h_contact = max(float(np.nanmax(film_um[inside])) if inside.any() else 0.0, 0.25)
    z1 = z1 * 1e6
    z2 = z2 * 1e6
    relief = max(float(np.ptp(z1)), float(np.ptp(z2)), h_contact)
    gap = offset if offset is not None else 1.5 * relief
    ax.plot(x, -gap - z1, color="tab:gray", lw=0.8)
    ax.plot(x, -2.0 * gap + z2, color="tab:gray", lw=0.8)
    ax.set_ylim(-2.0 * gap - 1.2 * relief, 3.0 * h_contact)
    ax.set_ylabel("film; surfaces below, offset (µm)")


def plot_film_histogram(result):
    """Distribution of the film thickness over the Hertz area and the counting period.

    The last bin holds every film at or above its lower edge; it is drawn (and named in the
    legend) only where it holds node-steps.
    """
    fig, ax = new_figure()
    edges = result.film_edges * 1e6
    share = result.film_counts / max(result.film_counts.sum(), 1)
    ax.stairs(share[:-1], edges[:-1], fill=True, color="tab:gray", label="film thickness")
    if result.film_counts[-1] > 0:
        ax.stairs(share[-1:], edges[-2:], fill=True, color="tab:orange",
                  label=f"overflow: h >= {edges[-2]:.3g} µm")
    ax.set_xlabel("film thickness h (µm)")
    ax.set_ylabel("fraction of node-steps in the Hertz contact")
    ax.set_ylim(0.0, 1.15 * max(float(share.max()), 1e-12))
    ax.legend(loc="upper left", fontsize=8)
    return fig


def plot_flow_vectors(result, problem, arrows=(14, 12)):
    """Film contours and lubricant flow vectors at the last step on equal axes, the Hertz
    ellipse heavy and an arrow scale (Fig. 14). Arrows are drawn on and around the contact
    (within 1.3 times the ellipse), scaled so that the key's flow, about the 90th percentile
    there, spans 0.9 arrow spacings.

    Parameters
    ----------
    result : TransientResult
    problem : PointContact
    arrows : (int, int)
        About how many arrows along x and along y.
    """
    xa, ya = result.x / problem.a, result.y / problem.a
    fig, ax, aspect = _map_figure(xa, ya)
    X, Y = np.meshgrid(xa, ya, indexing="ij")
    h_um = result.film * 1e6
    b_a = getattr(problem, "b", problem.a) / problem.a
    inside = X**2 + (Y / b_a) ** 2 <= 1.0
    top = 3.0 * float(np.median(h_um[inside])) if inside.any() else float(h_um.max())
    levels = MaxNLocator(12).tick_values(0.0, max(top, 1e-6))
    cs = ax.contourf(X, Y, np.clip(h_um, None, levels[-1]), levels=levels, cmap="viridis")
    fig.colorbar(cs, ax=ax, label="film thickness h (µm)", shrink=0.9)
    sx = max(len(xa) // arrows[0], 1)
    sy = max(len(ya) // arrows[1], 1)
    sub = (slice(sx // 2, None, sx), slice(sy // 2, None, sy))
    qx, qy = result.flow_x[sub] * 1e6, result.flow_y[sub] * 1e6  # mm^2/s
    near = X[sub] ** 2 + (Y[sub] / b_a) ** 2 <= 1.3**2  # arrows on and around the contact
    magnitude = np.hypot(qx, qy)[near]
    reference = _round_125(float(np.percentile(magnitude, 90))) if magnitude.size else 0.0
    if reference > 0:
        spacing = min(sx * (xa[1] - xa[0]), sy * (ya[1] - ya[0]) if len(ya) > 1 else 1.0)
        drawn = ax.quiver(X[sub][near], Y[sub][near], qx[near], qy[near], color="white",
                          angles="xy", scale_units="xy", scale=reference / (0.9 * spacing),
                          width=0.006, edgecolor="k", linewidth=0.3)
        ax.quiverkey(drawn, 0.06, 0.96, reference, f"{reference:g} mm²/s per unit width",
                     labelpos="E", coordinates="axes", color="k", fontproperties={"size": 8})
    hertz_outline(ax, b_a, label="Hertz contact")
    ax.set_xlabel("x / a  (entrainment ->)")
    ax.set_ylabel(map_ylabel(aspect))
    ax.set_aspect(aspect)
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize=8,
               frameon=False)
    return fig


def _map_figure(xa, ya):
    """A figure for a map over x/a, y/a, sized to the domain's shape as drawn, and the axes'
    aspect (:func:`~asperity.plotting.style.map_aspect`: to scale unless very tall)."""
    aspect = map_aspect(np.ptp(xa), np.ptp(ya))
    tall = aspect * float(np.ptp(ya) / max(np.ptp(xa), 1e-12))
    height = float(np.clip(3.6 * tall, 2.4, 5.5))
    width = float(np.clip(height / tall, 2.2, 6.0))
    return *new_figure(width + 1.8, height + 1.1), aspect


def _round_125(value: float) -> float:
    """The largest 1, 2 or 5 times a power of ten not above ``value`` (an arrow-key length)."""
    if not value > 0 or not np.isfinite(value):
        return 0.0
    power = 10.0 ** np.floor(np.log10(value))
    return float(max(m for m in (1.0, 2.0, 5.0) if m * power <= value * (1 + 1e-12)) * power)
