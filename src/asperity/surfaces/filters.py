"""The ISO 16610-21 Gaussian profile filter: separating waviness from roughness.

Weighting function (ISO 16610-21 eq. 1) with cut-off wavelength ``lambda_c``::

    s(x) = exp(-pi (x / (alpha lambda_c))^2) / (alpha lambda_c),   alpha = sqrt(ln 2 / pi)

whose amplitude transmission for a sine of wavelength ``lam`` is
``exp(-pi (alpha lambda_c / lam)^2)`` -- exactly 50 % at ``lam = lambda_c``. The filtered profile
(the mean line) is the waviness; profile minus mean line is the roughness.

Periodic profiles are filtered exactly in Fourier space. Non-periodic profiles are convolved with
the weighting function sampled on the grid and truncated at +-lambda_c (its value there is
6.5e-7 of the peak); near the ends, where the kernel runs past the data, the weights inside the
data are renormalised to sum to one (the zero-order end correction). ISO 16610-21 recommends
discarding half a cut-off at each end for evaluation; this is left to the caller.
"""

from __future__ import annotations

import numpy as np
import scipy.fft
from scipy.signal import fftconvolve

from ..elastic.convolution import grid_spacing
from ..errors import InputError, check_positive
from .topography import Profile

__all__ = ["ALPHA", "gaussian_filter", "gaussian_transmission", "split_waviness"]

ALPHA = float(np.sqrt(np.log(2.0) / np.pi))


def gaussian_transmission(wavelength, cutoff):
    """Amplitude transmission of the mean line, ``exp(-pi (alpha cutoff / wavelength)^2)``."""
    lam = np.asarray(wavelength, dtype=float)
    return np.exp(-np.pi * (ALPHA * cutoff / lam) ** 2)


def gaussian_filter(heights, x, cutoff, *, periodic=False) -> np.ndarray:
    """Mean line (waviness) of a profile by the ISO 16610-21 Gaussian filter.

    Parameters
    ----------
    heights : array_like, shape (n,)
        Profile heights (m).
    x : array_like, shape (n,)
        Uniform positions (m).
    cutoff : float
        Cut-off wavelength lambda_c (m); must be at least two grid spacings.
    periodic : bool
        Filter as a periodic signal (exact transmission) instead of with end correction.

    Returns
    -------
    ndarray, shape (n,)
        The mean line.
    """
    z = np.asarray(heights, dtype=float)
    h = grid_spacing(x, "x")
    if z.shape != np.shape(x):
        raise InputError("heights", f"one height per position, shape {np.shape(x)}", z.shape)
    if not np.all(np.isfinite(z)):
        raise InputError("heights", "finite heights (no NaN or infinity)")
    cutoff = check_positive("cutoff", cutoff)
    if cutoff < 2 * h:
        raise InputError("cutoff", f"a cut-off of at least two grid spacings ({2 * h:.4g} m)",
                         cutoff)
    if periodic:
        wavelength_inv = scipy.fft.rfftfreq(z.size, h)  # 1 / lambda
        gain = np.exp(-np.pi * (ALPHA * cutoff * wavelength_inv) ** 2)
        return scipy.fft.irfft(scipy.fft.rfft(z, workers=-1) * gain, n=z.size, workers=-1)
    half = int(np.ceil(cutoff / h))
    t = np.arange(-half, half + 1) * h
    weights = np.exp(-np.pi * (t / (ALPHA * cutoff)) ** 2)
    mean_line = fftconvolve(z, weights, mode="same")
    norm = fftconvolve(np.ones_like(z), weights, mode="same")
    return mean_line / norm


def split_waviness(profile: Profile, cutoff) -> tuple[Profile, Profile]:
    """Split a profile into (waviness, roughness) with the Gaussian filter at ``cutoff``.

    A periodic profile is filtered periodically. Roughness + waviness = the profile.
    """
    if not isinstance(profile, Profile):
        raise InputError("profile", "a Profile", type(profile).__name__)
    mean_line = gaussian_filter(profile.z, profile.x, cutoff, periodic=profile.periodic)
    return profile.with_heights(mean_line), profile.with_heights(profile.z - mean_line)
