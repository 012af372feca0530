"""Contact spots of a rough contact: the connected patches of its contact mask.

The real area of a rough contact is the sum of many small spots (micro-contacts). A mesh that
resolves the apparent contact can still give each spot only a cell or two, and a spot's area is
then not converged: its boundary cells count whole, so the area is too large by a share that
falls as ``1 / sqrt(cells)`` (first order in the cell size; docs/tangential.md, "Contact spots").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

__all__ = ["ContactSpots", "contact_spots"]


@dataclass(frozen=True)
class ContactSpots:
    """The spots of a contact mask: the cells and the load of each, in label order."""

    cells: np.ndarray
    """Cells per spot."""
    loads: np.ndarray
    """Load carried by each spot, N (pressure times cell area, summed)."""

    @property
    def count(self) -> int:
        """Number of spots."""
        return int(self.cells.size)

    def load_median_cells(self) -> int:
        """Cells of the spot at the load's median: half the load is carried by spots of this
        many cells or fewer (0 with no spot). A count, so an int: as a float it printed with
        four digits, 65540 cells of a 65536-cell grid."""
        if self.count == 0 or not self.loads.sum() > 0:
            return 0
        order = np.argsort(self.cells, kind="stable")
        share = np.cumsum(self.loads[order]) / self.loads.sum()
        return int(self.cells[order][np.searchsorted(share, 0.5)])

    def load_share_below(self, cells: float) -> float:
        """Share of the load carried by spots of fewer than ``cells`` cells."""
        total = float(self.loads.sum())
        return float(self.loads[self.cells < cells].sum()) / total if total > 0 else 0.0

    def cell_percentiles(self, q=(10, 50, 90)) -> np.ndarray:
        """Percentiles ``q`` of the cells per spot (by spot count, not load)."""
        return np.percentile(self.cells, q) if self.count else np.zeros(len(q))


def contact_spots(contact, pressure, cell_area: float = 1.0,
                  periodic: bool = False) -> ContactSpots:
    """Label the spots of a contact mask (4-connected) and sum their cells and loads.

    Parameters
    ----------
    contact : ndarray of bool, shape (nx, ny)
        Contact indicator.
    pressure : ndarray, shape (nx, ny)
        Contact pressure, Pa.
    cell_area : float
        Area of one cell, m^2 (the loads are pressure times it).
    periodic : bool
        The grid is periodic: a spot cut by an edge continues on the opposite edge and is
        counted once (labels joined by :func:`scipy.sparse.csgraph.connected_components`).

    Returns
    -------
    ContactSpots
    """
    c = np.asarray(contact, dtype=bool)
    labels, count = ndimage.label(c)
    if count == 0:
        return ContactSpots(np.zeros(0, dtype=int), np.zeros(0))
    if periodic:
        pairs = [(labels[0, :], labels[-1, :]), (labels[:, 0], labels[:, -1])]
        a = np.concatenate([p[0] for p in pairs])
        b = np.concatenate([p[1] for p in pairs])
        joined = (a > 0) & (b > 0)
        graph = coo_matrix((np.ones(joined.sum()), (a[joined] - 1, b[joined] - 1)),
                           shape=(count, count))
        count, root = connected_components(graph, directed=False)
        labels = np.where(labels > 0, root[labels - 1] + 1, 0)
    index = np.arange(1, count + 1)
    cells = np.bincount(labels.ravel(), minlength=count + 1)[1:]
    loads = ndimage.sum(np.asarray(pressure, dtype=float) * cell_area, labels, index)
    return ContactSpots(cells.astype(int), np.asarray(loads, dtype=float))
