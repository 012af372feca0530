"""Nodal fields of an EHL grid shared by the steady and transient solvers.

Values at the Hertz centre and along the centre line ``y = 0`` of a field indexed ``[ix, iy]``
(linear interpolation between nodes), and the central film of the Hertzian start from the
film formulas of :mod:`asperity.ehl.formulas`.
"""

from __future__ import annotations

import numpy as np

from . import formulas
from .problem import LineContact

__all__ = ["at_centre", "centre_line", "film_estimate"]


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


def film_estimate(problem) -> float:
    """Central film of the Hertzian start, m: Moes (line) or Nijenbanning (point).

    Nijenbanning's fit covers ``ry >= rx``; for ``ry < rx`` it is evaluated at ``ry = rx``,
    which is good enough for a start value.
    """
    lub = problem.lubricant
    args = (problem.mean_speed, lub.viscosity, lub.pressure_viscosity, problem.reduced_modulus)
    if isinstance(problem, LineContact):
        return formulas.moes_line(problem.load_per_length, problem.radius, *args).central
    ry = max(problem.ry, problem.rx)
    return formulas.nijenbanning_point(problem.load, problem.rx, ry, *args).central
