"""Rows across y of a point contact's mesh, doubled where its film needs them.

The default mesh of a point contact has ``dY = b/10`` across y (:meth:`PointContact.
default_nodes`). The side lobes of a heavily loaded contact are narrower than that, and on
too few rows its minimum film comes out too thin or collapses onto a line of dry nodes
(docs/ehl-robustness.md, "Minimum films on dY = b/10"). Both the transient run's smooth
start (:func:`asperity.ehl.smooth_start.start_rows`) and the steady runner
(:mod:`asperity.runners.ehl_steady`) solve such a contact again on doubled rows; this module
holds the rule they share for how far the rows may be doubled.
"""

from __future__ import annotations

from .problem import MIN_CELL_ASPECT
from .solver import SOFT_CELL_ASPECT, SOFT_MAX_NY

__all__ = ["MAX_ROW_DOUBLINGS", "doubled_rows"]

#: At most this many doublings of the rows across y (four times the nodes and about four
#: times the cost at most: a run's mesh is the user's time).
MAX_ROW_DOUBLINGS = 2


def doubled_rows(problem, nx: int, ny: int, width: float, dx: float,
                 max_nodes: int | None = None, aspect: float = MIN_CELL_ASPECT) -> list[int]:
    """The doublings ``2 (ny - 1) + 1``, ``4 (ny - 1) + 1`` of a point contact's rows that
    keep its mesh solvable, at most :data:`MAX_ROW_DOUBLINGS` of them.

    A doubling is kept while the cells stay long across y (``dY >= aspect dX``, and
    ``SOFT_CELL_ASPECT dX`` with at most ``SOFT_MAX_NY`` rows for a soft contact,
    :attr:`PointContact.soft`: the x-line relaxation diverges on shorter cells) and
    ``nx ny <= max_nodes``.

    Parameters
    ----------
    problem : PointContact
        The contact.
    nx, ny : int
        Nodes along x and across y of the mesh.
    width : float
        Extent of the domain across y, m.
    dx : float
        Spacing along x, m.
    max_nodes : int, optional
        Most nodes of a mesh.
    aspect : float
        Least ``dY / dX`` of the finer cells (``MIN_CELL_ASPECT``, 3, the default mesh's;
        the steady runner asks for :data:`asperity.ehl.solver.FINE_CELL_ASPECT`, 6, as its
        mesh advice does: a ball at M = 1822, k = 0.32 diverged on 4.1 dX; and 1.5 for
        contacts up to M = 300, :data:`asperity.runners.ehl_steady.SIDE_LOBE_SHORT_ASPECT`).

    Returns
    -------
    list of int
        The finer row counts, coarsest first (empty where none is allowed).
    """
    aspect = max(aspect, SOFT_CELL_ASPECT) if problem.soft else aspect
    rows = []
    for _ in range(MAX_ROW_DOUBLINGS):
        finer = 2 * ((rows[-1] if rows else ny) - 1) + 1
        if width / (finer - 1) < aspect * dx * (1 - 1e-9) \
                or (max_nodes is not None and nx * finer > max_nodes) \
                or (problem.soft and finer > SOFT_MAX_NY):
            break
        rows.append(finer)
    return rows
