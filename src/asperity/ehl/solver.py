"""Steady isothermal EHL of smooth point and line contacts by the coupled differential method.

The elastic deflection is imposed in differential form (Holmes et al. 2003, Eq. 1), the
Reynolds equation with Eyring flow factors (Eq. 2), and both are relaxed together node by node
(Eq. 7) or row by row (x-line relaxation), with cavitation (p >= 0) and contact (h >= 0,
Eq. 8). The far-field pressure sum and the Dirichlet edge values of h are refreshed by FFT
every ``refresh`` sweeps; the rigid separation ``H0`` is shifted at every node to balance the
load. The discretisation is documented in ``docs/ehl.md``.

:class:`EHLState` keeps everything a time-stepping solver needs to advance (p, h, H0, the
far-field arrays, the active set, the time-term switches ``theta``, ``mass`` and ``rhs_t``).

References
----------
M. J. A. Holmes, H. P. Evans, T. G. Hughes, R. W. Snidle, Proc. IMechE J 217 (2003) 289-303.
H. P. Evans, T. G. Hughes, Proc. IMechE C 214 (2000) 563-584.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..elastic.convolution import Convolution, grid_spacing
from ..elastic.differential import (
    differential_coefficients,
    line_differential_coefficients,
    strip_integral,
)
from ..elastic.kernels import love_integral
from ..errors import InputError, check_int, check_positive
from ..solution import SolverResult, renamed_keywords
from .kernels import (
    column_sweep,
    damp_oscillations,
    far_field,
    five_point_laplacian,
    line_sweep,
    point_sweep,
)
from .line_newton import solve_line_newton
from .lubricant import friction_coefficient
from .nodal import at_centre as _at_centre
from .nodal import centre_line as _centre_line
from .nodal import upwind_difference
from .problem import LineContact, PointContact

__all__ = ["EHLState", "LineContactState", "SteadyResult", "solve_steady"]

#: Smooth pressure (over p_hertz) 0.1 a downstream of the inlet above which the inlet lies in
#: the pressure build-up: on the gear case an inlet at -1.4a gives 1.1 % and a central film
#: 12 % below that of an inlet at -2a (-1.1a: 13 %, film -47 %; -1.6a: 0.4 %, -5 %).
STARVED_INLET = 0.01

#: Default separation shift per sweep per unit relative load error (dimensionless film units).
POINT_LOAD_GAIN = 0.05
LINE_LOAD_GAIN = 0.01
#: A line contact on a mesh finer than its default one (``problem.default_nodes``) for which
#: no :class:`LoadTangent` is at hand (one grid, ``method="line"``, or an unconverged coarser
#: grid) gets ``LINE_LOAD_GAIN (dX / dX_default)^3.5`` on that grid. The point update of a
#: line contact moves the pressure, and so the load, only slowly after a shift of the
#: separation: on the seed's line contact (-2.5a..1.5a) the load error reaches 63 % of its
#: value 6000 sweeps later 1, 7, 38 and 250 sweeps after the shift on 101, 201, 401 and
#: 801 nodes (~ N^2.6), so the per-sweep load correction, an integral control of that lag,
#: overshoots and cycles unless its gain falls about as fast: the largest gains that
#: converged there were 2.5e-3, 8.8e-4 and 2.2e-4 on 401, 513 and 801 nodes (default 257:
#: 0.01); the exponent 3.5 gives 2.1e-3, 8.8e-4, 1.9e-4. Not smaller: where the point
#: relaxation keeps drifting slowly the gain sets the load error left (drift / gain), and
#: the Newtonian M = 100 line contact on twice its default resolution converged with
#: 8.8e-4, not with 6.3e-4 (docs/ehl-robustness.md).
LINE_GAIN_EXPONENT = 3.5
#: A point contact on a mesh finer than its default one gets ``POINT_LOAD_GAIN (dX /
#: dX_default)`` on that grid. The circular contact of the seed's aspect-ratio study (a/b = 1,
#: M = 174, L = 6.9; default 257 x 41 on its domain) converged on 401 x 101 with 0.05 in 240
#: sweeps, and on the seed's 801 x 201 (dX / dX_default = 0.32) cycled at residual 0.1-0.7
#: for 20000 sweeps with 0.05 (the film drifting to 2.4 times its value) and with 0.025,
#: and converged with 0.016 and 0.0125 (docs/ehl-robustness.md, "Point contacts on meshes
#: much finer than the default").
POINT_GAIN_EXPONENT = 1.0

#: A steady x-line relaxation has stalled when its residual after a refresh cycle is above
#: ``STALL_RATIO`` times the residual ``STALL_CYCLES`` cycles before (:func:`_relax`).
STALL_CYCLES = 20
STALL_RATIO = 0.9

#: A grid of a line contact's first grid sequence (:func:`solve_steady`) gives up, and leaves
#: the solve to its fallback, once for ``STUCK_SWEEPS`` sweeps no residual has fallen below
#: ``STALL_RATIO`` times the last one that did. A cam contact on a short domain (161
#: nodes) kept its best at 1e-2 from sweep 1,000 to 20,000, a case file's 40,000 sweeps per
#: grid took most of the run's 36 s; the slowest grid that converged (129 nodes, 14,120
#: sweeps) halved its best every 1,000-2,000 sweeps (docs/ehl-robustness.md, "Line contacts
#: on a short domain").
STUCK_SWEEPS = 5000

#: A point contact's grid steered by a :class:`LoadTangent` is given up once its residual
#: has grown to ``TANGENT_BLOWUP`` times the least it reached on that grid (and above
#: ``tol``), and the sequence is solved again with the load gain (:func:`solve_steady`).
#: A 6309 bearing's outer-race contact (M = 2520, k = 0.58, its side lobes on their floor)
#: on 1025 x 153 reached 2.7e-5, stalled at 4-5e-5 and then grew by about 1.05 per cycle to
#: 1e4 by its 5000th sweep; sequenced with the gain it converges in 730 sweeps.
TANGENT_BLOWUP = 100.0

#: Far-field refresh interval of the last fallback of a line contact's point update
#: (:func:`solve_steady`, default ``refresh`` only): when both grid sequences end
#: unconverged with a refresh every 10 sweeps, the first sequence is solved again with a
#: refresh every ``LINE_RETRY_REFRESH`` sweeps. A user's roller on its inner race with an
#: Eyring oil at low sliding (R = 4 mm, 500 kN/m, 5 m/s, tau0 = 5-20 MPa, slide/roll 0.05;
#: Moes M = 36.8, L = 15.9) did not converge on its 257-node default mesh: the Eyring flow
#: factor at the sliding shear gives the Hertz zone's Poiseuille term about the weight of
#: the wedge in the nodal update, and the cycle of 10 sweeps at a lagged far field then has
#: a growing oscillation at the outlet (1.0012 per cycle at the fixed point, 10 MPa; 0.999
#: with 3 sweeps). Only as a fallback: with 3 sweeps the seed's line contact did not
#: converge on 1601 nodes (docs/ehl-robustness.md, "Not in the table").
LINE_RETRY_REFRESH = 3

#: Sweeps at most of the relaxation that checks a line contact's Newton solution
#: (:func:`_relax_line_or_newton`); from the solution it converges in one refresh cycle
#: (10 sweeps, changes below 1e-10 on the rollers of docs/ehl-robustness.md, session 38).
NEWTON_CHECK_SWEEPS = 500
#: Newton steps at most from a line contact's unconverged relaxation, and from the finest
#: grid's converged one (:func:`_relax_line_or_newton`). From a converged state Newton
#: took 2-3 steps (the isoviscous rollers at M = 62 and 118, the robustness table's line
#: rows M = 10, L = 10 and M = 20, L = 2); on a stiff piezoviscous
#: Hertz zone (a roller bearing's inner race at M = 305, L = 6.8, 2049 nodes) it did not
#: converge in 40 steps, which took 15 s; on the robustness table's piezoviscous line rows
#: the converged relaxation's central film lay within 0.03 % of Newton's discrete solution
#: (docs/ehl-robustness.md, session 38).
NEWTON_STEPS = 40
POLISH_STEPS = 6

#: Sweep limit on the coarser grids of a point contact's grid sequence (at most ``max_iter``):
#: a coarse grid only gives the next grid its start. A 6205 ball bearing's inner-race contact
#: (M = 18,080, k = 9.3, docs/ehl-robustness.md) spent 5000 of its 6130 sweeps, 5 of 20 s,
#: on a 65 x 39 grid whose a/16 cells do not resolve its film and never converged; the next
#: grid converged from that state in 260 sweeps. Every other point contact of the robustness
#: table converges on each coarse grid in fewer sweeps. Line contacts keep ``max_iter``:
#: their load tangents come from converged coarse grids (:class:`LoadTangent`).
COARSE_SWEEPS = 1000

#: A point contact whose x-line relaxation ends unconverged on cells with ``dY <
#: Y_LINES_BELOW dX`` (the default mesh has ``dY >= 3 dX``) is solved again with a y-line
#: sweep after every x-line sweep (:attr:`EHLState.y_lines`). On such cells the rows couple
#: as strongly across y as along x, and the x-lines alone cycled: a steel ball on glass on
#: 257 x 257 square cells (M = 65, L = 6.3) at residual 0.4 after 5000 sweeps, converged in
#: 750 with the y-lines; an a/b = 4 ellipse on 257 x 257 nodes (dY = dX/4) at 0.9, converged
#: in 1270 (docs/ehl-robustness.md, "Square cells"). Only as a fallback: the a/b = 4 ellipse
#: of the seed's aspect-ratio study on 401 x 101 square cells converged without them (3066
#: sweeps) and cycled with them.
Y_LINES_BELOW = 3.0
#: Cells (``dY >= FINE_CELL_ASPECT dX``) that the runners' mesh advice asks for. On cells a
#: few dX across, fine meshes of a thin film let the zebra x-line relaxation swing whole
#: rows between no pressure and three times the Hertz pressure, and the cells it needs grow
#: longer as dY shrinks: a user's 3/4 in steel ball on glass (PAO, 20 N, 0.1 m/s, Moes
#: M = 611, L = 2.4, central film 32 nm, ``H_c`` = 0.017) converged at ``dY = b/36`` on
#: 3 dX (with the load tangent), at ``b/54`` on 4 and 5.3 dX and at ``b/72`` on 6 dX,
#: and did not at ``b/72`` on 3 or 4 dX (865 x 289, 1153 x 289) with any load gain, the
#: tangent or y-line sweeps (docs/ehl-robustness.md, "A thin film on fine meshes").
FINE_CELL_ASPECT = 6.0

#: Cells (``dY >= SOFT_CELL_ASPECT dX``) and nodes across y (at most ``SOFT_MAX_NY``) on which
#: the steady solve of an isoviscous elastic point contact (:attr:`PointContact.soft`: a PDMS
#: ball on glass) converges, with its fallback (:data:`SOFT_RETRY_REFRESH`). With the
#: defaults alone a PDMS ball at M = 434 on -2.5a..1.5a, +-2b converged on 1025 x 65
#: (dY = 16 dX, 952 sweeps) and 1025 x 129 (8 dX, 3,926), not on 385 x 129 (3 dX, residual
#: 9e-3), so the limit was 8 dX until session 39's fallback: 385 x 129 now converges in 3,503
#: sweeps of the fallback (9,793 in all, 77 s; minimum film 1651.7 nm against 1657 nm on
#: 1025 x 129), and so does the glycerol-lubricated ball at M = 964 on 385 x 129 given as
#: one grid (3,508, 9,938 in all, 107 s; 344.7 against 345.6 nm). Not on more nodes across:
#: the PDMS ball on 769 x 257 (b/64, 3 dX) with a refresh every sweep and the fallback's
#: gain on every grid ended at residual 0.025 after 5,000 sweeps (176 s; with 0.0017 and
#: 0.003 too, 0.021), a wave running along the centre line from inlet to outlet every
#: 100-150 sweeps, with or without y-line sweeps; the glycerol ball on 1025 x 257 did not
#: converge with the defaults (residual 0.024) nor with the fallback's settings on its four
#: grids (0.039 after 5,000 sweeps, 328 s). So the runners' mesh advice keeps to these cells
#: and nodes (docs/ehl-robustness.md, "A PDMS ball's minimum film across y").
SOFT_CELL_ASPECT = 3.0
SOFT_MAX_NY = 129

#: Far-field refresh interval and load gain of the last fallback of a soft point contact
#: (:attr:`PointContact.soft`; :func:`_soft_retry`): when its finest grid ends unconverged
#: with the defaults (a refresh every 10 sweeps, halved where it stalls, and a separation
#: shift of ``POINT_LOAD_GAIN`` per unit load error), it is relaxed again from the coarser
#: grid's solution with a refresh every ``SOFT_RETRY_REFRESH`` sweeps and a gain of
#: ``SOFT_GAIN_PER_FILM H_c`` (``H_c`` Nijenbanning's central film in Hertzian units, scaled
#: like the default gain on grids finer than the default mesh). ``2/15 H_c`` is the shift
#: Newton's step would take on the isoviscous-elastic film's ``h ~ w^(-2/15)``
#: (Nijenbanning's asymptote ``H_EI = 2.42 M^(-2/15)``), which makes the gain follow the
#: film. The factor 3 on it is measured, not derived: within the relaxation the load answers
#: a shift only weakly (on 385 x 129 a shift dH0 moved the relative load by 2.8 dH0 after one
#: sweep and by at most 23 dH0, 20 sweeps on, against the film law's 540 dH0), so the gain
#: that converges fastest is a few Newton steps per sweep. Measured on the PDMS ball
#: (M = 434, ``H_c`` = 0.0139 estimated, Newton's step 0.00185) on 385 x 129 with a refresh
#: every sweep on all three grids: gains 0.0017, 0.003, 0.0045, 0.006, 0.008 converged in
#: 4,018, 2,490, 1,641, 406, 975 finest-grid sweeps, 0.01 cycled (docs/ehl-robustness.md,
#: session 39); 0.4 ``H_c`` is 3 Newton steps, 0.0056 (the glycerol ball at M = 964: 0.0030).
#: Only as a fallback: with a refresh every sweep the default mesh took 1,930 sweeps instead
#: of 952.
SOFT_RETRY_REFRESH = 1
SOFT_GAIN_PER_FILM = 0.4


class _XFastest:
    """A nodal field of :class:`EHLState`, stored x-fastest (Fortran order) whatever is assigned.

    The line sweep solves rows ``y = const`` (:func:`asperity.ehl.kernels.line_sweep`), whose
    nodes are then contiguous in memory: on 801 x 201 nodes a rough sweep took 7.4 instead of
    10 ms (median of 9).
    """

    def __set_name__(self, owner, name):
        self.name = "_" + name

    def __get__(self, obj, objtype=None):
        return self if obj is None else getattr(obj, self.name)

    def __set__(self, obj, value):
        setattr(obj, self.name, np.asfortranarray(value))


class EHLState:
    """Dimensionless state of an EHL solve on one grid (see :mod:`asperity.ehl.problem`).

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact.
    x, y : ndarray
        Node (cell-centre) coordinates, m; ``y = [0.]`` for a line contact.
    near : int
        Number K of pressure coefficients ``f_{k,0}``, ``1 <= |k| <= K``, kept implicit along x
        by the line relaxation (0: only the centre coefficient, the seed's point update).

    Attributes
    ----------
    P, H : ndarray
        Dimensionless pressure and film, indexed ``[ix, iy]`` and stored x-fastest (like
        ``kind``, ``rhs_t`` and ``efar``: assigned arrays are converted to Fortran order).
    H0 : float
        Dimensionless rigid separation.
    kind : ndarray of int8
        Active set: 0 fluid, 1 cavitated, 2 contact.
    theta, mass, rhs_t
        Time-scheme weight, ``lam/dT`` and the explicit part of the time-discrete Reynolds
        equation; ``1, 0, 0`` for a steady solve.
    damping : float
        Factor on the change of P and H at nodes that oscillate from sweep to sweep
        (:meth:`sweep`); 1 switches it off.
    relaxation : float
        Factor on the change of P and H at every node (under-relaxation, :meth:`sweep`); 1
        (default) switches it off.
    density_newton : bool
        Whether the x-line relaxation takes the density's Newton term (:meth:`_sweep`);
        on by default, off in the transient solver.
    y_lines : bool
        Whether a line sweep is followed by a y-line sweep
        (:func:`asperity.ehl.kernels.column_sweep`, at the same flow factors); off by
        default (:data:`Y_LINES_BELOW`).
    """

    P = _XFastest()
    H = _XFastest()
    kind = _XFastest()
    rhs_t = _XFastest()
    efar = _XFastest()

    def __init__(self, problem, x, y, near: int = 0):
        self.problem = problem
        self.line = isinstance(problem, LineContact)
        self.x = np.asarray(x, dtype=float)
        self.y = np.asarray(y, dtype=float)
        a = problem.a
        self.X = self.x / a
        self.Y = self.y / a
        self.dX = grid_spacing(self.x, "x") / a
        self.dY = 1.0 if self.line else grid_spacing(self.y, "y") / a
        shape = (self.X.size, self.Y.size)
        self.c = problem.elastic_factor
        self.lam = problem.lam
        # Convolution with the dimensionless film kernel D; its far-field sum f * P is the
        # 5-point Laplacian of D * P (f is defined as the discrete Laplacian of D), see refresh
        if self.line:
            self._d_conv = Convolution.from_coefficients(
                lambda X, Y: strip_integral(X, self.dX), self.dX, 1.0, shape, False
            )
            self.f_near = line_differential_coefficients(np.arange(near + 1) * self.dX, self.dX)
        else:
            self._d_conv = Convolution.from_coefficients(
                lambda X, Y: love_integral(X, Y, self.dX, self.dY), self.dX, self.dY, shape, False
            )
            self.f_near = differential_coefficients(
                np.arange(near + 1) * self.dX, 0.0, self.dX, self.dY
            )
        Xg, Yg = np.meshgrid(self.X, self.Y, indexing="ij")
        ry_ratio = 0.0 if self.line else problem.rx / problem.ry
        self.geometry = 0.5 * Xg**2 + 0.5 * ry_ratio * Yg**2
        self.roughness = np.zeros(shape)
        self.P = np.zeros(shape)
        self.H = np.zeros(shape)
        self.H0 = 0.0
        self.kind = np.zeros(shape, dtype=np.int8)
        self.theta = 1.0
        self.mass = 0.0
        self.rhs_t = np.zeros(shape)
        self.efar = np.zeros(shape)
        self.refreshes = 0
        self.damping = 1.0
        self.relaxation = 1.0
        self.density_newton = True
        self.y_lines = False
        self._p_before = np.empty(shape, order="F")
        self._h_before = np.empty(shape, order="F")
        self._last_change = np.zeros(shape, order="F")
        self._has_change = False
        self.lag_derivatives = True
        self._derivatives = None
        self.edge = np.zeros(shape, dtype=bool)
        self.edge[[0, -1], :] = True
        if not self.line:
            self.edge[:, [0, -1]] = True

    @property
    def film_kernel(self) -> Convolution:
        """The convolution with the dimensionless film kernel D (``W = D * P``, :meth:`refresh`)."""
        return self._d_conv

    @property
    def cell_area(self) -> float:
        """Dimensionless cell area dX dY (dX for a line contact)."""
        return self.dX if self.line else self.dX * self.dY

    def load(self) -> float:
        """Dimensionless load sum P dX dY (compare with ``problem.load_integral``)."""
        return float(self.P.sum() * self.cell_area)

    def rigid_film(self, W) -> np.ndarray:
        """H = H0 + geometry + phi + c D*P for the deflection sum ``W = D*P``."""
        return self.H0 + self.geometry + self.roughness + self.c * W

    @property
    def roughness(self) -> np.ndarray:
        """Dimensionless roughness phi / (a^2/Rx) at the nodes (zero for smooth surfaces).

        Setting it also evaluates the fixed source ``Delta_h phi + curvature`` of the
        deflection equation, once per change of the surfaces instead of at every refresh.
        """
        return self._roughness

    @roughness.setter
    def roughness(self, phi):
        self._roughness = np.asarray(phi, dtype=float)
        self._source = self.laplacian(self._roughness) + self.problem.curvature

    def laplacian(self, field) -> np.ndarray:
        """5-point Laplacian ``Delta_h`` of a nodal field (zero on the edges), x-fastest."""
        field = np.asarray(field, dtype=float)
        out = np.empty(field.shape, order="F")
        five_point_laplacian(field, self.dX**2, self.dY**2, not self.line, out)
        return out

    def refresh(self):
        """FFT refresh of the far-field sum ``efar`` and of the Dirichlet edge films.

        ``efar = Delta_h phi + curvature + c (S - sum_{|k|<=K} f_k0 P_{i+k})`` with
        ``S = f * P`` the full sum at the current pressure; the edges get
        ``H = H0 + geometry + phi + c W``, ``W = D * P`` (EHL-NOTES sec. 2). Since ``f`` is the
        5-point Laplacian of ``D`` (:mod:`asperity.elastic.differential`), ``S = Delta_h W``
        exactly at the interior nodes, where ``efar`` is used: a refresh costs one forward and
        one inverse FFT and one compiled pass over the nodes
        (:func:`asperity.ehl.kernels.far_field`, into ``efar`` in place).
        """
        W = np.asfortranarray(self._d_conv(self.P))
        far_field(W, self.P, self._source, self.c, self.f_near, self.dX**2, self.dY**2,
                  not self.line, self.efar)
        edge = self.edge  # the film at the edge nodes only (0.11 against 0.27 ms, 801 x 201)
        self.H[edge] = self.H0 + self.geometry[edge] + self.roughness[edge] + self.c * W[edge]
        self.refreshes += 1
        self._derivatives = None

    def film_from_pressure(self) -> np.ndarray:
        """The integral film H0 + geometry + phi + c D*P (for checks and initial guesses)."""
        return self.rigid_film(self._d_conv(self.P))

    def shift_separation(self, delta: float):
        """Add ``delta`` to H0 and to the film at every node (Delta_h const = 0)."""
        self.H0 += delta
        self.H += delta

    def flow_coefficients(self, slopes: bool = False):
        """Dimensionless (eps_x, eps_y, rho_bar) at the current (P, H), lagged in a sweep;
        with ``slopes`` also (d eps_x/dP, d eps_y/dP) at constant H and d rho_bar/dP (analytic,
        :meth:`asperity.ehl.lubricant.Lubricant.flow_field`, which takes the dimensionless
        fields and scales its results in its one pass over the nodes)."""
        prob = self.problem
        return prob.lubricant.flow_field(self.P, self.H, prob.sliding_speed, slopes=slopes,
                                         units=self.flow_units, density_slope=slopes)

    @property
    def flow_units(self) -> tuple[float, float, float]:
        """The ``units`` of :meth:`Lubricant.flow_field` for the dimensionless fields: the
        Hertz pressure, the film scale ``a^2/Rx`` and ``12 eta0 Rx^3 / a^6`` on the flow
        factors (which makes them the dimensionless ``eps``)."""
        prob = self.problem
        return (prob.p_hertz, prob.film_scale,
                12.0 * prob.lubricant.viscosity * prob.rx**3 / prob.a**6)

    def sweep(self, method: str):
        """One relaxation sweep (``"point"`` or ``"line"``); returns max |dP|, max |dH|.

        Oscillation damping: at nodes where this sweep changes P with the opposite sign to the
        previous sweep (a node alternating between two states, e.g. cavitated and fluid, or two
        values of its lagged flow factor ``eps(p, h)`` that drive its neighbours), the changes
        of P and H are scaled by ``damping``; with ``relaxation`` < 1 the changes at every node
        are scaled by it as well (under-relaxation). The fixed point is unchanged; the returned
        changes are the sweep's own, before either factor. :meth:`start_iteration` forgets the
        previous change.
        """
        if self.damping >= 1.0 and self.relaxation >= 1.0:
            return self._sweep(method)
        np.copyto(self._p_before, self.P)
        np.copyto(self._h_before, self.H)
        dp, dh = self._sweep(method)
        damp_oscillations(self.P, self.H, self._p_before, self._h_before, self._last_change,
                          self.damping, self._has_change, self.relaxation)
        self._has_change = True
        return dp, dh

    def start_iteration(self):
        """Forget the previous sweep's change (call when the problem changes, e.g. a new step)."""
        self._has_change = False

    def _sweep(self, method: str):
        """The compiled sweep of :mod:`asperity.ehl.kernels` at the current flow factors.

        The Newton terms of the flow factors (:func:`asperity.ehl.kernels._newton`) and, in
        the x-line relaxation, of the density (:func:`asperity.ehl.kernels._density_newton`)
        only stabilise the update, which is unchanged at the fixed point, so while
        ``lag_derivatives`` is set their derivatives are evaluated once per far-field refresh
        (fewer sweeps as well as cheaper ones on rough surfaces); otherwise at every sweep
        (more robust where a node keeps changing state). The density's term matters for a
        compressible oil and a thick film (the lagged density's factor of
        :class:`LineContactState`, which gives the point update of a line contact its own
        form of the term): without it the ball bearing and the circular contact at M = 1000,
        L = 19 of docs/ehl-robustness.md ("Compressible point contacts and long ellipses at
        large L") diverged.
        """
        if self._derivatives is None or not self.lag_derivatives:
            ex, ey, rho, *self._derivatives = self.flow_coefficients(slopes=True)
        else:
            ex, ey, rho = self.flow_coefficients()
        dex, dey, drho = self._derivatives
        if method == "point":
            return point_sweep(
                self.P, self.H, ex, ey, rho, self.efar, self.rhs_t, self.lam, self.dX, self.dY,
                self.theta, self.mass, self.c, self.f_near, dex, dey,
            )
        dp, dh = line_sweep(
            self.P, self.H, ex, ey, rho, self.efar, self.rhs_t, self.lam, self.dX, self.dY,
            self.theta, self.mass, self.c, self.f_near, self.kind, dex, dey,
            drho if self.density_newton else None,
        )
        if self.y_lines:
            dpy, dhy = column_sweep(
                self.P, self.H, ex, ey, rho, self.efar, self.rhs_t, self.lam, self.dX, self.dY,
                self.theta, self.mass, self.c, self.f_near, self.kind, dex, dey)
            dp, dh = max(dp, dpy), max(dh, dhy)
        return dp, dh

    def hertz_start(self, film: float):
        """Hertzian pressure and the film it deflects to, with central film ``film`` (dimless)."""
        prob = self.problem
        Xg, Yg = np.meshgrid(self.X, self.Y, indexing="ij")
        r2 = Xg**2 if self.line else Xg**2 + (Yg * prob.a / prob.b) ** 2
        self.P = np.sqrt(np.clip(1.0 - r2, 0.0, None))
        self.P[self.edge] = 0.0
        self.H0 = 0.0
        H = self.film_from_pressure()
        self.H0 = film - _at_centre(self, H)
        self.H = H + self.H0
        self.kind[:] = 0
        self.kind[self.P <= 0] = 1

    def interpolate_from(self, coarse: EHLState):
        """Initial guess by (bi)linear interpolation of a coarser solution."""
        self.H0 = coarse.H0
        if self.line:
            self.P = np.interp(self.X, coarse.X, coarse.P[:, 0])[:, None]
            self.H = np.interp(self.X, coarse.X, coarse.H[:, 0])[:, None]
        else:
            self.P = _bilinear(coarse.X, coarse.Y, coarse.P, self.X, self.Y)
            self.H = _bilinear(coarse.X, coarse.Y, coarse.H, self.X, self.Y)
        self.P[self.edge] = 0.0
        self.kind[:] = 0
        self.kind[self.P <= 0] = 1


class LineContactState(EHLState):
    """A line contact's point update with the density's pressure derivative.

    :meth:`EHLState.sweep` evaluates the density ``rho(p)`` once per sweep, so the point
    update solves the Reynolds row for ``h`` at a lagged density. Where the Couette flow
    dominates (the Hertz zone) that row fixes ``rho h``: a pressure change ``dp`` changes the
    next sweep's film by ``-h rho' dp / rho``, and the deflection row turns a film change
    ``dh`` into a pressure change ``(|D0| / C0) dh`` (``D0 = -2/dX^2``, ``C0 = -c f_00 ~ 1/dX``).
    The lag is an iteration with the factor ``-G f``, ``G = h rho' |D0| / (rho C0)`` per
    node and ``f = |B0| / (|B0| + |A0| |D0| / C0)`` the Couette share of the nodal update
    (``A0``, ``B0`` of :mod:`asperity.ehl.kernels`); ``G`` grows like ``h / dX``. For a
    compressible oil and a thick film (large Moes L) ``G f`` passes 1 where the pressure
    rises into the Hertz zone and the pressure there oscillates from sweep to sweep without
    bound: the roller of docs/ehl-robustness.md ("Compressible line contacts at large L",
    M = 20, L = 18) has at most 0.8, 1.4, 2.4, 5.2 on 71, 141, 281, 801 nodes and diverged
    from 141 nodes on; the seed's line contact (L = 6.9, Eyring) at most 0.27.

    Here the Couette flux is linearised in the pressure, ``rho(p) h ~ rho* h + h* rho' dp``,
    with the node's own deflection row ``dp = (|D0| / C0) dh`` (a Newton step in the nodal
    update): ``rho(p) h ~ (rho* + s) h - s h*``, ``s = h* rho' |D0| / C0``, where ``*``
    marks the values at the start of the sweep (``rho'`` analytic, from
    :meth:`~asperity.ehl.lubricant.Lubricant.flow_field`). The compiled sweep
    (:func:`asperity.ehl.kernels.point_sweep`) receives ``rho* + s`` as the density, and the
    explicit term ``rhs_t`` receives what ``s h*`` contributes to the wedge and time terms,
    ``theta lam U(s h*) / dX + mass s h*`` (``U`` the upwind difference,
    :func:`~asperity.ehl.nodal.upwind_difference`), so that the two cancel when ``h = h*``:
    the converged solution is that of :class:`EHLState`, steady (``theta = 1``,
    ``mass = 0``) or a timestep. An incompressible oil has ``s = 0`` and the same update;
    with ``density_newton`` off the density is lagged as in :class:`EHLState`. The transient
    stepper keeps it off unless a step fails without it
    (:meth:`asperity.ehl.stepper.TimeStepper.advance`): a lightly loaded roller (M = 5.3,
    L = 21) went from its steady solution to a pressure oscillating by 2-3 p_h at step 5
    with the density lagged, and converges with the term.
    """

    def _sweep(self, method: str):
        if method != "point" or not self.density_newton:
            return super()._sweep(method)
        # rho' at the current pressure (the flow factors' slopes stay lagged as in EHLState)
        ex, ey, rho, *slopes = self.flow_coefficients(slopes=True)
        if self._derivatives is None or not self.lag_derivatives:
            self._derivatives = slopes
        dex, dey, _ = self._derivatives
        stiff = (2.0 / self.dX**2) / (-self.c * self.f_near[0])
        s = slopes[2] * self.H * stiff
        s[self.P <= 0.0] = 0.0
        rhs_t = (self.rhs_t + self.theta * self.lam / self.dX * upwind_difference(s * self.H)
                 + self.mass * s * self.H)
        return point_sweep(
            self.P, self.H, ex, ey, np.asfortranarray(rho + s), self.efar,
            np.asfortranarray(rhs_t), self.lam, self.dX, self.dY, self.theta, self.mass,
            self.c, self.f_near, dex, dey,
        )


def _bilinear(xc, yc, field, x, y):
    """Bilinear interpolation of ``field[ix, iy]`` from grid (xc, yc) onto (x, y)."""
    tmp = np.array([np.interp(x, xc, field[:, j]) for j in range(field.shape[1])]).T
    return np.array([np.interp(y, yc, tmp[i]) for i in range(tmp.shape[0])])


@dataclass(frozen=True, repr=False)
class SteadyResult(SolverResult):
    """Steady EHL solution, SI units.

    The result protocol of :class:`asperity.solution.SolverResult`: ``converged``,
    ``iterations`` (the sweeps on the finest grid), ``residual``, ``message``, ``warnings``
    (a starved inlet, no convergence), ``to_dataset()``.

    Attributes
    ----------
    x, y : ndarray
        Node coordinates, m (``y = [0.]`` for a line contact).
    pressure, film : ndarray
        p (Pa) and h (m), indexed ``[ix, iy]``.
    central_film : float
        h at the Hertz centre (0, 0), m.
    minimum_film_centreline : float
        Minimum of h along y = 0, m.
    minimum_film : float
        Minimum of h over the whole domain (the side lobes of a point contact), m.
    max_pressure : float
        Pa.
    load_error : float
        (computed load - applied load) / applied load.
    friction_coefficient : float
        Traction on surface 1 over load: Eyring mean shear plus the Poiseuille term, with a
        boundary-friction coefficient on dry nodes (:func:`asperity.ehl.friction_coefficient`).
    separation : float
        Rigid separation h0 (may be negative), m.
    sweeps, fft_refreshes : int
        Relaxation sweeps and far-field FFT refreshes on the finest grid; ``total_sweeps``
        over all grids.
    converged : bool
        Whether pressure change, film change (relative to the larger of the central and the
        mean edge film) and load error all fell below the tolerance.
    residual : float
        Final convergence measure (the largest of the three, relative).
    history : ndarray
        Rows (sweep, max |dP|, max |dH|/H_ref, load error) at every refresh on the finest grid,
        ``H_ref`` the larger of the central and the mean edge film.
    levels : tuple
        Node counts (nx, ny) of the grids solved, coarse to fine.
    method : str
        Relaxation used (``"line"`` or ``"point"``).
    y_lines : bool
        Whether every x-line sweep was followed by a y-line sweep (the fallback of
        :data:`Y_LINES_BELOW`).
    soft_retry : bool
        Whether the finest grid is that of the soft point contact's fallback (a refresh
        every :data:`SOFT_RETRY_REFRESH` sweeps, a gain of :data:`SOFT_GAIN_PER_FILM`
        ``H_c``).
    inlet_pressure : float
        Largest pressure 0.1 a downstream of the inlet boundary, over p_hertz; above
        ``STARVED_INLET`` (0.01) the domain starts inside the pressure build-up, the p = 0
        boundary starves the film and :func:`solve_steady` warns.
    """

    x: np.ndarray
    y: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    central_film: float
    minimum_film: float
    minimum_film_centreline: float
    max_pressure: float
    load_error: float
    friction_coefficient: float
    separation: float
    sweeps: int
    total_sweeps: int
    fft_refreshes: int
    converged: bool
    residual: float
    history: np.ndarray
    levels: tuple
    method: str
    inlet_pressure: float
    y_lines: bool = False
    soft_retry: bool = False

    VARIABLES = {"pressure": ("Pa", "film pressure"), "film": ("m", "film thickness")}

    @property
    def iterations(self) -> int:
        """Relaxation sweeps on the finest grid (``sweeps``)."""
        return self.sweeps

    @property
    def warnings(self) -> tuple[str, ...]:
        """A starved inlet (``inlet_pressure`` above ``STARVED_INLET``) and no convergence."""
        out = list(SolverResult.warnings.fget(self))
        if self.inlet_pressure > STARVED_INLET:
            out.append(f"the inlet lies inside the pressure build-up (pressure 0.1 a downstream "
                       f"of it {self.inlet_pressure:.1%} of the Hertz pressure): the film is "
                       "starved; start the domain further upstream")
        return tuple(out)

    def centre_line(self):
        """(x, p, h) along y = 0 (interpolated between rows), SI."""
        if self.y.size == 1:
            return self.x, self.pressure[:, 0], self.film[:, 0]
        p = np.array([np.interp(0.0, self.y, row) for row in self.pressure])
        h = np.array([np.interp(0.0, self.y, row) for row in self.film])
        return self.x, p, h


def _film_scale(state) -> float:
    """Fixed film scale of the convergence test: the larger of H_c and the mean edge film.

    Dividing max |dH| by the central film alone blows up in the dry limit (H_c -> 0) although
    p, h and the load have converged; the edge films stay of the order of the rigid gap.
    """
    return max(_at_centre(state, state.H), float(np.mean(state.H[state.edge])), 1e-12)


def _relax(state, method, *, tol, max_sweeps, refresh, gain, callback, sweep_offset=0,
           tangent=None, load_factor=1.0, stall_refresh=None, give_up=False, blow_up=False):
    """Relax one grid to convergence in at most ``max_sweeps`` sweeps; return (converged,
    residual, sweeps, history).

    The residual is tested at every far-field refresh, ``refresh`` sweeps apart; the cycle
    that reaches ``max_sweeps`` ends there (a limit of 3 or 5 used to run a whole cycle and
    report 10 sweeps).
    The load target is ``load_factor`` times the problem's. Without ``tangent`` the
    separation is shifted by ``gain`` times the relative load error after every sweep; with
    a :class:`LoadTangent` the state is moved along it to remove the load error before every
    far-field refresh instead.

    With ``stall_refresh`` (default: the x-line relaxation, ``method="line"``) a relaxation
    that stalls (the residual at the end of a refresh cycle above ``STALL_RATIO`` times its
    value ``STALL_CYCLES`` cycles before) refreshes the far field twice as often from then
    on: with the far field lagged over 10 sweeps a thick, low-L film (circle, M = 10, L = 3)
    kept swinging at residual 0.16, and converged with a refresh every 5
    (docs/ehl-robustness.md). Relaxations that converge steadily never stall by this test,
    so they keep ``refresh``. :func:`_sequence` also sets it for the tangent-steered grids of
    a line contact's fallback sequence (``tangents_from="every_grid"``): a cam contact on a
    short domain (-1.5a..1.5a, 101-201 nodes) swung there at residual 0.15 with a refresh
    every 10 sweeps and converged with one every 3 or 1 (docs/ehl-robustness.md,
    "Line contacts on a short domain").

    With ``give_up`` the relaxation stops unconverged once no residual has fallen below
    ``STALL_RATIO`` times the last one that did for ``STUCK_SWEEPS`` sweeps
    (:data:`STUCK_SWEEPS`). With ``blow_up`` it stops unconverged once a residual exceeds
    :data:`TANGENT_BLOWUP` times the least one so far.
    """
    target = state.problem.load_integral * load_factor
    if stall_refresh is None:
        stall_refresh = method == "line"
    state.start_iteration()
    cycle_residuals = []
    anchor, anchor_sweeps = np.inf, 0  # the last residual 10 % below the one before it
    history = []
    residual = np.inf
    sweeps = 0
    load_err = 0.0
    while sweeps < max_sweeps:
        if tangent is not None and sweeps:
            tangent.correct(state, load_err)
        state.refresh()
        for _ in range(min(refresh, max_sweeps - sweeps)):  # the limit counts sweeps
            dp, dh = state.sweep(method)
            sweeps += 1
            load_err = (state.load() - target) / target
            if tangent is None:
                state.shift_separation(gain * load_err)
        hc = _film_scale(state)
        residual = max(dp, dh / hc, abs(load_err))
        history.append((sweeps, dp, dh / hc, load_err))
        if callback is not None:
            callback(sweep_offset + sweeps, residual)
        if not np.all(np.isfinite(state.P)) or not np.all(np.isfinite(state.H)):
            return False, np.inf, sweeps, history
        if residual < tol:
            state.refresh()
            return True, residual, sweeps, history
        if blow_up and cycle_residuals and residual > TANGENT_BLOWUP * min(cycle_residuals):
            break
        cycle_residuals.append(residual)
        if residual < STALL_RATIO * anchor:
            anchor, anchor_sweeps = residual, sweeps
        if give_up and sweeps - anchor_sweeps >= STUCK_SWEEPS:
            break
        if stall_refresh and refresh > 1 and len(cycle_residuals) > STALL_CYCLES \
                and residual > STALL_RATIO * cycle_residuals[-1 - STALL_CYCLES]:
            refresh = max(1, refresh // 2)
            cycle_residuals.clear()
    state.refresh()
    return False, residual, sweeps, history


class LoadTangent:
    """Change of a steady solution (line or point contact) per relative change of the load,
    on a grid.

    ``(dP, dH, dH0) = (s1 - s0) / STEP`` between the converged states ``s0`` at the load and
    ``s1`` at ``1 + STEP`` times the load (:meth:`between`). :meth:`correct` moves a state on
    a finer grid along it: the load changes at once by the wanted amount, and the film in
    the Hertz zone, the pressure shape and the separation change together as they do between
    the two solutions, whereas a shift of the separation alone leaves the pressure to relax
    in from the inlet over many sweeps (docs/ehl-robustness.md, "Line contacts on fine
    meshes").

    With the default gain a point contact's grid with more nodes than its default mesh,
    sequenced from a converged coarser grid, is steered by that grid's tangent too
    (:func:`solve_steady`, ``point_tangent``). The seed's circle (a/b = 1, M = 174) on
    801 x 201 took 779 sweeps on the finest grid (13 s) against 6271 (100 s) with the
    scaled gain; the seed's gear case on 801 x 201 160 against 500; a user's ball on glass
    at M = 611 on 433 x 145, which cycled with the gain, converged (docs/ehl-robustness.md,
    "A thin film on fine meshes"). The default mesh and coarser grids keep the gain: a
    tangent costs a second solve of the grid below.
    """

    #: Relative load step of the difference.
    STEP = 0.01
    #: Residual (:func:`_relax`) below which the solution at ``1 + STEP`` times the load is
    #: good enough for the tangent when it does not reach the solve's ``tol``: the tangent
    #: only steers the load correction (the fixed point is that of the Reynolds and
    #: deflection equations whatever the tangent); ``STEP / 100`` is 1 % of the load step
    #: the difference resolves (a bound on the sweep's changes, not a measured error of the
    #: quotient). The Roelands + Dowson-Higginson line
    #: contact at M = 100, L = 3 ended that solve on 513 nodes at 1.1e-5 (tol 1e-5) after
    #: 5000 sweeps; without a tangent its default mesh (1025 nodes) took the gain 0.01 and
    #: cycled (residual 0.87), with it it converged in 1270 sweeps (docs/ehl-robustness.md).
    RESIDUAL = 1e-2 * STEP

    def __init__(self, X, Y, dP, dH, dH0):
        self.X, self.Y, self.dP, self.dH, self.dH0 = X, Y, dP, dH, dH0
        self._on_grid = None  # (X, Y, dP, dH) of the last finer grid, interpolated once

    @classmethod
    def between(cls, s0, s1):
        """The tangent from the converged states ``s0`` and ``s1`` (loads 1 and 1 + STEP)."""
        return cls(s0.X.copy(), s0.Y.copy(), (s1.P - s0.P) / cls.STEP,
                   (s1.H - s0.H) / cls.STEP, (s1.H0 - s0.H0) / cls.STEP)

    def correct(self, state, load_error):
        """Move ``state`` by ``-load_error`` along the tangent, interpolated (bi)linearly onto
        its grid with the pressure part scaled to carry exactly the relative load (P >= 0
        kept). The interpolation is done once per grid: a relaxation calls this before
        every far-field refresh."""
        dP, dH = self._interpolated(state)
        state.P = np.maximum(state.P - load_error * dP, 0.0)
        state.H = state.H - load_error * dH
        state.H0 -= load_error * self.dH0

    def _interpolated(self, state):
        """``(dP, dH)`` on the grid of ``state``, ``dP`` scaled to carry the problem's load."""
        cached = self._on_grid
        if cached is not None and cached[0] is state.X and cached[1] is state.Y:
            return cached[2], cached[3]
        if state.line:
            dP = np.interp(state.X, self.X, self.dP[:, 0])[:, None]
            dH = np.interp(state.X, self.X, self.dH[:, 0])[:, None]
        else:
            dP = _bilinear(self.X, self.Y, self.dP, state.X, state.Y)
            dH = _bilinear(self.X, self.Y, self.dH, state.X, state.Y)
        dP *= state.problem.load_integral / (dP.sum() * state.cell_area)
        self._on_grid = (state.X, state.Y, dP, dH)
        return dP, dH


@renamed_keywords(max_sweeps="max_iter")
def solve_steady(
    problem,
    *,
    nx: int | None = None,
    ny: int | None = None,
    domain=None,
    method: str | None = None,
    levels: int | None = None,
    near: int = 4,
    tol: float = 1e-5,
    max_iter: int = 5000,
    refresh: int | None = None,
    load_gain: float | None = None,
    initial_film: float | None = None,
    boundary_friction: float = 0.1,
    damping: float = 1.0,
    point_tangent: bool = True,
    callback=None,
) -> SteadyResult:
    """Steady smooth EHL solution of a point or line contact.

    Parameters
    ----------
    problem : PointContact or LineContact
        The contact (SI).
    nx, ny : int, optional
        Nodes along x and y on the finest grid (``ny`` is ignored for a line contact); the
        seed's mesh is 801 x 201 on its domain. Default ``problem.default_nodes(domain)``:
        dX from the estimated film (a discretisation error of the central film near 2 %),
        ``dY >= 3 dX`` (docs/ehl-robustness.md).
    domain : ((x0, x1), (y0, y1)), optional
        In m; default ``problem.default_domain()``: the seed's -2.5a..1.5a, -2b..2b, with the
        inlet moved upstream where Hamrock & Dowson's fully flooded inlet distance asks for
        it (thick films, low M) and the sides moved out with it. Must hold the Hertz contact.
    method : {"line", "point"}, optional
        x-line relaxation or the seed's point update (Eq. 7). Default: ``"line"`` for a point
        contact, ``"point"`` for a line contact (x-line relaxation of the single row of a line
        contact diverges: every off-centre pressure coefficient is then lagged at once).
        A line contact's point update that ends a grid unconverged is followed by Newton on
        the same discrete equations (up to 2049 nodes), and its finest grid's converged
        relaxation is polished by up to :data:`POLISH_STEPS` Newton steps
        (:mod:`asperity.ehl.line_newton`, :func:`_relax_line_or_newton`).
        A point contact whose x-line relaxation ends unconverged on cells with ``dY < 3 dX``
        is solved again with a y-line sweep after every x-line sweep
        (:data:`Y_LINES_BELOW`; ``y_lines`` of the result). A soft point contact
        (:attr:`PointContact.soft`) whose finest grid still ends unconverged with the
        default ``refresh`` and ``load_gain`` is relaxed again from the coarser grid's
        solution with a refresh every sweep and a gain of :data:`SOFT_GAIN_PER_FILM` ``H_c``
        (:func:`_soft_retry`; ``soft_retry`` of the result).
    levels : int, optional
        Grid sequencing: solve first on ``levels - 1`` grids coarsened by 2 in each direction
        (node counts ``(n - 1)/2 + 1``) and interpolate each solution as the next start.
        Default: :func:`sequencing_levels` of the mesh, ``(nx, ny)`` (the default mesh where
        they are not given; ``(nx, 1)`` for a line contact). Needed on fine meshes: a grid
        with more nodes than the default mesh takes its load steering from the converged
        grid below it (see ``load_gain``); a user's ball on glass on 865 x 289 nodes, solved
        on that one grid (the default before session 42 where ``nx`` was given), cycled for
        5000 sweeps (docs/ehl-robustness.md, "A thin film on fine meshes").
    near : int
        Number of x-neighbour pressure coefficients kept implicit by the line relaxation.
    tol : float
        Convergence when max |dP| per sweep, max |dH| / H_ref (H_ref the larger of the central
        and the mean edge film) and the relative load error are
        all below ``tol`` at a far-field refresh.
    max_iter : int
        Sweep limit per grid (the sweeps run, also within a refresh cycle); a solve whose
        finest grid reaches it returns ``converged=False``. A line contact's grid solved by
        Newton after its relaxation (see ``method``) checks that solution by a second
        relaxation of at most ``min(max_iter, NEWTON_CHECK_SWEEPS)`` sweeps, counted in its
        ``sweeps`` too: up to twice the limit (the old spelling ``max_sweeps`` is accepted with a
        DeprecationWarning). A point contact's coarser grids stop at
        ``min(max_iter, COARSE_SWEEPS)``, converged or not: they only give the next grid
        its start (:data:`COARSE_SWEEPS`).
    refresh : int, optional
        Sweeps between FFT refreshes of the far field and the edge films; default 10. With
        the default, a line contact's point update whose grid sequences both end
        unconverged (see ``load_gain``) is solved a last time with a refresh every
        :data:`LINE_RETRY_REFRESH` sweeps (Eyring line contacts at low sliding); a given
        value is used throughout.
    load_gain : float, optional
        Separation shift per sweep per unit relative load error (dimensionless film units);
        default the problem's own, ``problem.load_gain()``: ``0.05 H_c`` on every grid for a
        rigid point contact (:meth:`PointContact.load_gain`), else None, and then
        0.05 (point contact), 0.01 (line contact) on grids coarser than the default
        mesh. With the default, a line contact's grids from the default mesh on (when
        sequenced from a converged coarser grid) use no gain: before each far-field refresh
        the state is moved along the :class:`LoadTangent` of the next coarser grid (its
        solutions at the load and 1 % above, the latter converged or at a residual below
        :attr:`LoadTangent.RESIDUAL`) to remove the load error; without one, a grid
        finer than the default mesh gets ``0.01 (dX / dX_default)^3.5``
        (:data:`LINE_GAIN_EXPONENT`: the point update's load answers a shift of the
        separation the more slowly the finer the mesh, and a larger gain overshoots). When
        that sequence ends unconverged (a grid of it whose best residual has stopped falling
        for :data:`STUCK_SWEEPS` sweeps ends it early) it is solved again with every
        converged grid's tangent steering the next (line contacts at L = 2), refreshing the
        far field more often where a grid stalls. A point contact's grid with more nodes
        than the default mesh is steered by the tangent of the converged grid below it in
        the same way (see ``point_tangent``); without one, a grid finer than
        the default mesh gets ``0.05 (dX / dX_default)`` (:data:`POINT_GAIN_EXPONENT`).
        A given value is used on every grid, without the tangent.
    initial_film : float, optional
        Central film of the Hertzian start, m; default Nijenbanning's (point) or Moes' (line)
        Newtonian central film.
    boundary_friction : float
        Friction coefficient assumed where h = 0 (dry nodes).
    damping : float
        Factor 0 < damping <= 1 on the change of P and H at nodes whose change alternates in
        sign from sweep to sweep (:meth:`EHLState.sweep`); 1 (default) switches it off.
    point_tangent : bool
        With the default ``load_gain``, steer a point contact's grids with more nodes than
        the default mesh by the :class:`LoadTangent` of the converged grid below (a line
        contact's always are). False: the per-sweep gain on every grid, as before session
        42; the transient runs' steady start keeps it (:func:`asperity.ehl.smooth_start.
        smooth_start`), since their measured results and fallbacks rest on that start and a
        run of minutes would gain seconds.
    callback : callable, optional
        ``callback(iteration, residual)`` after every refresh.

    Returns
    -------
    SteadyResult
    """
    line, method = check_contact_and_method(problem, method)
    if load_gain is None:
        load_gain = problem.load_gain()
    scale_gain = load_gain is None
    if load_gain is None:
        load_gain = LINE_LOAD_GAIN if line else POINT_LOAD_GAIN
    tol = check_positive("tol", tol)
    load_gain = check_positive("load_gain", load_gain)
    damping = check_damping(damping)
    default_nx, default_ny = problem.default_nodes(domain)
    if levels is None:
        if nx is None:
            levels = sequencing_levels(default_nx, default_ny)
        else:
            nx = check_int("nx", nx, 9, "an integer number of nodes >= 9")
            ny = 1 if line else check_int("ny", default_ny if ny is None else ny, 9,
                                          "an integer number of nodes >= 9")
            levels = sequencing_levels(nx, ny)
    nx = default_nx if nx is None else nx
    ny = default_ny if ny is None else ny
    levels = check_int("levels", levels, 1)
    max_iter = check_int("max_iter", max_iter, 1)
    default_refresh = refresh is None
    refresh = check_int("refresh", 10 if refresh is None else refresh, 1)
    near = check_int("near", near, 0)
    if line:
        ny = 1
    grids = _grid_sequence(nx, ny, levels, line)
    if initial_film is None:
        h_start = problem.film_estimate() / problem.film_scale
    else:
        h_start = check_positive("initial_film", initial_film) / problem.film_scale
    k_near = near if method == "line" else 0
    settings = dict(method=method, tol=tol, max_iter=max_iter, refresh=refresh,
                    load_gain=load_gain, damping=damping, callback=callback,
                    scale_gain=scale_gain, default_nx=default_nx, default_ny=default_ny,
                    near=k_near, h_start=h_start)
    use_tangent = scale_gain and (method == "point" if line else bool(point_tangent))
    run = _sequence(problem, grids, domain,
                    tangents_from="below_default" if use_tangent else None, **settings)
    total = run.total
    if use_tangent and line and not run.converged:
        # the point update's load loop stalled or cycled: a line contact at low L (M 20 to
        # 1000, L = 2) converges with the tangent of every converged grid steering the next
        # one; on rows that converge without it (M = 50, L = 20) it can stall, so it is the
        # fallback (docs/ehl-robustness.md, "Line contacts at L = 2")
        retry = _sequence(problem, grids, domain, tangents_from="every_grid", **settings)
        total += retry.total
        if retry.converged or retry.residual < run.residual:
            run = retry
    if use_tangent and not line and _blew_up(run):
        # a point contact's grid steered by the tangent grew unstable (a bearing contact whose
        # side lobes sit on their floor, :data:`TANGENT_BLOWUP`): the load gain instead
        retry = _sequence(problem, grids, domain, tangents_from=None, **settings)
        total += retry.total
        if retry.converged or retry.residual < run.residual:
            run = retry
    if use_tangent and line and not run.converged and default_refresh \
            and refresh > LINE_RETRY_REFRESH:
        # an Eyring oil at low sliding (roller, M = 36.8, L = 15.9, tau0 = 5-20 MPa,
        # slide/roll 0.05): the Hertz zone's Poiseuille term weighs as much as the wedge and
        # the cycle of 10 sweeps at a lagged far field grows an oscillation at the outlet;
        # a refresh every 3 sweeps converges (docs/ehl-robustness.md, "Not in the table")
        retry = _sequence(problem, grids, domain, tangents_from="below_default",
                          **{**settings, "refresh": LINE_RETRY_REFRESH})
        total += retry.total
        if retry.converged or retry.residual < run.residual:
            run = retry
    if not run.converged and not line and method == "line" and not run.state.y_lines \
            and run.state.dY < Y_LINES_BELOW * run.state.dX:
        retry = _sequence(problem, grids, domain, tangents_from=None, y_lines=True, **settings)
        total += retry.total
        if retry.converged or retry.residual < run.residual:
            run = retry
    soft_retry = False
    if not run.converged and not line and method == "line" and problem.soft \
            and default_refresh and scale_gain:
        retry = _soft_retry(problem, grids, domain, run, settings)
        total += retry.total
        if retry.converged or retry.residual < run.residual:
            run, soft_retry = retry, True
    result = _result(run.state, run.converged, run.residual, run.sweeps, total, run.history,
                     grids, method, boundary_friction, soft_retry=soft_retry)
    if result.inlet_pressure > STARVED_INLET:
        warnings.warn(
            f"domain: the inlet at x = {result.x[0] / problem.a:.2f} a lies inside the pressure "
            f"build-up (the pressure 0.1 a downstream of it is {result.inlet_pressure:.1%} of "
            "the Hertz pressure), so the p = 0 inlet starves the film; expected x_min further "
            "upstream (the seed: -2.5 a)", RuntimeWarning, stacklevel=2)
    return result


def _blew_up(run) -> bool:
    """Whether the finest grid of a sequence ``run`` ended unconverged with a residual that is
    not finite or :data:`TANGENT_BLOWUP` times the least of its history (what ``blow_up`` in
    :func:`_relax` stops on); a grid that merely ran out of sweeps did not."""
    if run.converged:
        return False
    if not np.isfinite(run.residual):
        return True
    history = np.abs(np.asarray(run.history, dtype=float))
    if history.size == 0:
        return False
    least = float(np.min(np.max(history[:, 1:], axis=1)))
    return run.residual > TANGENT_BLOWUP * least


class _Sequenced(NamedTuple):
    """The finest grid of a grid sequence: its state, whether it converged, its residual,
    sweeps and residual history, the sweeps of the whole sequence (``total``) and the state
    of the grid before the finest (``coarse``; None for one grid)."""

    state: EHLState
    converged: bool
    residual: float
    sweeps: int
    total: int
    history: np.ndarray
    coarse: EHLState | None = None


def _sequence(problem, grids, domain, *, method, tol, max_iter, refresh, load_gain, damping,
              callback, scale_gain, default_nx, default_ny, near, h_start, tangents_from,
              y_lines=False, start=None, finest=None) -> _Sequenced:
    """Solve the grids of a sequence coarse to fine, each from the last one's solution
    (with ``y_lines``, :attr:`EHLState.y_lines` on every grid).

    ``start``: a coarser grid's state to interpolate the first grid's start from (else
    the Hertzian start). ``finest``: ``(refresh, gain)`` of the finest grid, instead of
    ``refresh`` and the (scaled) ``load_gain`` (:func:`_soft_retry`).

    ``tangents_from``: which converged grids also solve at 1 % more load for the
    :class:`LoadTangent` that steers the next grid's load: ``"below_default"`` the grids
    whose next grid is the default mesh or finer, ``"every_grid"`` all, None none.
    """
    line = isinstance(problem, LineContact)
    state, coarse = start, None
    tangent = None
    total = 0
    for level, (gx, gy) in enumerate(grids):
        x, y = problem.grid(gx, gy, domain)
        new = (LineContactState if line else EHLState)(problem, x, y, near)
        new.damping = damping
        new.y_lines = y_lines
        if state is None:
            new.hertz_start(h_start)
        else:
            new.interpolate_from(state)
        state, coarse = new, state
        gain = load_gain
        if scale_gain and tangent is None:
            gain = _scaled_gain(gain, gx, default_nx, line)
        cycle = refresh
        if finest is not None and level + 1 == len(grids):
            cycle, gain = finest
        limit = max_iter if line or level + 1 == len(grids) else min(max_iter, COARSE_SWEEPS)
        relax = dict(tol=tol, max_sweeps=limit, refresh=cycle, gain=gain, callback=callback,
                     tangent=tangent,
                     stall_refresh=method == "line" or (tangents_from == "every_grid"
                                                        and tangent is not None),
                     give_up=line and tangents_from == "below_default",
                     blow_up=not line and tangent is not None)
        converged, residual, sweeps, history = _relax_line_or_newton(
            state, method, line, polish=level + 1 == len(grids), sweep_offset=total, **relax)
        total += sweeps
        wanted = tangents_from == "every_grid" or (
            tangents_from == "below_default" and level + 1 < len(grids)
            and (grids[level + 1][0] >= default_nx if line
                 else grids[level + 1][0] * grids[level + 1][1] > default_nx * default_ny))
        if wanted and converged and level + 1 < len(grids):
            other = (LineContactState if line else EHLState)(problem, x, y, near)
            other.damping, other.y_lines = damping, y_lines
            other.interpolate_from(state)
            # the perturbed solve by the gain alone: steered by the coarser grid's tangent
            # it would end within tol by that tangent and hand it on (line M = 1000, L = 10
            # then cycled on its finest grid)
            _, other_residual, extra, _ = _relax_line_or_newton(
                other, method, line, tol=tol, max_sweeps=max_iter, refresh=refresh, gain=gain,
                callback=None, tangent=None if tangents_from == "every_grid" else tangent,
                load_factor=1.0 + LoadTangent.STEP,
                give_up=line and tangents_from == "below_default")
            total += extra
            if other_residual < max(tol, LoadTangent.RESIDUAL):
                tangent = LoadTangent.between(state, other)
    return _Sequenced(state, converged, residual, sweeps, total, history, coarse)


def _soft_retry(problem, grids, domain, run, settings) -> _Sequenced:
    """The finest grid of a soft point contact (:attr:`PointContact.soft`) relaxed again
    from the coarser grid's solution, with a far-field refresh every
    :data:`SOFT_RETRY_REFRESH` sweeps and a separation shift of :data:`SOFT_GAIN_PER_FILM`
    times the estimated central film per unit load error.

    The coarser grid is the failed sequence's own (``run.coarse``); a solve on one grid gets
    the coarser grids of :func:`sequencing_levels` first, solved with the defaults (from the
    Hertzian start where the mesh cannot be halved). The lagged far field and the default
    gain (0.05, against a central film ``H_c`` of 0.007-0.013 in Hertzian units) each made
    the relaxation of a PDMS ball cycle on 385 x 129 nodes (docs/ehl-robustness.md,
    "A PDMS ball's minimum film across y").
    """
    nx, ny = grids[-1]
    gain = _scaled_gain(SOFT_GAIN_PER_FILM * problem.film_estimate() / problem.film_scale,
                        nx, settings["default_nx"], line=False)
    finest = (SOFT_RETRY_REFRESH, gain)
    if run.coarse is not None:
        return _sequence(problem, grids[-1:], domain, tangents_from=None, start=run.coarse,
                         finest=finest, **settings)
    sequence = _grid_sequence(nx, ny, sequencing_levels(nx, ny, min_nx=17), line=False)
    return _sequence(problem, sequence, domain, tangents_from=None, finest=finest, **settings)


def _grid_sequence(nx: int, ny: int, levels: int, line: bool) -> list[tuple[int, int]]:
    """Node counts of ``levels`` grids, coarse to fine, each coarsened by 2 in x (and in y
    for a point contact) from ``(nx, ny)``: ``(n - 1)/2 + 1``."""
    grids = [(nx, ny)]
    for _ in range(levels - 1):
        cx, cy = grids[-1]
        if (cx - 1) % 2 or (not line and (cy - 1) % 2):
            raise InputError("nx, ny", f"node counts 2^k m + 1 for {levels} levels", (nx, ny))
        grids.append(((cx - 1) // 2 + 1, cy if line else (cy - 1) // 2 + 1))
    return grids[::-1]


def _scaled_gain(gain: float, nx: int, default_nx: int, line: bool) -> float:
    """A load gain on a grid of ``nx`` nodes finer than the default mesh's ``default_nx``:
    ``gain (dX / dX_default)^e`` (:data:`LINE_GAIN_EXPONENT`, :data:`POINT_GAIN_EXPONENT`);
    unchanged on the default mesh and coarser."""
    if nx <= default_nx:
        return gain
    exponent = LINE_GAIN_EXPONENT if line else POINT_GAIN_EXPONENT
    return gain * ((default_nx - 1) / (nx - 1)) ** exponent


def _relax_line_or_newton(state, method, line, polish=False, **relax):
    """:func:`_relax`, then Newton for a line contact's point update that ended unconverged
    (or, with ``polish``, converged).

    The steady discrete equations are solved by Newton
    (:func:`asperity.ehl.line_newton.solve_line_newton`) from the grid's start (the
    interpolated coarser solution) or, failing that, from the relaxed state, and the
    relaxation runs again from the solution for at most :data:`NEWTON_CHECK_SWEEPS` sweeps:
    its own convergence test decides, so the discretisation and the test are those of the
    relaxation. Isoviscous rollers at M = 31-118 (L = 0), whose point update relaxes the
    smooth pressure error over about ``nx^2`` sweeps, did not converge on 513-2049 nodes in
    40,000 sweeps per grid; with Newton every grid converges. With ``polish`` (the finest
    grid) a converged relaxation is also solved by Newton from its state: there the test on
    a sweep's changes passes while the slow smooth error is still large (a polyurethane
    roller at M = 62 on 1025 nodes: central film 0.66 % under the discrete solution), and the
    state is kept only if the relaxation from the Newton solution converges too
    (docs/ehl-robustness.md, "Session 38: line contacts"). Returns
    ``_relax``'s tuple, the sweeps and history of both relaxations together.
    """
    start = (state.P.copy(), state.H0) if line and method == "point" else None
    converged, residual, sweeps, history = _relax(state, method, **relax)
    if start is None or not np.all(np.isfinite(state.P)) or (converged and not polish):
        return converged, residual, sweeps, history
    relaxed = (state.P.copy(), state.H.copy(), state.H0)
    target = state.problem.load_integral * relax.get("load_factor", 1.0)
    solved = False
    for P, H0 in ((relaxed[0], relaxed[2]),) if converged else (start, relaxed[::2]):
        state.P, state.H0 = P, H0
        # the Newton step tests its rows and iterates for finite values itself; an overflowed
        # viscosity's zero flow factors made numpy warn at every division (alpha 999 1/GPa)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            solved = solve_line_newton(state, target,
                                       max_steps=POLISH_STEPS if converged else NEWTON_STEPS)
        if solved:
            break
    if solved:
        check = {**relax, "max_sweeps": min(relax["max_sweeps"], NEWTON_CHECK_SWEEPS),
                 "sweep_offset": relax.get("sweep_offset", 0) + sweeps}
        checked, check_residual, more, tail = _relax(state, method, **check)
        if checked or not converged:
            history = history + [(sweeps + row[0], *row[1:]) for row in tail]
            return checked, check_residual, sweeps + more, history
    state.P, state.H, state.H0 = relaxed
    state.refresh()
    return converged, residual, sweeps, history


def sequencing_levels(nx: int, ny: int, min_nx: int = 33) -> int:
    """Grid-sequencing levels of a mesh: halve (at most 3 times) while the coarsest grid keeps
    at least ``min_nx`` nodes along x and 17 across (``ny = 1``: a line contact).

    33 along x for a default mesh (and a line contact's given mesh); the transient runs'
    steady start on the user's own mesh takes 17 (:func:`asperity.ehl.solve_transient`). On
    9 nodes across (dY = b/2) the gear case's coarsest grid did not converge."""
    levels = 1
    while levels < 4:
        f = 2**levels
        if (nx - 1) % f or (nx - 1) // f + 1 < min_nx:
            break
        if ny > 1 and ((ny - 1) % f or (ny - 1) // f + 1 < 17):
            break
        levels += 1
    return levels


def check_contact_and_method(problem, method):
    """Validate the problem and the relaxation; return (is a line contact, method).

    ``method`` None gives the default: x-line relaxation for a point contact, the point
    update for a line contact.
    """
    if not isinstance(problem, PointContact | LineContact):
        raise InputError("problem", "a PointContact or LineContact")
    line = isinstance(problem, LineContact)
    if method is None:
        method = "point" if line else "line"
    if method not in ("line", "point"):
        raise InputError("method", '"line" or "point"', method)
    return line, method


def check_damping(value) -> float:
    """Validate an oscillation-damping factor 0 < damping <= 1."""
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating) \
            or not 0.0 < value <= 1.0:
        raise InputError("damping", "a factor 0 < damping <= 1", value)
    return float(value)


def _result(state, converged, residual, sweeps, total, history, grids, method, mu_b, *,
            soft_retry=False):
    """The :class:`SteadyResult` of the finest grid's ``state``."""
    prob = state.problem
    p = state.P * prob.p_hertz
    h = state.H * prob.film_scale
    hc = _at_centre(state, h)
    centre = _centre_line(state, h)
    load_err = (state.load() - prob.load_integral) / prob.load_integral
    mu = np.nan  # a blown-up or separated iterate carries no load to take friction of
    if np.isfinite(p).all() and np.isfinite(h).all() and p.sum() > 0.0:
        mu = friction_coefficient(
            state.x, p, np.maximum(h, 0.0), prob.lubricant.eta(p), prob.sliding_speed,
            prob.lubricant.eyring_stress, boundary_friction=mu_b,
        )
    near_inlet = int(np.searchsorted(state.x, state.x[0] + 0.1 * prob.a))
    return SteadyResult(
        x=state.x, y=state.y, pressure=p, film=h, central_film=hc,
        minimum_film=float(h.min()), minimum_film_centreline=float(centre.min()),
        max_pressure=float(p.max()), load_error=float(load_err), friction_coefficient=mu,
        separation=state.H0 * prob.film_scale, sweeps=sweeps, total_sweeps=total,
        fft_refreshes=state.refreshes, converged=bool(converged), residual=float(residual),
        history=np.array(history), levels=tuple(grids), method=method,
        inlet_pressure=float(state.P[min(near_inlet, state.x.size - 1)].max()),
        y_lines=state.y_lines, soft_retry=soft_retry,
    )
