"""Figures of a gear pair along its path of contact, against the pinion roll angle.

Each panel marks the points A-E of the path (dotted verticals); the single-tooth contact zone
B-D is shaded unless the overlap ratio reaches 1 (the load is then shared uniformly), and the
shading has a legend entry. The load sharing of a spur pair jumps at B and D (ISO/TR 13989-1:
2/3 outside, 1 on B..D); the load and Hertz pressure are drawn with the value on both sides of
each jump at the same roll angle, so the jump is a step and not a ramp to the neighbouring node;
the films, lambda, friction and temperatures step there too where the path result holds the
solves of the two-pair sides (``solve_path(..., two_pair_sides=True)``, as ``asperity run``
solves them), and are drawn with their line broken across each jump where it does not.
Temperatures are drawn in deg C (bulk and contact temperature), with the flash temperature rise
(K) as the axis on the right, so that one axis never mixes the two. Positions whose EHL solve
did not converge are crossed out (red x, with a legend entry) on the film, lambda, friction
and temperature curves: their values are drawn but are not solutions.
"""

from __future__ import annotations

import math

import numpy as np

from ..gears.loading import load_jumps
from ..gears.path import BOUNDARY_LUBRICATION_LAMBDA
from .style import new_figure

__all__ = ["conditions_figure", "film_figure", "friction_temperature_figure", "solved_curve",
           "step_curve"]

BAND_LABEL = "single tooth contact B-D"
UNCONVERGED_LABEL = "EHL solve not converged (not a solution)"


def _cross_unconverged(ax, result, values, label: bool = False):
    """A red x on ``values`` at the loaded positions whose EHL solve did not converge, with a
    legend entry when ``label``."""
    bad = (result.load > 0) & ~np.asarray(result.converged, dtype=bool)
    if bad.any():
        ax.plot(_angle(result)[bad], np.asarray(values, dtype=float)[bad], "x", color="C3",
                ms=8, mew=1.5, label=UNCONVERGED_LABEL if label else None, zorder=5)


def _mark_points(ax, result, band_label: bool = False):
    """Dotted verticals and labels at A-E (C only where it lies on the path); shade B-D
    (single tooth contact) where it matters, with a legend entry when ``band_label``."""
    rb1 = result.pair.rb[0]
    pts = {k: math.degrees(v / rb1) for k, v in result.pair.points.items()
           if k != "C" or result.pair.pitch_on_path}
    if result.pair.overlap_ratio < 1.0:  # helical pairs with full overlap share uniformly
        lo, hi = sorted((pts["B"], pts["D"]))
        ax.axvspan(lo, hi, color="0.92", zorder=0, label=BAND_LABEL if band_label else None)
    for name, angle in pts.items():
        ax.axvline(angle, color="0.5", ls=":", lw=0.8)
        ax.annotate(name, (angle, 1.0), xycoords=("data", "axes fraction"), ha="center",
                    va="bottom", fontsize=8)


def _angle(result):
    return np.degrees(result.kin.roll_angle)


def _jumps(result):
    """The load-sharing jumps at the result's positions on B and D
    (:func:`~asperity.gears.loading.load_jumps`)."""
    return load_jumps(result.pair, result.kin.rho1)


def step_curve(result, values, exponent: float = 1.0):
    """Roll angles (deg) and ``values`` with the load-sharing jumps at B and D as steps.

    Where a path node lies on B or D (as :meth:`GearPair.path` places them), a second point
    at the same roll angle carries the value on the two-pair side of the jump: the node's
    value times ``(X_outside / X_node) ** exponent`` (X the load sharing factor). The load is
    proportional to X (``exponent`` 1); the Hertz pressure to X^(1/2) in a line contact and
    X^(1/3) in an elliptical one, at the same radius.

    Parameters
    ----------
    result : GearPathResult
    values : array_like
        One value per path position.
    exponent : float
        Power of X the value scales with.

    Returns
    -------
    (ndarray, ndarray)
        Roll angles and values, with the duplicated points inserted.
    """
    def point(k, jump, angle, value):
        return angle, value * (jump.outside / jump.share) ** exponent

    return _inserted(result, values, point)


