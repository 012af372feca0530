"""Form removal: the least-squares polynomial of a profile or surface (ISO 25178-2's F-operator).

The nominal form (a tilt, a cylinder's curvature) is the least-squares polynomial of a chosen
degree in the coordinates -- a line or a plane for degree 1, in x and y of total degree at most
``degree`` for a surface -- fitted to all points (to the measured ones only where missing
points were filled) and subtracted. Coordinates are scaled to [-1, 1] before the fit so that
high degrees stay well conditioned. A periodic surface has no form: only its mean is removed.
"""

from __future__ import annotations

import numpy as np
from numpy.polynomial import polynomial

from ..errors import InputError, check_int
from .topography import Profile, Topography

__all__ = ["principal_radii", "remove_form"]


def _scaled(coord: np.ndarray) -> np.ndarray:
    span = coord[-1] - coord[0]
    return 2 * (coord - coord[0]) / span - 1 if span else np.zeros_like(coord)


def remove_form(surface, degree: int = 1, measured=None):
    """The surface minus its least-squares polynomial form of ``degree`` (0: the mean).

    Parameters
    ----------
    surface : Profile or Topography
    degree : int
        0 mean, 1 line/plane, 2 parabola/quadric, ... (total degree in x and y for a surface).
    measured : ndarray of bool, optional
        The points the form is fitted to (default all): the measured ones of a surface whose
        missing points were filled, so that the fill does not tilt the reference (ISO
        25178-2's mean plane is of the measured points). The form is subtracted everywhere.

    Returns
    -------
    Profile or Topography
        Same grid, heights from the fitted form.
    """
    degree = check_int("form_degree", degree, 0)
    if not isinstance(surface, Profile | Topography):
        raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
    z = surface.z
    keep = _measured(measured, z.shape)
    if surface.periodic or degree == 0:
        return surface.with_heights(z - z[keep].mean())
    if isinstance(surface, Profile):
        if degree >= keep.sum():
            raise InputError("form_degree", f"a degree below the {keep.sum()} points", degree)
        fit = np.polynomial.Polynomial.fit(surface.x[keep], z[keep], degree)
        return surface.with_heights(z - fit(surface.x))
    X, Y = np.meshgrid(_scaled(surface.x), _scaled(surface.y), indexing="ij")
    vander = polynomial.polyvander2d(X.ravel(), Y.ravel(), [degree, degree])
    i, j = np.meshgrid(np.arange(degree + 1), np.arange(degree + 1), indexing="ij")
    terms = vander[:, (i + j).ravel() <= degree]
    if terms.shape[1] >= keep.sum():
        raise InputError("form_degree", f"a degree with fewer terms than the {keep.sum()} "
                         "points", degree)
    coef = np.linalg.lstsq(terms[keep.ravel()], z[keep], rcond=None)[0]
    return surface.with_heights(z - (terms @ coef).reshape(z.shape))


def _measured(measured, shape) -> np.ndarray:
    """A mask of the points to fit to: ``measured``, or all points."""
    if measured is None:
        return np.ones(shape, bool)
    keep = np.asarray(measured, bool)
    if keep.shape != shape:
        raise InputError("measured", f"a mask of the surface's shape {shape}", keep.shape)
    return keep


def principal_radii(topography: Topography) -> tuple[float, float, float]:
    """Principal radii of curvature of the least-squares quadric of a topography.

    The quadric ``z = c0 + c1 x + c2 y + a x^2 + b x y + c y^2`` is fitted to all points in
    centred physical coordinates; its Hessian ``[[2 a, b], [b, 2 c]]`` has the principal
    curvatures k1, k2 as eigenvalues (the second fundamental form of a nearly flat surface,
    slopes << 1), and the radii are ``1 / |k|`` (inf where k = 0).

    Returns
    -------
    (float, float, float)
        The smaller radius, the larger (m), and the direction of the stronger curvature in
        degrees counter-clockwise from x, in [0, 180).
    """
    if not isinstance(topography, Topography):
        raise InputError("surface", "a Topography", type(topography).__name__)
    X, Y = np.meshgrid(topography.x - topography.x.mean(), topography.y - topography.y.mean(),
                       indexing="ij")
    terms = np.stack([np.ones(X.size), X.ravel(), Y.ravel(), X.ravel() ** 2,
                      (X * Y).ravel(), Y.ravel() ** 2], axis=1)
    a, b, c = np.linalg.lstsq(terms, topography.z.ravel(), rcond=None)[0][3:]
    curvatures, directions = np.linalg.eigh(np.array([[2 * a, b], [b, 2 * c]]))
    order = np.argsort(-np.abs(curvatures))
    with np.errstate(divide="ignore"):
        radii = 1.0 / np.abs(curvatures[order])
    strong = directions[:, order[0]]
    return (float(radii[0]), float(radii[1]),
            float(np.degrees(np.arctan2(strong[1], strong[0])) % 180.0))
