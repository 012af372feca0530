"""Figures of rough surfaces: profiles (seed Fig. 1 style), height maps, spectra, Fig. 4.2,
the P/W/R profile families and the material ratio curve with its equivalent straight line."""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import LogFormatterSciNotation, LogLocator, NullFormatter

from ..errors import InputError
from ..surfaces.machining import TurnedSurface, roughness_along
from ..surfaces.material_ratio import equivalent_line, material_ratio_curve, rk_parameters
from ..surfaces.parameters import power_spectrum
from ..surfaces.topography import Profile, Topography
from .style import map_aspect, map_ylabel, new_figure, plt

__all__ = ["plot_families", "plot_material_ratio", "plot_profiles", "plot_spectrum",
           "plot_surface", "plot_texture", "plot_topography", "plot_turning_roughness"]


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
    ax.set(xlabel="x (mm)", ylabel="height (µm, offset)", title=title)
    return fig


#: Longest side (m) of a height map below which its axes are in um rather than mm (a 60 um
#: field of view read 0.00 ... 0.06 mm).
MAP_IN_UM = 1e-3


#: Colour of masked (not measured) points in a height map.
MASKED_COLOUR = "0.75"


def _draw_map(ax, topography: Topography, title: str, masked=None):
    """A height map (µm) over x, y in um (fields under :data:`MAP_IN_UM`) or mm, x to the
    right and y up, with its colour bar beside it: the colour bar is an inset of the map's
    axes, so that it stays against the map when the map is narrower than its cell. It is
    drawn to scale unless one side is more than
    :data:`~asperity.plotting.style.MAX_MAP_ASPECT` times the other
    (:func:`~asperity.plotting.style.map_aspect`: a 3 x 50 map was a sliver under its colour
    bar's label, its x ticks on top of each other). Points ``masked`` (not measured: filled
    for the filters) are drawn in :data:`MASKED_COLOUR`, left out of the colour scale, and the
    title counts them."""
    scale, unit = (1e6, "µm") if max(np.ptp(topography.x), np.ptp(topography.y)) < MAP_IN_UM \
        else (1e3, "mm")
    heights = topography.z.T * 1e6
    cmap = plt.get_cmap("viridis").with_extremes(bad=MASKED_COLOUR)
    if masked is not None and np.any(masked):
        heights = np.ma.masked_array(heights, np.asarray(masked, bool).T)
        title = (f"{title}\ngrey: {int(np.sum(masked))} masked points (not measured; filled "
                 "only for the filters)")
    mesh = ax.pcolormesh(topography.x * scale, topography.y * scale, heights, shading="auto",
                         cmap=cmap)
    aspect = map_aspect(*(n * h for n, h in zip(topography.shape, topography.spacing,
                                                 strict=True)))
    ax.set(xlabel=f"x ({unit})", ylabel=map_ylabel(aspect, f"y ({unit})"), title=title,
           aspect=aspect)
    ax.figure.colorbar(mesh, cax=ax.inset_axes([1.03, 0.0, 0.035, 1.0]), label="height (µm)")
    return mesh


def _log_q_axis(ax, q) -> None:
    """Log ticks along q readable at any span: minor ticks unlabelled, and majors at 1, 2 and
    5 per decade over less than two decades (where matplotlib labelled every minor tick, their
    labels overlapping)."""
    q = np.asarray(q)
    span = np.log10(q[q > 0].max() / q[q > 0].min())
    if span < 2:
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0), numticks=12))
        ax.xaxis.set_major_formatter(LogFormatterSciNotation(
            labelOnlyBase=False, minor_thresholds=(np.inf, np.inf)))  # label every major
    ax.xaxis.set_minor_formatter(NullFormatter())


def plot_topography(topography: Topography, title="Topography", masked=None):
    """Height map (µm) over x, y (um or mm, :func:`_draw_map`), x to the right; ``masked``
    points drawn grey."""
    fig, ax = new_figure(5.8, 4.8)
    _draw_map(ax, topography, title, masked)
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
    _draw_spectrum(ax, spec, title)
    return fig


#: Decades of the PSD drawn below its peak: lower values are the FFT's round-off floor.
PSD_DECADES = 12
#: Fewest wavevectors of a spectrum drawn as a line; fewer are drawn as points, and the panel
#: says the field is too small for a spectrum (a 3 x 50 map has one: its panel was empty).
FEW_WAVEVECTORS = 8


