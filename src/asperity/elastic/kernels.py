"""Influence coefficients of uniformly loaded rectangular cells on an elastic half-space.

A cell of size ``dx`` x ``dy`` centred at the origin carries a uniform pressure or a uniform
tangential traction. The functions here return the surface displacement at the points
``(x, y)`` per unit load, obtained by integrating the point-load solutions of Boussinesq and
Cerruti in closed form over the cell (Love 1929; Johnson 1985, eqs. 3.25, 3.86).

Geometric integrals (pure geometry, in m) are kept apart from the elastic constants so that
the same arrays serve one body, two bodies, and the EHL differential coefficients.

References
----------
A. E. H. Love, Phil. Trans. R. Soc. A 228 (1929) 377-420.
K. L. Johnson, *Contact Mechanics*, 1985, sec. 3.2 (Boussinesq, Cerruti), eq. 3.25.
J. R. Barber, *Elasticity*, 3rd ed., 2010, ch. 21-22 (Fourier solutions of the half-space).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..materials import Material, contact_modulus

__all__ = [
    "love_integral",
    "cerruti_integrals",
    "normal_influence",
    "TangentialInfluence",
    "tangential_influence",
    "tangential_transfer",
]


def _corner_sum(fun, x, y, a, b):
    """sum over the four corners of F(X, Y) with X = x -/+ a, Y = y -/+ b (double integral)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    return fun(x + a, y + b) - fun(x - a, y + b) - fun(x + a, y - b) + fun(x - a, y - b)


