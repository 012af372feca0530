"""Filling missing points of measured surfaces (points an optical profiler could not measure).

Profiles: linear interpolation between the nearest measured neighbours (``numpy.interp``),
constant beyond the first and last measured points. Topographies: harmonic interpolation, the
solution of Laplace's equation on the missing pixels with the measured pixels as boundary
values: every filled height is the mean of its four neighbours (fewer at the border of the
image, a zero-slope condition there). This is the smoothest fill, with no new extrema, and the
method SurfaceTopography calls ``interpolate_undefined_data("harmonic")``.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse
import scipy.sparse.linalg

from ..errors import InputError

__all__ = ["fill_missing"]


def _fill_profile(z: np.ndarray, good: np.ndarray) -> np.ndarray:
    i = np.arange(z.size)
    out = z.copy()
    out[~good] = np.interp(i[~good], i[good], z[good])
    return out


def _fill_harmonic(z: np.ndarray, good: np.ndarray) -> np.ndarray:
    nx, ny = z.shape
    missing = np.flatnonzero(~good.ravel())
    number = -np.ones(z.size, dtype=int)
    number[missing] = np.arange(missing.size)
    ix, iy = np.unravel_index(missing, z.shape)
    rows, cols, vals = [], [], []
    rhs = np.zeros(missing.size)
    degree = np.zeros(missing.size)
    flat = z.ravel()
    for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        jx, jy = ix + dx, iy + dy
        inside = (jx >= 0) & (jx < nx) & (jy >= 0) & (jy < ny)
        degree += inside
        k = np.flatnonzero(inside)
        neighbour = np.ravel_multi_index((jx[k], jy[k]), z.shape)
        unknown = number[neighbour] >= 0
        rows.append(k[unknown])
        cols.append(number[neighbour[unknown]])
        vals.append(-np.ones(unknown.sum()))
        np.add.at(rhs, k[~unknown], flat[neighbour[~unknown]])
    rows.append(np.arange(missing.size))
    cols.append(np.arange(missing.size))
    vals.append(degree)
    a = scipy.sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                         np.concatenate(cols))),
                                shape=(missing.size, missing.size))
    out = flat.copy()
    out[missing] = scipy.sparse.linalg.spsolve(a.tocsc(), rhs)
    return out.reshape(z.shape)


def fill_missing(z) -> tuple[np.ndarray, int]:
    """Heights with the missing (non-finite) points filled, and how many were filled.

    Parameters
    ----------
    z : array_like, 1-D or 2-D
        Heights with NaN (or infinity) where a point is missing.

    Returns
    -------
    filled : ndarray
        Linear interpolation along a profile, harmonic interpolation over a topography (module
        docstring); unchanged where measured.
    count : int

    Raises
    ------
    InputError
        When fewer than two points (a profile) or no point (a topography) were measured.
    """
    z = np.asarray(z, dtype=float)
    good = np.isfinite(z)
    count = int(z.size - good.sum())
    if count == 0:
        return z.copy(), 0
    if good.sum() < 2:
        raise InputError("heights", "at least two measured points", f"{count} of {z.size} "
                         "missing")
    return (_fill_profile(z, good) if z.ndim == 1 else _fill_harmonic(z, good)), count
