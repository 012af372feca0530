"""Nodal fields of an EHL grid shared by the steady and transient solvers.

Values at the Hertz centre and along the centre line ``y = 0`` of a field indexed ``[ix, iy]``
(linear interpolation between nodes). The start film is the problem's own
:meth:`film_estimate`.
"""

from __future__ import annotations

import numpy as np

__all__ = ["at_centre", "centre_line"]


def at_centre(state, field) -> float:
    """Value of a nodal field at the Hertz centre (0, 0), bilinear.

    ``state`` gives the dimensionless node coordinates ``X``, ``Y`` and ``line`` (an
    :class:`~asperity.ehl.solver.EHLState`).
    """
    row = np.array([np.interp(0.0, state.X, field[:, j]) for j in range(field.shape[1])])
    return float(row[0]) if state.line else float(np.interp(0.0, state.Y, row))


def centre_line(state, field) -> np.ndarray:
    """A nodal field along y = 0 (linear interpolation between rows); see :func:`at_centre`."""
    if state.line:
        return field[:, 0]
    return np.array([np.interp(0.0, state.Y, field[i]) for i in range(field.shape[0])])
