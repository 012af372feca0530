"""Transient mixed EHL of rough surfaces moving through a point or line contact.

The seed's procedure (Holmes, Evans & Snidle, J. Tribol. 127 (2005) 61): start from the smooth
steady solution, feed the roughness of both surfaces in from the inlet boundary as they move at
their own speeds ``u1``, ``u2``, run until the slower rough surface has crossed the whole domain
("fully rough"), then count contacts over a further period. Each timestep solves the coupled
differential deflection / time-dependent Reynolds equations of :mod:`asperity.ehl.solver`
(docs/ehl.md) with the squeeze term by the theta-scheme, Crank-Nicolson (``theta = 1/2``) by
default, which with the second-order upwind wedge term is unconditionally stable
(EHL-NOTES sec. 4). Where the update gives ``h < 0`` the node is in contact: ``h = 0`` and ``p``
from the deflection equation alone (seed Eq. 8).

Time discretisation (dimensionless, ``T = t u_mean / a``, node P)::

    theta L^{n+1} + (1 - theta) L^n - lam [(rho H)^{n+1} - (rho H)^n] / dT = 0

with ``L`` the discrete Reynolds operator (Poiseuille + wedge). The explicit part enters the
nodal update through ``EHLState.rhs_t = (1 - theta) L^n + (lam/dT) (rho H)^n``; ``L^n`` is
taken as zero at nodes that were cavitated or in contact at level n (the Reynolds equation
does not hold there).

Structure: :func:`solve_transient` checks the inputs, moves the surfaces and drives the run;
one timestep and the iteration settings are :class:`~asperity.ehl.stepper.TimeStepper` and
:class:`~asperity.ehl.stepper.StepOptions`; the per-step records and the counting-period
statistics are :class:`~asperity.ehl.statistics.StepHistory` and
:class:`~asperity.ehl.statistics.ContactStatistics`; checkpoints are
:class:`~asperity.ehl.checkpoint.Checkpointer`.

Roughness. Surface k (height ``z_k``, metal below, as :class:`~asperity.surfaces.Profile` or
:class:`~asperity.surfaces.Topography`) moves at ``u_k`` along +x. At time t the node at x
carries the surface point that crossed the inlet ``x_in`` (the first node) at
``t - (x - x_in)/u_k``; points that have not yet reached the inlet at t = 0 are rough, those
downstream are smooth. With ``d = u_k t - (x - x_in)`` the distance travelled past the inlet,
the height is ``z_k(s_end - d)`` for ``d >= 0`` (``s_end`` the last data point, so the profile
enters end first) and 0 for ``d < 0``; heights between data points come from the surface's
cubic splines. The gap gains ``phi = -(z1 + z2)`` (two surfaces facing each other), which enters
the deflection equation as its 5-point Laplacian and the Dirichlet edge films.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_int, check_positive
from ..solution import SolverResult, renamed_keywords
from ..surfaces.topography import Profile, Topography
from .checkpoint import Checkpointer, fingerprint
from .kernels import CAVITATED, CONTACT
from .nodal import centre_line
from .problem import LineContact
from .smooth_start import smooth_start
from .statistics import (
    COUNT_RATE_UNITS,
    ContactStatistics,
    StepHistory,
    flow_vectors,
    hertz_mask,
)
from .stepper import StepOptions, TimeStepper
from .uncertainty import (
    StandardError,
    batch_means,
    block_bootstrap_max,
    block_edges,
    counting_period_warning,
)

__all__ = ["FEATURE_CELLS_ACROSS", "FEATURE_CELLS_ALONG", "FIXED_POINT_LIMIT", "GIVE_UP_STEPS",
           "HISTOGRAM_RQ", "ROUGHNESS_CELLS", "TransientResult", "default_warmup_steps",
           "solve_transient"]

#: Mesh cells per half-width of a single feature along x (the rolling direction) and across
#: y that a case's default mesh gives it (:meth:`asperity.ehl.PointContact.default_nodes`
#: with :meth:`asperity.cases.EHLTransientCase.feature_spacing`); a waviness gets twice as
#: many along its direction per wavelength. Measured on a bump through a ball-on-disc
#: contact (docs/ehl-transient.md, "The default mesh of a transient case").
FEATURE_CELLS_ALONG = 8
FEATURE_CELLS_ACROSS = 3

#: Mesh cells per correlation length (along x and across y) that a case's default mesh gives
#: a gaussian topography: twice the limit below which the mesh check warns
#: (:data:`asperity.diagnostics.MIN_CELLS_PER_CORRELATION_LENGTH`; between 2 and about 4 cells
#: the real contact area and the asperity pressures still move with the mesh,
#: docs/references.md, "Roughness on the mesh").
ROUGHNESS_CELLS = 4

#: Steps in a row that did not converge with any fallback after which a run stops. A user's
#: cam-nose line contact (M = 44, L = 6.1, Roelands, Eyring 4 MPa, slide/roll 0.1, ground
#: surfaces), whose smooth steady start had not converged (a 2.3 um film where the converged
#: Newtonian one is 109 nm), failed each of its first 700 steps at 800-2,000 sweeps: an hour
#: that could only end in an unconverged run. A step that fails with every fallback is
#: otherwise rare: the worst case of docs/ehl-transient.md, a Newtonian spur reducer, fails
#: none of its 1,984 since the under-relaxation fallback (session 33).
GIVE_UP_STEPS = 10

#: Largest change of p (in Hertz pressures) and of h (in central films) that relaxing a run's
#: converged last step on may bring before the result warns (:meth:`TransientResult.
#: fixed_point_warning`). The gear case at the seed's spacing moves by 0.1-0.2 % with the
#: default tolerance, the a/b = 4 contact on the seed's square cells by 3 % of p_h and 1 % of
#: the film (docs/ehl-transient.md, "How far a converged step is from its fixed point").
FIXED_POINT_LIMIT = 0.01

#: The default film histogram reaches the estimated central film plus this many RMS heights of
#: the summed roughness (without flattening the film is the smooth one minus the summed
#: heights). Up to twice the central film alone, a cam with ground surfaces (Ra 0.25 and
#: 0.3 um on a 150 nm film) had 60 % of its node-steps in the overflow bin
#: (docs/ehl-transient.md, "The film histogram's range").
HISTOGRAM_RQ = 4.0


class MovingSurface:
    """A rough surface entering the domain at the inlet and moving along +x at ``speed``.

    Parameters
    ----------
    surface : Profile or Topography
        Heights, metal below. A profile is extruded across y (transverse-ground surface).
    speed : float
        Surface speed along x, m/s (> 0).
    x, y : ndarray
        Node coordinates of the solver grid, m; the inlet is ``x[0]``.
    duration : float
        Time the run lasts, s; a non-periodic surface must be long enough to feed it.
    field : str
        Name of the argument, for error messages.
    """

    def __init__(self, surface, speed, x, y, duration, field):
        if not isinstance(surface, Profile | Topography):
            raise InputError(field, "a Profile, a Topography or None", type(surface).__name__)
        if not speed > 0:
            raise InputError(field, "a surface speed > 0 to carry the roughness in from the "
                                    "inlet", speed)
        if y.size == 1 and isinstance(surface, Topography):
            raise InputError(field, "a Profile for a line contact")
        self.surface = surface
        self.speed = float(speed)
        self.x = x
        self.y = y
        self.s_end = float(surface.x[-1])
        if not surface.periodic:
            need = self.speed * duration
            have = float(surface.x[-1] - surface.x[0])
            if need > have:
                raise InputError(field, f"a periodic surface or one at least {need:.4g} m long "
                                        f"along x for this run (it is {have:.4g} m)")
        if isinstance(surface, Topography):
            try:
                on_rows = surface.sample(surface.x, y)
            except InputError:
                raise InputError(field, "a topography covering the solver's y range "
                                        f"[{y[0]:.4g}, {y[-1]:.4g}] m, or a periodic one") from None
            # resampled once onto the solver's rows, so that each step interpolates along x only
            # (tensor-product splines do not depend on the order of the two directions)
            self.surface = Topography(surface.x, y, on_rows, periodic=surface.periodic)

    def heights(self, t: float) -> np.ndarray:
        """Heights ``z_k`` (m) at the nodes at time ``t``, shape ``(x.size, y.size)``."""
        d = self.speed * t - (self.x - self.x[0])
        rough = d >= 0.0
        z = np.zeros((self.x.size, self.y.size))
        if rough.any():
            s = self.s_end - d[rough]
            if isinstance(self.surface, Profile):
                z[rough] = self.surface.sample(s)[:, None]
            else:
                z[rough] = self.surface.sample(s, self.y)
        return z


@dataclass(frozen=True, repr=False)
class TransientResult(SolverResult):
    """Transient mixed-EHL run, SI units; steps are numbered 1..``steps`` (0: the steady start).

    The result protocol of :class:`asperity.solution.SolverResult`: ``converged``,
    ``iterations`` (sweeps over all steps), ``residual``, ``message``, ``warnings``,
    ``to_dataset()`` (the variables ``asperity run`` writes, on x, y, step, snapshot, film_bin).

    Attributes
    ----------
    x, y : ndarray
        Node coordinates, m.
    dt : float
        Timestep, s.
    warmup_steps, counting_steps, steps : int
        Steps until both rough surfaces fill the domain, steps counted, and their sum.
    steps_done : int
        Steps completed (less than ``steps`` only when a step produced non-finite values or
        ``GIVE_UP_STEPS`` steps in a row did not converge with any fallback).
    pressure, film : ndarray
        p (Pa) and h (m) at the last step, ``[ix, iy]``.
    surface1, surface2 : ndarray
        Heights z1, z2 (m) at the nodes at the last step.
    contact_count : ndarray of int
        Q, timesteps of the counting period with ``h = 0``, per node.
    contact_count_rate : ndarray
        Q per ms of counting time (seed Figs. 4-8).
    contact_time_fraction : float
        Fraction of counting timesteps with contact at one or more nodes (seed Table 2).
    contact_nodes, hertz_contact_nodes : ndarray of int
        Per counting step (index ``step - warmup_steps - 1``): nodes in contact, over the
        domain and inside the Hertz contact; -1 for steps not counted (or not known: a run
        resumed from a checkpoint written before they were kept).
    hertz_nodes : int
        Nodes inside the Hertz contact (:func:`hertz_mask`).
    block_contact_count, block_steps : ndarray of int
        The counting period cut into :data:`~asperity.ehl.uncertainty.BLOCKS` blocks of
        consecutive steps: per block the contact count per node, shape ``(blocks, nx, ny)``,
        and its steps (the standard errors of :meth:`standard_errors`).
    max_pressure, min_film : ndarray
        Per step (index ``step - 1``): largest p (Pa) and smallest h (m) over the domain.
    film_edges, film_counts : ndarray
        Histogram of h over the Hertz contact area and the counting period (bins in m).
    least_film : ndarray
        h (m) at the counting step with the least film at any node, ``[ix, iy]`` (NaN
        without counting steps): where the minimum film of :meth:`summary` sits.
    flow_x, flow_y : ndarray
        Lubricant flow per unit width at the last step, m^2/s (:func:`flow_vectors`).
    snapshot_steps : ndarray of int
        Steps at which the centre line was recorded.
    centre_pressure, centre_film, centre_surface1, centre_surface2 : ndarray
        p, h, z1, z2 along y = 0 at those steps, shape ``(len(snapshot_steps), x.size)``.
    sweeps, refreshes, residuals, step_converged, load_errors : ndarray
        Per step: relaxation sweeps, far-field FFT refreshes, final residual, convergence flag,
        relative load error.
    refresh_intervals, load_gains, density_newton : ndarray
        Per step: sweeps between far-field refreshes at the start of the step, load gain and
        whether the row solve kept the density's Newton term, as the step ended (changed from
        a step that had to be relaxed again: :meth:`~asperity.ehl.stepper.TimeStepper.advance`).
    tries : ndarray of int
        Per step: how often it was relaxed (1: it converged at the first try; more: relaxed
        again with safer settings).
    y_lines : ndarray of bool
        Per step: relaxed once more with y-line sweeps after failing with every setting
        (:attr:`~asperity.ehl.stepper.TimeStepper.can_add_y_lines`).
    relaxation : ndarray
        Per step: the factor on every node's change of a sweep as the step ended (1: none;
        :data:`~asperity.ehl.stepper.UNDER_RELAXATION` after the last fallback).
    fixed_point_pressure, fixed_point_film : float
        How far the last step is from the fixed point of its equations: the largest change of
        p (in Hertz pressures) and of h (in central-film estimates) when it is relaxed on to a
        hundredth of ``tol`` (:meth:`~asperity.ehl.stepper.TimeStepper.check_fixed_point`);
        NaN when the run did not end with a converged step, or was resumed from the checkpoint
        of its last step (whose explicit part is not kept). Above :data:`FIXED_POINT_LIMIT` the
        result warns.
    fixed_point_sweeps : int
        Sweeps of that check (0: not made).
    fixed_point_settled : bool
        Whether the check reached its own tolerance (if not, the distances are lower bounds).
    iterations : int
        Relaxation sweeps over all steps.
    converged : bool
        Steady start and every step converged.
    residual : float
        Largest final residual of any step.
    steady_central_film : float
        Central film of the smooth steady start, m.
    steady_film : ndarray
        Film of the smooth steady start, m, shape (nx, ny) (NaN when resumed from a
        checkpoint written before it was kept).
    contact_film : float
        Film at or below which a node counts as in contact, m.
    steady_converged : bool
        Whether the smooth steady start converged (a run goes on from an unconverged one: its
        steps relax the state to the transient solution, but ``converged`` is then False).
    method, theta
        Relaxation and time-scheme weight used.
    """

    x: np.ndarray
    y: np.ndarray
    dt: float
    warmup_steps: int
    counting_steps: int
    steps: int
    steps_done: int
    pressure: np.ndarray
    film: np.ndarray
    surface1: np.ndarray
    surface2: np.ndarray
    contact_count: np.ndarray
    contact_count_rate: np.ndarray
    contact_time_fraction: float
    contact_nodes: np.ndarray
    hertz_contact_nodes: np.ndarray
    hertz_nodes: int
    block_contact_count: np.ndarray
    block_steps: np.ndarray
    max_pressure: np.ndarray
    min_film: np.ndarray
    film_edges: np.ndarray
    film_counts: np.ndarray
    least_film: np.ndarray
    flow_x: np.ndarray
    flow_y: np.ndarray
    snapshot_steps: np.ndarray
    centre_pressure: np.ndarray
    centre_film: np.ndarray
    centre_surface1: np.ndarray
    centre_surface2: np.ndarray
    sweeps: np.ndarray
    refreshes: np.ndarray
    residuals: np.ndarray
    step_converged: np.ndarray
    load_errors: np.ndarray
    refresh_intervals: np.ndarray
    load_gains: np.ndarray
    density_newton: np.ndarray
    tries: np.ndarray
    y_lines: np.ndarray
    relaxation: np.ndarray
    fixed_point_pressure: float
    fixed_point_film: float
    fixed_point_sweeps: int
    fixed_point_settled: bool
    iterations: int
    converged: bool
    residual: float
    steady_central_film: float
    steady_film: np.ndarray
    contact_film: float
    steady_converged: bool
    method: str
    theta: float

    VARIABLES = {
        "contact_count_rate": (COUNT_RATE_UNITS, "contact count rate Q: counting steps with "
                               "contact at the node per millisecond of counting time"),
        "contact_count": ("1", "number of counting steps with contact at the node"),
        "contact_nodes": ("1", "nodes in contact at the counting step (-1: not counted)",
                          ("counting_step",)),
        "hertz_contact_nodes": ("1", "nodes in contact inside the Hertz contact at the counting "
                                "step (-1: not counted)", ("counting_step",)),
        "block_contact_count": ("1", "contact count per node in each block of consecutive "
                                "counting steps", ("block", "x", "y")),
        "block_steps": ("1", "counting steps in the block", ("block",)),
        "pressure": ("Pa", "pressure at the last step"),
        "film": ("m", "film thickness at the last step"),
        "steady_film": ("m", "film thickness of the smooth steady start"),
        "least_film": ("m", "film thickness at the counting step with the least film"),
        "surface1": ("m", "height of surface 1 at the last step"),
        "surface2": ("m", "height of surface 2 at the last step"),
        "flow_x": ("m2 s-1", "lubricant flow per unit width along x"),
        "flow_y": ("m2 s-1", "lubricant flow per unit width along y"),
        "max_pressure": ("Pa", "maximum pressure per step", ("step",)),
        "min_film": ("m", "minimum film per step", ("step",)),
        "sweeps": ("1", "relaxation sweeps per step", ("step",)),
        "step_converged": ("1", "step converged (1) or not (0)", ("step",)),
        "refresh_interval": ("1", "relaxation sweeps between far-field refreshes at the start "
                             "of the step", ("step",), "refresh_intervals"),
        "load_gain": ("1", "separation shift per sweep per relative load error", ("step",),
                      "load_gains"),
        "density_newton": ("1", "row solve with the density's Newton term (1) or the density "
                           "lagged (0)", ("step",)),
        "tries": ("1", "relaxations of the step (1: converged at the first try)", ("step",)),
        "y_lines": ("1", "step relaxed once more with y-line sweeps (1) or not (0)", ("step",)),
        "relaxation": ("1", "factor on every change of a sweep (1: none; under-relaxed in the "
                       "last fallback)", ("step",)),
        "film_counts": ("1", "film thickness histogram over the counting period", ("film_bin",)),
        "centre_pressure": ("Pa", "pressure on the centre line y = 0", ("snapshot", "x")),
        "centre_film": ("m", "film on the centre line y = 0", ("snapshot", "x")),
        "centre_surface1": ("m", "surface 1 height on the centre line", ("snapshot", "x")),
        "centre_surface2": ("m", "surface 2 height on the centre line", ("snapshot", "x")),
    }

    def coordinates(self) -> dict:
        """x (entrainment) and y (transverse), the step number, the counting steps, the
        counting period's blocks, the snapshot steps and the film-histogram bin centres."""
        return {"x": (self.x, "m", "x, entrainment direction"),
                "y": (self.y, "m", "y, transverse direction"),
                "step": (np.arange(1, self.steps + 1), "1", "time step"),
                "counting_step": (np.arange(self.warmup_steps + 1, self.steps + 1), "1",
                                  "time step of the counting period"),
                "block": (np.arange(1, self.block_steps.size + 1), "1",
                          "block of consecutive counting steps"),
                "snapshot": (self.snapshot_steps, "1", "step of the snapshot"),
                "film_bin": (0.5 * (self.film_edges[1:] + self.film_edges[:-1]), "m",
                             "film thickness bin centre")}

    #: Attributes of the ``time`` coordinate along ``step`` (CF: an elapsed time in s; no
    #: reference date, so xarray keeps it as numbers instead of decoding dates).
    TIME_ATTRS = {"units": "s", "long_name": "time since the start of the run, at the end of "
                  "the step", "axis": "T"}

    def to_dataset(self):
        """:meth:`SolverResult.to_dataset` with a ``time`` coordinate (s) along ``step``
        (:attr:`times`), so that ``ds.swap_dims(step="time")`` or ``ds.max_pressure.plot(
        x="time")`` work as they do for any time series."""
        dataset = super().to_dataset()
        return dataset.assign_coords(time=("step", self.times, dict(self.TIME_ATTRS)))

    @property
    def times(self) -> np.ndarray:
        """Time at the end of each step, s (``dt`` times the step number)."""
        return self.dt * np.arange(1, self.steps + 1)

    @property
    def counting_time(self) -> float:
        """Length of the counting period, s."""
        return self.counting_steps * self.dt

    @property
    def warnings(self) -> tuple[str, ...]:
        """No convergence, a last step far from its fixed point (:meth:`fixed_point_warning`),
        and a counting period too short for its statistics (:meth:`counting_warning`)."""
        return (*SolverResult.warnings.fget(self), *self.fixed_point_warning(),
                *self.counting_warning())

    def standard_errors(self) -> dict[str, StandardError]:
        """The counting-period statistics with their standard errors
        (:mod:`asperity.ehl.uncertainty`): ``contact_time_fraction`` and
        ``hertz_contact_count_rate`` (the mean of Q over the Hertz contact, per ms) by batch
        means of their per-step series, ``max_contact_count_rate`` (the largest Q, per ms) by
        the block bootstrap of the blocks' count maps. Empty when no step was counted or the
        per-step series are not known for every counted step (a run resumed from a
        checkpoint written before they were kept)."""
        counted = max(0, min(self.steps_done, self.steps) - self.warmup_steps)
        nodes = self.contact_nodes[:counted]
        if not counted or np.any(nodes < 0):
            return {}
        per_ms = 1.0 / (self.dt * 1e3)
        blocks = self.block_steps == np.diff(block_edges(self.counting_steps))  # complete ones
        estimates = {"contact_time_fraction": batch_means(nodes > 0)}
        if self.hertz_nodes:
            hertz = self.hertz_contact_nodes[:counted] * (per_ms / self.hertz_nodes)
            estimates["hertz_contact_count_rate"] = batch_means(hertz)
        estimates["max_contact_count_rate"] = block_bootstrap_max(
            self.block_contact_count[blocks], self.block_steps[blocks], scale=per_ms)
        return estimates

    def counting_warning(self) -> list[str]:
        """A line when the counting period is too short for the contact-time fraction, the
        largest count rate or the Hertz zone's mean rate (their standard error above
        :data:`~asperity.ehl.uncertainty.RELATIVE_ERROR_LIMIT` of the value, or too few
        steps to tell; :func:`~asperity.ehl.uncertainty.counting_period_warning`)."""
        estimates = self.standard_errors()
        words = {"contact_time_fraction": ("the contact-time fraction", "%"),
                 "max_contact_count_rate": ("the largest contact count rate", "per ms"),
                 "hertz_contact_count_rate": ("the mean count rate over the Hertz contact",
                                              "per ms")}
        counted = max(0, min(self.steps_done, self.steps) - self.warmup_steps)
        return counting_period_warning({words[k][0]: (e, words[k][1])
                                        for k, e in estimates.items()}, counted)

    def fixed_point_warning(self) -> list[str]:
        """A line when the last step, relaxed on, moved p or h by more than
        :data:`FIXED_POINT_LIMIT` (of the Hertz pressure, of the central film): the steps stop
        on the change per sweep while the relaxation still drifts, so every step's state may
        be that far from its solution. Lowering the tolerance brings the stop closer, about in
        proportion over a tenfold change (the tail of a step contracts geometrically), less
        so at one step: on a narrow contact on square cells (201 x 51) 2.0, 1.3, 0.18 and
        0.08 % of p_h at the tolerances 1e-3, 3e-4, 1e-4 and 3e-5."""
        worst = max(self.fixed_point_pressure, self.fixed_point_film)
        if not worst > FIXED_POINT_LIMIT:
            return []
        if not np.isfinite(worst):
            return [f"solver.tolerance: the last step, relaxed past its tolerance, diverged "
                    f"within {self.fixed_point_sweeps} sweeps: its state is no solution of "
                    "the step's equations; lower the tolerance or the time step (time.dt)"]
        fold = math.ceil(worst / FIXED_POINT_LIMIT)
        moved = "moved" if self.fixed_point_settled else "moved (and was still moving)"
        return [f"solver.tolerance: the last step, relaxed {self.fixed_point_sweeps} sweeps "
                f"past its tolerance, {moved} p by up to {self.fixed_point_pressure:.2%} of "
                f"the Hertz pressure and h by up to {self.fixed_point_film:.2%} of the central "
                f"film (limit {FIXED_POINT_LIMIT:.0%}): the steps stop while the relaxation "
                "still drifts toward their solution, as on the cells dy < 3 dx of a narrow "
                "contact, so each step's p and h may be that far off; lower the tolerance "
                f"(solver.tolerance) by more than {fold}-fold: the distance falls about as the "
                "tolerance, not in proportion at every step"]

    def summary(self) -> dict:
        """Scalars for ``summary.json``: contact-time fraction and its standard error
        (:meth:`standard_errors`), extremes of the counting period, and how far the last step
        is from its fixed point (p as a fraction of the Hertz pressure, h of the central
        film)."""
        counted = slice(self.warmup_steps, self.steps_done)
        maxp = self.max_pressure[counted]
        minh = self.min_film[counted]
        errors = self.standard_errors()
        fraction = errors.get("contact_time_fraction")
        return {
            "contact_time_fraction": float(self.contact_time_fraction),
            "contact_time_fraction_standard_error": float(fraction.standard_error)
            if fraction else float("nan"),
            "max_pressure_pa": float(maxp.max()) if maxp.size else float("nan"),
            "minimum_film_thickness_m": float(minh.min()) if minh.size else float("nan"),
            "counting_time_s": float(self.counting_time),
            "timestep_s": float(self.dt),
            "steps": int(self.steps),
            "mean_sweeps_per_step": float(self.sweeps[: self.steps_done].mean())
            if self.steps_done else 0.0,
            "fixed_point_distance_pressure_fraction": float(self.fixed_point_pressure),
            "fixed_point_distance_film_fraction": float(self.fixed_point_film),
            "converged": bool(self.converged),
        }


