"""Statistics of a transient mixed-EHL run: contact counts, film distribution, flow vectors.

The seed (Holmes, Evans & Snidle, J. Tribol. 127 (2005) 61) counts, at every mesh point, the
number of timesteps of the fully rough period in which the surfaces are in contact (``h = 0``,
its Eq. 8), the contact count ``Q``, and normalises it by the analysis time (Figs. 4-8,
``Q/ms``); Table 2 gives the percentage of timesteps with contact at one or more mesh points.
Fig. 14 draws the lubricant flow vectors, the Poiseuille + Couette mass flow per unit width.
"""

from __future__ import annotations

import numpy as np

from .problem import LineContact
from .uncertainty import block_edges

__all__ = ["COUNT_RATE_UNITS", "ContactStatistics", "StepHistory", "count_rate", "flow_vectors",
           "hertz_mask"]


def hertz_mask(problem, x, y) -> np.ndarray:
    """True at nodes inside the Hertz contact, ``(x/a)^2 + (y/b)^2 <= 1`` (``|x| <= a``, line).

    Parameters
    ----------
    problem : PointContact or LineContact
    x, y : ndarray
        Node coordinates, m.
    """
    Xg, Yg = np.meshgrid(np.asarray(x) / problem.a, np.asarray(y), indexing="ij")
    if isinstance(problem, LineContact):
        return np.abs(Xg) <= 1.0
    return Xg**2 + (Yg / problem.b) ** 2 <= 1.0


def flow_vectors(problem, x, y, pressure, film):
    """Lubricant flow per unit width at the nodes, density-weighted (seed Fig. 14).

    ``q_x = (rho/rho0) u_mean h - sigma_x dp/dx``, ``q_y = -sigma_y dp/dy`` with the Eyring flow
    factors of :func:`asperity.ehl.eyring_flow_factors` (divided by rho0) and central
    differences (one-sided on the edges); zero where ``h = 0``.

    Parameters
    ----------
    problem : PointContact or LineContact
    x, y : ndarray
        Node coordinates, m.
    pressure, film : ndarray
        p (Pa) and h (m), indexed ``[ix, iy]``.

    Returns
    -------
    qx, qy : ndarray
        Flow per unit width in m^2/s (mass flow over rho0); ``qy = 0`` for a line contact.
    """
    lub = problem.lubricant
    h = np.maximum(film, 0.0)
    sx, sy, rho = lub.flow_field(pressure, h, problem.sliding_speed)
    qx = rho * problem.mean_speed * h - sx * np.gradient(pressure, x, axis=0)
    if pressure.shape[1] > 1:
        qy = -sy * np.gradient(pressure, y, axis=1)
    else:
        qy = np.zeros_like(qx)
    dry = film <= 0.0
    qx[dry] = 0.0
    qy[dry] = 0.0
    return qx, qy


#: Units of :func:`count_rate` in result.nc: per millisecond, as the seed's Figs. 4-8, the
#: figures and summary.json's ``max_contact_count_rate_per_ms`` give it. Written "1/ms", which
#: UDUNITS and pint read as 1000 s-1; "ms-1", written before, reads to a person (and to a
#: parser that splits it as "m s-1") as metres per second.
COUNT_RATE_UNITS = "1/ms"


def count_rate(count, steps: int, dt: float) -> np.ndarray:
    """Contact count Q per node over ``steps`` timesteps of ``dt`` (s), per ms (Figs. 4-8):
    ``count / (steps dt / 1 ms)``, in :data:`COUNT_RATE_UNITS`."""
    if not steps:
        return np.zeros(np.shape(count))
    return np.asarray(count) / (steps * dt * 1e3)


