"""Random rough surfaces by Fourier filtering of white noise, and waviness.

A field with power spectral density S(q) is made by filtering Gaussian white noise w:
``z = IFFT(FFT(w) * A(q))`` with ``A = sqrt(S)`` on the discrete wavevectors of the grid
(Hu & Tonder, Int. J. Mach. Tools Manuf. 32 (1992) 83; Persson et al., J. Phys.: Condens. Matter
17 (2005) R1). With ``E|FFT(w)_k|^2 = N``, the expected mean square height is ``mean(A^2)``, so
scaling A to ``mean(A^2) = rms^2`` makes the *expected* rms exactly the requested one: a single
realisation scatters around it (a long-wavelength self-affine spectrum, few modes carrying most
of the power, by tens of percent). With ``exact=True`` the realisation is rescaled so that its
own Rq/Sq (or Rdq/Sdq) is the requested value, as measured by
:func:`~asperity.surfaces.roughness_parameters`. The mean (q = 0 mode) is zero. All generated
surfaces are periodic, on cell-centre grids starting at ``spacing / 2``, with
``n = round(length / spacing)`` points. Randomness comes only from
``numpy.random.default_rng(seed)``.
"""

from __future__ import annotations

import numpy as np
import scipy.fft

from ..errors import InputError, check_positive
from ..formatting import format_quantity
from .parameters import roughness_parameters
from .topography import Profile, Topography, cell_centres

__all__ = [
    "add_waviness",
    "gaussian_profile",
    "gaussian_topography",
    "self_affine_profile",
    "self_affine_topography",
]

#: ACF shapes and the factor c with beta = correlation_length / c, so that the ACF falls to 0.2
#: at the correlation length (the ISO 25178 Sal threshold): exp(-c^2) = 0.2, exp(-c) = 0.2.
_ACF_SCALE = {"gaussian": np.sqrt(np.log(5.0)), "exponential": np.log(5.0)}


def _grid(length, spacing, field: str = "length") -> tuple[int, float]:
    length = check_positive(field, length)
    spacing = check_positive("spacing", spacing)
    n = int(round(length / spacing))
    if n < 4:
        raise InputError(field, "at least 4 grid spacings", length)
    return n, spacing


def _pair(value, field: str) -> tuple[float, float]:
    """A scalar or a pair of positive numbers as a pair."""
    v = np.atleast_1d(np.asarray(value, dtype=float))
    if v.size == 1:
        v = np.repeat(v, 2)
    if v.shape != (2,):
        raise InputError(field, "a number or a pair (x, y)", value)
    return check_positive(field, v[0]), check_positive(field, v[1])


def _wavevectors(shape, spacings):
    """Angular wavevector components (rad/m) on the full FFT grid, indexed [ix, iy]."""
    axes = [2 * np.pi * scipy.fft.fftfreq(n, d) for n, d in zip(shape, spacings, strict=True)]
    return np.meshgrid(*axes, indexing="ij")


