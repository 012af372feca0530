"""How much the side boundaries of a point contact's domain move its film.

The Reynolds equation is solved with p = 0 on the side boundaries y = y0, y1. Where the
pressure has not decayed there, the boundary cuts off the side leakage. A side pressure of
0.26 % of p_h lowered the minimum film of a ball-on-disc case by 3.9 % and that of the gear
case by 0.06 % (docs/ehl-robustness.md, "Side boundaries"), so the pressure at the sides alone
does not say whether the film has moved. :func:`side_probe` measures it: the smooth steady
contact solved twice at twice the mesh spacing, on the given domain and with both sides moved
out, everything else the same.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .solver import sequencing_levels, solve_steady

__all__ = ["MIN_NODES", "SideProbe", "side_probe"]

#: Fewest nodes of a probe solve along x or y (the solver's own minimum).
MIN_NODES = 9


@dataclass(frozen=True)
class SideProbe:
    """The steady film on the given domain and on one with the sides moved out.

    Attributes
    ----------
    y_bounds, wide_y_bounds : (float, float)
        Side boundaries of the two solves, m.
    minimum_film, central_film : (float, float)
        Minimum and central film of the two solves, m.
    converged : bool
        Whether both solves converged.
    nodes : (int, int)
        Nodes (nx, ny) of the solve on the given domain (the wide one has more along y).
    """

    y_bounds: tuple[float, float]
    wide_y_bounds: tuple[float, float]
    minimum_film: tuple[float, float]
    central_film: tuple[float, float]
    converged: bool
    nodes: tuple[int, int]

    @property
    def minimum_film_change(self) -> float:
        """Minimum film on the given domain relative to the wider one, minus 1."""
        return self.minimum_film[0] / self.minimum_film[1] - 1.0

    @property
    def central_film_change(self) -> float:
        """Central film on the given domain relative to the wider one, minus 1."""
        return self.central_film[0] / self.central_film[1] - 1.0


def side_probe(problem, x, y, widen: float = 1.0) -> SideProbe:
    """Solve the smooth steady contact on the domain of ``x``, ``y`` and with wider sides.

    Both solves use twice the mesh spacing of the given nodes (``(n - 1) // 2 + 1`` nodes on
    the given domain, at least 9), or the default mesh of that domain
    (:meth:`PointContact.default_nodes`) where it is coarser: on 401 x 101 nodes of a
    ball-on-disc case the steady solver did not converge in its default sweeps (151 s), on
    its default mesh it does in seconds. They are grid-sequenced like a default mesh
    (:func:`~asperity.ehl.solver.sequencing_levels`), with the solver's defaults otherwise;
    the wide domain adds whole cells of the coarsest grid on each side (at least ``widen``
    b).

    Parameters
    ----------
    problem : PointContact
        The contact (SI).
    x, y : ndarray
        Nodes of the solution whose domain is probed, m.
    widen : float
        How far each side boundary moves out, in units of the Hertz semi-axis b.

    Returns
    -------
    SideProbe
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    x_bounds = (float(x[0]), float(x[-1]))
    y_bounds = (float(y[0]), float(y[-1]))
    default = problem.default_nodes((x_bounds, y_bounds))
    nx, ny = (max(MIN_NODES, min((n.size - 1) // 2 + 1, d))
              for n, d in zip((x, y), default, strict=True))
    levels = sequencing_levels(nx, ny)
    dy = (y[-1] - y[0]) / (ny - 1)
    step = 2 ** (levels - 1)  # whole cells of the coarsest sequenced grid on each side
    extra = step * max(1, math.ceil(widen * problem.b / dy / step))
    wide = (y_bounds[0] - extra * dy, y_bounds[1] + extra * dy)
    # the probes share the inlet of the solution probed: whoever checks it reports it, once
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "domain: the inlet", RuntimeWarning)
        narrow_res = solve_steady(problem, nx=nx, ny=ny, domain=(x_bounds, y_bounds),
                                  levels=levels)
        wide_res = solve_steady(problem, nx=nx, ny=ny + 2 * extra, domain=(x_bounds, wide),
                                levels=levels)
    return SideProbe(y_bounds, wide,
                     (narrow_res.minimum_film, wide_res.minimum_film),
                     (narrow_res.central_film, wide_res.central_film),
                     bool(narrow_res.converged and wide_res.converged), (nx, ny))
