"""Areal surface texture (ISO 25178-2/-3): the S-F or S-L surface, its parameters, Str and Std.

The *scale-limited surface* of ISO 25178-3: form removed by least squares (the F-operator,
:func:`~asperity.surfaces.form.remove_form`), wavelengths shorter than the S-filter's nesting
index removed, and, when an L-filter nesting index is given, the wavelengths longer than it
removed too (both the areal Gaussian filter of ISO 16610-61,
:func:`~asperity.surfaces.filters.areal_gaussian_filter`). With an L-filter the result is the
S-L surface, without one the S-F surface; the output says which. The S-L surface of a
non-periodic map is evaluated inside half the L-filter's nesting index of each border, where the
filter runs past the data (``_interior``: ISO 16610-21's half cut-off of a profile's ends).

Spatial parameters (ISO 25178-2 clause 4.3) from the autocorrelation function (ACF) of the
scale-limited surface, zero-padded so that lags wrap nowhere (circular when periodic), from the
lag at which it falls to s = 0.2 along each direction (1 degree steps; the ACF interpolated
along the direction by ``scipy.ndimage.map_coordinates`` out to half the field, the crossing
interpolated linearly between the bracketing lags:
:func:`~asperity.surfaces.parameters.acf_decay_lengths`):

- Sal: the shortest of those lags (NaN when the ACF decays along no direction);
- Str (texture aspect ratio): Sal divided by the longest, from 0 for a strong lay to 1 for an
  isotropic texture; a direction that does not decay within half the field counts with that
  length, so Str is then an upper bound.

Std (texture direction, clause 4.3.3): the angular power spectrum -- the power of the
Hann-windowed surface summed over wavevectors in 0.5 degree sectors -- has its maximum at the
direction across the lay; Std is reported as the direction *of the lay* (the grooves),
counter-clockwise from the x axis, in [0, 180) degrees, refined as the direction of the
power-weighted centroid of the wavevectors within 10 degrees of the maximum (the window's
leakage around a wavevector is symmetric, so the centroid does not snap to the grid).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import scipy.fft

from ..errors import InputError
from .cutoffs import lambda_s_for
from .filters import areal_gaussian_filter
from .form import principal_radii, remove_form
from .material_ratio import rk_parameters, section_height_difference, volume_parameters
from .parameters import acf_decay_lengths, roughness_parameters
from .profiles import height_moments
from .topography import Topography

__all__ = ["ISOTROPIC_STR", "AreaFamilies", "ArealEvaluation", "areal_evaluation",
           "areal_families",
           "areal_parameters", "form_left_in", "measured_heights", "small_grid",
           "texture_aspect_ratio", "texture_direction"]

#: Str above which a surface is isotropic (ISO 25178-2's guide: above 0.5 nearly isotropic,
#: below 0.3 strongly anisotropic), and its Std (lay direction) is noted as undefined.
ISOTROPIC_STR = 0.5

#: ACF threshold s of Sal and Str (ISO 25178-2 default).
ACF_THRESHOLD = 0.2
#: Fraction of the S-F surface's Sq that a polynomial one degree higher than the form removed
#: must take off for form to be taken as left in (:func:`form_left_in`).
FORM_LEFT_IN = 0.02
#: How many times the variance the next-degree terms remove that form must remove.
FORM_DOMINANCE = 4.0
#: Points per side of the grid on which :func:`form_left_in` fits (every k-th point).
FORM_CHECK_POINTS = 512
#: Fewest points along each side for the spatial parameters: the ACF is followed out to half
#: the field, at least 4 lags then to interpolate its fall to 0.2 between, and the angular
#: spectrum of Std has at least 4 wavevectors a side; a 5 x 5 map gave Sal 0.29 um, Str 82 %
#: and Std 0 deg, a 3 x 50 one Sal and Str from one lag across.
SPATIAL_MIN_SIDE = 8
#: Fewest (measured) points for the material-ratio parameters (Sk family, Sdc, Smr, volumes):
#: the material ratio curve is read to 1 / n, the equivalent line fitted over 40 % of the
#: points and Spk, Svk and Vmp, Vvv are of the few beyond the core (about 20 of 256).
MATERIAL_MIN_POINTS = 256


@dataclass(frozen=True)
class AreaFamilies:
    """The scale-limited surfaces of a measured topography.

    Attributes
    ----------
    primary : Topography
        Form removed (the F-operator) and S-filtered: the S-F surface.
    scale_limited : Topography
        The S-L surface when an L-filter is given, otherwise the S-F surface.
    s_filter, l_filter : float or None
        Nesting indices applied (m).
    notes, warnings : tuple of str
    evaluation : (slice, slice)
        The part of the measured grid that ``scale_limited`` covers: all of it, or with an
        L-filter the interior without half its nesting index at each border
        (:func:`areal_families`).
    """

    primary: Topography
    scale_limited: Topography
    s_filter: float | None
    l_filter: float | None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    evaluation: tuple[slice, slice] = (slice(None), slice(None))

    @property
    def label(self) -> str:
        """``"S-L"`` or ``"S-F"`` (the surface the parameters are of)."""
        return "S-L" if self.l_filter is not None else "S-F"

    def evaluated(self, mask):
        """A mask of the measured grid (or None) cut to the evaluated area."""
        return None if mask is None else np.asarray(mask, bool)[self.evaluation]


def form_left_in(surface: Topography, degree: int, advice: str | None = None) -> str | None:
    """A warning when form is left in a surface from which the form of ``degree`` was removed.

    ``advice`` ends the warning (default: the fixes of an S-F surface's evaluation,
    ``--form-degree`` or ``--cutoff``).

    The polynomials of ``degree + 1`` and ``degree + 2`` are fitted to ``surface`` (every k-th
    point, at most :data:`FORM_CHECK_POINTS` a side: the form is smooth). Form is taken to be
    left in when removing the first lowers Sq by more than :data:`FORM_LEFT_IN` (it then holds
    more than sqrt(1 - 0.98^2) = 20 % of Sq in quadrature) and the variance it removes is more
    than :data:`FORM_DOMINANCE` times what the terms of the next degree remove beyond it: a
    cylinder or ball is a quadric, which the cubic terms do not add to, whereas waviness or
    roughness of long correlation projects onto both alike (on 256 x 256 Gaussian surfaces of
    correlation length 1/13 of the field the ratio was 0.05 to 2.3). Under a plane the radius
    named is the smaller principal radius of the least-squares quadric
    (:func:`~asperity.surfaces.form.principal_radii`).
    """
    step = [max(1, -(-n // FORM_CHECK_POINTS)) for n in surface.shape]
    coarse = Topography(surface.x[::step[0]], surface.y[::step[1]],
                        surface.z[::step[0], ::step[1]])
    if min(coarse.shape) < degree + 4 or not np.ptp(coarse.z) > 0:
        return None
    variance = [float(np.var(coarse.z))] + [float(np.var(remove_form(coarse, d).z))
                                            for d in (degree + 1, degree + 2)]
    sq, lower = np.sqrt(variance[:2])
    if lower >= (1 - FORM_LEFT_IN) * sq or (
            variance[0] - variance[1] <= FORM_DOMINANCE * (variance[1] - variance[2])):
        return None
    if degree <= 1:
        radius, _, angle = principal_radii(coarse)
        what = (f"a curvature of about {radius * 1e3:.3g} mm radius, strongest at "
                f"{round(angle) % 180:.0f} deg from x")
    else:
        what = "a form of higher degree"
    surface_name = "S-F surface" if advice is None else "map"
    if advice is None:
        advice = (f"and its height, material-ratio and volume parameters include it; for a "
                  f"curved part (cylinder, ball, crown) remove it: --form-degree {degree + 1} "
                  f"(case file: evaluation.form_degree = {degree + 1}); for a flat part whose "
                  "waviness is as long as the field, give --cutoff (the S-L surface) instead")
    return (f"form: a polynomial of degree {degree + 1} takes {100 * (1 - lower / sq):.2g} % "
            f"off Sq ({sq * 1e6:.4g} -> {lower * 1e6:.4g} um; limit {100 * FORM_LEFT_IN:g} %): "
            f"form is left in the {surface_name} ({what}), "
            f"{advice}")


def areal_families(topography: Topography, *, form_degree=1, l_filter=None,
                   s_filter="iso", exclude=None) -> AreaFamilies:
    """Form removal, S-filter and L-filter of a topography (module docstring).

    Parameters
    ----------
    topography : Topography
    form_degree : int
        Degree of the least-squares polynomial form removed (1: a plane).
    l_filter : float, optional
        L-filter nesting index (m); none by default (the S-F surface).
    s_filter : "iso", None or float
        S-filter nesting index (m): ``"iso"`` takes the one ISO 25178-3 pairs with the L-filter
        (2.5 um for 0.8 mm, as ISO 3274) where the spacing allows; None for none.
    exclude : ndarray of bool, optional
        Points left out of the form's fit (masked missing points, filled): the plane is that
        of the measured points, as ISO 25178-2 takes it, not tilted by the fill.
    """
    if not isinstance(topography, Topography):
        raise InputError("surface", "a Topography", type(topography).__name__)
    notes, warnings = [], []
    measured = None if exclude is None else ~np.asarray(exclude, bool)
    surface = remove_form(topography, form_degree, measured)
    if l_filter is None and not topography.periodic:
        form = form_left_in(surface, form_degree)
        if form is not None:
            warnings.append(form)
    notes.append("form removed: " + ("mean (periodic surface)" if topography.periodic else
                                     f"least-squares polynomial of degree {form_degree}")
                 + ("" if measured is None else
                    f", fitted to the {int(measured.sum())} measured points only"))
    spacing = max(topography.spacing)
    if s_filter == "iso":
        s_filter = None if l_filter is None else lambda_s_for(l_filter, spacing)[0]
    x, y, periodic = topography.x, topography.y, topography.periodic
    if s_filter is not None:
        surface = surface.with_heights(areal_gaussian_filter(surface.z, x, y, s_filter,
                                                             periodic=periodic))
        notes.append(f"S-filter {s_filter * 1e6:.4g} um (areal Gaussian, ISO 16610-61)")
    else:
        notes.append("no S-filter: the spacing bounds the short wavelengths")
    limited, evaluation = surface, (slice(None), slice(None))
    if l_filter is not None:
        extent = min(topography.x.size * topography.spacing[0],
                     topography.y.size * topography.spacing[1])
        if l_filter > extent:
            raise InputError("cutoff", f"an L-filter nesting index within the field "
                             f"({extent:.4g} m; a plain number is metres: give the unit, e.g. "
                             "\"80 um\")", f"{l_filter:.4g} m")
        long = areal_gaussian_filter(surface.z, x, y, l_filter, periodic=periodic)
        limited = surface.with_heights(surface.z - long)
        notes.append(f"L-filter {l_filter * 1e3:.4g} mm (areal Gaussian, first-moment end "
                     "correction at the borders): parameters of the S-L surface")
        if not periodic:
            limited, evaluation = _interior(limited, l_filter, notes, warnings)
    else:
        notes.append("no L-filter (give --cutoff): parameters of the S-F surface")
    return AreaFamilies(surface, limited, s_filter, l_filter, tuple(notes), tuple(warnings),
                        evaluation)


def _interior(limited: Topography, l_filter: float, notes: list, warnings: list):
    """The S-L surface without half the nesting index at each border, and its slices.

    Within lambda/2 of a border the kernel (cut at +-lambda) loses a large part of its weight
    and the end correction, a local Gaussian-weighted plane, follows the roughness more than
    the filter does inside: on a 400 um map (1 um spacing) of 0.1 um roughness with or without
    waves of 250 to 400 um, Sq of the whole S-L surface was 0.75 % low at lambda = 25 um and
    0.44 to 1.15 % low at 80 um against the same surface filtered with 60 um of data beyond
    each border, with single points off by up to 1.9 Sq; without lambda/2 of each border,
    within 0.024 % and 0.015 Sq. This is ISO 16610-21's half cut-off of run-in and run-out of
    a profile, taken at each border of the map. A field shorter than twice lambda along an
    axis is kept whole, with a warning.
    """
    border = [int(math.ceil(0.5 * l_filter / h - 1e-9)) for h in limited.spacing]
    short = [n * h for n, h, b in zip(limited.shape, limited.spacing, border, strict=True)
             if n * h < 2 * l_filter or n - 2 * b < 2]
    if short:
        warnings.append(
            f"L-filter: the field is {min(short) * 1e6:.4g} um across, less than twice the "
            f"nesting index {l_filter * 1e6:.4g} um (limit {2 * l_filter * 1e6:.4g} um), so "
            "the border of half a nesting index where the filter runs past the data is kept "
            "in the parameters (on a 400 um map at 80 um it made Sq 0.4 .. 1.2 % low); measure "
            "a field at least twice the nesting index across, or give a shorter --cutoff")
        return limited, (slice(None), slice(None))
    evaluation = tuple(slice(b, n - b) for n, b in zip(limited.shape, border, strict=True))
    inner = Topography(limited.x[evaluation[0]], limited.y[evaluation[1]],
                       limited.z[evaluation])
    notes.append(f"S-L parameters over the {inner.shape[0]} x {inner.shape[1]} points inside "
                 f"half the nesting index ({0.5 * l_filter * 1e6:.4g} um) of the borders, where "
                 "the filter runs past the data (as ISO 16610-21 leaves half a cut-off at "
                 "each end of a profile)")
    return inner, evaluation


def _decay(topography: Topography, threshold: float) -> tuple[float, float, str | None]:
    """Sal, Str and, when the ACF does not decay along every direction, a note saying so
    (module docstring)."""
    angles, lengths = acf_decay_lengths(topography, threshold=threshold)
    reach = 0.5 * min(n * h for n, h in zip(topography.shape, topography.spacing, strict=True))
    if not np.isfinite(lengths).any():
        return math.nan, math.nan, (
            f"Sal, Str: the autocorrelation falls to {threshold:g} along no direction within "
            f"half the field ({reach * 1e6:.4g} um): not defined (n/a); a larger field or an "
            "L-filter (--cutoff) gives them")
    if np.isfinite(lengths).all():
        return float(lengths.min()), float(lengths.min() / lengths.max()), None
    kept = angles[~np.isfinite(lengths)]
    middle = math.degrees(math.atan2(np.mean(np.sin(np.radians(2 * kept))),
                                     np.mean(np.cos(np.radians(2 * kept))))) / 2 % 180
    lengths = np.where(np.isfinite(lengths), lengths, reach)
    ratio = float(lengths.min() / lengths.max())
    return float(lengths.min()), ratio, (
        f"Str = {100 * ratio:.3g} % is an upper bound: along {kept.size} of {angles.size} "
        f"directions, about {middle:.0f} deg from x (a lay), the autocorrelation does not fall "
        f"to {threshold:g} within half the field ({reach * 1e6:.4g} um), which is taken as "
        "their length, so a larger field gives a smaller Str; Sal is exact")


def texture_aspect_ratio(topography: Topography, threshold=ACF_THRESHOLD) -> tuple[float, bool]:
    """Str (module docstring) and whether it is exact (False: an upper bound)."""
    _, ratio, note = _decay(topography, threshold)
    return ratio, note is None


def texture_direction(topography: Topography) -> float:
    """Std (module docstring): the lay direction in degrees, [0, 180)."""
    z = topography.z - topography.z.mean()
    (nx, ny), (hx, hy) = z.shape, topography.spacing
    window = np.outer(np.hanning(nx), np.hanning(ny))
    power = np.abs(scipy.fft.rfftn(z * window, workers=-1)) ** 2
    qx = scipy.fft.fftfreq(nx, hx)[:, None]
    qy = scipy.fft.rfftfreq(ny, hy)[None, :]
    angle = np.degrees(np.arctan2(np.broadcast_to(qy, power.shape),
                                  np.broadcast_to(qx, power.shape))) % 180.0
    ring = np.hypot(qx / qx.max(), qy / qy.max())
    keep = ring > 2.0 / min(nx, ny)  # leave out the mean and the window's own leakage
    bins = np.arange(0.0, 180.5, 0.5)
    spectrum, _ = np.histogram(angle[keep], bins=bins, weights=power[keep])
    peak = 0.5 * (bins[np.argmax(spectrum)] + bins[np.argmax(spectrum) + 1])
    offset = (angle[keep] - peak + 90.0) % 180.0 - 90.0
    near = np.abs(offset) <= 10.0
    # the power-weighted centroid of the wavevectors there, each turned to the peak's side
    vx = np.broadcast_to(qx, power.shape)[keep][near]
    vy = np.broadcast_to(qy, power.shape)[keep][near]
    side = np.sign(vx * math.cos(math.radians(peak)) + vy * math.sin(math.radians(peak)))
    weights = power[keep][near] * side
    refined = math.degrees(math.atan2(np.sum(weights * vy), np.sum(weights * vx)))
    return float((refined + 90.0) % 180.0)


def areal_parameters(families: AreaFamilies, exclude=None) -> dict[str, dict[str, float]]:
    """ISO 25178-2 parameters of the scale-limited surface (:func:`areal_evaluation`'s)."""
    return areal_evaluation(families, exclude).parameters


class ArealEvaluation(NamedTuple):
    """What :func:`areal_evaluation` returns."""

    #: Parameters by group (see :func:`areal_evaluation`).
    parameters: dict[str, dict[str, float]]
    #: Notes on them: Str an upper bound, Sal and Str undefined, the filled map used.
    notes: tuple[str, ...]
    #: The heights the height, material-ratio and volume parameters are of (m; measured
    #: points only, from their own mean: :func:`measured_heights`).
    heights: np.ndarray
    #: Whether there are enough of them for the material-ratio parameters (:func:`small_grid`).
    material: bool
    #: The warning of a grid too small for some parameters, None when it is not.
    small: str | None


def areal_evaluation(families: AreaFamilies, exclude=None) -> ArealEvaluation:
    """ISO 25178-2 parameters of the scale-limited surface, grouped as the standard groups them,
    with the notes on them and the heights they are of.

    Parameters
    ----------
    families : AreaFamilies
    exclude : ndarray of bool, optional
        Points of the measured grid to leave out of the height, functional and volume
        parameters (masked missing points): those are of the measured points, their heights
        measured from the mean of the measured points. The hybrid and spatial ones, which need
        the whole grid (differences, the ACF and the spectrum), use the filled map, and a note
        says so.

    Returns
    -------
    ArealEvaluation
        Its ``parameters``: ``height``: Sa Sq Ssk Sku Sp Sv Sz (from the mean plane of the
        scale-limited surface); ``hybrid``: Sdq Sdr; ``spatial``: Sal Str Std (degrees);
        ``functional``: Sk Spk Svk Smr1 Smr2 Sdc (C(20 %) - C(80 %)); ``volume``: Vmp Vmc Vvc
        Vvv (m^3/m^2).
    """
    surface = families.scale_limited
    slopes = roughness_parameters(surface)
    z = measured_heights(surface.z, families.evaluated(exclude))
    spatial_ok, material_ok, small = small_grid(surface.shape, z.size)
    sal, str_value, note = (_decay(surface, ACF_THRESHOLD) if spatial_ok else
                            (math.nan, math.nan, None))
    notes = () if note is None else (note,)
    if str_value > ISOTROPIC_STR:
        notes += (f"Std: the surface is isotropic (Str = {100 * str_value:.3g} % > "
                  f"{100 * ISOTROPIC_STR:g} %), so it has no lay for Std to give the direction of; "
                  "its value is the strongest direction of the spectrum, which noise sets",)
    if z.size < surface.z.size:
        notes += (f"Sdq, Sdr, Sal, Str and Std need the whole grid: they are of the map with "
                  f"its {surface.z.size - z.size} masked points filled (harmonic "
                  "interpolation); the height, material-ratio and volume parameters are of "
                  f"the {z.size} measured points, from their own mean plane",)
    return ArealEvaluation({
        "height": height_moments(z, "S"),
        "hybrid": {"Sdq": slopes["Sdq"], "Sdr": slopes["Sdr"]},
        "spatial": {"Sal": sal, "Str": str_value,
                    "Std": texture_direction(surface) if spatial_ok else math.nan},
        "functional": ({**rk_parameters(z, "S"), "Sdc": section_height_difference(z)}
                       if material_ok else dict.fromkeys(_FUNCTIONAL, math.nan)),
        "volume": volume_parameters(z) if material_ok else dict.fromkeys(_VOLUME, math.nan),
    }, notes, z, material_ok, small)


_FUNCTIONAL = ("Sk", "Spk", "Svk", "Smr1", "Smr2", "Sdc")
_VOLUME = ("Vmp", "Vmc", "Vvc", "Vvv")


def small_grid(shape, points: int) -> tuple[bool, bool, str | None]:
    """Whether a grid of ``shape`` with ``points`` measured points is large enough for the
    spatial parameters (:data:`SPATIAL_MIN_SIDE`) and the material-ratio ones
    (:data:`MATERIAL_MIN_POINTS`), and a warning when it is not for either: those are left out
    (n/a), and the standard errors of Ssk and Sku, sqrt(6 / n) and sqrt(24 / n) for Gaussian
    heights, say how little the moments of so few points mean."""
    spatial = min(shape) >= SPATIAL_MIN_SIDE
    material = points >= MATERIAL_MIN_POINTS
    if spatial and material:
        return True, True, None
    out = []
    if not spatial:
        out.append(f"Sal, Str and Std need at least {SPATIAL_MIN_SIDE} points along each side")
    if not material:
        out.append(f"the material-ratio and volume parameters (Sk family, Sdc, Smr, Vmp ... "
                   f"Vvv) need at least {MATERIAL_MIN_POINTS} points")
    grid = " x ".join(str(n) for n in shape)
    return spatial, material, (
        f"grid: the {grid} map ({points} points evaluated) is too small (limit: "
        + " and ".join(out) + "), so they are left out (n/a); Ssk and Sku of "
        f"{points} points have standard errors of about {math.sqrt(6 / points):.2g} and "
        f"{math.sqrt(24 / points):.2g} (sqrt(6/n), sqrt(24/n) for Gaussian heights); measure "
        "a larger field")


def measured_heights(z: np.ndarray, exclude) -> np.ndarray:
    """The heights ``z`` without the points ``exclude`` (all when None), re-centred on their
    own mean when some are left out: the reference of the height parameters is the mean of
    the measured points (with the form fitted to them, :func:`areal_families`, that mean is
    already 0 on an S-F surface; a filter's leakage of the fill shifts it slightly)."""
    if exclude is None:
        return np.asarray(z, dtype=float).ravel()
    kept = np.asarray(z, dtype=float)[~np.asarray(exclude, bool)]
    if kept.size == 0:
        raise InputError("heights", "at least one measured point in the evaluated area")
    return kept - kept.mean()