def _filter_noise(amplitude: np.ndarray, seed) -> np.ndarray:
    """Real field ``IFFT(FFT(w) * amplitude)`` from white noise; amplitude on the full grid."""
    shape = amplitude.shape
    w = np.random.default_rng(seed).standard_normal(shape)
    half = amplitude[..., : shape[-1] // 2 + 1]
    spectrum = scipy.fft.rfftn(w, workers=-1) * half
    return scipy.fft.irfftn(spectrum, s=shape, workers=-1)


def _difference_gain2(q, h):
    """|e^{i q h} - 1|^2 / h^2: the power gain of a forward difference quotient."""
    return (2.0 * np.sin(0.5 * q * h) / h) ** 2


def _gaussian_spectrum(qs, lengths, acf: str):
    if acf not in _ACF_SCALE:
        raise InputError("acf", f"one of {sorted(_ACF_SCALE)}", acf)
    betas = [ell / _ACF_SCALE[acf] for ell in lengths]
    if acf == "gaussian":
        # FT of exp(-sum (tau_i / beta_i)^2) is proportional to exp(-sum (q_i beta_i)^2 / 4).
        return np.exp(-sum((q * b) ** 2 for q, b in zip(qs, betas, strict=True)) / 4.0)
    # FT of exp(-|tau|/beta): 1-D Lorentzian, 2-D (1 + (q beta)^2)^(-3/2).
    s2 = sum((q * b) ** 2 for q, b in zip(qs, betas, strict=True))
    return (1.0 + s2) ** (-(len(qs) + 1) / 2.0)


def _scaled(spectrum: np.ndarray, rms: float, field: str) -> np.ndarray:
    """Amplitudes ``sqrt(spectrum)`` (mean removed) scaled to an expected rms height ``rms``.

    ``field`` names the input that shaped the spectrum, for the error when no wavelength the
    grid holds carries power (a Gaussian correlation length many times the surface's length
    makes ``exp(-(q beta)^2 / 4)`` underflow at every nonzero wavevector).
    """
    spectrum = spectrum.copy()
    spectrum.flat[0] = 0.0
    if not spectrum.mean() > 0.0:
        raise InputError(field, "a length the surface can hold: no wavelength between the grid "
                         "spacing and the surface's length carries power (make it shorter "
                         "than the surface)")
    return np.sqrt(spectrum) * (rms / np.sqrt(spectrum.mean()))


def _exact(surface, rms_height=None, rms_slope=None):
    """The surface rescaled so that its own rms height (or rms slope) is the requested one."""
    area = isinstance(surface, Topography)
    if rms_height is not None:
        key, target = ("Sq" if area else "Rq"), rms_height
    else:
        key, target = ("Sdq" if area else "Rdq"), rms_slope
    measured = roughness_parameters(surface)[key]
    return surface.with_heights(surface.z * (target / measured))


def gaussian_profile(length, spacing, rms, correlation_length, *, acf="gaussian",
                     seed=0, exact=False) -> Profile:
    """Periodic profile with Gaussian heights and a given autocorrelation.

    Parameters
    ----------
    length, spacing : float
        Profile length and grid spacing (m).
    rms : float
        Expected rms height Rq (m).
    correlation_length : float
        Lag (m) at which the autocorrelation falls to 0.2 (ISO 25178 Sal convention).
    acf : {"gaussian", "exponential"}
        ``exp(-(tau/beta)^2)`` or ``exp(-|tau|/beta)``, beta chosen from correlation_length.
    seed : int or None
        Seed of ``numpy.random.default_rng``.
    exact : bool
        Rescale the realisation so that its Rq is ``rms`` exactly (default: the expected Rq).
    """
    n, h = _grid(length, spacing)
    rms = check_positive("rms", rms)
    ell = check_positive("correlation_length", correlation_length)
    (q,) = _wavevectors((n,), (h,))
    amplitude = _scaled(_gaussian_spectrum([q], [ell], acf), rms, "correlation_length")
    z = _filter_noise(amplitude, seed)
    profile = Profile(cell_centres(n, h), z, periodic=True)
    return _exact(profile, rms) if exact else profile


def gaussian_topography(size, spacing, rms, correlation_length, *, acf="gaussian",
                        seed=0, exact=False) -> Topography:
    """Periodic topography with Gaussian heights, isotropic or anisotropic autocorrelation.

    Parameters
    ----------
    size : float or (float, float)
        Side lengths (Lx, Ly) in m.
    spacing : float or (float, float)
        Grid spacings (dx, dy) in m.
    rms : float
        Expected rms height Sq (m).
    correlation_length : float or (float, float)
        Lags (m) along x and y at which the autocorrelation falls to 0.2; different values make
        an anisotropic surface (a long correlation along y gives ridges across the rolling
        direction, like a transverse-ground finish).
    acf, seed
        As in :func:`gaussian_profile`.
    exact : bool
        Rescale the realisation so that its Sq is ``rms`` exactly (default: the expected Sq).
    """
    (lx, ly), (dx, dy) = _pair(size, "size"), _pair(spacing, "spacing")
    nx, dx = _grid(lx, dx, "size")
    ny, dy = _grid(ly, dy, "size")
    rms = check_positive("rms", rms)
    ells = _pair(correlation_length, "correlation_length")
    qx, qy = _wavevectors((nx, ny), (dx, dy))
    amplitude = _scaled(_gaussian_spectrum([qx, qy], ells, acf), rms, "correlation_length")
    z = _filter_noise(amplitude, seed)
    topography = Topography(cell_centres(nx, dx), cell_centres(ny, dy), z, periodic=True)
    return _exact(topography, rms) if exact else topography


def _self_affine(shape, spacings, hurst, rms_height, rms_slope, rolloff, cutoff, seed):
    hurst = float(hurst)
    if not 0.0 < hurst < 1.0:
        raise InputError("hurst", "a Hurst exponent 0 < H < 1", hurst)
    if (rms_height is None) == (rms_slope is None):
        raise InputError("rms_height", "exactly one of rms_height and rms_slope")
    qs = _wavevectors(shape, spacings)
    q = np.sqrt(sum(c**2 for c in qs))
    longest = max(n * d for n, d in zip(shape, spacings, strict=True))
    shortest = 2.0 * max(spacings)
    rolloff = longest if rolloff is None else check_positive("rolloff_wavelength", rolloff)
    cutoff = shortest if cutoff is None else check_positive("short_cutoff", cutoff)
    if cutoff < shortest * (1 - 1e-12):
        raise InputError("short_cutoff", f"at least two grid spacings "
                         f"({format_quantity(shortest, 'm')})", cutoff)
    if rolloff <= cutoff:
        raise InputError("rolloff_wavelength", "a wavelength longer than short_cutoff", rolloff)
    q_r, q_s = 2 * np.pi / rolloff, 2 * np.pi / cutoff
    # Isotropic self-affine PSD: C ~ q^-(1 + 2H) for a profile, q^-(2 + 2H) for an area;
    # flat below the roll-off, zero beyond the short cut-off.
    exponent = -(len(shape) + 2.0 * hurst)
    spectrum = np.where(q <= q_s * (1 + 1e-12), np.maximum(q, q_r) ** exponent, 0.0)
    spectrum.flat[0] = 0.0
    if rms_height is not None:
        amp = _scaled(spectrum, check_positive("rms_height", rms_height), "short_cutoff")
    else:
        # Expected mean-square forward-difference slope, the quantity Rdq / Sdq measure.
        gain = sum(_difference_gain2(c, d) for c, d in zip(qs, spacings, strict=True))
        slope2 = np.mean(spectrum * gain)
        amp = np.sqrt(spectrum) * (check_positive("rms_slope", rms_slope) / np.sqrt(slope2))
    return _filter_noise(amp, seed)


def self_affine_profile(length, spacing, hurst, *, rms_height=None, rms_slope=None,
                        rolloff_wavelength=None, short_cutoff=None, seed=0,
                        exact=False) -> Profile:
    """Periodic self-affine (fractal) profile by Fourier filtering.

    The one-sided PSD is ``C(q) ~ q^-(1+2H)`` between the roll-off wavevector
    ``2 pi / rolloff_wavelength`` (flat below it) and ``2 pi / short_cutoff`` (zero above),
    Persson et al. (2005) and Jacobs, Junge & Pastewka, Surf. Topogr. Metrol. Prop. 5 (2017)
    013001.

    Parameters
    ----------
    length, spacing : float
        Profile length and grid spacing (m).
    hurst : float
        Hurst exponent, 0 < H < 1.
    rms_height, rms_slope : float
        Give exactly one: the expected rms height (m), or the expected rms slope of forward
        differences (the Rdq of :func:`~asperity.surfaces.roughness_parameters`).
    rolloff_wavelength : float, optional
        Longest self-affine wavelength (m); default the profile length (no roll-off).
    short_cutoff : float, optional
        Shortest wavelength (m), at least two spacings (the default).
    seed : int or None
        Seed of ``numpy.random.default_rng``.
    exact : bool
        Rescale the realisation so that its own Rq (or Rdq) is the requested value; by default
        only the expected value is (one realisation of a spectrum with a long roll-off
        wavelength scatters by tens of percent).
    """
    n, h = _grid(length, spacing)
    z = _self_affine((n,), (h,), hurst, rms_height, rms_slope, rolloff_wavelength, short_cutoff,
                     seed)
    profile = Profile(cell_centres(n, h), z, periodic=True)
    return _exact(profile, rms_height, rms_slope) if exact else profile


def self_affine_topography(size, spacing, hurst, *, rms_height=None, rms_slope=None,
                           rolloff_wavelength=None, short_cutoff=None, seed=0,
                           exact=False) -> Topography:
    """Periodic isotropic self-affine topography, ``C(q) ~ q^-2(1+H)``.

    Parameters are those of :func:`self_affine_profile`; ``size`` and ``spacing`` may be pairs
    (x, y), ``rms_slope`` is then the rms gradient Sdq and ``exact=True`` makes the
    realisation's Sq (or Sdq) the requested value.
    """
    (lx, ly), (dx, dy) = _pair(size, "size"), _pair(spacing, "spacing")
    nx, dx = _grid(lx, dx, "size")
    ny, dy = _grid(ly, dy, "size")
    z = _self_affine((nx, ny), (dx, dy), hurst, rms_height, rms_slope, rolloff_wavelength,
                     short_cutoff, seed)
    topography = Topography(cell_centres(nx, dx), cell_centres(ny, dy), z, periodic=True)
    return _exact(topography, rms_height, rms_slope) if exact else topography


def add_waviness(surface, wavelength, amplitude, *, direction="x", phase=0.0):
    """Add the sinusoid ``amplitude * sin(2 pi s / wavelength + phase)`` along x or y.

    Parameters
    ----------
    surface : Profile or Topography
    wavelength, amplitude : float
        Wavelength (m) and amplitude (half the peak-to-valley, m; zero allowed).
    direction : {"x", "y"}
        Coordinate along which the waviness varies; a Profile has only "x". Waviness along y on
        a transverse-ground topography is the transverse waviness of the mixed-EHL seed.
    phase : float
        Phase (rad) at s = 0.
    """
    wavelength = check_positive("wavelength", wavelength)
    amplitude = check_positive("amplitude", amplitude, allow_zero=True)
    if direction not in ("x", "y") or (direction == "y" and isinstance(surface, Profile)):
        allowed = '"x"' if isinstance(surface, Profile) else '"x" or "y"'
        raise InputError("direction", allowed, direction)
    s = getattr(surface, direction)
    wave = amplitude * np.sin(2 * np.pi * s / wavelength + float(phase))
    if isinstance(surface, Topography):
        wave = wave[:, None] if direction == "x" else wave[None, :]
    elif not isinstance(surface, Profile):
        raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
    return surface.with_heights(surface.z + wave)
