"""The surface data model: a :class:`Profile` z(x) and a :class:`Topography` z(x, y).

Both hold heights on uniform cell-centre coordinates (SI, metres), arrays indexed ``[ix, iy]``
with x the rolling (first) direction. They are frozen: every operation returns a new object.
Heights between the grid points come from cubic splines (``scipy.interpolate.CubicSpline``,
periodic end conditions when the data are periodic), built once per object and cached, so that a
transient solver can call :meth:`Profile.sample` every time step at no rebuilding cost.

A *periodic* surface repeats with period ``n * spacing`` (the point after the last one is the
first); generators that filter noise by FFT produce periodic surfaces.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.interpolate import CubicSpline

from ..errors import InputError
from ..grids import grid_spacing

__all__ = ["Profile", "Topography", "cell_centres"]


def cell_centres(n: int, spacing: float) -> np.ndarray:
    """Cell-centre coordinates ``(i + 1/2) * spacing``, i = 0 .. n-1, of a surface on [0, n h]."""
    return (np.arange(int(n)) + 0.5) * float(spacing)


def _readonly(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.flags.writeable = False
    return a


def _spline_along(coord: np.ndarray, values: np.ndarray, periodic: bool, axis: int):
    """Cubic spline through ``values`` along ``axis``; periodic splines close the period."""
    if periodic:
        h = coord[1] - coord[0]
        knots = np.append(coord, coord[-1] + h)
        first = np.take(values, [0], axis=axis)
        return CubicSpline(knots, np.concatenate([values, first], axis=axis), axis=axis,
                           bc_type="periodic")
    return CubicSpline(coord, values, axis=axis, bc_type="not-a-knot")


def _wrap_or_check(points, coord: np.ndarray, periodic: bool, field: str) -> np.ndarray:
    """Map query positions into the period, or check that they lie inside the data."""
    p = np.asarray(points, dtype=float)
    if not np.all(np.isfinite(p)):
        raise InputError(field, "finite positions")
    h = coord[1] - coord[0]
    if periodic:
        return coord[0] + np.mod(p - coord[0], coord.size * h)
    lo, hi = coord[0], coord[-1]
    tol = 1e-9 * h
    if p.size and (p.min() < lo - tol or p.max() > hi + tol):
        raise InputError(field, f"positions within the data [{lo:.6g}, {hi:.6g}] m of a "
                                "non-periodic surface")
    return np.clip(p, lo, hi)


@dataclass(frozen=True, eq=False)
class Profile:
    """Heights ``z`` (m) on uniform, increasing positions ``x`` (m).

    Attributes
    ----------
    x : ndarray, shape (n,)
        Uniformly spaced cell-centre positions.
    z : ndarray, shape (n,)
        Heights, metal below (a larger z is higher material).
    periodic : bool
        True when the profile repeats with period ``n * spacing``.
    """

    x: np.ndarray
    z: np.ndarray
    periodic: bool = False

    def __post_init__(self):
        grid_spacing(self.x, "x")
        z = np.asarray(self.z, dtype=float)
        if z.shape != np.shape(self.x):
            raise InputError("z", f"heights of the same shape as x {np.shape(self.x)}", z.shape)
        if not np.all(np.isfinite(z)):
            raise InputError("z", "finite heights (no NaN or infinity)")
        object.__setattr__(self, "x", _readonly(self.x))
        object.__setattr__(self, "z", _readonly(z))
        object.__setattr__(self, "periodic", bool(self.periodic))

    @property
    def spacing(self) -> float:
        """Grid spacing (m)."""
        return float(self.x[1] - self.x[0])

    @property
    def length(self) -> float:
        """Length covered by the cells, ``n * spacing`` (m); the period when periodic."""
        return self.x.size * self.spacing

    @cached_property
    def _spline(self) -> CubicSpline:
        return _spline_along(self.x, self.z, self.periodic, axis=0)

    def sample(self, x) -> np.ndarray:
        """Heights at arbitrary positions by a cached cubic spline.

        Parameters
        ----------
        x : array_like
            Positions (m). A periodic profile wraps them into its period; a non-periodic one
            accepts only positions inside ``[x[0], x[-1]]``.

        Returns
        -------
        ndarray
            Heights (m), same shape as ``x``.
        """
        return self._spline(_wrap_or_check(x, self.x, self.periodic, "x"))

    def with_heights(self, z) -> Profile:
        """The same positions with new heights."""
        return Profile(self.x, z, self.periodic)

    def extrude(self, y) -> Topography:
        """A topography constant across ``y``: a transverse-ground surface, ridges along y.

        Parameters
        ----------
        y : array_like
            Uniform cell-centre positions across the rolling direction (m).
        """
        y = np.asarray(y, dtype=float)
        grid_spacing(y, "y")
        return Topography(self.x, y, np.repeat(self.z[:, None], y.size, axis=1), self.periodic)


@dataclass(frozen=True, eq=False)
class Topography:
    """Heights ``z[ix, iy]`` (m) on uniform, increasing ``x`` and ``y`` (m).

    Attributes
    ----------
    x, y : ndarray
        Uniformly spaced cell-centre positions; x is the rolling (first) direction.
    z : ndarray, shape (x.size, y.size)
        Heights, metal below.
    periodic : bool
        True when the surface repeats in both directions.
    """

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    periodic: bool = False

    def __post_init__(self):
        grid_spacing(self.x, "x")
        grid_spacing(self.y, "y")
        z = np.asarray(self.z, dtype=float)
        shape = (np.size(self.x), np.size(self.y))
        if z.shape != shape:
            raise InputError("z", f"heights of shape (x.size, y.size) = {shape}", z.shape)
        if not np.all(np.isfinite(z)):
            raise InputError("z", "finite heights (no NaN or infinity)")
        object.__setattr__(self, "x", _readonly(self.x))
        object.__setattr__(self, "y", _readonly(self.y))
        object.__setattr__(self, "z", _readonly(z))
        object.__setattr__(self, "periodic", bool(self.periodic))

    @property
    def spacing(self) -> tuple[float, float]:
        """Grid spacings (dx, dy) in m."""
        return float(self.x[1] - self.x[0]), float(self.y[1] - self.y[0])

    @property
    def shape(self) -> tuple[int, int]:
        """Number of points (nx, ny)."""
        return self.z.shape

    @cached_property
    def _spline_x(self) -> CubicSpline:
        return _spline_along(self.x, self.z, self.periodic, axis=0)

    def sample(self, x, y=None) -> np.ndarray:
        """Heights on the grid ``x`` by ``y`` (outer product) by tensor cubic splines.

        The spline along x (all columns at once) is built once and cached; the spline along y
        is built per call unless ``y`` is the surface's own ``y`` (or None), when only the x
        interpolation is done -- the case of a surface moving in the rolling direction.

        Parameters
        ----------
        x : array_like, 1-D
            Positions along x (m); wrapped into the period when periodic.
        y : array_like, 1-D, optional
            Positions along y (m); default the surface's own ``y``.

        Returns
        -------
        ndarray, shape (len(x), len(y))
        """
        xs = np.atleast_1d(_wrap_or_check(x, self.x, self.periodic, "x"))
        if xs.ndim != 1:
            raise InputError("x", "a 1-D array of positions")
        along_x = self._spline_x(xs)
        if y is None or (np.shape(y) == self.y.shape and np.array_equal(y, self.y)):
            return along_x
        ys = np.atleast_1d(_wrap_or_check(y, self.y, self.periodic, "y"))
        if ys.ndim != 1:
            raise InputError("y", "a 1-D array of positions")
        return _spline_along(self.y, along_x, self.periodic, axis=1)(ys)

    def with_heights(self, z) -> Topography:
        """The same grid with new heights."""
        return Topography(self.x, self.y, z, self.periodic)

    def profile(self, iy: int) -> Profile:
        """The profile along x at column ``iy``."""
        return Profile(self.x, self.z[:, iy], self.periodic)