def solved_curve(result, name: str, scale: float = 1.0):
    """Roll angles (deg) and ``getattr(result, name) * scale`` (a value the EHL solves give,
    one per path position: films, lambda, friction, temperatures) with the load-sharing jumps
    at B and D as steps where the two-pair side is solved, else with the line broken there.

    Where ``result.two_pair_side`` holds a converged solve of the jump's two-pair side
    (:func:`asperity.gears.solve_path` with ``two_pair_sides``), a second point at the roll
    angle of B (D) carries its value; otherwise a NaN point breaks the line between the node
    on B and the one before it (between D and the one after it): drawn node to node, a line
    from the last two-pair node to the single-pair node on B drew a ramp where the load, and
    with it the film, jumps.
    """
    values = np.asarray(getattr(result, name), dtype=float) * scale
    side = result.two_pair_side

    def point(k, jump, angle, value):
        if side is None or not side.converged[k]:
            return np.nan, np.nan
        return angle, float(getattr(side, name)[k]) * scale

    return _inserted(result, values, point)


def _inserted(result, values, point):
    """Roll angles and ``values`` with one point inserted at each jump of :func:`_jumps`, on
    its two-pair side: ``point(k, jump, angle, value)`` gives it from the k-th jump and its
    node's angle and value."""
    x = list(_angle(result))
    y = list(np.asarray(values, dtype=float))
    inserts = [(jump.index if jump.side < 0 else jump.index + 1,
                *point(k, jump, x[jump.index], y[jump.index]))
               for k, jump in enumerate(_jumps(result))]
    for pos, angle, value in sorted(inserts, reverse=True):
        x.insert(pos, angle)
        y.insert(pos, value)
    return np.array(x), np.array(y)


def film_figure(result, title, sigma_label: str = "sigma the composite roughness"):
    """Central and minimum film (solver, formulas) and lambda against the roll angle.

    ``sigma_label`` says what sigma of lambda = h_min / sigma is (e.g.
    ``"sigma = sqrt(Ra1² + Ra2²)"``); its value in um is added.
    """
    fig, (ax, ax2) = new_figure(6.4, 6.0, nrows=2, sharex=True)
    ax.plot(*solved_curve(result, "central_film", 1e6), "C0-o", ms=3,
            label="central film (solver)")
    ax.plot(*solved_curve(result, "minimum_film", 1e6), "C1-o", ms=3,
            label="minimum film (solver)")
    ax.plot(*solved_curve(result, "formula_central", 1e6), "C0--",
            label=f"central ({result.formula_names[0]})")
    ax.plot(*solved_curve(result, "formula_minimum", 1e6), "C1--",
            label=f"minimum ({result.formula_names[1]})")
    _cross_unconverged(ax, result, result.central_film * 1e6, label=True)
    _cross_unconverged(ax, result, result.minimum_film * 1e6)
    ax.set_ylabel("film thickness (µm)")
    _mark_points(ax, result, band_label=True)
    ax.legend(fontsize=7)
    ax.set_title(title, pad=14)
    ax2.plot(*solved_curve(result, "specific_film"), "C2-o", ms=3)
    _cross_unconverged(ax2, result, result.specific_film)
    ax2.axhline(1.0, color="C3", lw=0.8, ls="--", label="lambda = 1")
    if np.nanmin(result.specific_film) < 1.0:
        ax2.axhline(BOUNDARY_LUBRICATION_LAMBDA, color="C3", lw=0.8, ls=":",
                    label=f"lambda = {BOUNDARY_LUBRICATION_LAMBDA:g}: boundary lubrication")
    ax2.legend(fontsize=7)
    ax2.set_ylabel(f"lambda = h_min / sigma\n{sigma_label} = "
                   f"{result.composite_roughness * 1e6:.3g} µm", fontsize=9)
    ax2.set_xlabel("pinion roll angle (deg)")
    _mark_points(ax2, result)
    return fig