def _draw_spectrum(ax, spec, title):
    """The PSD on log-log axes, its unit as a power (m³ for a profile, m⁴ for a map), down to
    :data:`PSD_DECADES` below its peak (a Gaussian spectrum falls to round-off at 1e-57 m⁴,
    which squeezed the measured part into the top of the panel); under
    :data:`FEW_WAVEVECTORS` of them, as points with a word on it."""
    few = spec.q.size < FEW_WAVEVECTORS
    ax.loglog(spec.q, spec.psd, "ko-" if few else "k-", lw=0.8, ms=4)
    positive = spec.psd[spec.psd > 0]
    if few:
        _few_wavevectors(ax, spec.q, positive)
    else:
        _log_q_axis(ax, spec.q)
        if positive.size:
            ax.set_ylim(bottom=max(positive.min(), positive.max() * 10.0**-PSD_DECADES) / 2)
    ax.set(xlabel="q (rad/m)", ylabel=f"C (q) ({'m³' if spec.dim == 1 else 'm⁴'})",
           title=title)


def _few_wavevectors(ax, q, positive) -> None:
    """Limits a decade around a spectrum of few points, and the word that the field is too
    small for a spectrum, below them."""
    ax.set_xlim(q.min() / 3, q.max() * 3)
    _log_q_axis(ax, ax.get_xlim())
    if positive.size:
        ax.set_ylim(positive.min() / 10, positive.max() * 10)
    ax.text(0.5, 0.08, f"only {q.size} wavevector{'s' if q.size != 1 else ''}: the field is "
            "too small for a spectrum", transform=ax.transAxes, ha="center", va="center",
            fontsize=8, wrap=True)


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
    ax.set(xlabel="distance along workpiece (mm)", ylabel=f"{parameter} (µm)", title=title)
    if any(labels) or parameter == "Rt":
        ax.legend(fontsize=8)
    return fig


def plot_material_ratio(heights, prefix="R", ax=None, title="Material ratio curve",
                        construction=True):
    """The Abbott-Firestone curve with the ISO 13565-2 equivalent straight line.

    Draws the curve (heights in um against material ratio in %), the 40 % window the line was
    fitted in, the line from 0 to 100 %, the core limits at Mr1/Mr2 (Smr1/Smr2) and the
    triangles of the reduced peak and valley heights.

    Parameters
    ----------
    heights : array_like
        Roughness profile over the evaluation length, or the scale-limited surface (m).
    prefix : "R" or "S"
    ax : matplotlib Axes, optional
        Draw into it instead of a new figure.
    construction : bool
        Draw the equivalent line and the Rk (Sk) construction; False: the curve alone, titled
        as too few points for it (a map too small for the Sk family,
        :func:`~asperity.surfaces.areal.small_grid`).
    """
    fig = None
    if ax is None:
        fig, ax = new_figure(5.0, 4.2)
    mr, c = material_ratio_curve(heights)
    if not construction:
        ax.plot(mr * 100, c * 1e6, "k.-", lw=1.0, ms=3, label="material ratio curve")
        ax.set(xlabel="material ratio (%)", ylabel="height (µm)", xlim=(0, 100),
               title=f"{title}: {np.size(heights)} points, too few for the "
                     f"{'Sk' if prefix == 'S' else 'Rk'} construction")
        ax.title.set_fontsize(9)
        return fig if fig is not None else ax.figure
    line = equivalent_line(heights)
    rk = rk_parameters(heights, prefix)
    names = ("Sk", "Spk", "Svk", "Smr1", "Smr2") if prefix == "S" else (
        "Rk", "Rpk", "Rvk", "Mr1", "Mr2")
    k, pk, vk, m1, m2 = (rk[n] for n in names)
    top, bottom = line(0.0), line(1.0)
    ax.plot(mr * 100, c * 1e6, "k-", lw=1.0, label="material ratio curve")
    ax.plot([0, 100], [top * 1e6, bottom * 1e6], "C0--", lw=1.0, label="equivalent line")
    lo, hi = line.window
    ax.axvspan(lo * 100, hi * 100, color="C0", alpha=0.08, lw=0, label="40 % window")
    ax.hlines([top * 1e6, bottom * 1e6], 0, 100, colors="0.5", lw=0.6)
    ax.fill([0, 0, m1 * 100], [top * 1e6, (top + pk) * 1e6, top * 1e6], color="C3", alpha=0.3,
            lw=0, label=f"{names[1]} = {pk * 1e6:.3g} µm")
    ax.fill([100, 100, m2 * 100], [bottom * 1e6, (bottom - vk) * 1e6, bottom * 1e6], color="C2",
            alpha=0.3, lw=0, label=f"{names[2]} = {vk * 1e6:.3g} µm")
    ax.set(xlabel="material ratio (%)", ylabel="height (µm)", xlim=(0, 100),
           title=f"{title}: {names[0]} = {k * 1e6:.3g} µm, {names[3]} = {m1 * 100:.3g} %, "
                 f"{names[4]} = {m2 * 100:.3g} %")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=7, loc="upper right")
    return fig if fig is not None else ax.figure


