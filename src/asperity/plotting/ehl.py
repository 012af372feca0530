"""Figures of a steady EHL solution in the style of the mixed-EHL seed's Fig. 2.

Contour maps of pressure and film thickness (each in the unit its largest value reads best in:
GPa for a steel contact, kPa for a rubber one) over x/a and y/a on equal axes, so that
the Hertz ellipse (drawn heavy) looks like the ellipse it is (y compressed, and labelled so,
for a domain more than ``MAX_MAP_ASPECT`` times taller than wide); profiles along the entrainment
centre line y = 0 (pressure and film on their own axes, Hertz pressure dashed); and a
transverse section at x = 0 that shows the side constrictions of a point contact.
"""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import MaxNLocator

from ..formatting import display_unit
from .style import hertz_outline, map_aspect, map_ylabel, new_figure, plt

__all__ = ["contour_maps", "centre_line_profiles", "transverse_section"]


def _shown(values, unit, magnitude=None):
    """``values`` (SI ``unit``) in the unit that ``magnitude`` (default: their largest value)
    reads best in (:func:`asperity.formatting.display_unit`), the factor and that unit's
    label: a PDMS ball's 255 kPa was drawn as 0.00025 GPa. A film takes the unit of its
    central value, not of the gap at the domain's edge."""
    values = np.asarray(values, dtype=float)
    if magnitude is None:
        magnitude = float(np.max(np.abs(values)))
    scale, label = display_unit(magnitude, unit)
    return values * scale, scale, label


def _film_levels(film_um, h_c_um):
    """Film contour levels from the minimum to twice the central film (the contact region),
    at round values (both in the same unit)."""
    lo = float(np.min(film_um))
    hi = max(2.0 * h_c_um, lo * 1.5, lo + 1e-6 * max(abs(lo), h_c_um, 1e-30))
    return MaxNLocator(14).tick_values(lo, hi)


def contour_maps(x, y, pressure, film, a, b, central_film, title="Steady EHL"):
    """Pressure (left) and film (right) contours over x/a, y/a on equal axes, the
    Hertz ellipse heavy (it looks like the ellipse it is: b/a tall); a domain more than
    :data:`~asperity.plotting.style.MAX_MAP_ASPECT` times taller than wide is drawn with y
    compressed to that ratio (:func:`~asperity.plotting.style.map_aspect`).

    Parameters
    ----------
    x, y : ndarray
        Node coordinates, m.
    pressure, film : ndarray
        p (Pa) and h (m), indexed ``[ix, iy]``.
    a, b : float
        Hertz semi-axes along x and y, m.
    central_film : float
        h at the centre, m (sets the film contour range).
    title : str
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    xa, ya = np.asarray(x) / a, np.asarray(y) / a
    X, Y = np.meshgrid(xa, ya, indexing="ij")
    aspect = map_aspect(np.ptp(xa), np.ptp(ya))
    tall = aspect * float(np.ptp(ya) / max(np.ptp(xa), 1e-12))  # height / width of a panel
    height = float(np.clip(3.4 * tall, 2.4, 7.5))
    width = float(np.clip(height / tall, 2.0, 4.5))
    fig, (ax_p, ax_h) = plt.subplots(1, 2, figsize=(2 * width + 3.2, height + 1.2),
                                     layout="constrained", sharey=True)
    p_shown, _, p_unit = _shown(pressure, "Pa")
    levels = MaxNLocator(12).tick_values(0.0, max(p_shown.max(), 1e-12))
    filled = ax_p.contourf(X, Y, p_shown, levels=levels, cmap="magma_r")
    ax_p.contour(X, Y, p_shown, levels=levels[1::2], colors="k", linewidths=0.4)
    fig.colorbar(filled, ax=ax_p, label=f"pressure ({p_unit})", shrink=0.9)
    ax_p.set(xlabel="x / a  (entrainment ->)", ylabel=map_ylabel(aspect),
             title=f"pressure ({p_unit})")

    h_shown, h_scale, h_unit = _shown(film, "m", central_film)
    h_levels = _film_levels(h_shown, central_film * h_scale)
    filled = ax_h.contourf(X, Y, np.clip(h_shown, None, h_levels[-1]), levels=h_levels,
                           cmap="viridis")
    ax_h.contour(X, Y, h_shown, levels=h_levels[1::2], colors="k", linewidths=0.4)
    fig.colorbar(filled, ax=ax_h, label=f"film thickness ({h_unit})", shrink=0.9)
    ax_h.set(xlabel="x / a  (entrainment ->)", title=f"film thickness ({h_unit})")
    for ax in (ax_p, ax_h):
        hertz_outline(ax, b / a, label="Hertz contact")
        ax.set_aspect(aspect)
    fig.legend(*ax_p.get_legend_handles_labels(), loc="outside lower center", fontsize=8,
               frameon=False)
    fig.suptitle(title, fontsize=11)
    return fig


#: Dry Hertz peak over the EHL peak above which the centre-line figure keeps the EHL
#: pressure's scale and marks the Hertz curve off scale (a rigid glass ball in glycerol:
#: 0.71 MPa against 109 MPa).
HERTZ_OFF_SCALE = 3.0


def centre_line_profiles(x, pressure, film, a, hertz_pressure=None, title="Centre line y = 0"):
    """Pressure and film along the centre line, on two stacked axes over x/a.

    Parameters
    ----------
    x : ndarray
        Node coordinates, m.
    pressure, film : ndarray
        p (Pa) and h (m) along y = 0.
    a : float
        Hertz semi-axis (half-width) along x, m.
    hertz_pressure : ndarray, optional
        The dry Hertz pressure on the same nodes, Pa (dashed).
    title : str
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, (ax_p, ax_h) = plt.subplots(2, 1, figsize=(6.4, 5.6), layout="constrained",
                                     sharex=True, height_ratios=(3, 2))
    xa = np.asarray(x) / a
    p_shown, p_scale, p_unit = _shown(pressure, "Pa")
    ax_p.plot(xa, p_shown, "k-", lw=1.8, label="EHL pressure")
    if hertz_pressure is not None:
        hertz = np.asarray(hertz_pressure)
        peak, ehl_peak = float(hertz.max()), float(np.max(pressure))
        if peak > HERTZ_OFF_SCALE * ehl_peak > 0.0:  # a nearly rigid contact: its pressure
            # is a few per cent of Hertz's and drawn on Hertz's scale it is a flat line
            ax_p.set_ylim(0.0, 1.15 * ehl_peak * p_scale)
            label = "dry Hertz (off scale; p_h in the results)"  # its nodes miss the peak
        else:
            label = "dry Hertz"
        ax_p.plot(xa, hertz * p_scale, "r--", lw=1.0, label=label)
    ax_p.set(ylabel=f"pressure ({p_unit})", title=title)
    inside = np.abs(xa) <= 1.0
    h_um, _, h_unit = _shown(film, "m", float(np.median(np.asarray(film)[inside]))
                             if inside.any() else None)
    ax_h.plot(xa, h_um, "b-", lw=1.4)
    i_min = int(np.argmin(h_um))
    ax_h.annotate(f"h_min = {h_um[i_min]:.4g} {h_unit}", (xa[i_min], h_um[i_min]),
                  xytext=(-90, 25), textcoords="offset points", fontsize=8,
                  arrowprops={"arrowstyle": "->", "lw": 0.8})
    top = 3.0 * float(np.median(h_um[inside])) if inside.any() else float(h_um.max())
    ax_h.set(xlabel="x / a  (entrainment ->)", ylabel=f"film ({h_unit})")
    limit = max(top, 1.2 * float(h_um.min()), 1e-9)
    if np.isfinite(limit):  # a blown-up, unconverged film (NaN, inf) keeps matplotlib's own
        ax_h.set_ylim(0.0, limit)
    for ax in (ax_p, ax_h):
        ax.axvspan(-1.0, 1.0, color="0.92", zorder=0, label="Hertz width")
    ax_p.legend(loc="upper left", fontsize=8)
    return fig


