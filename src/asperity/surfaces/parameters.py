"""Roughness parameters (ISO 4287 profiles, ISO 25178 areas), power spectra, autocorrelation.

Heights are referenced to the least-squares mean line (profiles) or plane (areas) before any
parameter is computed; a *periodic* surface is referenced to its mean only (a tilt would break
the periodicity). Slopes are forward difference quotients ``(z[i+1] - z[i]) / h`` -- the
definition of Rdq in SurfaceTopography (Jacobs, Junge & Pastewka 2017) -- over the n - 1 pairs of
a non-periodic surface, or all n pairs (wrapping around) of a periodic one. They need the
coordinates: without ``x`` (and ``y``) the slope parameters are left out of the result.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.fft
from scipy.ndimage import map_coordinates

from ..errors import InputError
from ..grids import grid_spacing
from .topography import Profile, Topography

__all__ = [
    "PowerSpectrum",
    "amplitude_moments",
    "acf_decay_lengths",
    "autocorrelation_length",
    "power_spectrum",
    "residual_heights",
    "rms_gradient",
    "roughness_parameters",
]

#: Number of sampling lengths in the ISO 4287 evaluation length, and the fewest points that a
#: sampling length must hold for Rz to be averaged over them (otherwise Rz = Rt).
N_SAMPLING = 5
MIN_POINTS_PER_SAMPLING = 10


def _unpack(heights, x, y, periodic):
    """Heights, coordinates and periodicity from arrays or a Profile / Topography."""
    if isinstance(heights, Profile):
        return heights.z, heights.x, None, heights.periodic
    if isinstance(heights, Topography):
        return heights.z, heights.x, heights.y, heights.periodic
    z = np.asarray(heights, dtype=float)
    if z.ndim not in (1, 2) or min(z.shape) < 3:
        raise InputError("heights", "a 1-D profile or 2-D height map with at least 3 points "
                                    "per axis", z.shape)
    if not np.all(np.isfinite(z)):
        raise InputError("heights", "finite heights (no NaN or infinity)")
    for name, coord, n in (("x", x, z.shape[0]), ("y", y, z.shape[-1] if z.ndim == 2 else 0)):
        if coord is not None and np.size(coord) != n:
            raise InputError(name, f"{n} coordinates, one per height along that axis",
                             np.size(coord))
    if z.ndim == 1 and y is not None:
        raise InputError("y", "no y coordinates for a 1-D profile")
    if z.ndim == 2 and (x is None) != (y is None):
        raise InputError("y" if y is None else "x", "both x and y, or neither, for a height map")
    return z, x, y, bool(periodic)


def residual_heights(heights, periodic: bool = False) -> np.ndarray:
    """Heights minus the least-squares mean line (1-D) or plane (2-D); minus the mean if periodic.

    On a full uniform grid the centred index coordinates are orthogonal to each other and to
    the constant, so the least-squares coefficients are plain projections onto them.
    """
    z = np.asarray(heights, dtype=float)
    r = z - z.mean()
    if periodic:
        return r
    for axis, n in enumerate(z.shape):
        shape = [1] * z.ndim
        shape[axis] = n
        t = (np.arange(n, dtype=float) - 0.5 * (n - 1)).reshape(shape)
        r = r - t * (np.sum(z * t) / (np.sum(t * t) * z.size / n))
    return r


def _forward_differences(r, h, axis, periodic):
    if periodic:
        return (np.roll(r, -1, axis=axis) - r) / h
    return np.diff(r, axis=axis) / h


def amplitude_moments(r, prefix: str, scale: float) -> dict:
    """Mean |r|, rms, skewness, kurtosis, highest peak and deepest valley of heights ``r``
    measured from their mean line or plane (ISO 4287 4.1-4.2, ISO 25178-2 4.1), keyed
    ``{prefix}a``, ``q``, ``sk``, ``ku``, ``p``, ``v``; a surface whose rms is below ``1e-13
    scale`` is refused as flat (its skewness and kurtosis are undefined)."""
    rq = float(np.sqrt(np.mean(r**2)))
    if rq <= 1e-13 * scale:
        raise InputError("heights", "a surface that is not flat after removing the mean "
                                    "line/plane (Rq > 0)")
    return {
        f"{prefix}a": float(np.mean(np.abs(r))),
        f"{prefix}q": rq,
        f"{prefix}sk": float(np.mean(r**3) / rq**3),
        f"{prefix}ku": float(np.mean(r**4) / rq**4),
        f"{prefix}p": float(r.max()),
        f"{prefix}v": float(-r.min()),
    }


def rms_gradient(surface) -> tuple[str, float]:
    """The rms slope of a profile (Rdq) or topography (Sdq) by forward differences of its
    heights as they are: no mean line or plane removed (a tilt counts, as it does in a
    contact) and missing (NaN) points left out, so that it exists for any surface, a flat or
    tilted one included (:func:`roughness_parameters` refuses those).

    ``Rdq = sqrt(<(dz/dx)^2>)``; ``Sdq = sqrt(<(dz/dx)^2 + (dz/dy)^2>)`` over the nodes where
    both forward differences exist (ISO 25178-2's Sdq, as in :func:`roughness_parameters`).

    Returns
    -------
    (str, float)
        ``("Rdq", value)`` or ``("Sdq", value)``; NaN without two points along each axis.
    """
    z = np.asarray(surface.z, dtype=float)
    with np.errstate(all="ignore"):
        if z.ndim == 1:
            if z.size < 2:
                return "Rdq", float("nan")
            return "Rdq", float(np.sqrt(np.nanmean((np.diff(z) / surface.spacing) ** 2)))
        if min(z.shape) < 2:
            return "Sdq", float("nan")
        dx, dy = surface.spacing
        gx = np.diff(z, axis=0)[:, :-1] / dx
        gy = np.diff(z, axis=1)[:-1, :] / dy
        return "Sdq", float(np.sqrt(np.nanmean(gx**2 + gy**2)))


def roughness_parameters(heights, x=None, y=None, *, periodic=False) -> dict:
    """ISO roughness parameters of a profile (ISO 4287) or a topography (ISO 25178-2).

    Parameters
    ----------
    heights : array_like (n,) or (nx, ny), or Profile or Topography
        Heights (m), indexed ``[ix, iy]``. A Profile/Topography supplies its own coordinates
        and periodicity, and ``x``, ``y``, ``periodic`` are then ignored.
    x, y : array_like, optional
        Uniform coordinates (m); needed only for the slope parameters.
    periodic : bool
        Reference to the mean instead of the least-squares line/plane, and include the
        wrap-around pair in slopes.

    Returns
    -------
    dict
        Profiles: ``Ra, Rq, Rsk, Rku, Rp, Rv, Rz, Rt`` and with ``x`` also ``Rdq``. Rp is the
        highest peak and Rv the deepest valley (positive) relative to the mean line;
        Rt = Rp + Rv; Rz is the mean over 5 equal sampling lengths of the peak-to-valley height
        within each (ISO 4287 with the evaluation length = 5 sampling lengths), or Rt when a
        sampling length would hold fewer than 10 points.
        Areas: ``Sa, Sq, Ssk, Sku, Sp, Sv, Sz`` (Sz = Sp + Sv) and with ``x``, ``y`` also
        ``Sdq`` (rms gradient sqrt(<dz/dx^2 + dz/dy^2>) over the nodes where both forward
        differences exist, as SurfaceTopography's ``rms_gradient``) and ``Sdr`` (developed
        interfacial area ratio, as a fraction, from the gradient averaged over each grid cell).
        Lengths in m, ratios dimensionless.
    """
    z, x, y, periodic = _unpack(heights, x, y, periodic)
    r = residual_heights(z, periodic)
    if r.ndim == 1:
        out = amplitude_moments(r, "R", np.max(np.abs(z)))
        out["Rt"] = out["Rp"] + out["Rv"]
        if r.size >= N_SAMPLING * MIN_POINTS_PER_SAMPLING:
            out["Rz"] = float(np.mean([s.max() - s.min() for s in np.array_split(r, N_SAMPLING)]))
        else:
            out["Rz"] = out["Rt"]
        if x is not None:
            dz = _forward_differences(r, grid_spacing(x, "x"), 0, periodic)
            out["Rdq"] = float(np.sqrt(np.mean(dz**2)))
        return out
    out = amplitude_moments(r, "S", np.max(np.abs(z)))
    out["Sz"] = out["Sp"] + out["Sv"]
    if x is not None:
        gx = _forward_differences(r, grid_spacing(x, "x"), 0, periodic)
        gy = _forward_differences(r, grid_spacing(y, "y"), 1, periodic)
        # Gradient vectors at the nodes where both forward differences exist.
        node_x, node_y = (gx, gy) if periodic else (gx[:, :-1], gy[:-1, :])
        out["Sdq"] = float(np.sqrt(np.mean(node_x**2 + node_y**2)))
        # Gradient per grid cell: mean of the differences on its two opposite edges.
        if periodic:
            cx = 0.5 * (gx + np.roll(gx, -1, axis=1))
            cy = 0.5 * (gy + np.roll(gy, -1, axis=0))
        else:
            cx = 0.5 * (gx[:, :-1] + gx[:, 1:])
            cy = 0.5 * (gy[:-1, :] + gy[1:, :])
        out["Sdr"] = float(np.mean(np.sqrt(1.0 + cx**2 + cy**2) - 1.0))
    return out


@dataclass(frozen=True)
class PowerSpectrum:
    """A one-sided power spectral density of heights.

    Attributes
    ----------
    q : ndarray
        Angular wavevectors 2 pi / wavelength (rad/m), q > 0.
    psd : ndarray
        Profile (``dim == 1``): C1(q) in m^3 with ``Rq^2 = sum(psd) * dq``. Area (``dim == 2``):
        the 2-D PSD C2 (m^4) averaged over annuli of width dq, with
        ``Sq^2 ~= sum(2 pi q psd dq)``.
    dq : float
        Spacing of q (rad/m).
    dim : int
        1 for a profile, 2 for a topography.
    """

    q: np.ndarray
    psd: np.ndarray
    dq: float
    dim: int


def _window(n: int, window: str | None) -> np.ndarray:
    if window is None:
        return np.ones(n)
    if window != "hann":
        raise InputError("window", 'None or "hann"', window)
    w = np.hanning(n)
    return w / np.sqrt(np.mean(w**2))


def power_spectrum(heights, x=None, y=None, *, window=None) -> PowerSpectrum:
    """Power spectral density of a profile, or the radially averaged PSD of a topography.

    The mean is removed (not the tilt); ``window="hann"`` tapers non-periodic data (scaled to
    keep the mean square) to reduce leakage. Definitions as in Jacobs et al. (2017) with the
    one-sided normalisation of :class:`PowerSpectrum`.

    Parameters
    ----------
    heights : array_like or Profile or Topography
    x, y : array_like
        Uniform coordinates (m); taken from a Profile/Topography when given one.
    window : None or "hann"
    """
    z, x, y, _ = _unpack(heights, x, y, False)
    if x is None:
        raise InputError("x", "coordinates (the spacing is needed for a spectrum)")
    r = z - z.mean()
    if r.ndim == 1:
        n, h = r.size, grid_spacing(x, "x")
        spec = np.abs(scipy.fft.rfft(r * _window(n, window), workers=-1)) ** 2
        dq = 2 * np.pi / (n * h)
        c = spec / (n**2 * dq)
        c[1:(n + 1) // 2] *= 2.0  # fold the negative wavevectors (not DC or Nyquist)
        return PowerSpectrum(dq * np.arange(1, c.size), c[1:], dq, 1)
    (nx, ny), hx, hy = r.shape, grid_spacing(x, "x"), grid_spacing(y, "y")
    w = np.outer(_window(nx, window), _window(ny, window))
    spec = np.abs(scipy.fft.fftn(r * w, workers=-1)) ** 2
    dqx, dqy = 2 * np.pi / (nx * hx), 2 * np.pi / (ny * hy)
    c2 = spec / ((nx * ny) ** 2 * dqx * dqy)
    qx = 2 * np.pi * scipy.fft.fftfreq(nx, hx)
    qy = 2 * np.pi * scipy.fft.fftfreq(ny, hy)
    qn = np.hypot(qx[:, None], qy[None, :])
    dq = max(dqx, dqy)
    nbins = int(min(np.abs(qx).max(), np.abs(qy).max()) / dq)
    index = np.rint(qn / dq).astype(int).ravel()
    keep = (index >= 1) & (index <= nbins)
    counts = np.bincount(index[keep], minlength=nbins + 1)[1:]
    sums = np.bincount(index[keep], weights=c2.ravel()[keep], minlength=nbins + 1)[1:]
    qsum = np.bincount(index[keep], weights=qn.ravel()[keep], minlength=nbins + 1)[1:]
    filled = counts > 0
    return PowerSpectrum(qsum[filled] / counts[filled], sums[filled] / counts[filled], dq, 2)


def _autocorrelation(r: np.ndarray, periodic: bool) -> np.ndarray:
    """Normalised autocorrelation R(tau)/R(0) on the FFT lag grid (zero-padded if not periodic)."""
    shape = r.shape if periodic else tuple(2 * n for n in r.shape)
    f = scipy.fft.rfftn(r, s=shape, workers=-1)
    acf = scipy.fft.irfftn(np.abs(f) ** 2, s=shape, workers=-1)
    return acf / acf.flat[0]


def _first_crossing(values: np.ndarray, threshold: float, step: float) -> float:
    """The first position where ``values`` (sampled every ``step`` from 0) fall to
    ``threshold``, interpolated linearly between the samples bracketing it; NaN if never."""
    below = np.flatnonzero(values <= threshold)
    if below.size == 0:
        return math.nan
    k = below[0]
    if k == 0:
        return 0.0
    return float((k - 1 + (values[k - 1] - threshold) / (values[k - 1] - values[k])) * step)


def acf_decay_lengths(heights, x=None, y=None, *, periodic=False, threshold=0.2,
                      directions=180) -> tuple[np.ndarray, np.ndarray]:
    """The lag at which the areal ACF first falls to ``threshold``, along each direction.

    ISO 25178-2 clause 4.3.1-4.3.2 define Sal and Str from the horizontal distance at which
    f_ACF(tx, ty) decays to s along each direction. The ACF (:func:`autocorrelation_length`'s)
    is sampled along rays from lag zero, ``directions`` of them over [0, 180) degrees, every half
    of the smaller spacing, by bilinear interpolation of the lag grid
    (``scipy.ndimage.map_coordinates``), out to half the field; the crossing is interpolated
    linearly between the samples that bracket it -- along the x and y axes exactly the linear
    interpolation between the bracketing grid lags.

    Parameters
    ----------
    heights : array_like (nx, ny) or Topography
    x, y : array_like, optional
        Uniform coordinates (m); lags in grid units without them.
    periodic : bool
    threshold : float
    directions : int

    Returns
    -------
    angles : ndarray
        Directions in degrees, counter-clockwise from x.
    lengths : ndarray
        Decay length (m) along each; NaN where the ACF does not decay within half the field.
    """
    z, x, y, periodic = _unpack(heights, x, y, periodic)
    if z.ndim != 2:
        raise InputError("heights", "a 2-D height map", z.shape)
    hx, hy = (1.0, 1.0) if x is None else (grid_spacing(x, "x"), grid_spacing(y, "y"))
    acf = scipy.fft.fftshift(_autocorrelation(residual_heights(z, periodic), periodic))
    cx, cy = (n // 2 for n in acf.shape)
    step = 0.5 * min(hx, hy)
    r = np.arange(0.0, 0.5 * min(z.shape[0] * hx, z.shape[1] * hy), step)
    angles = np.arange(directions) * 180.0 / directions
    lengths = np.array([
        _first_crossing(map_coordinates(acf, [cx + r * math.cos(a) / hx,
                                              cy + r * math.sin(a) / hy], order=1),
                        threshold, step)
        for a in np.radians(angles)])
    return angles, lengths


def autocorrelation_length(heights, x=None, y=None, *, periodic=False, threshold=0.2) -> float:
    """Autocorrelation length: the shortest lag at which the ACF has decayed to ``threshold``.

    The ACF is the (biased) autocorrelation of the residual heights (see
    :func:`residual_heights`), circular when periodic, otherwise of the zero-padded data.
    For a profile the first crossing of ``threshold`` is interpolated linearly (Rsal-like); for
    a topography it is ISO 25178-2 Sal: the shortest of the decay lengths along all directions
    (:func:`acf_decay_lengths`, each interpolated between the lags that bracket it).

    Returns
    -------
    float
        The length in m (in grid units when no coordinates are given), or NaN when the ACF
        never decays to ``threshold`` within the data (half the field of a topography).
    """
    z, x, y, periodic = _unpack(heights, x, y, periodic)
    if z.ndim == 2:
        lengths = acf_decay_lengths(z, x, y, periodic=periodic, threshold=threshold)[1]
        return float(np.nanmin(lengths)) if np.isfinite(lengths).any() else math.nan
    r = residual_heights(z, periodic)
    acf = _autocorrelation(r, periodic)
    h = 1.0 if x is None else grid_spacing(x, "x")
    half = acf[: r.size // 2 + 1] if periodic else acf[: r.size]
    return _first_crossing(half, threshold, h)