class ContactStatistics:
    """Accumulator of the counting-period statistics over the nodes of one grid.

    Parameters
    ----------
    shape : tuple of int
        Node-array shape ``(nx, ny)``.
    film_edges : ndarray
        Bin edges (m) of the film-thickness histogram; films beyond the last edge are counted
        in the last bin.
    region : ndarray of bool
        Nodes whose film enters the histogram (normally the Hertz contact).
    counting_steps : int
        Steps the counting period will have: the length of the per-step series and of the
        :data:`~asperity.ehl.uncertainty.BLOCKS` blocks (:func:`~asperity.ehl.uncertainty.
        block_edges`) whose count maps are kept for the standard errors
        (:mod:`asperity.ehl.uncertainty`).

    Attributes
    ----------
    count : ndarray of int64
        Contact count Q per node: timesteps with ``h = 0`` at the node.
    steps : int
        Timesteps accumulated.
    steps_with_contact : int
        Timesteps with contact at one or more nodes.
    film_counts : ndarray of int64
        Film histogram over ``region`` and the accumulated timesteps.
    least_film : ndarray
        The film (m) of the accumulated timestep with the least film at any node (the first
        such step), NaN before the first: where the reported minimum film sits and how the
        mesh resolves it.
    contact_nodes, region_contact_nodes : ndarray of int64
        Per counting step: nodes in contact, over all nodes and over ``region``; -1 for steps
        not accumulated (or, after :meth:`restore` from a checkpoint written before they were
        kept, not known).
    block_counts : ndarray of int32, shape (blocks, nx, ny)
        Contact count per node in each block of consecutive counting steps (incomplete where
        the series are -1).
    block_steps : ndarray of int64
        Steps accumulated in each block.
    """

    def __init__(self, shape, film_edges, region, counting_steps: int = 1):
        self.film_edges = np.asarray(film_edges, dtype=float)
        self.region = np.asarray(region, dtype=bool)
        self.count = np.zeros(shape, dtype=np.int64)
        self.steps = 0
        self.steps_with_contact = 0
        self.film_counts = np.zeros(self.film_edges.size - 1, dtype=np.int64)
        self.least_film = np.full(shape, np.nan)
        self._least = np.inf  # least_film's least value
        self.edges = block_edges(counting_steps)
        self.contact_nodes = np.full(counting_steps, -1, dtype=np.int64)
        self.region_contact_nodes = np.full(counting_steps, -1, dtype=np.int64)
        self.block_counts = np.zeros((self.edges.size - 1, *shape), dtype=np.int32)
        self.block_steps = np.zeros(self.edges.size - 1, dtype=np.int64)

    def add(self, film, contact):
        """Accumulate one timestep: film (m) and the contact mask (True where ``h = 0``)."""
        if self.steps < self.contact_nodes.size:
            block = int(np.searchsorted(self.edges, self.steps, side="right")) - 1
            self.contact_nodes[self.steps] = np.count_nonzero(contact)
            self.region_contact_nodes[self.steps] = np.count_nonzero(contact & self.region)
            self.block_counts[block] += contact
            self.block_steps[block] += 1
        self.count += contact
        self.steps += 1
        self.steps_with_contact += bool(contact.any())
        edges = self.film_edges
        values = np.clip(film[self.region], edges[0], edges[-1])
        self.film_counts += np.histogram(values, edges)[0]
        least = film.min()
        if least < self._least:
            self._least = least
            self.least_film[...] = film

    def contact_time_fraction(self) -> float:
        """Fraction of the accumulated timesteps with contact at one or more nodes (Table 2)."""
        return self.steps_with_contact / self.steps if self.steps else 0.0

    def count_rate(self, dt: float) -> np.ndarray:
        """Contact count per node normalised by the analysis time, per ms (Figs. 4-8)."""
        return count_rate(self.count, self.steps, dt)

    def arrays(self) -> dict:
        """The accumulator as plain arrays (for a checkpoint)."""
        return {"stat_count": self.count, "stat_steps": np.int64(self.steps),
                "stat_steps_with_contact": np.int64(self.steps_with_contact),
                "stat_film_counts": self.film_counts, "stat_least_film": self.least_film,
                "stat_contact_nodes": self.contact_nodes,
                "stat_region_contact_nodes": self.region_contact_nodes,
                "stat_block_counts": self.block_counts, "stat_block_steps": self.block_steps}

    def restore(self, arrays):
        """Set the accumulator from :meth:`arrays` output (a checkpoint written before the
        least film was kept leaves it NaN until a later step sets it; one written before the
        per-step series and block maps were kept leaves the steps it had counted at -1,
        unknown, so that no standard error is given)."""
        self.count = np.array(arrays["stat_count"], dtype=np.int64)
        self.steps = int(arrays["stat_steps"])
        self.steps_with_contact = int(arrays["stat_steps_with_contact"])
        self.film_counts = np.array(arrays["stat_film_counts"], dtype=np.int64)
        if "stat_least_film" in arrays:
            self.least_film = np.array(arrays["stat_least_film"], dtype=float)
            self._least = np.nanmin(self.least_film, initial=np.inf)
        if "stat_block_counts" in arrays:
            self.contact_nodes[...] = arrays["stat_contact_nodes"]
            self.region_contact_nodes[...] = arrays["stat_region_contact_nodes"]
            self.block_counts[...] = arrays["stat_block_counts"]
            self.block_steps[...] = arrays["stat_block_steps"]
        else:  # the series stay -1, unknown, for the steps counted before
            self.block_steps[...] = np.diff(np.minimum(self.edges, self.steps))


