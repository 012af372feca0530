"""Whether a measured surface's size, heights and slopes are plausible in the units read, and
which units would make them so.

A file that gives no unit is read as metres; a unit the file names may be wrong (um written
under an 'X (mm)' header). The numbers then say which unit they are in: a roughness
measurement is at most :data:`PLAUSIBLE_LENGTH` long, a profile at least
:data:`SHORTEST_PROFILE` (two of ISO 4288's shortest cut-offs), sampled between
:data:`FINEST_SPACING` and :data:`COARSEST_SPACING`, with a peak-to-valley height below
:data:`PLAUSIBLE_HEIGHT` and an rms slope below :data:`PLAUSIBLE_SLOPE`, not both flatter than
:data:`FLAT_SLOPE` and smoother than :data:`FLAT_HEIGHT`. The slope is that of the heights less
their least-squares plane (line), by forward differences. :func:`suggested_units` tries the
length units a file is written in, commonest first, for the axes whose unit is in doubt and
returns the first that makes the surface plausible; the advice the reader gives names it
(heights in nm with ``--spacing "1 um"`` are advised ``--z-unit nm``, a Talysurf trace with x in
mm ``--x-unit mm``), not always um. :func:`suggested_spacing` does the same for a spacing the
user gave, which no unit of the file changes (a 0.5 nm pixel meant as 0.5 um).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..formatting import format_quantity
from .parameters import residual_heights, rms_gradient
from .topography import Profile

__all__ = ["COARSEST_SPACING", "FINEST_SPACING", "FLAT_HEIGHT", "FLAT_SLOPE", "PLAUSIBLE_HEIGHT",
           "PLAUSIBLE_LENGTH", "PLAUSIBLE_SLOPE", "SHORTEST_PROFILE", "X_UNITS", "Z_UNITS",
           "SPACING_FACTORS", "Scales", "doubts", "suggested_spacing", "suggested_units",
           "unit_option"]

#: Peak-to-valley height (m) above which heights are taken to be in another unit than read,
#: and the length (m) of a profile or side of a topography above which its x unit is doubted.
PLAUSIBLE_HEIGHT = 1e-2
PLAUSIBLE_LENGTH = 1.0
#: RMS slope (Rdq, Sdq) above which the units are doubted: a mean slope angle of 45 degrees,
#: steeper than machined surfaces are and beyond the small-slope assumption of the half-space
#: contact models.
PLAUSIBLE_SLOPE = 1.0
#: RMS slope and rms height (m) below both of which the units are doubted the other way: a
#: surface that flat and that smooth (0.06 mrad, 5 nm) is an optical flat, not a machined
#: one (lapped and polished steel: rms slopes 0.005-0.05, Sq 10 nm and more).
FLAT_SLOPE, FLAT_HEIGHT = 1e-3, 5e-9
#: Shortest profile (m) that can be evaluated: two of ISO 4288's shortest cut-offs, 0.08 mm.
SHORTEST_PROFILE = 0.16e-3
#: Finest and coarsest grid spacings (m) of a roughness measurement read without an x unit: an
#: AFM's nanometre pixels; the 50 um beyond which no ISO 4288 cut-off is sampled (ISO 3274:
#: 5 um at the longest, 8 mm) and optical and stylus instruments do not sample roughness.
FINEST_SPACING, COARSEST_SPACING = 1e-9, 50e-6
#: Length units tried for the coordinates and for the heights, commonest first (metres per
#: unit and name).
X_UNITS = ((1e-6, "um"), (1e-3, "mm"), (1e-9, "nm"), (1.0, "m"))
Z_UNITS = ((1e-6, "um"), (1e-9, "nm"), (1e-3, "mm"), (1.0, "m"))
#: Factors tried on a spacing the user gave, the slips of its unit first (nm for um, um for
#: mm, and the other way round).
SPACING_FACTORS = (1e3, 1e-3, 1e6, 1e-6)


@dataclass(frozen=True)
class Scales:
    """The sizes of a surface as read (m): what :func:`doubts` judges.

    Attributes
    ----------
    profile : bool
    length : float
        The longest side, ``n * spacing``.
    spacing : float
        The coarser grid spacing.
    finest : float
        The finer grid spacing.
    height : float
        Peak-to-valley height.
    rms : float
        RMS height about the least-squares plane (line).
    slope : float
        RMS slope of the heights about that plane (line), forward differences.
    """

    profile: bool
    length: float
    spacing: float
    finest: float
    height: float
    rms: float
    slope: float

    @classmethod
    def of(cls, surface) -> Scales:
        """The scales of a Profile or Topography (filled: no missing points)."""
        z = np.nan_to_num(np.asarray(surface.z, dtype=float))
        level = residual_heights(z, surface.periodic)
        spacing = np.atleast_1d(surface.spacing)
        return cls(isinstance(surface, Profile),
                   float(max(n * h for n, h in zip(z.shape, spacing, strict=True))),
                   float(spacing.max()), float(spacing.min()), float(np.ptp(z)),
                   float(np.sqrt(np.mean(level**2))),
                   rms_gradient(surface.with_heights(level))[1])

    def scaled(self, x: float, z: float) -> Scales:
        """The scales with the coordinates times ``x`` and the heights times ``z``."""
        return Scales(self.profile, self.length * x, self.spacing * x, self.finest * x,
                      self.height * z, self.rms * z, self.slope * z / x)


def doubts(scales: Scales, x_in_doubt: bool = True, short: bool = True) -> list[str]:
    """What is implausible about a surface of these scales (empty: nothing).

    ``x_in_doubt`` (the x unit read for want of one, or suggested) also tests the spacing
    against :data:`FINEST_SPACING` and :data:`COARSEST_SPACING`, which a unit the file names
    or a pixel size is not held to; ``short`` tests a profile against
    :data:`SHORTEST_PROFILE` (no larger unit than metres makes a short trace in metres longer:
    the reader leaves that to the evaluation, which refuses it)."""
    out = []
    if scales.length > PLAUSIBLE_LENGTH:
        out.append(f"length {_m(scales.length)} (limit {PLAUSIBLE_LENGTH:g} m)")
    if short and scales.profile and scales.length < SHORTEST_PROFILE:
        out.append(f"length {_m(scales.length)} (limit: at least {SHORTEST_PROFILE * 1e3:g} mm, "
                   "two of ISO 4288's shortest cut-offs)")
    if x_in_doubt and scales.spacing > COARSEST_SPACING:
        out.append(f"spacing {_m(scales.spacing)} (limit {COARSEST_SPACING * 1e6:g} um)")
    if x_in_doubt and scales.finest < FINEST_SPACING:
        out.append(f"spacing {_m(scales.finest)} (limit: at least {FINEST_SPACING * 1e9:g} nm)")
    if scales.height > PLAUSIBLE_HEIGHT:
        out.append(f"peak-to-valley {_m(scales.height)} (limit {PLAUSIBLE_HEIGHT * 1e3:g} mm)")
    if scales.slope > PLAUSIBLE_SLOPE:
        out.append(f"rms slope {scales.slope:.4g} (limit {PLAUSIBLE_SLOPE:g})")
    if scales.slope < FLAT_SLOPE and scales.rms < FLAT_HEIGHT:
        out.append(f"rms slope {scales.slope:.3g} and rms height {scales.rms * 1e9:.3g} nm "
                   f"(limits: at least {FLAT_SLOPE:g} or {FLAT_HEIGHT * 1e9:g} nm; an optical "
                   "flat)")
    return out


def _m(length: float) -> str:
    return format_quantity(length, "m")


def suggested_units(scales: Scales, x_factor: float | None,
                    z_factor: float | None) -> tuple[str | None, str | None] | None:
    """The units of the coordinates and heights that make a surface plausible.

    Parameters
    ----------
    scales : Scales
        Of the surface as read.
    x_factor, z_factor : float or None
        Metres per unit read of the coordinates and of the heights, where that unit is in
        doubt (read for want of one, or implausible); None where it is not, which keeps it.

    Returns
    -------
    (str or None, str or None) or None
        The names of the units to give (None for an axis kept), the first plausible pair of
        :data:`X_UNITS` and :data:`Z_UNITS`; None when no pair is plausible.
    """
    xs = [(None, None)] if x_factor is None else X_UNITS
    zs = [(None, None)] if z_factor is None else Z_UNITS
    for x, x_name in xs:
        for z, z_name in zs:
            trial = scales.scaled(1.0 if x is None else x / x_factor,
                                  1.0 if z is None else z / z_factor)
            if not doubts(trial, x_factor is not None):
                return x_name, z_name
    return None


def suggested_spacing(scales: Scales) -> float | None:
    """The factor on a spacing given by the user that makes a surface plausible, its heights
    kept.

    Parameters
    ----------
    scales : Scales
        Of the surface as read, with the spacing given.

    Returns
    -------
    float or None
        The first of :data:`SPACING_FACTORS` whose spacing passes :func:`doubts` with the
        spacing held to :data:`FINEST_SPACING` and :data:`COARSEST_SPACING`; None when none
        does (heights 1000 times too large stay too high whatever the spacing).
    """
    return next((f for f in SPACING_FACTORS if not doubts(scales.scaled(f, 1.0))), None)


def unit_option(x_name: str | None = None, z_name: str | None = None) -> str:
    """``--x-unit mm and --z-unit um (case file: x_unit = "mm", z_unit = "um")``: how to give
    the units named (None: not that axis)."""
    given = [(axis, name) for axis, name in (("x", x_name), ("z", z_name)) if name]
    return (" and ".join(f"--{axis}-unit {name}" for axis, name in given) + " (case file: "
            + ", ".join(f"{axis}_unit = \"{name}\"" for axis, name in given) + ")")
