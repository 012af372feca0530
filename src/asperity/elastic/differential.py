"""Differential-deflection coefficients: the discrete Laplacian of the cell influence coefficients.

The surface separation of two elastic half-spaces under a piecewise-constant pressure on
``dx`` x ``dy`` cells is ``h = h0 + x^2/(2 Rx) + y^2/(2 Ry) + phi + (2/(pi E')) sum D p`` with
``D_kl = I(k dx, l dy)`` Love's rectangle integral (:func:`~asperity.elastic.love_integral`).
Applying the 5-point Laplacian ``Delta_h`` to that sum gives the differential form of the
deflection equation used by Evans & Hughes (2000) and Holmes et al. (2003, Eq. 1)::

    Delta_h h = Delta_h phi + 1/Rx + 1/Ry + (2/(pi E')) sum_kl f_{k-i, l-j} p_kl

with ``f_kl = (D_{k+1,l} - 2 D_kl + D_{k-1,l})/dx^2 + (D_{k,l+1} - 2 D_kl + D_{k,l-1})/dy^2``.
The identity is exact for the discrete operators, so ``f`` carries no discretisation error of
its own. ``f_00 < 0``, every other ``f`` is positive and the far field decays like
``dx dy / rho^3``, which is what lets a relaxation solver treat only the centre term implicitly.

For a line contact (plane strain) the strip integral ``D(x) = -2 int ln|x - s| ds`` over a
strip of width ``dx`` replaces Love's rectangle (Johnson 1985, eq. 2.25; the arbitrary
constant of the 2-D solution drops out of the second difference).

References
----------
H. P. Evans, T. G. Hughes, Proc. IMechE C 214 (2000) 563-584.
M. J. A. Holmes, H. P. Evans, T. G. Hughes, R. W. Snidle, Proc. IMechE J 217 (2003) 289-303.
"""

from __future__ import annotations

import numpy as np

from .kernels import love_integral

__all__ = ["differential_coefficients", "line_differential_coefficients", "strip_integral"]


def differential_coefficients(x, y, dx: float, dy: float):
    """Differential-deflection coefficients ``f(x, y)`` of a ``dx`` x ``dy`` cell, in 1/m.

    Parameters
    ----------
    x, y : array_like
        Offsets of the field node from the loaded cell centre, m (normally integer multiples
        of ``dx`` and ``dy``).
    dx, dy : float
        Cell size, m.

    Returns
    -------
    ndarray
        ``f = [D(x+dx) - 2 D(x) + D(x-dx)]/dx^2 + [D(y+dy) - 2 D(y) + D(y-dy)]/dy^2`` with
        ``D = love_integral``. Multiplying by ``2/(pi E')`` and by the pressure gives the
        5-point Laplacian of the deflection (Holmes et al. 2003, Eq. 1). For a square cell,
        ``f(0, 0) dx = -9.9498``.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    d0 = love_integral(x, y, dx, dy)
    fx = love_integral(x + dx, y, dx, dy) - 2.0 * d0 + love_integral(x - dx, y, dx, dy)
    fy = love_integral(x, y + dy, dx, dy) - 2.0 * d0 + love_integral(x, y - dy, dx, dy)
    return fx / dx**2 + fy / dy**2


def strip_integral(x, dx: float):
    """Plane-strain strip integral ``D(x) = -2 int_{-dx/2}^{dx/2} ln|x - s| ds``, in m.

    The combined normal displacement of two bodies under a uniform pressure ``p`` on the strip
    is ``2 p D / (pi E')`` up to an additive constant (Johnson 1985, eq. 2.25).
    """
    x = np.asarray(x, dtype=float)

    def antiderivative(t):  # int ln|t| dt = t ln|t| - t, with 0 ln 0 = 0
        with np.errstate(divide="ignore", invalid="ignore"):
            tl = np.where(t == 0.0, 0.0, t * np.log(np.abs(np.where(t == 0.0, 1.0, t))))
        return tl - t

    return -2.0 * (antiderivative(x + 0.5 * dx) - antiderivative(x - 0.5 * dx))


def line_differential_coefficients(x, dx: float):
    """Line-contact coefficients ``f(x) = [D(x+dx) - 2 D(x) + D(x-dx)]/dx^2``, in 1/m.

    ``D`` is :func:`strip_integral`; ``d^2 h/dx^2 = 1/R + (2/(pi E')) sum f p`` is then exact for
    the 3-point second difference. ``f(0) dx = -6.5917`` is negative and all other coefficients
    are positive, decaying like ``2 dx / x^2``.
    """
    x = np.asarray(x, dtype=float)
    d = strip_integral(x + dx, dx) - 2.0 * strip_integral(x, dx) + strip_integral(x - dx, dx)
    return d / dx**2