def plot_families(families, title="Profiles", axes=None, masked=None):
    """P with its W mean line, and R with the evaluation length marked (two stacked axes);
    the stretches of points ``masked`` (not measured: filled for the filter) shaded grey."""
    fig = None
    if axes is None:
        fig, axes = new_figure(7.0, 4.5, nrows=2, sharex=True)
    p, w, r = families.primary, families.waviness, families.roughness
    ev = families.evaluation
    for k, (start, stop) in enumerate(_runs(masked)):
        for ax in axes:
            ax.axvspan(p.x[start] * 1e3, p.x[stop - 1] * 1e3, color=MASKED_COLOUR, alpha=0.6,
                       lw=0, label="masked: not measured (filled)" if k == 0 and ax is axes[0]
                       else "_nolegend_")
    axes[0].plot(p.x * 1e3, p.z * 1e6, "k-", lw=0.5, label="primary P")
    axes[0].plot(w.x * 1e3, w.z * 1e6, "C3-", lw=1.2,
                 label=f"waviness W (lambda_c = {families.cutoff * 1e3:.3g} mm)")
    axes[1].plot(r.x * 1e3, r.z * 1e6, "k-", lw=0.5, label="roughness R")
    for edge in (r.x[ev.start], r.x[ev.stop - 1]):
        axes[1].axvline(edge * 1e3, color="C0", lw=0.8, ls="--")
    for k in range(1, families.sampling_lengths):
        axes[1].axvline(r.x[ev.start] * 1e3 + k * families.cutoff * 1e3, color="0.7", lw=0.5)
    axes[0].set(ylabel="height (µm)", title=title)
    axes[1].set(xlabel="x (mm)", ylabel="height (µm)")
    for ax in axes:
        ax.legend(fontsize=7, loc="upper right")
    return fig if fig is not None else axes[0].figure


def _runs(mask) -> list[tuple[int, int]]:
    """The (start, stop) index ranges where a 1-D mask is True (none for None)."""
    if mask is None or not np.any(mask):
        return []
    edges = np.diff(np.r_[0, np.asarray(mask, int), 0])
    return list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1), strict=True))


def plot_texture(texture, title="Surface texture"):
    """One figure of a :class:`~asperity.surfaces.texture.TextureEvaluation`: the P/W/R
    profiles (or the scale-limited height map), the PSD and the material ratio curve -- of
    the measured points: masked ones (:attr:`~asperity.surfaces.texture.TextureEvaluation.
    excluded`) are marked in the profiles or map and left out of the curve, as they are out
    of the parameters."""
    from ..surfaces.areal import AreaFamilies, measured_heights

    fam = texture.families
    fig = plt.figure(figsize=(9.5, 7.5), layout="constrained")
    grid = fig.add_gridspec(2, 2)
    excluded = texture.excluded
    if isinstance(fam, AreaFamilies):
        surface = fam.scale_limited
        masked = fam.evaluated(excluded)
        _draw_map(fig.add_subplot(grid[0, :]), surface, f"{title}: {fam.label} surface",
                  masked)
        heights, prefix = measured_heights(surface.z, masked), "S"
        construction = np.isfinite(texture.groups["functional"]["Sk"])
    else:
        top = grid[0, :].subgridspec(2, 1, hspace=0.05)
        axes = [fig.add_subplot(top[0])]
        axes.append(fig.add_subplot(top[1], sharex=axes[0]))
        plot_families(fam, title=f"{title}: P, W and R profiles", axes=axes, masked=excluded)
        heights, prefix = fam.evaluated("R"), "R"
        if excluded is not None:
            heights = heights[~np.asarray(excluded, bool)[fam.evaluation]]
        construction = True
    ax = fig.add_subplot(grid[1, 0])
    primary = fam.primary
    spec = power_spectrum(primary, window=None if primary.periodic else "hann")
    _draw_spectrum(ax, spec, "Power spectral density (form removed" + (
        "" if texture.surface.periodic else ", Hann window")
        + ("" if excluded is None else "; masked points filled") + ")")
    ax.title.set_fontsize(9)
    plot_material_ratio(heights, prefix, ax=fig.add_subplot(grid[1, 1]),
                        title=f"{'R' if prefix == 'R' else fam.label}",
                        construction=construction)
    return fig
