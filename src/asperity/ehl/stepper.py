"""One timestep of the transient mixed-EHL solver: its settings, explicit part and relaxation.

The time-discrete equations (Holmes, Evans & Snidle, J. Tribol. 127 (2005) 61, with the
theta-scheme of docs/ehl-transient.md; dimensionless, ``T = t u_mean / a``, node P)::

    theta L^{n+1} + (1 - theta) L^n - lam [(rho H)^{n+1} - (rho H)^n] / dT = 0

with ``L`` the discrete Reynolds operator (Poiseuille + wedge, :func:`reynolds_operator`),
coupled to the differential deflection equation and the contact condition (seed Eqs. 1-8) of
:class:`~asperity.ehl.solver.EHLState`. :class:`TimeStepper` advances the state by one step:
it forms the explicit part ``rhs_t = (1 - theta) L^n + (lam/dT) (rho H)^n``, moves the
surfaces, then relaxes (p, h, H0) at level n+1 by refresh cycles of x-line (or point) sweeps
with the far-field deflection lagged over a cycle, Anderson-mixed once the asperity-scale
errors are relaxed (:mod:`asperity.ehl.anderson`). :class:`StepOptions` holds the settings of
that iteration; they change the path to the fixed point, not the discrete equations.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from ..errors import InputError, check_int, check_positive
from .anderson import AndersonMixer
from .kernels import CAVITATED, CONTACT
from .nodal import upwind_difference
from .problem import LineContact
from .solver import (
    Y_LINES_BELOW,
    EHLState,
    LineContactState,
    check_contact_and_method,
    check_damping,
)

__all__ = ["BLOWN_UP_FLOOR", "BLOWN_UP_RISE", "BLOWN_UP_SWEEPS", "DIVERGED", "LINE_REFRESH",
           "MIX_BELOW", "REFRESH_EVERY_SWEEP_BELOW", "UNDAMPED_BELOW", "UNDER_RELAXATION",
           "FixedPointCheck", "StepOptions", "StepReport", "TimeStepper", "reynolds_operator"]

#: A step whose pressure exceeds this many Hertz pressures is taken as diverged.
DIVERGED = 1e3

#: A try of a step is given up as blown up once its residual has stayed above both
#: ``BLOWN_UP_RISE`` times the smallest residual of the try and ``BLOWN_UP_FLOOR`` (a change of
#: 5 % of p_h in one sweep) for ``BLOWN_UP_SWEEPS`` sweeps in a row, rather than after all of
#: ``max_sweeps`` (:meth:`TimeStepper.relax`). The failed tries of the fallback tests and of
#: a user's ridge through a crowned roller grew by about 2 times per sweep from their start
#: to changes of 1-3 p_h and stayed there without reaching ``DIVERGED``; those of the a/b = 4
#: seed-mesh run fell to 7-8e-3, grew back slowly to 0.1-0.2 by sweep 80-110 and stayed
#: there. None came back within 400 sweeps. Of 18,102 tries that converged (47 runs: the
#: examples, the reduced studies, the fallback tests, the roller, 200 steps of that a/b = 4
#: run) none had its residual so far up for more than 3 sweeps in a row, and the fallback
#: relaxes the step from its start, so where the try would have failed anyway the run is
#: the same to the bit (docs/ehl-transient.md, "A try that blows up is given up at once").
BLOWN_UP_RISE = 5.0
BLOWN_UP_FLOOR = 0.05
BLOWN_UP_SWEEPS = 20

#: Residual of a refresh cycle below which its result joins the Anderson history: the
#: asperity-scale errors of the new step (changes of order p_h) are relaxed by then and what
#: is left is the slow smooth part (:meth:`TimeStepper.relax`).
MIX_BELOW = 1e-2

#: Residual of a refresh cycle below which the rest of the step refreshes the far field at
#: every sweep instead of every ``refresh`` sweeps: the asperity-scale changes of the first
#: sweeps are local and need no fresh far field, the tail is the far field lagged over a
#: cycle and the load loop, and a step's convergence is only seen on the first sweep after
#: a refresh. On the gear benchmark (C-C, xi = 0.25) it took the sweeps per rough step from
#: 26.0 to 16.5 (261 x 57) and from 20.3 to 14.8 (seed spacing, 571 x 201), the refreshes
#: from 9.6 to 12.7 and 10.6 to 12.8 (docs/ehl-transient.md, "Cost").
REFRESH_EVERY_SWEEP_BELOW = 0.3

#: Residual of a refresh cycle below which the rest of the step relaxes without the
#: oscillation damping (``StepOptions.damping``). Damped to the end, the narrow contact of the
#: aspect-ratio study (a/b = 4, C-C, xi = 0.25) on square cells (201 x 51) stalled in the tail
#: at a residual of 2-4e-4, 85.4 sweeps per step against 33.3 undamped from 1e-2; the gear
#: benchmark at the seed's spacing 14.70 against 13.97 (0.1: 14.20, 0.3: 14.40); undamped
#: from the start it took 20.77 (docs/ehl-transient.md, "Cost").
UNDAMPED_BELOW = 1e-2

#: Sweeps between far-field refreshes of the row solve of a line contact (point contacts: 3).
#: A single row's FFT refresh costs little more than the call's overheads, and with a refresh
#: every 3 sweeps a smooth, lightly loaded roller (Moes M = 5.3, L = 21) blew up at the first
#: try of a step, its changes growing 2.5-3 times per sweep within a refresh cycle. At every
#: sweep: the roller 21.5 -> 17.1 sweeps per step and no step relaxed again; the rough
#: ``holmes-rough-AA-line`` 21.2 -> 19.6 (10.4 -> 9.9 s); a user's Newtonian spur reducer
#: (1984 steps) 12 -> 9 failed steps, 142 -> 133 s; a 20,160-step smooth line 9.9 -> 9.0
#: sweeps per step at the same wall time (docs/ehl-transient.md, "Session 32").
LINE_REFRESH = 1

#: Rise of the residual, over its best of the try, at which an undamped step takes the
#: oscillation damping back for the rest of the try. A user's Newtonian gear contact (line,
#: slide/roll -1.5) had an asperity in contact at the node before the outlet boundary: its
#: pressure alternated from sweep to sweep against the lagged edge film, decaying by about 0.9
#: per sweep while damped and growing by 1.7 per sweep once undamped, and the step failed with
#: every fallback. Damped again: none of its first 530 steps failed (5 before), 19 -> 12 of
#: its 1984; the gear examples and the a/b = 4 tail above unchanged within 0.3 % in sweeps
#: (docs/ehl-transient.md, "Line contacts: the row solve").
REDAMP_RISE = 2.0

#: Factor on every node's change of a sweep in the last fallback of a step that fails with
#: every other setting (:meth:`TimeStepper.fall_back`). A user's Newtonian spur reducer (line
#: contact, Roelands viscosity, ground flanks of Ra 0.4 and 0.6 um, asperity pressures of
#: 10-30 GPa) failed 9 of its 1,984 steps: each try ran into an exact limit cycle of the
#: active set, with changes of 1.5-12 p_h per sweep to its end, and neither the far field
#: implicit over the whole row (``near`` 127) nor the other fallbacks broke it. Under-relaxed
#: by 0.5, steps 1,251-1,280 all converged at their first try, 32-294 sweeps each
#: (docs/ehl-transient.md, "Session 33").
UNDER_RELAXATION = 0.5


@dataclass(frozen=True)
class StepOptions:
    """Settings of the transient solver's iteration within a timestep.

    Build with :meth:`for_problem`, which applies the problem-dependent defaults and checks
    the values. Only ``theta`` changes the discrete equations (the time scheme); the others
    change the path to their solution.

    Attributes
    ----------
    method : {"line", "point"}
        x-line relaxation (point contacts) or the seed's point update (line contacts).
    theta : float
        Time-scheme weight, 1/2 (Crank-Nicolson) to 1 (implicit Euler).
    near : int
        x-neighbour pressure coefficients implicit in the line relaxation (0 with the point
        update).
    tol : float
        Per-step convergence: max |dP|, max |dH| relative to the estimated central film and
        the relative load error below ``tol`` on the first sweep after a far-field refresh.
    max_sweeps : int
        Sweep limit per step.
    refresh : int
        Sweeps between FFT refreshes of the far field and the edge films at the start of a
        step; once a refresh cycle ends below ``REFRESH_EVERY_SWEEP_BELOW`` the step
        refreshes at every sweep.
    acceleration : int
        Memory of the Anderson mixing of the refresh cycles; 0 off.
    load_gain : float
        Separation shift per sweep per relative load error.
    damping : float
        Factor on the change at nodes oscillating from sweep to sweep, until a refresh cycle
        of the step ends below ``UNDAMPED_BELOW``; 1 off.
    density_newton : bool
        Whether the update keeps the density's pressure derivative (the x-line row solve's
        Newton term, :meth:`asperity.ehl.solver.EHLState._sweep`, or the linearised density
        of a line contact's point update, :class:`~asperity.ehl.solver.LineContactState`);
        off by default, the density lagged (:meth:`TimeStepper.advance` switches it on for a
        step that fails without it).
    relaxation : float
        Factor on every node's change of a sweep (under-relaxation); 1 (default) off,
        ``UNDER_RELAXATION`` in the last fallback (:meth:`TimeStepper.fall_back`).
    """

    method: str
    theta: float
    near: int
    tol: float
    max_sweeps: int
    refresh: int
    acceleration: int
    load_gain: float
    damping: float
    density_newton: bool = False
    relaxation: float = 1.0

    @classmethod
    def for_problem(cls, problem, *, method=None, theta=0.5, near=2, tol=1e-4, max_sweeps=400,
                    refresh=None, acceleration=None, load_gain=None, damping=0.7) -> StepOptions:
        """Options for ``problem`` with its defaults (see :func:`asperity.ehl.solve_transient`).

        ``method`` None: line relaxation (a line contact's one row solved at once).
        ``refresh`` None: 1 for the row solve of a line contact (``LINE_REFRESH``), else 3.
        ``acceleration`` None: 3 with line relaxation, 0 with the point update. ``load_gain``
        None: ``0.15 min(1, b/a)`` (point contact), 0.03 (line contact).

        Raises
        ------
        InputError
            For a value out of range, naming the argument.
        """
        line, method = check_contact_and_method(problem, method or "line")
        theta = float(theta)
        if not 0.5 <= theta <= 1.0:
            raise InputError("theta", "a time-scheme weight 0.5 <= theta <= 1", theta)
        tol = check_positive("tol", tol)
        if load_gain is None:
            load_gain = 0.03 if line else 0.15 * min(1.0, problem.b / problem.a)
        load_gain = check_positive("load_gain", load_gain)
        damping = check_damping(damping)
        max_sweeps = check_int("max_sweeps", max_sweeps, 1)
        if refresh is None:
            refresh = LINE_REFRESH if line and method == "line" else 3
        refresh = check_int("refresh", refresh, 1)
        near = check_int("near", near, 0)
        if acceleration is None:
            acceleration = 3 if method == "line" else 0
        acceleration = check_int("acceleration", acceleration, 0)
        return cls(method=method, theta=theta, near=near, tol=tol, max_sweeps=max_sweeps,
                   refresh=refresh, acceleration=acceleration, load_gain=load_gain,
                   damping=damping)

    @property
    def implicit_near(self) -> int:
        """Near-field coefficients the sweep keeps implicit (none with the point update)."""
        return self.near if self.method == "line" else 0


class StepReport(NamedTuple):
    """Outcome of one timestep's relaxation.

    ``sweeps`` and ``refreshes`` count the finest-grid relaxation sweeps and the far-field
    FFT refreshes the step took (a retried step's included); ``load_error`` is the relative
    load error after the last sweep; ``refresh``, ``load_gain`` and ``density_newton`` the
    sweeps between refreshes, the load gain and whether the density's Newton term was kept,
    as the step ended; ``tries`` how often the step was relaxed, 1 when its first relaxation
    converged, ``y_lines`` whether its last relaxation added y-line sweeps
    (:meth:`TimeStepper.advance`) and ``relaxation`` the factor on every change of a sweep as
    the step ended (1: none).
    """

    converged: bool
    residual: float
    sweeps: int
    refreshes: int
    load_error: float
    refresh: int
    load_gain: float
    density_newton: bool
    tries: int = 1
    y_lines: bool = False
    relaxation: float = 1.0


def reynolds_operator(state: EHLState, ex, ey, rho) -> np.ndarray:
    """Discrete Reynolds operator ``L`` (Poiseuille + upwind wedge) of the current state.

    The same finite differences as the nodal update (docs/ehl.md): arithmetic face
    conductances, second-order upwind ``(3/2, -2, 1/2)`` wedge (first order next to the inlet);
    zero on the edges and at cavitated or contact nodes. ``ex, ey, rho`` are the state's
    :meth:`~asperity.ehl.solver.EHLState.flow_coefficients`.
    """
    P = state.P
    q = rho * state.H
    L = np.zeros_like(P)
    dx2 = state.dX**2
    fe = 0.5 * (ex[1:-1] + ex[2:]) / dx2
    fw = 0.5 * (ex[1:-1] + ex[:-2]) / dx2
    L[1:-1] = fe * (P[2:] - P[1:-1]) + fw * (P[:-2] - P[1:-1])
    L -= state.lam * upwind_difference(q) / state.dX  # (its last node is an edge: zeroed)
    if not state.line:
        dy2 = state.dY**2
        fn = 0.5 * (ey[:, 1:-1] + ey[:, 2:]) / dy2
        fs = 0.5 * (ey[:, 1:-1] + ey[:, :-2]) / dy2
        L[:, 1:-1] += fn * (P[:, 2:] - P[:, 1:-1]) + fs * (P[:, :-2] - P[:, 1:-1])
    L[state.edge] = 0.0
    L[(P <= 0.0) | (state.H <= 0.0)] = 0.0
    return L


class FixedPointCheck(NamedTuple):
    """How far a converged step's state is from the fixed point of its discrete equations
    (:meth:`TimeStepper.check_fixed_point`).

    ``pressure`` is the largest change of p over the nodes in Hertz pressures, ``film`` the
    largest change of h in central-film estimates (the convergence test's film scale), when
    the step is relaxed ``sweeps`` sweeps further; ``settled`` whether that relaxation reached
    its own, hundred times smaller tolerance (if not, the distances are lower bounds).
    """

    pressure: float
    film: float
    sweeps: int
    settled: bool


class TimeStepper:
    """Advances an :class:`~asperity.ehl.solver.EHLState` by timesteps of fixed length.

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact.
    x, y : ndarray
        Node coordinates, m.
    options : StepOptions
        Iteration settings.
    dt : float
        Timestep, s.
    film_scale : float
        Dimensionless film of the convergence test's film criterion (the estimated central
        film over ``problem.film_scale``).

    Attributes
    ----------
    state : EHLState
        The state advanced in place; set its P, H, H0, kind and roughness before the first
        :meth:`advance`.
    """

    #: Most halvings of the load gain for steps that do not converge (:meth:`advance`).
    GAIN_HALVINGS = 2

    #: Steps after the last step relaxed again with safer settings after which the stepper
    #: goes back to the run's own settings (:meth:`advance`). The safer settings are not
    #: safer for every later step: the aspect-ratio study's a/b = 4 contact at the seed's
    #: mesh needed every fallback at its first step (from a steady start that had not
    #: converged), kept them, and diverged at step 1167 with none left; on 131 x 29 the same
    #: contact with the density's Newton term failed from step 420 on and converged at every
    #: step with the density lagged (docs/ehl-transient.md, "Fallbacks").
    RESTORE_AFTER = 200

    #: Sweeps at most of :meth:`check_fixed_point`.
    CHECK_SWEEPS = 200

    def __init__(self, problem, x, y, options: StepOptions, dt: float, film_scale: float):
        self.problem = problem
        self.options = options
        state = LineContactState if isinstance(problem, LineContact) else EHLState
        self.state = state(problem, x, y, options.implicit_near)
        self.mass = self.state.lam / (dt * problem.mean_speed / problem.a)
        self.film_scale = film_scale
        self.mixer = AndersonMixer(options.acceleration) if options.acceleration else None
        #: The run's own settings, which :meth:`advance` goes back to.
        self.initial = options
        #: Times the load gain has been halved for a step that did not converge.
        self.halvings = 0
        #: Steps since the last step that was relaxed again (:attr:`RESTORE_AFTER`).
        self.since_retry = 0

    def advance(self, phi) -> StepReport:
        """One timestep to the dimensionless roughness ``phi`` of level n+1: the step set up
        (:meth:`start_step`) and relaxed (:meth:`relax`). The last separation shift also
        moves the h = 0 contact nodes; they are put back to 0.

        A step that does not converge is relaxed again from its start with safer settings
        (:meth:`fall_back`), which the later steps keep until :attr:`RESTORE_AFTER`
        steps have passed without another such step; the stepper then goes back to the run's
        own settings, so that a hard stretch of the run (a steady start that had not
        converged, a ridge entering the contact) leaves neither a costlier nor a less robust
        iteration, nor an empty list of fallbacks, to the rest of it. On cells less than 3 times
        as wide across as they are long (``dY < 3 dX``) a step that fails with every setting
        is relaxed once more with y-line sweeps (:attr:`can_add_y_lines`). A step that begins with
        the run's own settings again falls back after a quarter of ``max_sweeps``: on the
        a/b = 4 seed-mesh run the refresh of the case failed again at 2 of its first 3 such
        steps, after all 400 sweeps each, where the steps converge in 10-50.
        The separation shifted at every sweep against a far field lagged over several
        sweeps can grow into an oscillation of the load and of the pressure at the outlet
        constriction on fine meshes: a smooth ball-on-disc contact (Moes M = 208, L = 9.5)
        diverged from its steady solution at a/64 x b/32 and a/128 x b/44 with a refresh
        every 3 sweeps to the end of a step and converged in 3-9 sweeps per step with one at
        every sweep (since the step refreshes at every sweep once its residual is below
        ``REFRESH_EVERY_SWEEP_BELOW`` it converges with the default, and needs the fallback
        with a refresh every 6 sweeps); the same contact with a bump diverged on cells of
        a/128 by 3.2 a/128 at step 736 of 1843 with a refresh at every sweep and the gain
        0.15, and converged at every step with 0.075 (docs/ehl-transient.md, "The default
        mesh and time steps of a transient case").

        The density is lagged by default: its Newton term left the sweeps per step of the
        gear case as they were and made the narrow contact (a/b = 4) of the aspect-ratio
        study fail from step 420 on. Where the oil's compressibility weighs more it is the
        lagged density that fails: a ridge entering a ball-bearing contact (Moes M = 1947,
        L = 18.5) set off an oscillation of the active set that grew 2-2.5 times per sweep
        at every setting of refresh and gain, and converged in 4 sweeps per step with the
        term (docs/ehl-transient.md).
        """
        restored = self.options != self.initial and self.since_retry >= self.RESTORE_AFTER
        if restored:
            self.options = self.initial
            self.halvings = 0
        self.start_step(phi)
        state = self.state
        before = (state.P.copy(), state.H.copy(), state.H0, state.kind.copy())
        report = self.relax(self.options.max_sweeps // 4 if restored else None)
        tries = 1
        first = self.options
        while not report.converged and self.fall_back(first):
            state.P, state.H, state.H0, state.kind = (before[0].copy(), before[1].copy(),
                                                      before[2], before[3].copy())
            again = self.relax()
            tries += 1
            report = again._replace(sweeps=report.sweeps + again.sweeps,
                                    refreshes=report.refreshes + again.refreshes)
        y_lines = not report.converged and self.can_add_y_lines
        if y_lines:
            state.P, state.H, state.H0, state.kind = (before[0].copy(), before[1].copy(),
                                                      before[2], before[3].copy())
            state.y_lines = True
            try:
                again = self.relax()
            finally:
                state.y_lines = False
            tries += 1
            report = again._replace(sweeps=report.sweeps + again.sweeps,
                                    refreshes=report.refreshes + again.refreshes)
        self.since_retry = 0 if tries > 1 else self.since_retry + 1
        if not report.converged and not report.residual < BLOWN_UP_FLOOR:
            # a step that stayed far from its fixed point with every setting (or went
            # non-finite) leaves its start, not its last iterate, to the next step
            state.P, state.H, state.H0, state.kind = before
        np.maximum(self.state.H, 0.0, out=self.state.H)
        return report._replace(tries=tries, y_lines=y_lines)

    @property
    def can_add_y_lines(self) -> bool:
        """Whether a step that fails with every setting can be relaxed once more with a
        y-line sweep after every x-line sweep (:func:`asperity.ehl.kernels.column_sweep`, the
        steady solver's fallback for such cells): x-line relaxation of a point contact on
        cells with ``dY < Y_LINES_BELOW dX``. For that step only, since a sweep then costs
        about twice as much: on the a/b = 4 seed-mesh run (square cells) step 1225 failed
        with every setting (residual 0.15 after 401 sweeps) and converged with them in 71
        more (docs/ehl-transient.md)."""
        state = self.state
        return bool(self.options.method == "line" and not state.line
                    and state.dY < Y_LINES_BELOW * state.dX)

    def fall_back(self, first: StepOptions) -> bool:
        """Switch to the next safer settings for a step that did not converge; False when
        none is left. ``first`` are the settings the step was first relaxed with. In this
        order:

        1. the far field refreshed at every sweep (when ``refresh > 1``);
        2. for a compressible lubricant, the density's Newton term in the update
           (:attr:`can_add_density_term`), when the step began with the density lagged;
        3. the load gain halved, at most ``GAIN_HALVINGS`` times in all;
        4. the density lagged again, when the step began with its Newton term: the term
           that carries the heavily loaded bearing contact made the narrow a/b = 4 contact
           fail (:meth:`advance`);
        5. every change of a sweep under-relaxed by ``UNDER_RELAXATION``: it breaks the limit
           cycles of the active set in which the steps of a Newtonian contact with asperity
           pressures of 10-30 GPa ended with every setting above. It is last because it
           about doubles the sweeps of a step that converges without it.
        """
        opts = self.options
        if opts.refresh > 1:
            self.options = replace(opts, refresh=1)
        elif self.can_add_density_term and not first.density_newton:
            self.options = replace(opts, density_newton=True)
        elif self.halvings < self.GAIN_HALVINGS:
            self.halvings += 1
            self.options = replace(opts, load_gain=opts.load_gain / 2)
        elif opts.density_newton and first.density_newton:
            self.options = replace(opts, density_newton=False)
        elif opts.relaxation > UNDER_RELAXATION:
            self.options = replace(opts, relaxation=UNDER_RELAXATION)
        else:
            return False
        return True

    def resume_settings(self, refresh: int, load_gain: float, density_newton: bool = False,
                        since_retry: int = 0, relaxation: float = 1.0):
        """Take up the refresh interval, load gain, density term and under-relaxation a
        checkpointed step ended with (:class:`StepReport`) and the steps since the last step
        relaxed again; 0, NaN, False or 1 (a checkpoint written before they were recorded)
        leaves the option as it is."""
        if 0 < refresh < self.options.refresh:
            self.options = replace(self.options, refresh=refresh)
        if density_newton:
            self.options = replace(self.options, density_newton=True)
        if 0 < relaxation < self.options.relaxation:
            self.options = replace(self.options, relaxation=float(relaxation))
        if np.isfinite(load_gain) and load_gain < self.options.load_gain:
            self.halvings = round(np.log2(self.options.load_gain / load_gain))
            self.options = replace(self.options, load_gain=load_gain)
        self.since_retry = int(since_retry)

    @property
    def can_add_density_term(self) -> bool:
        """Whether the update lags a density that varies with pressure and has a form with
        its pressure derivative (a compressible lubricant; the x-line relaxation, or the
        point update of a line contact, :class:`~asperity.ehl.solver.LineContactState`), so
        that a failing step can be relaxed again with it."""
        has_term = self.options.method == "line" or isinstance(self.problem, LineContact)
        return (not self.options.density_newton and has_term
                and self.problem.lubricant.compressible)

    def start_step(self, phi):
        """Set up the step to the roughness ``phi`` of level n+1 from the current state
        (level n): the explicit part of the theta-scheme, then the film moved with the
        surfaces (``H += phi - phi^n``, which keeps the deflection equation's source
        consistent)."""
        state = self.state
        ex, ey, rho = state.flow_coefficients()
        theta = self.options.theta
        state.theta = theta
        state.mass = self.mass
        state.rhs_t = (1.0 - theta) * reynolds_operator(state, ex, ey, rho) \
            + self.mass * rho * state.H
        state.H += phi - state.roughness
        state.roughness = phi

    def relax(self, max_sweeps: int | None = None) -> StepReport:
        """Relax the current step to convergence by refresh cycles, in at most ``max_sweeps``
        sweeps (default: the options').

        The far field is refreshed every ``refresh`` sweeps until a refresh cycle ends with a
        residual below ``REFRESH_EVERY_SWEEP_BELOW``, then at every sweep; the step has
        converged when the first sweep after a refresh changes p by less than ``tol``, h by
        less than ``tol * film_scale`` and leaves a relative load error below ``tol``. The
        oscillation damping acts until a cycle ends below ``UNDAMPED_BELOW``, and again for
        the rest of the try once a cycle ends above ``REDAMP_RISE`` times the best residual
        of the try while undamped (a node alternating against a lagged neighbour that only
        the damping holds). A step still unconverged after a quarter of ``max_sweeps`` goes
        on with the Newton derivatives evaluated at every sweep (:meth:`EHLState._sweep`). A
        step whose pressure diverges (``DIVERGED``) or whose residual has blown up and stays
        up (``BLOWN_UP_RISE``, ``BLOWN_UP_FLOOR``, ``BLOWN_UP_SWEEPS``) is given up at once,
        unconverged, so that :meth:`advance` relaxes it again with safer settings without
        spending the rest of ``max_sweeps`` on it.

        With Anderson acceleration each refresh cycle (refresh and sweeps) is a fixed-point
        map of ``(P, H / film_scale, H0 / film_scale)``; once a cycle ends with a residual
        below ``MIX_BELOW`` the next cycle starts from the mixer's extrapolation (clipped to
        p, h >= 0 and to the active set), and the history is forgotten whenever the residual
        is above it again. The convergence test is unchanged: a sweep from the mixed state
        must itself change nothing by more than ``tol``.
        """
        state, opts, mixer = self.state, self.options, self.mixer
        tol, refresh = opts.tol, opts.refresh
        max_sweeps = opts.max_sweeps if max_sweeps is None else max_sweeps
        target = state.problem.load_integral
        refreshes_before = state.refreshes
        state.density_newton = opts.density_newton
        state.start_iteration()
        state.damping = opts.damping
        state.relaxation = opts.relaxation
        state.lag_derivatives = True
        if mixer is not None:
            mixer.reset()
        sweeps = 0
        interval = refresh
        residual = best = np.inf
        load_err = np.inf
        above = 0
        redamped = False

        def report(converged, residual):
            return StepReport(converged, residual, sweeps, state.refreshes - refreshes_before,
                              load_err, refresh, opts.load_gain, opts.density_newton,
                              relaxation=opts.relaxation)

        while sweeps < max_sweeps:
            if sweeps >= max_sweeps // 4:
                state.lag_derivatives = False
            state.refresh()
            first = sweeps + 1
            start = self.mix_vector() if mixer is not None else None
            for _ in range(interval):
                dp, dh = state.sweep(opts.method)
                sweeps += 1
                load_err = (state.load() - target) / target
                state.shift_separation(opts.load_gain * load_err)
                residual = max(dp, dh / self.film_scale, abs(load_err))
                if not (np.isfinite(residual) and np.abs(state.P).max() < DIVERGED):
                    return report(False, np.inf)
                best = min(best, residual)
                above = above + 1 if residual > max(BLOWN_UP_RISE * best, BLOWN_UP_FLOOR) else 0
                if above == BLOWN_UP_SWEEPS:
                    return report(False, residual)
                if residual < tol or sweeps >= max_sweeps:
                    break
            if residual < tol and sweeps == first:
                return report(True, residual)
            if residual < REFRESH_EVERY_SWEEP_BELOW:
                interval = 1
            if residual < UNDAMPED_BELOW and not redamped:
                state.damping = 1.0
            elif state.damping == 1.0 and residual > REDAMP_RISE * best:
                state.damping = opts.damping
                redamped = True
            if mixer is not None:
                if residual < MIX_BELOW:
                    self.set_mixed(mixer.mix(start, self.mix_vector()))
                else:
                    mixer.reset()
        return report(False, residual)

    def check_fixed_point(self, sweeps: int | None = None) -> FixedPointCheck:
        """Relax the current (converged) step on, to a hundredth of its tolerance in at most
        ``sweeps`` sweeps (default :attr:`CHECK_SWEEPS`), measure how far p and h move, and
        put p, h, H0, the active set, the refresh count and the options back as they were.
        The far field ``efar`` and the flow-factor derivatives are left at the relaxed-on
        state: :meth:`relax` rebuilds both before its first sweep.

        A step stops when a sweep changes p and h by less than ``tol``. The state is then
        within ``tol rho / (1 - rho)`` of the fixed point for a relaxation that contracts by
        ``rho`` per sweep: a few ``tol`` on the gear case at the seed's spacing (rho about
        0.65; measured 1-2e-3 p_h and 0.05-0.1 % of the film at 571 x 201), but some
        hundred ``tol`` where the relaxation drifts slowly, as at the asperity contacts of
        the narrow a/b = 4 contact on the seed's square cells (rho 0.94-0.99: 3e-2 p_h and
        1 % of the film, docs/ehl-transient.md, "How far a converged step is from its fixed
        point").
        """
        state, opts = self.state, self.options
        before = (state.P.copy(), state.H.copy(), state.H0, state.kind.copy(), state.refreshes)
        self.options = replace(opts, tol=opts.tol / 100,
                               max_sweeps=self.CHECK_SWEEPS if sweeps is None else sweeps)
        try:
            report = self.relax()
            dp = float(np.max(np.abs(state.P - before[0])))
            dh = float(np.max(np.abs(state.H - before[1]))) / self.film_scale
        finally:
            self.options = opts
            state.P, state.H, state.H0, state.kind, state.refreshes = before
        if not np.isfinite(report.residual):
            dp = dh = np.inf
        return FixedPointCheck(float(dp), float(dh), int(report.sweeps), bool(report.converged))

    def mix_vector(self) -> np.ndarray:
        """The iterate ``(P, H / film_scale, H0 / film_scale)`` as one vector (comparable
        scales; the fields in their x-fastest memory order)."""
        state, scale = self.state, self.film_scale
        n = state.P.size
        v = np.empty(2 * n + 1)
        v[:n] = state.P.ravel(order="F")
        np.divide(state.H.ravel(order="F"), scale, out=v[n:2 * n])
        v[-1] = state.H0 / scale
        return v

    def set_mixed(self, v):
        """Set (P, H, H0) from a mixed vector: p, h >= 0, p = 0 cavitated, h = 0 in contact."""
        state, scale = self.state, self.film_scale
        n = state.P.size
        state.P = np.maximum(v[:n].reshape(state.P.shape, order="F"), 0.0)
        state.H = np.maximum(v[n:2 * n].reshape(state.H.shape, order="F") * scale, 0.0)
        state.H0 = float(v[-1]) * scale
        state.P[state.kind == CAVITATED] = 0.0
        state.H[state.kind == CONTACT] = 0.0
