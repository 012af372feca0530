"""The smooth steady start of a transient run, and rows across y on which it does not touch.

A transient run starts from the smooth steady solution on its own grid
(:func:`smooth_start`). A smooth EHL point contact has a film everywhere, but on a mesh too
coarse across its side lobes the steady solution of a heavily loaded contact has a line of
nodes with no film at ``|y|`` near ``b`` (docs/ehl-robustness.md, "A smooth start that
touches"), and a run counts those nodes as contacts at every step: a traction-drive contact
(Moes M = 3091, dY = b/14) reported contact in 100 % of its steps with no roughness in the
contact (docs/ehl-transient.md, session 40). :func:`start_rows` doubles the rows of a
default mesh until the smooth start no longer touches.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .rows import doubled_rows
from .solver import sequencing_levels, solve_steady

__all__ = ["StartRows", "smooth_start", "start_rows", "touching_mask"]


def smooth_start(problem, nx: int, ny: int, domain, *, method: str | None = None,
                 near: int = 2, tol: float = 1e-4):
    """The smooth steady start of :func:`asperity.ehl.solve_transient` on its grid.

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact.
    nx, ny : int
        Nodes along x and across y (1 for a line contact).
    domain : tuple
        ``((x_min, x_max), (y_min, y_max))`` in m, as :meth:`problem.grid` takes it.
    method : str, optional
        Relaxation of the steady solve (None: the steady solver's own).
    near : int
        Near-field half-width of the deflection, nodes.
    tol : float
        Tolerance of the run's steps; the steady start is solved to ``min(tol, 1e-5)``.

    Returns
    -------
    SteadyResult
    """
    return solve_steady(problem, nx=nx, ny=ny, domain=domain, method=method,
                        levels=sequencing_levels(nx, ny, min_nx=17), near=near,
                        tol=min(tol, 1e-5), max_iter=20000, point_tangent=False)


def touching_mask(film, contact_film: float) -> np.ndarray:
    """Interior nodes where ``film <= contact_film`` (the contact statistics skip the
    boundary nodes), shape ``(nx, ny)``.

    Parameters
    ----------
    film : ndarray
        Film, m, shape (nx, ny) or (nx,).
    contact_film : float
        Film at or below which a node counts as in contact, m.
    """
    film = np.asarray(film, dtype=float)
    if film.ndim == 1:
        film = film[:, None]
    touching = film <= contact_film
    touching[[0, -1], :] = False
    if film.shape[1] > 2:
        touching[:, [0, -1]] = False
    return touching


@dataclass(frozen=True)
class StartRows:
    """What :func:`start_rows` chose.

    Attributes
    ----------
    ny : int
        Rows of the run.
    steady : SteadyResult
        The smooth steady start on ``nx x ny`` nodes.
    tried : tuple of (int, int, bool)
        ``(ny, touching nodes, converged)`` of every steady start solved, in order.
    """

    ny: int
    steady: object
    tried: tuple


def start_rows(problem, nx: int, ny: int, domain, *, contact_film: float | None = None,
               method: str | None = None, near: int = 2, tol: float = 1e-4,
               max_nodes: int | None = None) -> StartRows:
    """Rows across y of a point contact's default mesh on which its smooth start does not
    touch.

    The smooth start is solved on ``nx x ny`` nodes (:func:`smooth_start`); while it touches
    (:func:`touching_mask`) the rows are doubled, ``2 (ny - 1) + 1``, at most
    :data:`~asperity.ehl.rows.MAX_ROW_DOUBLINGS` times, within the cells and nodes of
    :func:`asperity.ehl.rows.doubled_rows`. A finer start that does not converge is not
    taken. Without a touching start the result is
    the start :func:`asperity.ehl.solve_transient` would have solved, to the bit.

    Parameters
    ----------
    problem : PointContact
        The contact.
    nx, ny : int
        The default mesh.
    domain : tuple
        ``((x_min, x_max), (y_min, y_max))`` in m.
    contact_film : float, optional
        Film at or below which a node counts as in contact, m (default the run's:
        ``tol`` times :meth:`problem.film_estimate`).
    method, near, tol
        As for :func:`smooth_start`.
    max_nodes : int, optional
        Most nodes of a run.

    Returns
    -------
    StartRows
    """
    if contact_film is None:
        contact_film = tol * problem.film_estimate()
    x, y = problem.grid(nx, ny, domain)
    steady = smooth_start(problem, nx, ny, domain, method=method, near=near, tol=tol)
    touching = int(touching_mask(steady.film, contact_film).sum())
    tried = [(ny, touching, bool(steady.converged))]
    for finer in doubled_rows(problem, nx, ny, y[-1] - y[0], x[1] - x[0], max_nodes):
        if not touching:
            break
        trial = smooth_start(problem, nx, finer, domain, method=method, near=near, tol=tol)
        count = int(touching_mask(trial.film, contact_film).sum())
        tried.append((finer, count, bool(trial.converged)))
        if not trial.converged:
            break
        ny, steady, touching = finer, trial, count
    return StartRows(ny, steady, tuple(tried))