def _x_asinh_y_over_x(X, Y):
    """X asinh(Y/|X|), zero where X == 0 (its limit)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        out = X * np.arcsinh(Y / np.abs(X))
    return np.where(X == 0.0, 0.0, out)


def _F_inv_r(X, Y):
    """Antiderivative of 1/r: X asinh(Y/|X|) + Y asinh(X/|Y|) (cancellation-free form)."""
    return _x_asinh_y_over_x(X, Y) + _x_asinh_y_over_x(Y, X)


def _F_xx_r3(X, Y):
    """Antiderivative of x^2/r^3 in x and y: Y asinh(X/|Y|)."""
    return _x_asinh_y_over_x(Y, X)


def _F_yy_r3(X, Y):
    """Antiderivative of y^2/r^3: X asinh(Y/|X|)."""
    return _x_asinh_y_over_x(X, Y)


def _F_xy_r3(X, Y):
    """Antiderivative of x y/r^3: -r."""
    return -np.hypot(X, Y)


def _F_x_r2(X, Y):
    """Antiderivative of x/r^2: Y ln(r) + X atan(Y/X) (terms in Y alone cancel in the sum)."""
    r = np.hypot(X, Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(r == 0.0, 0.0, Y * np.log(np.where(r == 0.0, 1.0, r)))
        t2 = np.where(X == 0.0, 0.0, X * np.arctan(Y / X))
    return t1 + t2


def _F_y_r2(X, Y):
    """Antiderivative of y/r^2 (x and y swapped)."""
    return _F_x_r2(Y, X)


def love_integral(x, y, dx, dy):
    """Geometric integral I = int int 1/r dA over a cell, in m (Love 1929; Johnson eq. 3.25).

    Parameters
    ----------
    x, y : array_like
        Field points relative to the cell centre, m.
    dx, dy : float
        Cell size, m.

    Returns
    -------
    ndarray
        I(x, y). The combined normal displacement of two bodies under a uniform pressure p on
        the cell is w = p I / (pi E*) = 2 p I / (pi E'). At the centre of a square of side s,
        I = 4 s asinh(1) = 3.5255 s.
    """
    return _corner_sum(_F_inv_r, x, y, 0.5 * dx, 0.5 * dy)


def cerruti_integrals(x, y, dx, dy):
    """Geometric integrals of the Cerruti/Boussinesq point-load kernels over a cell.

    Returns
    -------
    dict of ndarray
        ``inv_r`` (1/r), ``xx`` (x^2/r^3), ``yy`` (y^2/r^3), ``xy`` (xy/r^3), ``x_r2`` (x/r^2),
        ``y_r2`` (y/r^2), each integrated over the cell, evaluated at (x, y) relative to the
        cell centre.
    """
    a, b = 0.5 * dx, 0.5 * dy
    return {
        "inv_r": _corner_sum(_F_inv_r, x, y, a, b),
        "xx": _corner_sum(_F_xx_r3, x, y, a, b),
        "yy": _corner_sum(_F_yy_r3, x, y, a, b),
        "xy": _corner_sum(_F_xy_r3, x, y, a, b),
        "x_r2": _corner_sum(_F_x_r2, x, y, a, b),
        "y_r2": _corner_sum(_F_y_r2, x, y, a, b),
    }


def normal_influence(x, y, dx, dy, body1: Material, body2: Material):
    """Combined normal displacement of two bodies per unit pressure on a cell, m/Pa.

    w = I(x, y) / (pi E*), with I from :func:`love_integral` and E* from
    :func:`asperity.materials.contact_modulus`.
    """
    return love_integral(x, y, dx, dy) / (np.pi * contact_modulus(body1, body2))


@dataclass(frozen=True)
class TangentialInfluence:
    """Surface displacements per unit uniform load on a cell (m/Pa), u_i due to load j.

    ``xx``, ``xy`` (= ``yx``), ``yy``: in-plane displacement due to tangential traction;
    ``zx``, ``zy``: normal displacement due to tangential traction x, y; ``xz``, ``yz``:
    in-plane displacement due to pressure (reciprocity gives ``xz = -zx``).
    """

    xx: np.ndarray
    xy: np.ndarray
    yy: np.ndarray
    zx: np.ndarray
    zy: np.ndarray

    @property
    def xz(self) -> np.ndarray:
        return -self.zx

    @property
    def yz(self) -> np.ndarray:
        return -self.zy


def _pair(one: TangentialInfluence, two: TangentialInfluence) -> TangentialInfluence:
    """Two bodies' coefficients combined: in-plane terms add, normal coupling terms subtract."""
    return TangentialInfluence(
        xx=one.xx + two.xx,
        xy=one.xy + two.xy,
        yy=one.yy + two.yy,
        zx=one.zx - two.zx,
        zy=one.zy - two.zy,
    )


def _one_body(g, body: Material) -> TangentialInfluence:
    """Cerruti influence for one body (Johnson eq. 3.86 at z = 0), z positive into the body.

    u_x = q/(2 pi G) [(1 - nu)/r + nu x^2/r^3], u_y = q/(2 pi G) nu x y / r^3,
    u_z = q (1 - 2 nu)/(4 pi G) x / r^2  (Betti-consistent with Boussinesq's
    u_x = -p (1 - 2 nu)/(4 pi G) x / r^2).
    """
    if body.rigid:
        zero = np.zeros_like(g["inv_r"])
        return TangentialInfluence(zero, zero, zero, zero, zero)
    G, nu = body.shear_modulus, body.poisson_ratio
    c = 1.0 / (2.0 * np.pi * G)
    return TangentialInfluence(
        xx=c * ((1 - nu) * g["inv_r"] + nu * g["xx"]),
        xy=c * nu * g["xy"],
        yy=c * ((1 - nu) * g["inv_r"] + nu * g["yy"]),
        zx=0.5 * c * (1 - 2 * nu) * g["x_r2"],
        zy=0.5 * c * (1 - 2 * nu) * g["y_r2"],
    )


def tangential_influence(x, y, dx, dy, body1: Material, body2: Material | None = None):
    """Influence of uniform tangential traction on a cell, m/Pa.

    With one body, its own surface displacements (Cerruti). With two bodies, the *relative*
    displacement of body 1 with respect to body 2 when the traction q acts on body 1 and -q on
    body 2: in-plane terms add ((1 - nu)/G compliances), the normal coupling terms subtract and
    vanish for identical materials ((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2).
    """
    g = cerruti_integrals(x, y, dx, dy)
    one = _one_body(g, body1)
    if body2 is None:
        return one
    two = _one_body(g, body2)
    return _pair(one, two)


def _one_body_transfer(kx, ky, k, body: Material) -> TangentialInfluence:
    """Fourier transfer functions of one half-space's surface (z into the body), m/Pa.

    The 2-D Fourier transforms (``f(k) = int f(r) exp(-i k.r) dA``) of the Cerruti kernels of
    :func:`_one_body`, from FT(1/r) = 2 pi/k, FT(r) = -2 pi/k^3 (so that
    x^2/r^3 = d^2 r/dy^2 and x y/r^3 = -d^2 r/dx dy transform to 2 pi k_y^2/k^3 and
    -2 pi k_x k_y/k^3) and FT(ln r) = -2 pi/k^2 (x/r^2 = d ln r/dx)::

        u_x = [1 - nu k_x^2/k^2] q_x/(G k) - nu k_x k_y/(G k^3) q_y
        u_z = -i (1 - 2 nu) k_x/(2 G k^2) q_x   (and y alike)
    """
    if body.rigid:
        zero = np.zeros_like(k)
        return TangentialInfluence(zero, zero, zero, zero.astype(complex), zero.astype(complex))
    G, nu = body.shear_modulus, body.poisson_ratio
    return TangentialInfluence(
        xx=(1.0 - nu * kx * kx / (k * k)) / (G * k),
        xy=-nu * kx * ky / (G * k**3),
        yy=(1.0 - nu * ky * ky / (k * k)) / (G * k),
        zx=-0.5j * (1.0 - 2.0 * nu) * kx / (G * k * k),
        zy=-0.5j * (1.0 - 2.0 * nu) * ky / (G * k * k),
    )


def tangential_transfer(kx, ky, body1: Material, body2: Material | None = None):
    """Fourier transfer functions of the Cerruti half-space (continuum), m/Pa.

    The exact surface displacement of a half-space under a traction mode
    ``q exp(i k.r)`` is ``T(k) q exp(i k.r)``; ``T`` is returned for the wavevectors
    ``(kx, ky)`` (rad/m, ``k > 0``) as a :class:`TangentialInfluence` whose components are
    the transforms of :func:`tangential_influence`'s point-load kernels (Johnson 1985,
    eq. 3.86; Barber 2010, ch. 22), with the same one-body and two-body (relative
    displacement) conventions::

        T_xx = (1 - nu k_x^2/k^2)/(G k),  T_xy = -nu k_x k_y/(G k^3),
        T_yy = (1 - nu k_y^2/k^2)/(G k),  T_zx = -i (1 - 2 nu) k_x/(2 G k^2)

    summed over the bodies (``T_zx`` differenced).
    """
    kx, ky = np.broadcast_arrays(np.asarray(kx, dtype=float), np.asarray(ky, dtype=float))
    k = np.hypot(kx, ky)
    if np.any(k <= 0):
        raise InputError("kx, ky", "non-zero wavevectors (the mean mode is not defined)")
    one = _one_body_transfer(kx, ky, k, body1)
    if body2 is None:
        return one
    two = _one_body_transfer(kx, ky, k, body2)
    return _pair(one, two)
