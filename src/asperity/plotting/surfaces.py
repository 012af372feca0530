"""Figures of rough surfaces: profiles (seed Fig. 1 style), height maps, spectra, Fig. 4.2."""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..surfaces.machining import TurnedSurface, roughness_along
from ..surfaces.parameters import power_spectrum
from ..surfaces.topography import Profile, Topography
from .style import new_figure

__all__ = ["plot_profiles", "plot_spectrum", "plot_surface", "plot_topography",
           "plot_turning_roughness"]


def plot_profiles(profiles, offset=None, title="Surface profiles"):
    """Profiles stacked with a vertical offset, metal below (the mixed-EHL seed's Fig. 1).

    Parameters
    ----------
    profiles : dict of str to Profile, or a single Profile
    offset : float, optional
        Vertical spacing between traces (m); default 1.2 times the largest peak-to-valley.
    """
    if isinstance(profiles, Profile):
        profiles = {"": profiles}
    if not profiles:
        raise InputError("profiles", "at least one Profile")
    if offset is None:
        offset = 1.2 * max(np.ptp(p.z) for p in profiles.values())
    fig, ax = new_figure(7.0, 1.0 + 1.1 * len(profiles))
    for i, (name, p) in enumerate(profiles.items()):
        shift = -i * offset
        ax.plot(p.x * 1e3, (p.z + shift) * 1e6, "k-", lw=0.6)
        ax.fill_between(p.x * 1e3, (p.z + shift) * 1e6, (shift - 0.5 * offset) * 1e6,
                        color="0.85", lw=0)
        if name:
            ax.text(p.x[0] * 1e3, (shift + 0.25 * offset) * 1e6, f"({name})", fontsize=9)
    ax.set(xlabel="x (mm)", ylabel="height (um, offset)", title=title)
    return fig


def plot_topography(topography: Topography, title="Topography"):
    """Height map (um) over x, y (mm), x to the right."""
    fig, ax = new_figure(5.8, 4.8)
    x, y = topography.x * 1e3, topography.y * 1e3
    mesh = ax.pcolormesh(x, y, topography.z.T * 1e6, shading="auto", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="height (um)")
    ax.set(xlabel="x (mm)", ylabel="y (mm)", title=title, aspect="equal")
    return fig


def plot_surface(surface, title=None):
    """A profile trace or a height map, whichever ``surface`` is."""
    if isinstance(surface, Profile):
        return plot_profiles({"": surface}, title=title or "Profile")
    if isinstance(surface, Topography):
        return plot_topography(surface, title=title or "Topography")
    raise InputError("surface", "a Profile or a Topography", type(surface).__name__)


def plot_spectrum(surface, title="Power spectral density"):
    """Log-log PSD (1-D, or radially averaged 2-D) against wavevector q (rad/m)."""
    spec = power_spectrum(surface)
    fig, ax = new_figure()
    ax.loglog(spec.q, spec.psd, "k-", lw=0.8)
    unit = "m^3" if spec.dim == 1 else "m^4"
    ax.set(xlabel="q (rad/m)", ylabel=f"C (q) ({unit})", title=title)
    return fig


def plot_turning_roughness(results, window, labels=None, parameter="Rt",
                           title="Roughness along the workpiece"):
    """A roughness parameter along the workpiece for turned surfaces (Seireg Fig. 4.2 style).

    Parameters
    ----------
    results : TurnedSurface or sequence of TurnedSurface
    window : float
        Window length (m) of :func:`~asperity.surfaces.roughness_along`.
    labels : sequence of str, optional
    parameter : str
        "Rt" (with the kinematic f^2/8r dashed) or another profile parameter.
    """
    if isinstance(results, TurnedSurface):
        results = [results]
    labels = labels or [None] * len(results)
    fig, ax = new_figure()
    for res, label, marker in zip(results, labels, "os^vD<>", strict=False):
        centres, values = roughness_along(res.profile, window, parameter)
        ax.plot(centres * 1e3, values * 1e6, marker=marker, ms=4, lw=0.8, label=label)
    if parameter == "Rt":
        ax.axhline(results[0].kinematic_rt * 1e6, color="k", ls="--", lw=0.8,
                   label="kinematic f^2/(8r)")
    ax.set(xlabel="distance along workpiece (mm)", ylabel=f"{parameter} (um)", title=title)
    if any(labels) or parameter == "Rt":
        ax.legend(fontsize=8)
    return fig
