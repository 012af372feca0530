"""Nodal fields of an EHL grid shared by the steady and transient solvers.

Values at the Hertz centre and along the centre line ``y = 0`` of a field indexed ``[ix, iy]``
(linear interpolation between nodes), and the upwind difference of the Reynolds wedge term.
The start film is the problem's own :meth:`film_estimate`.
"""

from __future__ import annotations

import numpy as np

__all__ = ["at_centre", "centre_line", "upwind_difference"]


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


def upwind_difference(q) -> np.ndarray:
    """``dX`` times the upwind derivative dq/dX of the Reynolds wedge term at every node.

    The weights ``(c0, c1, c2) = (3/2, 2, 1/2)`` of the compiled sweeps
    (:mod:`asperity.ehl.kernels`): ``1.5 q_i - 2 q_{i-1} + 0.5 q_{i-2}``, first order
    ``q_1 - q_0`` next to the inlet and 0 at ``i = 0``; ``q`` indexed ``[ix, ...]``.
    """
    q = np.asarray(q)
    out = np.zeros_like(q)
    out[1] = q[1] - q[0]
    out[2:] = 1.5 * q[2:] - 2.0 * q[1:-1] + 0.5 * q[:-2]
    return out
