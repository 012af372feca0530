"""Figures of a gear pair along its path of contact, against the pinion roll angle.

Each panel marks the points A-E of the path (dotted verticals); the single-tooth contact zone
B-D is shaded unless the overlap ratio reaches 1 (the load is then shared uniformly).
"""

from __future__ import annotations

import math

import numpy as np

from .style import new_figure

__all__ = ["conditions_figure", "film_figure", "friction_temperature_figure"]


def _mark_points(ax, result):
    """Dotted verticals and labels at A-E; shade B-D (single tooth contact) where it matters."""
    rb1 = result.pair.rb[0]
    pts = {k: math.degrees(v / rb1) for k, v in result.pair.points.items()}
    if result.pair.overlap_ratio < 1.0:  # helical pairs with full overlap share uniformly
        lo, hi = sorted((pts["B"], pts["D"]))
        ax.axvspan(lo, hi, color="0.92", zorder=0)
    for name, angle in pts.items():
        ax.axvline(angle, color="0.5", ls=":", lw=0.8)
        ax.annotate(name, (angle, 1.0), xycoords=("data", "axes fraction"), ha="center",
                    va="bottom", fontsize=8)


def _angle(result):
    return np.degrees(result.kin.roll_angle)


def film_figure(result, title):
    """Central and minimum film (solver, formulas) and lambda against the roll angle."""
    fig, (ax, ax2) = new_figure(6.4, 6.0, nrows=2, sharex=True)
    x = _angle(result)
    ax.plot(x, result.central_film * 1e6, "C0-o", ms=3, label="central film (solver)")
    ax.plot(x, result.minimum_film * 1e6, "C1-o", ms=3, label="minimum film (solver)")
    ax.plot(x, result.formula_central * 1e6, "C0--",
            label=f"central ({result.formula_names[0]})")
    ax.plot(x, result.formula_minimum * 1e6, "C1--",
            label=f"minimum ({result.formula_names[1]})")
    ax.set_ylabel("film thickness (um)")
    ax.legend(fontsize=7)
    _mark_points(ax, result)
    ax.set_title(title, pad=14)
    ax2.plot(x, result.specific_film, "C2-o", ms=3)
    ax2.axhline(1.0, color="C3", lw=0.8, ls="--")
    ax2.set_ylabel("lambda = h_min / sigma")
    ax2.set_xlabel("pinion roll angle (deg)")
    _mark_points(ax2, result)
    return fig


def conditions_figure(result, title):
    """Load per length (or load), Hertz pressure, rolling and sliding speeds, reduced radius."""
    fig, axes = new_figure(6.4, 7.5, nrows=3, sharex=True)
    x = _angle(result)
    unit, scale = ("N/mm", 1e-3) if result.line else ("N", 1.0)
    axes[0].plot(x, result.load * scale, "C0-o", ms=3)
    axes[0].set_ylabel(f"normal load ({unit})")
    twin = axes[0].twinx()
    twin.plot(x, result.hertz_pressure * 1e-9, "C3-", label="Hertz p_max")
    twin.set_ylabel("Hertz pressure (GPa)", color="C3")
    axes[1].plot(x, result.kin.u1, "C0-", label="u1 (pinion)")
    axes[1].plot(x, result.kin.u2, "C1-", label="u2 (wheel)")
    axes[1].plot(x, result.kin.sliding_speed, "C2--", label="sliding u1 - u2")
    axes[1].set_ylabel("speed (m/s)")
    axes[1].legend(fontsize=7)
    axes[2].plot(x, result.kin.reduced_radius * 1e3, "C4-")
    axes[2].set_ylabel("reduced radius R (mm)")
    axes[2].set_xlabel("pinion roll angle (deg)")
    for ax in axes:
        _mark_points(ax, result)
    axes[0].set_title(title, pad=14)
    return fig


def friction_temperature_figure(result, title, bulk_temperature, newtonian=False):
    """Friction coefficient (EHL traction and mixed) and flash/contact temperature.

    ``newtonian``: the lubricant has no Eyring stress, so the EHL "traction" is a Newtonian
    film's ``eta du / h`` (labelled so); where it exceeds 1, which no traction does, the
    axis is logarithmic so that the mixed friction stays readable beside it.
    """
    fig, (ax, ax2) = new_figure(6.4, 6.0, nrows=2, sharex=True)
    x = _angle(result)
    law = "Newtonian, no tau0" if newtonian else "Eyring"
    ax.plot(x, result.ehl_friction, "C0--", label=f"EHL traction ({law})")
    ax.plot(x, result.friction, "C0-o", ms=3, label="with boundary share")
    if np.nanmax(result.ehl_friction) > 1.0:
        ax.set_yscale("log")
    ax.set_ylabel("friction coefficient")
    ax.legend(fontsize=7)
    _mark_points(ax, result)
    ax.set_title(title, pad=14)
    ax2.plot(x, result.flash_temperature, "C3-o", ms=3, label="flash temperature (K)")
    ax2.plot(x, result.contact_temperature, "C1-", label="contact temperature (deg C)")
    ax2.axhline(bulk_temperature, color="0.4", lw=0.8, ls="--", label="bulk temperature")
    ax2.set_ylabel("temperature")
    ax2.set_xlabel("pinion roll angle (deg)")
    ax2.legend(fontsize=7)
    _mark_points(ax2, result)
    return fig
