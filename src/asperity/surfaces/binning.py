"""Binning a large topography before its evaluation, and what a map costs to evaluate.

``asperity surface stats`` of a 4096 x 4096 map held about 180 bytes a point at its peak
(2.9 GB) and took 73 s on two cores (the zero-padded ACF of Sal/Str, the slopes, the Hann
spectrum of Std and the least-squares form each take a few seconds per 4 M points).
:func:`bin_surface` averages k x k blocks of points into one (k points of a profile), as an
instrument's pixel binning does: a box low-pass of width k spacings before the coarser sampling,
so that the roughness shorter than the new spacing is averaged, not aliased into it.
"""

from __future__ import annotations

import os

import numpy as np

from ..errors import InputError, check_int
from .topography import Profile, Topography

__all__ = ["BYTES_PER_POINT", "LARGE_MAP", "available_memory", "bin_surface", "large_map"]

#: Peak memory of the evaluation of a map per point (measured: 2.95 GB for 4096 x 4096).
BYTES_PER_POINT = 180
#: Points of a map above which its evaluation is said to be large (2048 x 2048).
LARGE_MAP = 2 ** 22


def available_memory() -> float | None:
    """Bytes of physical memory free now (Linux ``sysconf``), or None where unknown."""
    try:
        return float(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return None


def _binned_axis(coord: np.ndarray, k: int) -> np.ndarray:
    n = coord.size // k * k
    return coord[:n].reshape(-1, k).mean(axis=1)


def bin_surface(surface, k: int, mask=None):
    """The surface with each k x k block (k points of a profile) replaced by its mean.

    Parameters
    ----------
    surface : Profile or Topography
    k : int
        Points per block along each axis (1: unchanged). Points left over at the far end of an
        axis that does not divide by k are dropped.
    mask : ndarray of bool, optional
        Points to leave out (masked missing points); a block is left out when more than half
        of its points are.

    Returns
    -------
    (Profile or Topography, ndarray of bool or None, str)
        The binned surface, its mask and a note saying what was done.
    """
    k = check_int("--bin", k, 1)
    if not isinstance(surface, Profile | Topography):
        raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
    if k == 1:
        return surface, mask, ""
    shape = surface.z.shape
    if min(shape) // k < 8:
        raise InputError("--bin", f"a block of at most {min(shape) // 8} points (the surface "
                         f"is {' x '.join(map(str, shape))} points; 8 a side must remain)", k)
    cut = tuple(slice(0, n // k * k) for n in shape)
    blocks = [n // k for n in shape]
    split = [v for b in blocks for v in (b, k)]
    axes = tuple(range(1, 2 * len(shape), 2))
    blocked = surface.z[cut].reshape(split)
    z = blocked.mean(axis=axes)
    within = float(np.sqrt(np.mean(blocked.var(axis=axes))))
    binned_mask = None if mask is None else (
        np.asarray(mask, bool)[cut].reshape(split).mean(axis=axes) > 0.5)
    periodic = surface.periodic and all(n % k == 0 for n in shape)
    if isinstance(surface, Profile):
        binned = Profile(_binned_axis(surface.x, k), z, periodic=periodic)
        spacing = [surface.spacing]
    else:
        binned = Topography(_binned_axis(surface.x, k), _binned_axis(surface.y, k), z,
                            periodic=periodic)
        spacing = list(surface.spacing)
    size = " x ".join(map(str, shape))
    new = " x ".join(map(str, z.shape))
    step = " x ".join(f"{h * 1e6:.4g}" for h in spacing)
    coarse = " x ".join(f"{k * h * 1e6:.4g}" for h in spacing)
    return binned, binned_mask, (
        f"binned {' x '.join([str(k)] * len(shape))} (--bin {k}): {size} points of {step} um "
        f"-> {new} of {coarse} um, each the mean of its {k ** len(shape)}: the heights about "
        f"their block means, rms {within * 1e6:.4g} um, are averaged out (the rms height of "
        f"the whole is about sqrt(rms^2 + {within * 1e6:.4g}^2) um), and with them "
        f"wavelengths shorter than about "
        f"{2 * k * max(spacing) * 1e6:.4g} um; the slopes (Sdq, Sdr, Rdq) and Sal are those of "
        "the coarser grid")


def large_map(points: int) -> str | None:
    """A warning for a map of more than :data:`LARGE_MAP` points: what it costs, and the
    ``--bin`` that brings it under that size; None for a smaller one."""
    if points <= LARGE_MAP:
        return None
    k = int(np.ceil(np.sqrt(points / LARGE_MAP)))
    return (f"large map: {points / 1e6:.3g} M points (limit {LARGE_MAP / 1e6:.3g} M) need "
            f"about {BYTES_PER_POINT * points / 1e9:.2g} GB and a minute or more per 16 M "
            f"points (73 s for 4096 x 4096 on two cores); --bin {k} averages {k} x {k} "
            f"blocks ({points / k ** 2 / 1e6:.3g} M points), or cut a region in the "
            "instrument's software")