def conditions_figure(result, title):
    """Load per length (or load), Hertz pressure, rolling and sliding speeds, reduced radius;
    load and pressure step at B and D (:func:`step_curve`)."""
    fig, axes = new_figure(6.4, 7.5, nrows=3, sharex=True)
    x = _angle(result)
    unit, scale = ("N/mm", 1e-3) if result.line else ("N", 1.0)
    xs, load = step_curve(result, result.load * scale)
    axes[0].plot(xs, load, "C0-", label="normal load")
    axes[0].plot(x, result.load * scale, "C0o", ms=3)
    axes[0].set_ylabel(f"normal load ({unit})")
    # from zero: a helical pair's constant load was drawn on a 130-142 N/mm axis
    axes[0].set_ylim(0.0, 1.1 * float(np.nanmax(load)))
    twin = axes[0].twinx()
    xs, p = step_curve(result, result.hertz_pressure * 1e-9, 0.5 if result.line else 1 / 3)
    twin.plot(xs, p, "C3-", label="Hertz p_max")
    twin.set_ylabel("Hertz pressure (GPa)", color="C3")
    _mark_points(axes[0], result, band_label=True)
    handles, labels = axes[0].get_legend_handles_labels()
    more, more_labels = twin.get_legend_handles_labels()
    axes[0].legend(handles + more, labels + more_labels, fontsize=7, loc="lower center")
    axes[1].plot(x, result.kin.u1, "C0-", label="u1 (pinion)")
    axes[1].plot(x, result.kin.u2, "C1-", label="u2 (wheel)")
    axes[1].plot(x, result.kin.sliding_speed, "C2--", label="sliding u1 - u2")
    axes[1].set_ylabel("speed (m/s)")
    axes[1].legend(fontsize=7)
    axes[2].plot(x, result.kin.reduced_radius * 1e3, "C4-")
    axes[2].set_ylabel("reduced radius R (mm)")
    axes[2].set_xlabel("pinion roll angle (deg)")
    for ax in axes[1:]:
        _mark_points(ax, result)
    axes[0].set_title(title, pad=14)
    return fig


def friction_temperature_figure(result, title, bulk_temperature, newtonian=False):
    """Friction coefficient (EHL traction and mixed) and the contact temperature.

    ``newtonian``: the lubricant has no Eyring stress, so there is no EHL traction (it is NaN,
    left out; :func:`asperity.gears.solve_path`): the panel says so, and the friction and
    temperatures are drawn only where the asperities carry all the load. Temperatures: the
    left axis is deg C (contact = bulk + flash, and the bulk), the right axis the flash
    temperature rise in K on the same scale.
    """
    fig, (ax, ax2) = new_figure(6.4, 6.0, nrows=2, sharex=True)
    if newtonian:
        ax.plot([], [], " ", label="EHL traction left out (Newtonian: no lubricant.tau0)")
    else:
        ax.plot(*solved_curve(result, "ehl_friction"), "C0--",
                label="EHL traction (Eyring)")
    ax.plot(*solved_curve(result, "friction"), "C0-o", ms=3, label="with boundary share")
    _cross_unconverged(ax, result, result.friction, label=True)
    ax.set_ylabel("friction coefficient")
    _mark_points(ax, result, band_label=True)
    ax.legend(fontsize=7)
    ax.set_title(title, pad=14)
    ax2.plot(*solved_curve(result, "contact_temperature"), "C3-o", ms=3,
             label="contact temperature = bulk + flash")
    ax2.axhline(bulk_temperature, color="0.4", lw=0.8, ls="--", label="bulk temperature")
    _cross_unconverged(ax2, result, result.contact_temperature)
    ax2.set_ylabel("temperature (deg C)")
    rise = ax2.secondary_yaxis("right", functions=(lambda t: t - bulk_temperature,
                                                   lambda d: d + bulk_temperature))
    rise.set_ylabel("flash temperature rise (K)")
    ax2.set_xlabel("pinion roll angle (deg)")
    ax2.legend(fontsize=7)
    _mark_points(ax2, result)
    return fig