def transverse_section(y, pressure, film, b, title="Transverse section x = 0"):
    """Pressure and film across the contact at x = 0, over y/b (side view).

    Parameters
    ----------
    y : ndarray
        Node coordinates across the entrainment direction, m.
    pressure, film : ndarray
        p (Pa) and h (m) along x = 0.
    b : float
        Hertz semi-axis along y, m.
    title : str
        Figure title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = new_figure(6.4, 3.8)
    yb = np.asarray(y) / b
    p_shown, _, p_unit = _shown(pressure, "Pa")
    ax.plot(yb, p_shown, "k-", lw=1.8, label="pressure")
    ax.set(xlabel="y / b", ylabel=f"pressure ({p_unit})", title=title)
    ax2 = ax.twinx()
    film = np.asarray(film, dtype=float)
    inside = np.abs(yb) <= 1.0
    # the film's scale: the median over the Hertz width, or the centre's film where more
    # than half of that width has collapsed (probe case 04: a 0.0004 nm median, the 19 nm
    # central film drawn off the top of a 0-0.0012 nm axis)
    typical = (max(float(np.median(film[inside])), float(film[np.argmin(np.abs(yb))]))
               if inside.any() else None)
    h_um, h_scale, h_unit = _shown(film, "m", typical)
    ax2.plot(yb, h_um, "b-", lw=1.2, label="film")
    top = 3.0 * typical * h_scale if typical is not None else float(h_um.max())
    ax2.set_ylim(0.0, max(top, 1e-9))
    ax2.set_ylabel(f"film ({h_unit})", color="b")
    band = ax.axvspan(-1.0, 1.0, color="0.92", zorder=0)
    handles = [*ax.get_lines(), *ax2.get_lines(), band]
    fig.legend(handles, ["pressure", "film", "Hertz width"], loc="outside lower center",
               ncols=3, fontsize=8, frameon=False)
    return fig
