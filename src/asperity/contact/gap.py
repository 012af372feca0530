"""Undeformed gaps of rough bodies: an ellipsoid with roughness on a flat, a rough surface.

The undeformed gap ``g0(x, y)`` is what :func:`asperity.contact.solve_normal` closes. For two
smooth bodies near the point of first contact it is the paraboloid
``x^2 / (2 Rx) + y^2 / (2 Ry)`` with the relative radii of curvature Rx, Ry (Johnson,
*Contact Mechanics*, 1985, sec. 4.1); roughness heights ``z`` (m, positive towards the other
body) close it: ``g0 = x^2 / (2 Rx) + y^2 / (2 Ry) - z``. Only differences of ``g0`` matter
under load control (the approach absorbs a constant).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..surfaces import Profile, Topography

__all__ = ["ellipsoid_gap", "surface_gap"]


def _heights(roughness, x, y) -> np.ndarray:
    """Roughness heights on the grid x by y (a Profile varies along x only)."""
    if isinstance(roughness, Topography):
        if roughness.z.shape == (x.size, y.size) and np.allclose(roughness.x, x) and \
                np.allclose(roughness.y, y):
            return np.array(roughness.z)
        return roughness.sample(x, y)
    if isinstance(roughness, Profile):
        line = roughness.z if np.array_equal(roughness.x, x) else roughness.sample(x)
        return np.repeat(np.asarray(line)[:, None], y.size, axis=1)
    z = np.asarray(roughness, dtype=float)
    if z.shape != (x.size, y.size):
        raise InputError("roughness", f"a Topography, a Profile or heights of shape "
                                      f"(len(x), len(y)) = {(x.size, y.size)}", z.shape)
    return z


def ellipsoid_gap(rx, ry=None, x=None, y=None, roughness=None) -> np.ndarray:
    """Undeformed gap of an ellipsoid with roughness on a flat, ``x^2/(2 rx) + y^2/(2 ry) - z``.

    Parameters
    ----------
    rx, ry : float
        Relative radii of curvature along x and y, m (``ry`` defaults to ``rx``, a sphere;
        ``rx = inf`` gives a nominally flat contact, ``ry = inf`` a cylinder along y).
    x, y : array_like, optional
        Cell-centre coordinates, m; by default those of ``roughness`` (a Topography).
    roughness : Topography, Profile or array_like, optional
        Heights ``z`` (m, positive towards the flat). A Topography on another grid is sampled
        by its cubic splines; a Profile varies along x (ridges along y, a transverse-ground
        surface); an array must have the grid's shape.

    Returns
    -------
    ndarray, shape (len(x), len(y))
        The undeformed gap ``g0``, m, for :func:`asperity.contact.solve_normal`.
    """
    ry = rx if ry is None else ry
    for name, r in (("rx", rx), ("ry", ry)):
        if not float(r) > 0:
            raise InputError(name, "a radius of curvature > 0 (inf for flat), m", r)
    if x is None or y is None:
        if not isinstance(roughness, Topography):
            raise InputError("x, y", "the grid's coordinates, or a Topography as roughness")
        x, y = roughness.x, roughness.y
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    X, Y = np.meshgrid(x, y, indexing="ij")
    gap = np.zeros_like(X)
    if np.isfinite(rx):
        gap += X**2 / (2 * float(rx))
    if np.isfinite(ry):
        gap += Y**2 / (2 * float(ry))
    if roughness is not None:
        gap -= _heights(roughness, x, y)
    return gap


def surface_gap(topography: Topography) -> np.ndarray:
    """Undeformed gap of a rough surface on a rigid flat: ``max(z) - z`` (zero at the summit).

    Parameters
    ----------
    topography : Topography
        Heights ``z`` (m, positive towards the flat).

    Returns
    -------
    ndarray
        The gap on the topography's grid, m.
    """
    if not isinstance(topography, Topography):
        raise InputError("topography", "a Topography", type(topography).__name__)
    return topography.z.max() - topography.z
