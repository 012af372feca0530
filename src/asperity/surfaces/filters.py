"""The ISO 16610-21 Gaussian profile filter: separating waviness from roughness.

Weighting function (ISO 16610-21 eq. 1) with cut-off wavelength ``lambda_c``::

    s(x) = exp(-pi (x / (alpha lambda_c))^2) / (alpha lambda_c),   alpha = sqrt(ln 2 / pi)

whose amplitude transmission for a sine of wavelength ``lam`` is
``exp(-pi (alpha lambda_c / lam)^2)`` -- exactly 50 % at ``lam = lambda_c``. The filtered profile
(the mean line) is the waviness; profile minus mean line is the roughness.

Periodic profiles are filtered exactly in Fourier space. Non-periodic profiles are convolved with
the weighting function sampled on the grid and truncated at +-lambda_c (its value there is
6.5e-7 of the peak); near the ends, where the kernel runs past the data, the weights inside the
data are renormalised to sum to one (the zero-order end correction), or on request also made to
keep their first moment (a local Gaussian-weighted straight line, ISO 16610-28's moment
criterion to first order), which the roughness evaluation uses. ISO 16610-21 recommends
discarding half a cut-off at each end for evaluation (done by
:func:`asperity.surfaces.profiles.profile_families`).

Areal surfaces (ISO 16610-61, the areal Gaussian filter of ISO 25178-3's S- and L-filters):
the weighting function is the product of the profile one along x and along y, so the filter is
applied along each axis in turn (:func:`areal_gaussian_filter`), with the same end correction.
"""

from __future__ import annotations

import numpy as np
import scipy.fft
from scipy.signal import fftconvolve

from ..errors import InputError, check_positive
from ..formatting import format_quantity
from ..grids import grid_spacing
from .topography import Profile

__all__ = ["ALPHA", "areal_gaussian_filter", "gaussian_filter", "gaussian_transmission",
           "split_waviness"]

ALPHA = float(np.sqrt(np.log(2.0) / np.pi))


def gaussian_transmission(wavelength, cutoff):
    """Amplitude transmission of the mean line, ``exp(-pi (alpha cutoff / wavelength)^2)``."""
    lam = np.asarray(wavelength, dtype=float)
    return np.exp(-np.pi * (ALPHA * cutoff / lam) ** 2)


def gaussian_filter(heights, x, cutoff, *, periodic=False, axis=0,
                    end_correction="zero") -> np.ndarray:
    """Mean line (waviness) of a profile by the ISO 16610-21 Gaussian filter.

    Parameters
    ----------
    heights : array_like, shape (n,) or n along ``axis``
        Profile heights (m); a 2-D array is filtered along ``axis`` only.
    x : array_like, shape (n,)
        Uniform positions (m) along ``axis``.
    cutoff : float
        Cut-off wavelength lambda_c (m); must be at least two grid spacings.
    periodic : bool
        Filter as a periodic signal (exact transmission) instead of with end correction.
    axis : int
        Axis of ``heights`` along which ``x`` runs.
    end_correction : {"zero", "linear"}
        Near the ends of a non-periodic profile, where the kernel runs past the data:
        ``"zero"`` renormalises the weights inside the data to sum to one (a local weighted
        mean); ``"linear"`` fits a local straight line with the Gaussian weights and takes its
        value (the moment criterion of ISO 16610-28 to first order: the weights keep their
        zeroth and first moments, so a linear trend passes undistorted). Both equal the plain
        Gaussian filter wherever the whole kernel lies inside the data.

    Returns
    -------
    ndarray, shape of ``heights``
        The mean line.
    """
    z = np.asarray(heights, dtype=float)
    h = grid_spacing(x, "x")
    if z.ndim == 0 or z.shape[axis] != np.size(x):
        raise InputError("heights", f"one height per position along axis {axis}, "
                                    f"{np.size(x)} positions", z.shape)
    if not np.all(np.isfinite(z)):
        raise InputError("heights", "finite heights (no NaN or infinity)")
    cutoff = check_positive("cutoff", cutoff)
    if cutoff < 2 * h:
        raise InputError("cutoff", f"a cut-off of at least two grid spacings "
                         f"({format_quantity(2 * h, 'm')})",
                         cutoff)
    n = z.shape[axis]
    shape = [1] * z.ndim
    shape[axis] = -1
    if periodic:
        wavelength_inv = scipy.fft.rfftfreq(n, h)  # 1 / lambda
        gain = np.exp(-np.pi * (ALPHA * cutoff * wavelength_inv) ** 2).reshape(shape)
        return scipy.fft.irfft(scipy.fft.rfft(z, axis=axis, workers=-1) * gain, n=n, axis=axis,
                               workers=-1)
    half = int(np.ceil(cutoff / h))
    t = np.arange(-half, half + 1) * h
    weights = np.exp(-np.pi * (t / (ALPHA * cutoff)) ** 2)
    ones = np.ones(n)
    s0 = fftconvolve(ones, weights, mode="same").reshape(shape)
    t0 = fftconvolve(z, weights.reshape(shape), mode="same", axes=axis)
    if end_correction == "zero":
        return t0 / s0
    if end_correction != "linear":
        raise InputError("end_correction", '"zero" or "linear"', end_correction)
    # Kernel w(t) applied at x_i to z(x_i - t): the moments of the offsets x_j - x_i = -t.
    s1 = fftconvolve(ones, -t * weights, mode="same").reshape(shape)
    s2 = fftconvolve(ones, t * t * weights, mode="same").reshape(shape)
    t1 = fftconvolve(z, (-t * weights).reshape(shape), mode="same", axes=axis)
    return (s2 * t0 - s1 * t1) / (s0 * s2 - s1 * s1)


def areal_gaussian_filter(heights, x, y, cutoff, *, periodic=False,
                          end_correction="linear") -> np.ndarray:
    """Mean surface of a topography by the areal Gaussian filter (ISO 16610-61).

    The weighting function ``s(x) s(y)`` is separable, so this is :func:`gaussian_filter`
    along x and then along y, with its end correction at the borders of a non-periodic surface.

    Parameters
    ----------
    heights : array_like, shape (nx, ny)
    x, y : array_like
        Uniform positions (m).
    cutoff : float
        Nesting index (cut-off wavelength, m) of the S- or L-filter.
    periodic : bool
    end_correction : {"zero", "linear"}
        As for :func:`gaussian_filter`, along each axis.

    Returns
    -------
    ndarray, shape (nx, ny)
        The filtered (long-wavelength) surface.
    """
    along_x = gaussian_filter(heights, x, cutoff, periodic=periodic, axis=0,
                              end_correction=end_correction)
    return gaussian_filter(along_x, y, cutoff, periodic=periodic, axis=1,
                           end_correction=end_correction)


def split_waviness(profile: Profile, cutoff) -> tuple[Profile, Profile]:
    """Split a profile into (waviness, roughness) with the Gaussian filter at ``cutoff``.

    A periodic profile is filtered periodically. Roughness + waviness = the profile.
    """
    if not isinstance(profile, Profile):
        raise InputError("profile", "a Profile", type(profile).__name__)
    mean_line = gaussian_filter(profile.z, profile.x, cutoff, periodic=profile.periodic)
    return profile.with_heights(mean_line), profile.with_heights(profile.z - mean_line)
