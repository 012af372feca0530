"""Uniform grids: the one check of cell-centre coordinates that every layer shares.

Surfaces, the elastic half-space and the solvers all take 1-D arrays of uniformly spaced
cell-centre (or node) coordinates; :func:`grid_spacing` validates one and returns its spacing.
It lives here, below every other module, so that no layer imports another only for it.
"""

from __future__ import annotations

import numpy as np

from .errors import InputError

__all__ = ["grid_spacing"]


def grid_spacing(coord, name: str) -> float:
    """Uniform spacing of a coordinate array, m.

    Parameters
    ----------
    coord : array_like
        1-D, finite, increasing, uniformly spaced coordinates (to 1e-6 of the spacing).
    name : str
        The argument's name, for the error message.

    Returns
    -------
    float
        The mean spacing.

    Raises
    ------
    InputError
        Fewer than two points, non-finite, decreasing or non-uniform coordinates.
    """
    c = np.asarray(coord, dtype=float)
    if c.ndim != 1 or c.size < 2:
        raise InputError(name, "a 1-D array of at least 2 cell-centre coordinates")
    if not np.all(np.isfinite(c)):
        raise InputError(name, "finite coordinates")
    d = np.diff(c)
    h = d.mean()
    if h <= 0 or np.max(np.abs(d - h)) > 1e-6 * abs(h):
        raise InputError(name, "uniformly spaced, increasing coordinates")
    return float(h)
