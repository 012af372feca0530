"""How much the side boundaries of a point contact's domain, and the inlet of a point or line
contact's, move its film.

The Reynolds equation is solved with p = 0 on the side boundaries y = y0, y1. Where the
pressure has not decayed there, the boundary cuts off the side leakage. A side pressure of
0.26 % of p_h lowered the minimum film of a ball-on-disc case by 3.9 % and that of the gear
case by 0.06 % (docs/ehl-robustness.md, "Side boundaries"), so the pressure at the sides alone
does not say whether the film has moved. :func:`side_probe` measures it: the smooth steady
contact solved twice at twice the mesh spacing, on the given domain and with both sides moved
out, everything else the same.

The inlet boundary x = x0 is a meniscus of the same kind. Hamrock & Dowson's starvation fit
(:func:`asperity.diagnostics.ehl_inlet_length`) puts it too close at high M: a 6205 ball
bearing's contact (M = 18,100) lost 5.4 % of its central film with the inlet at -1.3 a against
-2.5 a, where the fit predicts none (docs/ehl-robustness.md). :func:`inlet_probe` measures it
the same way, with the inlet moved upstream; a line contact, which has no such fit here, only
that way (a cam contact lost 6.8 % of its central film with the inlet at -1.5 a).

A thick film whose fit adds a rigid-isoviscous film of its size (a wide ellipse at low M, a
soft ellipse at L = 0) carries part of its load by a pressure that reaches far beyond the
contact: its film rises when the inlet and the sides move out together, by more than either
alone shows (docs/ehl-robustness.md, "Soft ellipses at L = 0"). :func:`domain_probe` measures
that, with the inlet distance and the sides' half-widths scaled together.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .solver import sequencing_levels, solve_steady

__all__ = ["MIN_NODES", "DomainProbe", "InletProbe", "SideProbe", "domain_probe", "inlet_probe",
           "side_probe"]

#: Fewest nodes of a probe solve along x or y (the solver's own minimum).
MIN_NODES = 9


class _FilmChanges:
    """The relative film changes of a probe's two solves (``minimum_film``, ``central_film``:
    the given domain's and the other one's)."""

    @property
    def minimum_film_change(self) -> float:
        """Minimum film on the given domain relative to the other one, minus 1."""
        return self.minimum_film[0] / self.minimum_film[1] - 1.0

    @property
    def central_film_change(self) -> float:
        """Central film on the given domain relative to the other one, minus 1."""
        return self.central_film[0] / self.central_film[1] - 1.0


@dataclass(frozen=True)
class SideProbe(_FilmChanges):
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


@dataclass(frozen=True)
class InletProbe(_FilmChanges):
    """The steady film on the given domain and on one with the inlet moved upstream.

    Attributes
    ----------
    x_min, long_x_min : float
        Inlet boundaries of the two solves, m.
    minimum_film, central_film : (float, float)
        Minimum and central film of the two solves, m.
    converged : bool
        Whether both solves converged.
    nodes : (int, int)
        Nodes (nx, ny) of the solve on the given domain (the long one has more along x).
    """

    x_min: float
    long_x_min: float
    minimum_film: tuple[float, float]
    central_film: tuple[float, float]
    converged: bool
    nodes: tuple[int, int]


@dataclass(frozen=True)
class DomainProbe(_FilmChanges):
    """The steady film on the given domain and on one with the inlet and the sides moved out
    together.

    Attributes
    ----------
    x_min, long_x_min : float
        Inlet boundaries of the two solves, m.
    y_bounds, wide_y_bounds : (float, float)
        Side boundaries of the two solves, m.
    minimum_film, central_film : (float, float)
        Minimum and central film of the two solves, m.
    converged : bool
        Whether both solves converged.
    nodes : (int, int)
        Nodes (nx, ny) of the solve on the given domain.
    """

    x_min: float
    long_x_min: float
    y_bounds: tuple[float, float]
    wide_y_bounds: tuple[float, float]
    minimum_film: tuple[float, float]
    central_film: tuple[float, float]
    converged: bool
    nodes: tuple[int, int]


def _probe_nodes(problem, x, y):
    """``(x_bounds, y_bounds), (nx, ny), levels`` of a probe's solves on the domain of the
    nodes ``x``, ``y``: twice the mesh spacing, or the default mesh of that domain where it
    is coarser (:func:`side_probe`); one node across a line contact (``y = [0.]``)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    bounds = ((float(x[0]), float(x[-1])), (float(y[0]), float(y[-1])))
    default = problem.default_nodes(bounds)
    nx, ny = (max(MIN_NODES, min((n.size - 1) // 2 + 1, d)) if n.size > 1 else 1
              for n, d in zip((x, y), default, strict=True))
    return bounds, (nx, ny), sequencing_levels(nx, ny)


def _extension(length: float, spacing: float, levels: int) -> int:
    """Nodes added beyond a boundary to move it out by at least ``length``: whole cells of the
    coarsest sequenced grid, at least one of them."""
    step = 2 ** (levels - 1)
    return step * max(1, math.ceil(length / spacing / step))


def _solve_pair(problem, levels, given, other):
    """The steady solves ``(nx, ny, domain)`` of ``given`` and ``other`` at ``levels``; the
    short-inlet warning of the solver is left to whoever checks the solution probed."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "domain: the inlet", RuntimeWarning)
        return [solve_steady(problem, nx=nx, ny=ny, domain=domain, levels=levels)
                for nx, ny, domain in (given, other)]


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
    (x_bounds, y_bounds), (nx, ny), levels = _probe_nodes(problem, x, y)
    dy = (y_bounds[1] - y_bounds[0]) / (ny - 1)
    extra = _extension(widen * problem.b, dy, levels)
    wide = (y_bounds[0] - extra * dy, y_bounds[1] + extra * dy)
    narrow_res, wide_res = _solve_pair(problem, levels, (nx, ny, (x_bounds, y_bounds)),
                                       (nx, ny + 2 * extra, (x_bounds, wide)))
    return SideProbe(y_bounds, wide,
                     (narrow_res.minimum_film, wide_res.minimum_film),
                     (narrow_res.central_film, wide_res.central_film),
                     bool(narrow_res.converged and wide_res.converged), (nx, ny))


def inlet_probe(problem, x, y, x_min: float) -> InletProbe:
    """Solve the smooth steady contact on the domain of ``x``, ``y`` and with its inlet moved
    upstream to at least ``x_min``.

    Both solves use the nodes of :func:`side_probe` (twice the mesh spacing, or the default
    mesh of the domain where that is coarser), grid-sequenced, with the solver's defaults
    otherwise; the long domain adds whole cells of the coarsest grid upstream.

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact (SI).
    x, y : ndarray
        Nodes of the solution whose inlet is probed, m (``y = [0.]`` for a line contact).
    x_min : float
        Inlet of the longer domain, m (upstream of ``x[0]``; e.g. the default domain's).

    Returns
    -------
    InletProbe
    """
    (x_bounds, y_bounds), (nx, ny), levels = _probe_nodes(problem, x, y)
    dx = (x_bounds[1] - x_bounds[0]) / (nx - 1)
    extra = _extension(x_bounds[0] - x_min, dx, levels)
    long_x_min = x_bounds[0] - extra * dx
    short_res, long_res = _solve_pair(problem, levels, (nx, ny, (x_bounds, y_bounds)),
                                      (nx + extra, ny, ((long_x_min, x_bounds[1]), y_bounds)))
    return InletProbe(x_bounds[0], long_x_min,
                      (short_res.minimum_film, long_res.minimum_film),
                      (short_res.central_film, long_res.central_film),
                      bool(short_res.converged and long_res.converged), (nx, ny))


def domain_probe(problem, x, y, factor: float = 2.0) -> DomainProbe:
    """Solve the smooth steady point contact on the domain of ``x``, ``y`` and on one whose
    inlet distance ``-x[0]`` and side half-widths are ``factor`` times as large.

    Both solves use the nodes of :func:`side_probe` (twice the mesh spacing, or the default
    mesh of the domain where that is coarser), grid-sequenced, with the solver's defaults
    otherwise; the large domain adds whole cells of the coarsest grid upstream and on each
    side, at the same spacing.

    Parameters
    ----------
    problem : PointContact
        The contact (SI).
    x, y : ndarray
        Nodes of the solution whose domain is probed, m.
    factor : float
        Scale of the inlet distance and of the side half-widths (> 1).

    Returns
    -------
    DomainProbe
    """
    (x_bounds, y_bounds), (nx, ny), levels = _probe_nodes(problem, x, y)
    dx = (x_bounds[1] - x_bounds[0]) / (nx - 1)
    dy = (y_bounds[1] - y_bounds[0]) / (ny - 1)
    up = _extension((factor - 1.0) * max(-x_bounds[0], 0.0), dx, levels)
    low = _extension((factor - 1.0) * max(-y_bounds[0], 0.0), dy, levels)
    high = _extension((factor - 1.0) * max(y_bounds[1], 0.0), dy, levels)
    large = ((x_bounds[0] - up * dx, x_bounds[1]),
             (y_bounds[0] - low * dy, y_bounds[1] + high * dy))
    given, other = _solve_pair(problem, levels, (nx, ny, (x_bounds, y_bounds)),
                               (nx + up, ny + low + high, large))
    return DomainProbe(x_bounds[0], large[0][0], y_bounds, large[1],
                       (given.minimum_film, other.minimum_film),
                       (given.central_film, other.central_film),
                       bool(given.converged and other.converged), (nx, ny))