def default_warmup_steps(x, rough_speeds, dt: float) -> int:
    """Steps until every rough surface has crossed the domain ``x`` (the seed's warm-up):
    the crossing time of the slowest rough surface over ``dt``; 0 when all are smooth."""
    crossing = [(x[-1] - x[0]) / u for u in rough_speeds]
    return int(np.ceil(max(crossing) / dt - 1e-9)) if crossing else 0


@renamed_keywords(max_sweeps="max_iter")
def solve_transient(
    problem,
    roughness1=None,
    roughness2=None,
    *,
    nx: int | None = None,
    ny: int | None = None,
    domain=None,
    dt: float | None = None,
    counting_steps: int = 200,
    warmup_steps: int | None = None,
    theta: float = 0.5,
    method: str | None = None,
    near: int = 2,
    tol: float = 1e-4,
    max_iter: int = 400,
    refresh: int | None = None,
    acceleration: int | None = None,
    load_gain: float | None = None,
    damping: float = 0.7,
    contact_film: float | None = None,
    steady=None,
    film_edges=None,
    snapshot_steps=None,
    checkpoint=None,
    checkpoint_every: int = 100,
    resume: bool = False,
    callback=None,
) -> TransientResult:
    """Transient mixed EHL with rough surfaces moving through the contact (seed procedure).

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact; surface 1 moves at ``problem.u1``, surface 2 at ``problem.u2``
        (slide/roll ratio ``xi = (u1 - u2)/u_mean``).
    roughness1, roughness2 : Profile, Topography or None
        Heights of each surface (metal below); a profile varies along x and is extruded across
        y (transverse ground). None: smooth. A line contact takes profiles only.
    nx, ny : int, optional
        Nodes along x and y (``ny`` ignored for a line contact); the seed's mesh is 801 x 201.
        Default ``problem.default_nodes(domain)``, the steady default mesh (the surfaces'
        features are not looked at: a case file's ``[surface]`` tables are,
        :meth:`asperity.cases.EHLTransientCase.mesh`).
    domain : ((x0, x1), (y0, y1)), optional
        In m; default ``problem.default_domain()``.
    dt : float, optional
        Timestep, s; default the seed's ``dx / (2 u_max)``.
    counting_steps : int
        Steps over which contacts are counted once both rough surfaces fill the domain
        (the seed: 2370).
    warmup_steps : int, optional
        Steps before counting; default the time the slower rough surface takes to cross the
        domain (0 for smooth surfaces).
    theta : float
        Time-scheme weight, 1/2 (Crank-Nicolson, default) to 1 (implicit Euler).
    method : {"line", "point"}, optional
        Relaxation of the steps: default the line relaxation, for a line contact its one row
        solved at once (docs/ehl-transient.md, "Line contacts: the row solve"). The smooth
        steady start takes ``method`` as given, so by default the steady solver's own (the
        point update for a line contact, whose steady row solve does not converge).
    near : int
        x-neighbour pressure coefficients implicit in the line relaxation (2: the sweep costs
        half that of 4 and, with the acceleration, the step the least; it does not change the
        solution).
    tol : float
        Per-step convergence: max |dP|, max |dH| relative to the estimated central film, and
        the relative load error below ``tol`` on the first sweep after a far-field refresh.
    max_iter : int
        Sweep limit per relaxation of a step; a step reaching it is recorded as not converged
        (the old spelling ``max_sweeps`` is accepted with a DeprecationWarning). Such a step
        is first relaxed again from its start with a refresh at every sweep (when
        ``refresh > 1``), then with the density's Newton term (compressible lubricant) and
        then with the load gain halved, up to twice
        (:meth:`~asperity.ehl.stepper.TimeStepper.advance`), so it can take five times as
        many.
    refresh : int, optional
        Sweeps between FFT refreshes of the far field and the edge films at the start of a
        step (default 3; 1 for the row solve of a line contact,
        :data:`~asperity.ehl.stepper.LINE_REFRESH`), until a refresh cycle ends below a residual of
        :data:`~asperity.ehl.stepper.REFRESH_EVERY_SWEEP_BELOW`; then at every sweep. 1 from
        the first step that does not converge with it (``refresh_intervals`` of the result).
    acceleration : int, optional
        Memory of the Anderson acceleration of the refresh cycles
        (:class:`~asperity.ehl.anderson.AndersonMixer`); 0 switches it off. Default 3 with
        x-line relaxation (gear case at the seed's spacing: 34 -> 24 sweeps per step, with
        ``near`` 2) and 0 with the point update (on the rough line contact of Fig. 10 it made
        126 of 355 steps fail).
    load_gain : float, optional
        Separation shift per sweep per relative load error; default ``0.15 min(1, b/a)``
        (point contact: 0.15 for the gear case, 0.0375 at a/b = 4 where 0.15 diverged) and
        0.03 (line contact); halved, at most twice, from the first step that does not
        converge with a refresh at every sweep and (compressible lubricant) the density's
        pressure derivative in the update (``load_gains`` and ``density_newton`` of the
        result).
    damping : float
        Factor on the change of p and h at nodes whose change alternates in sign from sweep to
        sweep (:meth:`asperity.ehl.solver.EHLState.sweep`), until a refresh cycle of the step
        ends below :data:`asperity.ehl.stepper.UNDAMPED_BELOW`; 1 switches it off. Rough
        surfaces need it (docs/ehl-transient.md).
    contact_film : float, optional
        Film (m) at or below which a node counts as in contact in the statistics; default
        ``tol`` times the estimated central film (a film the iteration cannot tell from 0).
        Nodes set to ``h = 0`` by Eq. 8 always count.
    steady : SteadyResult, optional
        The smooth steady start on the same grid; computed when not given.
    film_edges : array_like, optional
        Bin edges (m) of the film histogram; default 50 bins from 0 to the estimated central
        film plus ``HISTOGRAM_RQ`` times the RMS of the summed roughness heights, at least
        twice the estimated central film.
    snapshot_steps : sequence of int, optional
        Steps (1..steps) at which the centre line (p, h, z1, z2) is kept; default the last.
    checkpoint : path, optional
        ``.npz`` file written atomically every ``checkpoint_every`` steps and at the end.
    checkpoint_every : int
        Steps between checkpoints.
    resume : bool
        Continue from ``checkpoint`` when it exists (it must come from a run with the same
        inputs); the result is bit-identical to an uninterrupted run.
    callback : callable, optional
        ``callback(step, residual)`` after every step.

    Returns
    -------
    TransientResult
    """
    opts = StepOptions.for_problem(problem, method=method, theta=theta, near=near, tol=tol,
                                   max_sweeps=max_iter, refresh=refresh,
                                   acceleration=acceleration, load_gain=load_gain,
                                   damping=damping)
    line = isinstance(problem, LineContact)
    counting_steps = check_int("counting_steps", counting_steps, 1)
    checkpoint_every = check_int("checkpoint_every", checkpoint_every, 1)
    if nx is None or (ny is None and not line):
        default = problem.default_nodes(domain)
        nx = default[0] if nx is None else nx
        ny = default[1] if ny is None else ny
    if line:
        ny = 1
    x, y = problem.grid(nx, ny, domain)
    nx, ny = x.size, y.size
    u_max = max(abs(problem.u1), abs(problem.u2))
    dt = 0.5 * (x[1] - x[0]) / u_max if dt is None else check_positive("dt", dt)

    given = [(r, u, f"roughness{k}") for k, (r, u) in
             enumerate(((roughness1, problem.u1), (roughness2, problem.u2)), start=1)
             if r is not None]
    for _, u, field in given:
        if not u > 0:
            raise InputError(field, "a surface speed > 0 to carry the roughness in", u)
    if warmup_steps is None:
        warmup_steps = default_warmup_steps(x, [u for _, u, _ in given], dt)
    warmup_steps = check_int("warmup_steps", warmup_steps, 0)
    total = warmup_steps + counting_steps
    moving = [MovingSurface(r, u, x, y, total * dt, field) for r, u, field in given]
    slots = [k for k, r in enumerate((roughness1, roughness2)) if r is not None]

    def heights(t):
        z = [np.zeros((nx, ny)), np.zeros((nx, ny))]
        for k, surface in zip(slots, moving, strict=True):
            z[k] = surface.heights(t)
        return z

    film_ref = problem.film_estimate()
    contact_film = opts.tol * film_ref if contact_film is None else float(contact_film)
    if not contact_film >= 0.0:
        raise InputError("contact_film", "a film thickness >= 0 in m", contact_film)
    if film_edges is None:
        rq = float(np.sqrt(sum(np.nanvar(r.z) for r, _, _ in given)))
        film_edges = np.linspace(0.0, max(2.0 * film_ref, film_ref + HISTOGRAM_RQ * rq), 51)
    film_edges = np.asarray(film_edges, dtype=float)
    if film_edges.ndim != 1 or film_edges.size < 2 or np.any(np.diff(film_edges) <= 0):
        raise InputError("film_edges", "at least two increasing bin edges in m")
    snaps = np.array([total] if snapshot_steps is None else snapshot_steps, dtype=np.int64)
    if snaps.ndim != 1 or np.any((snaps < 1) | (snaps > total)):
        raise InputError("snapshot_steps", f"steps between 1 and {total}", snapshot_steps)
    snaps = np.unique(snaps)

    stepper = TimeStepper(problem, x, y, opts, dt, film_ref / problem.film_scale)
    state = stepper.state
    hertz = hertz_mask(problem, x, y)
    stats = ContactStatistics((nx, ny), film_edges, hertz, counting_steps)
    history = StepHistory(total, snaps, nx)
    key = fingerprint(repr(problem), x, y, dt, warmup_steps, counting_steps, opts.theta,
                      opts.method, opts.near, opts.tol, opts.max_sweeps, opts.refresh,
                      opts.acceleration, opts.load_gain, opts.damping, contact_film,
                      film_edges, snaps,
                      *[(type(r).__name__, r.periodic, r.x, r.z) for r in
                        (roughness1, roughness2) if r is not None], slots)
    checkpointer = Checkpointer(checkpoint, key, checkpoint_every)

    start = 0
    arrays = checkpointer.load() if resume else None
    if arrays is not None:
        state.P = arrays["P"].copy()
        state.H = arrays["H"].copy()
        state.H0 = float(arrays["H0"])
        state.kind = arrays["kind"].copy()
        start = int(arrays["step"])
        steady_converged = bool(arrays["steady_converged"])
        steady_hc = float(arrays["steady_central_film"])
        steady_film = arrays.get("steady_film", np.full((nx, ny), np.nan))
        stats.restore(arrays)
        history.restore(arrays)
        if start:  # the settings a step before the checkpoint was relaxed again with
            retried = np.flatnonzero(history.record["tries"][:start] > 1)
            stepper.resume_settings(int(history.record["refresh_intervals"][start - 1]),
                                    float(history.record["load_gains"][start - 1]),
                                    bool(history.record["density_newton"][start - 1]),
                                    start - 1 - retried[-1] if retried.size else start,
                                    float(history.record["relaxation"][start - 1]))
    else:
        if steady is None:
            steady = smooth_start(problem, nx, ny, domain, method=method, near=opts.near,
                                  tol=opts.tol)
        if steady.pressure.shape != (nx, ny) or not np.allclose(steady.x, x):
            raise InputError("steady", f"a steady solution on the same {nx} x {ny} grid")
        state.P = steady.pressure / problem.p_hertz
        state.H = steady.film / problem.film_scale
        state.H0 = steady.separation / problem.film_scale
        state.kind[:] = 0
        state.kind[state.P <= 0.0] = CAVITATED
        state.kind[state.H <= 0.0] = CONTACT
        steady_converged = bool(steady.converged)
        steady_hc = float(steady.central_film)
        steady_film = np.asarray(steady.film, dtype=float)

    z1, z2 = heights(start * dt)
    state.roughness = -(z1 + z2) / problem.film_scale
    interior = ~state.edge
    steps_done = start
    failed_in_a_row = 0
    for step in range(start + 1, total + 1):
        z1, z2 = heights(step * dt)
        report = stepper.advance(-(z1 + z2) / problem.film_scale)
        p = state.P * problem.p_hertz
        h = state.H * problem.film_scale
        history.add(step, p, h, report)
        if step > warmup_steps:
            stats.add(h, (h <= contact_film) & interior)
        if history.wants_snapshot(step):
            history.snapshot(step, {name: centre_line(state, field) for name, field in (
                ("centre_pressure", p), ("centre_film", h), ("centre_surface1", z1),
                ("centre_surface2", z2))})
        steps_done = step
        failed_in_a_row = 0 if report.converged else failed_in_a_row + 1
        finite = np.isfinite(report.residual)
        if finite and checkpointer.due(step, total):
            checkpointer.save({
                "P": state.P, "H": state.H, "H0": np.float64(state.H0), "kind": state.kind,
                "step": np.int64(step), "steady_converged": np.bool_(steady_converged),
                "steady_central_film": np.float64(steady_hc), "steady_film": steady_film,
                **stats.arrays(),
                **history.arrays()})
        if callback is not None:  # after the checkpoint, so a callback sees this step's file
            callback(step, report.residual)
        if not finite or failed_in_a_row == GIVE_UP_STEPS:
            break

    record = history.record
    done = record["step_converged"][:steps_done]
    # the last step's explicit part (rhs_t) exists only where this call advanced it: a run
    # resumed from its final checkpoint is not checked
    check = stepper.check_fixed_point() if steps_done == total > start and done[-1] else None
    p = state.P * problem.p_hertz
    h = state.H * problem.film_scale
    if np.all(np.isfinite(p)) and np.all(np.isfinite(h)):
        qx, qy = flow_vectors(problem, x, y, p, h)
    else:
        qx = qy = np.full((nx, ny), np.nan)
    return TransientResult(
        x=x, y=y, dt=float(dt), warmup_steps=warmup_steps, counting_steps=counting_steps,
        steps=total, steps_done=steps_done, pressure=p, film=h, surface1=z1, surface2=z2,
        contact_count=stats.count, contact_count_rate=stats.count_rate(dt),
        contact_time_fraction=stats.contact_time_fraction(),
        contact_nodes=stats.contact_nodes, hertz_contact_nodes=stats.region_contact_nodes,
        hertz_nodes=int(np.count_nonzero(hertz)), block_contact_count=stats.block_counts,
        block_steps=stats.block_steps,
        film_edges=film_edges, film_counts=stats.film_counts, least_film=stats.least_film,
        flow_x=qx, flow_y=qy,
        snapshot_steps=snaps, iterations=int(record["sweeps"].sum()),
        converged=bool(steady_converged and steps_done == total and done.all()),
        residual=float(np.nanmax(record["residuals"])) if steps_done else float("nan"),
        steady_central_film=steady_hc, steady_film=steady_film, contact_film=contact_film,
        steady_converged=steady_converged, method=opts.method,
        theta=opts.theta,
        fixed_point_pressure=check.pressure if check else float("nan"),
        fixed_point_film=check.film if check else float("nan"),
        fixed_point_sweeps=check.sweeps if check else 0,
        fixed_point_settled=check.settled if check else False,
        **history.arrays(),
    )
