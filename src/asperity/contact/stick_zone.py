"""The stick zone of a partial-slip solution: its area, its parts and, where it is one, its ellipse.

Under a force alone Mindlin's stick zone is an ellipse similar to the Hertz contact ellipse,
its semi-axes scaled by ``(1 - Q/(mu P))^(1/3)`` (Johnson 1985, sec. 7.2); under a twist of a
circle it is a concentric circle (Lubkin 1951); under a force and a moment together it is an
off-centre, nearly elliptical zone; on two pads, or on the spots of a rough contact, it has
several parts. One "stick radius" describes only the circle. :func:`stick_zone` measures the
zone's area, its connected parts and the ellipse with the same area centroid and second moments
of area along x and y, and says whether the cells are that ellipse.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

__all__ = ["StickZone", "stick_zone"]


@dataclass(frozen=True)
class StickZone:
    """What the stick cells of a solution are."""

    area: float
    """Area of the stick cells, m^2."""
    parts: int
    """Number of connected (4-neighbour) parts."""
    centre: tuple[float, float]
    """Area centroid (x, y), m."""
    semi_axes: tuple[float, float]
    """Semi-axes (along x, along y) of the ellipse with the zone's area centroid and second
    moments of area, m: ``s_x = 2 sqrt(I_yy / A)``, ``s_y = 2 sqrt(I_xx / A)`` (an ellipse of
    semi-axes s_x, s_y has ``I_yy = A s_x^2 / 4``); each cell counts as a uniform rectangle."""
    mismatch: float
    """Cells in exactly one of the zone and that ellipse (drawn on the cell centres), over the
    zone's cells."""
    elliptical: bool
    """One part that is its ellipse: ``mismatch`` at most :data:`ELLIPSE_MISMATCH` or one cell
    over the fewest cells across the zone, whichever is larger."""
    circular: bool
    """Elliptical with semi-axes equal to within 2 % or half a cell."""

    @property
    def radius(self) -> float:
        """Radius of a circle of the zone's area, ``sqrt(A / pi)``, m (the zone's radius when it
        is :attr:`circular`)."""
        return math.sqrt(self.area / math.pi)


#: Largest share of mismatched cells (between the stick cells and their ellipse of moments)
#: at which a well-resolved stick zone is reported as that ellipse. Measured: Mindlin's ellipse
#: (a/b = 0.4, 48 cells across its short axis) 0.2 %; a force and a moment on a Hertz circle
#: (28 cells across) 1.8 %.
ELLIPSE_MISMATCH = 0.05


def stick_zone(stick, x, y) -> StickZone | None:
    """Measure the stick zone of a solution on a regular grid.

    Parameters
    ----------
    stick : ndarray of bool, shape (nx, ny)
        The stick cells.
    x, y : ndarray
        Cell-centre coordinates, m (uniform spacing).

    Returns
    -------
    StickZone or None
        None when no cell sticks.
    """
    stick = np.asarray(stick, dtype=bool)
    if not stick.any():
        return None
    dx, dy = float(x[1] - x[0]), float(y[1] - y[0])
    X, Y = np.meshgrid(x, y, indexing="ij")
    _, parts = ndimage.label(stick)
    xs, ys = X[stick], Y[stick]
    cx, cy = float(xs.mean()), float(ys.mean())
    sx = 2.0 * math.sqrt(float(np.mean((xs - cx) ** 2)) + dx * dx / 12.0)
    sy = 2.0 * math.sqrt(float(np.mean((ys - cy) ** 2)) + dy * dy / 12.0)
    ellipse = ((X - cx) / sx) ** 2 + ((Y - cy) / sy) ** 2 <= 1.0
    mismatch = float(np.count_nonzero(ellipse ^ stick)) / float(np.count_nonzero(stick))
    across = 2.0 * min(sx / dx, sy / dy)
    elliptical = parts == 1 and mismatch <= max(ELLIPSE_MISMATCH, 1.0 / across)
    circular = elliptical and abs(sx - sy) <= max(0.02 * max(sx, sy), 0.5 * max(dx, dy))
    return StickZone(area=float(stick.sum()) * dx * dy, parts=int(parts), centre=(cx, cy),
                     semi_axes=(sx, sy), mismatch=mismatch, elliptical=bool(elliptical),
                     circular=bool(circular))