class StepHistory:
    """Per-step records of a transient run and its centre-line snapshots.

    Parameters
    ----------
    steps : int
        Steps of the run (records are indexed ``step - 1``).
    snapshot_steps : ndarray of int
        Sorted steps whose centre line is kept.
    nx : int
        Nodes along x.

    Attributes
    ----------
    record : dict of ndarray
        Per step: ``max_pressure`` (Pa), ``min_film`` (m), ``sweeps``, ``refreshes`` (far-field
        FFT refreshes), ``residuals``, ``step_converged``, ``load_errors``,
        ``refresh_intervals`` (sweeps between refreshes at the step's end), ``load_gains``
        (the load gain at the step's end), ``density_newton`` (whether the row solve kept the
        density's Newton term at the step's end), ``tries`` (relaxations of the step, 1 at
        the first try), ``y_lines`` (its last relaxation added y-line sweeps),
        ``relaxation`` (the factor on every change of a sweep at the step's end, 1: none);
        NaN, 0 or False for steps not done.
    centre : dict of ndarray
        ``centre_pressure``, ``centre_film``, ``centre_surface1``, ``centre_surface2`` along
        y = 0 at the snapshot steps, shape ``(len(snapshot_steps), nx)``.
    """

    def __init__(self, steps: int, snapshot_steps, nx: int):
        self.snapshot_steps = np.asarray(snapshot_steps)
        self.record = {"max_pressure": np.full(steps, np.nan), "min_film": np.full(steps, np.nan),
                       "sweeps": np.zeros(steps, dtype=np.int64),
                       "refreshes": np.zeros(steps, dtype=np.int64),
                       "residuals": np.full(steps, np.nan),
                       "step_converged": np.zeros(steps, dtype=bool),
                       "load_errors": np.full(steps, np.nan),
                       "refresh_intervals": np.zeros(steps, dtype=np.int64),
                       "load_gains": np.full(steps, np.nan),
                       "density_newton": np.zeros(steps, dtype=bool),
                       "tries": np.zeros(steps, dtype=np.int64),
                       "y_lines": np.zeros(steps, dtype=bool),
                       "relaxation": np.full(steps, np.nan)}
        self.centre = {name: np.full((self.snapshot_steps.size, nx), np.nan) for name in
                       ("centre_pressure", "centre_film", "centre_surface1", "centre_surface2")}

    def add(self, step: int, pressure, film, report):
        """Record step ``step`` (1-based): its fields (Pa, m) and its solver report
        (:class:`asperity.ehl.stepper.StepReport`)."""
        n = step - 1
        self.record["max_pressure"][n] = pressure.max()
        self.record["min_film"][n] = film.min()
        self.record["sweeps"][n] = report.sweeps
        self.record["refreshes"][n] = report.refreshes
        self.record["residuals"][n] = report.residual
        self.record["step_converged"][n] = report.converged
        self.record["load_errors"][n] = report.load_error
        self.record["refresh_intervals"][n] = report.refresh
        self.record["load_gains"][n] = report.load_gain
        self.record["density_newton"][n] = report.density_newton
        self.record["tries"][n] = report.tries
        self.record["y_lines"][n] = report.y_lines
        self.record["relaxation"][n] = report.relaxation

    def wants_snapshot(self, step: int) -> bool:
        """Whether the centre line of step ``step`` is kept."""
        return bool(np.any(self.snapshot_steps == step))

    def snapshot(self, step: int, lines: dict):
        """Keep the centre lines ``lines`` (the keys of :attr:`centre`) of step ``step``."""
        k = int(np.flatnonzero(self.snapshot_steps == step)[0])
        for name, values in lines.items():
            self.centre[name][k] = values

    def arrays(self) -> dict:
        """All records as plain arrays (for a checkpoint and the result)."""
        return {**self.record, **self.centre}

    def restore(self, arrays):
        """Set the records from :meth:`arrays` output; a record the checkpoint lacks (written
        before it was recorded: the refresh counts or intervals, the relaxation) keeps its
        value for steps not done (0 or NaN)."""
        for name, values in (*self.record.items(), *self.centre.items()):
            if name in arrays:
                values[...] = arrays[name]
