"""Partial slip under a tangential force, a twisting moment, or both (frictional contact).

The normal pressure ``p`` is given and held fixed. The tangential traction ``q`` (the force per
unit area that body 1 transmits to body 2, so that its integral equals the applied force) solves
Kalker's complementary-energy problem (Kalker, *Three-dimensional elastic bodies in rolling
contact*, 1990, sec. 2.5)::

    minimise   1/2 q.K q - c.q
    subject to |q_i| <= mu_i p_i                 (Coulomb's friction disc per cell)
               sum_i q_i A = F,  sum_i (r_i - r_c) x q_i A = M      (equilibrium)

with ``K`` the relative in-plane compliance of the two half-spaces (Cerruti cells,
:func:`asperity.elastic.tangential_influence`) and ``c`` the relative in-plane displacement
caused by the pressure. The Lagrange multipliers of the equilibrium constraints are the rigid
shift ``delta`` and rotation ``omega`` of body 1 relative to body 2, and the relative slip is
``s = delta + omega z x (r - r_c) - (K q - c)``: zero where the surfaces stick, parallel to q
where they slip (|q| = mu p).

Normal-tangential coupling: the effect of the pressure on the tangential displacements is
included (``c``), the effect of the traction on the pressure is neglected (Goodman's
approximation). Both vanish, and the decoupling is exact, for identical materials or nu = 0.5
against a rigid body (Johnson 1985, sec. 7.1).

The ``fft`` method is an accelerated projected-gradient method (FISTA with adaptive restart:
Beck & Teboulle 2009; O'Donoghue & Candes 2015) on the FFT operator. Every iterate is
projected exactly onto {friction discs} n {equilibrium}: the projection is solved through its
three-variable dual by a semismooth Newton method (one compiled pass over the contact cells per
Newton step), and its multipliers, divided by the step length, converge to the rigid shift and
rotation. Each iteration costs one block convolution (four real FFTs on the padded grid); the
convergence check (relative duality gap of Coulomb's law) costs one more every ten iterations.
Unlike a clamp of each component, the projection acts on both components of a cell together.

Before solving, the load is checked against the friction capacity: the largest multiple
``t`` of the applied (F, M) that full slip can carry is, by convex duality,
``t = min over rigid motions y with b.y = 1 of sum_i mu_i p_i A |W_i(y)|`` (for a pure moment
the minimum over centres of rotation of int mu p |r - c| dA). If ``t <= 1`` the contact is in
gross slip and the full-slip traction about the instantaneous centre of rotation is returned.

With ``rotation="fixed"`` body 1 is guided so that it cannot twist (a fixture carries any moment):
the moment equation and the rotation multiplier are dropped, the rigid motion is a pure shift,
the capacity is ``t = sum mu_i p_i A / |F|`` and the moment the fixture supplies is reported as
``reaction_moment``.

The problem set-up, the capacity and the result are shared with Seireg's linear programming
(``method="lp"``) in :mod:`asperity.contact.friction`.
"""

from __future__ import annotations

from functools import lru_cache

import numba
import numpy as np

from ..elastic import (
    Convolution,
    grid_spacing,
    periodic_tangential_spectra,
    tangential_influence,
)
from ..errors import InputError
from ..materials import Material, coupling_compliance
from ..solution import renamed_keywords
from .friction import (
    FIXED,
    FREE,
    Constraints,
    FrictionProblem,
    RegionLoad,
    TangentialResult,
    friction_capacity,
    friction_problem,
    gross_slip_capacity,
    gross_slip_result,
    load_centroid,
    make_result,
)
from .tangential_lp import solve_lp

__all__ = [
    "RegionLoad",
    "TangentialOperator",
    "TangentialResult",
    "friction_capacity",
    "load_centroid",
    "solve_tangential",
    "tangential_operator",
]



class TangentialOperator:
    """The relative in-plane compliance of two half-spaces as a 2 x 2 block FFT convolution.

    ``op(q)`` returns the relative displacement (m) of body 1 with respect to body 2 for the
    traction ``q`` of shape ``(2, nx, ny)`` (Pa); ``op.pressure(p)`` the in-plane displacement
    caused by a pressure (zero for identical materials).
    """

    def __init__(self, xx: Convolution, xy: Convolution, yy: Convolution,
                 xz: Convolution | None, yz: Convolution | None):
        self.xx, self.xy, self.yy, self.xz, self.yz = xx, xy, yy, xz, yz
        self.shape = xx.shape
        self.fft_shape = xx.fft_shape
        # largest eigenvalue of the 2 x 2 symbol: a bound on the operator norm on the grid
        a, b, d = xx.spectrum.real, xy.spectrum.real, yy.spectrum.real
        self.norm_bound = float(np.max(0.5 * (a + d) + np.sqrt(0.25 * (a - d) ** 2 + b * b)))

    def __call__(self, q: np.ndarray) -> np.ndarray:
        # the Convolution's transforms: non-periodic, they skip the zero padding rows
        qx, qy = self.xx.spectrum_of(q[0]), self.xx.spectrum_of(q[1])
        ux = self.xx.inverse(self.xx.spectrum * qx + self.xy.spectrum * qy)
        uy = self.xx.inverse(self.xy.spectrum * qx + self.yy.spectrum * qy)
        return np.stack([ux, uy])

    def pressure(self, p: np.ndarray) -> np.ndarray:
        """Relative in-plane displacement due to the pressure p (Pa), m."""
        if self.xz is None:
            return np.zeros((2, *self.shape))
        return np.stack([self.xz(p), self.yz(p)])


@lru_cache(maxsize=8)
def _operator(nx, ny, dx, dy, body1, body2, periodic):
    coupled = coupling_compliance(body1, body2) != 0.0
    if periodic:
        spectra = periodic_tangential_spectra((nx, ny), dx, dy, body1, body2)

        def conv(component):
            return Convolution(getattr(spectra, component), (nx, ny), True)
    else:
        influence = {}  # the Cerruti integrals, evaluated once on the FFT grid for all components

        def component_of(name):
            def coefficient(X, Y):
                if "all" not in influence:
                    influence["all"] = tangential_influence(X, Y, dx, dy, body1, body2)
                return getattr(influence["all"], name)
            return coefficient

        def conv(component):
            return Convolution.from_coefficients(component_of(component), dx, dy, (nx, ny),
                                                 False)

    return TangentialOperator(conv("xx"), conv("xy"), conv("yy"),
                              conv("xz") if coupled else None, conv("yz") if coupled else None)


def tangential_operator(x, y, body1: Material, body2: Material, periodic: bool = False):
    """The cached :class:`TangentialOperator` for the cell-centre coordinates ``x``, ``y``.

    Non-periodic: exact uniform-traction (Cerruti) cells with zero padding (DC-FFT). Periodic:
    the periodic half-space, i.e. the exact response to every traction mode of the grid
    (:func:`asperity.elastic.periodic_tangential_spectra`: all periodic images, mean mode
    removed), the continuum model of the periodic normal operator.
    """
    dx, dy = grid_spacing(x, "x"), grid_spacing(y, "y")
    return _operator(len(x), len(y), dx, dy, body1, body2, bool(periodic))


# --- projection onto {friction discs} n {equilibrium} --------------------------------------


@numba.njit(cache=True)
def _dual_terms(z, g, X, Y, lam, q):
    """One pass of the projection's dual: q = P_D(z + B^T lam), psi, grad psi, Hessian.

    B^T lam = (lam0 - lam2 Y, lam1 + lam2 X); D = I inside the disc, (g/|v|)(I - n n^T)
    outside; Hessian sum_i B_i^T D_i B_i. X, Y are already divided by the length scale.
    """
    psi = 0.0
    r = np.zeros(3)
    J = np.zeros((3, 3))
    for i in range(g.size):
        vx = z[0, i] + lam[0] - lam[2] * Y[i]
        vy = z[1, i] + lam[1] + lam[2] * X[i]
        n = np.hypot(vx, vy)
        psi += 0.5 * (vx * vx + vy * vy)
        if n > g[i]:
            over = n - g[i]
            psi -= 0.5 * over * over
            b = g[i] / n
            ux, uy = vx / n, vy / n
            qx, qy = b * vx, b * vy
            d00, d01, d11 = b * (1.0 - ux * ux), -b * ux * uy, b * (1.0 - uy * uy)
        else:
            qx, qy = vx, vy
            d00, d01, d11 = 1.0, 0.0, 1.0
        q[0, i], q[1, i] = qx, qy
        r[0] += qx
        r[1] += qy
        r[2] += X[i] * qy - Y[i] * qx
        cx, cy = -Y[i], X[i]
        e0, e1 = d00 * cx + d01 * cy, d01 * cx + d11 * cy
        J[0, 0] += d00
        J[0, 1] += d01
        J[1, 1] += d11
        J[0, 2] += e0
        J[1, 2] += e1
        J[2, 2] += cx * e0 + cy * e1
    J[1, 0], J[2, 0], J[2, 1] = J[0, 1], J[0, 2], J[1, 2]
    return psi, r, J


def _project(z, g, cons: Constraints, target, lam, rows=FREE, max_iter=50):
    """Euclidean projection of z onto {|q_i| <= g_i} n {B q = target} (contact cells, 1-D).

    Semismooth Newton with backtracking on the dual: q = P_D(z + B^T lam) with B q = target,
    where lam minimises the convex psi(lam) = sum h(z + B^T lam) - target.lam,
    h(v) = |v|^2/2 - max(|v| - g, 0)^2/2 (grad h = P_D). ``lam`` is the warm start. Only the
    equilibrium ``rows`` are imposed (the others' multipliers stay zero: ``FIXED`` drops the
    moment). Returns (q, lam, ok).
    """
    X, Y = cons.X / cons.L, cons.Y / cons.L
    rows = list(rows)
    tol = 1e-12 * (np.abs(target[rows]).max() + g.sum())
    q = np.empty_like(z)
    psi, r, J = _dual_terms(z, g, X, Y, lam, q)
    sub = np.ix_(rows, rows)
    eye = np.eye(len(rows))
    for _ in range(max_iter):
        r = (r - target)[rows]
        if np.abs(r).max() <= tol:
            return q, lam, True
        step = np.zeros(3)
        step[rows] = np.linalg.lstsq(J[sub] + 1e-13 * np.trace(J[sub]) * eye, -r,
                                     rcond=None)[0]
        f0, t, slope, r0 = psi - target @ lam, 1.0, r @ step[rows], np.abs(r).max()
        while True:  # Armijo on psi, or a halved residual (psi's round-off near the end)
            trial = lam + t * step
            psi, r, J = _dual_terms(z, g, X, Y, trial, q)
            if (psi - target @ trial <= f0 + 1e-4 * t * slope
                    or np.abs((r - target)[rows]).max() <= 0.5 * r0 or t < 1e-10):
                break
            t *= 0.5
        lam = trial
    return q, lam, bool(np.abs((r - target)[rows]).max() <= 1e3 * tol)


# --- the solver ------------------------------------------------------------------------------


@renamed_keywords(center="centre")
def solve_tangential(pressure, x, y, mu, body1: Material, body2: Material, *,
                     force=(0.0, 0.0), moment=0.0, centre=None, method="fft", tol=1e-8,
                     callback=None, previous: TangentialResult | None = None,
                     periodic: bool = False, max_iter: int | None = None,
                     rotation: str = "free") -> TangentialResult:
    """Tangential traction, stick and slip zones and rigid motion under a force and a moment.

    Parameters
    ----------
    pressure : ndarray (nx, ny)
        Normal pressure on the cells, Pa (Hertz, uniform per region, or from ``solve_normal``).
    x, y : ndarray
        Uniformly spaced cell-centre coordinates, m.
    mu : float or ndarray (nx, ny)
        Coefficient(s) of friction, > 0.
    body1, body2 : Material
        The two bodies. Traction acts from body 1 on body 2.
    force : (float, float)
        Applied tangential force (Fx, Fy), N.
    moment : float
        Applied twisting moment Mz about ``centre``, N m (counter-clockwise positive).
    centre : (float, float), optional
        Reference point of the moment, m; by default the centre of the normal load (the
        pressure centroid, :func:`load_centroid`), so that a force alone causes no twist
        whatever the coordinates. The point used is :attr:`TangentialResult.centre`. The old
        spelling ``center`` is accepted with a DeprecationWarning.
    method : {"fft", "lp"}
        ``"fft"``: accelerated projected gradient on the FFT operator (module docstring).
        ``"lp"``: Seireg's modified linear programming with predetermined traction directions
        (:mod:`asperity.contact.tangential_lp`), for small grids.
    tol : float
        Tolerance on the relative duality gap of Coulomb's law (``residual``).
    callback : callable, optional
        ``callback(iteration, residual)`` after each iteration.
    previous : TangentialResult, optional
        State of the previous load step on the same grid (history: unloading, reversal). The
        new load is reached from it; shift and rotation are then totals. None: virgin contact.
    periodic : bool
        Periodic half-space (a representative cell of a rough interface; comparisons with
        periodic codes): the exact response to every traction mode of the cell
        (:func:`tangential_operator`). Displacements are then measured from their mean, and
        so is ``shift`` (the mean displacement under a net force is unbounded).
    max_iter : int, optional
        Iteration limit (default ``100 + 20 max(nx, ny)``).
    rotation : {"free", "fixed"}
        ``"fixed"``: body 1 is prevented from twisting (e.g. a guided slider, or a force acting
        through the centre of friction); the moment equation is dropped, ``rotation`` is 0
        and the fixture's moment is ``reaction_moment``.

    Returns
    -------
    TangentialResult
        ``gross_slip=True`` with the full-slip traction and ``excess`` when the load exceeds
        the friction capacity; ``converged=False`` when the iteration limit was hit.
    """
    if method not in ("fft", "lp"):
        raise InputError("method", "'fft' or 'lp'", method)
    if not (np.isfinite(tol) and tol > 0):
        raise InputError("tol", "a tolerance > 0", tol)
    prob = friction_problem(pressure, x, y, mu, force, moment, centre, rotation)
    op = tangential_operator(x, y, body1, body2, periodic)
    if previous is not None and previous.traction.shape != (2, *prob.g.shape):
        raise InputError("previous", "a result on the same grid", previous.traction.shape)
    if method == "lp" and previous is not None:
        raise InputError("previous", "None with method='lp' (virgin loading only)")
    if method == "lp" and periodic:
        raise InputError("periodic", "False with method='lp' (its influence matrix is the "
                                     "isolated half-space's; use method='fft')")
    loaded = np.any(prob.target[list(prob.rows)])
    if not loaded and previous is None:
        zero = np.zeros((2, *prob.g.shape))
        return make_result(zero, prob.g > 0, zero.copy(), np.zeros(3), prob, gross=False,
                           t=np.inf, iterations=0, converged=True, residual=0.0, conv=0,
                           method=method)
    if method == "lp":
        return solve_lp(prob, op.pressure(np.asarray(pressure, float)), x, y, body1, body2,
                        callback=callback)
    t, y_cap = (gross_slip_capacity(prob.g, prob.cons, prob.target, prob.rows) if loaded
                else (np.inf, None))
    if t <= 1.0:
        return gross_slip_result(prob, t, y_cap, method)

    if previous is None:
        linear = op.pressure(np.asarray(pressure, float))
        q0, y_prev = np.zeros((2, *prob.g.shape)), np.zeros(3)
    else:
        q0 = previous.traction
        linear = op(q0)
        y_prev = np.concatenate([previous.shift, [previous.rotation * prob.cons.L]])
        if prob.rows == FIXED and previous.rotation != 0.0:
            raise InputError("previous", "a state with rotation fixed (zero rotation)",
                             previous.rotation)
    q, iterations, converged, residual, yv, slip, conv = _fista(
        op, prob, linear, q0, tol, callback, max_iter or 100 + 20 * max(prob.g.shape))
    contact = prob.g > 0
    stick = contact & (np.hypot(q[0], q[1]) < prob.g * (1.0 - 1e-9))
    slip = np.where(stick, 0.0, slip)
    return make_result(q, stick, slip, yv + y_prev, prob, gross=False, t=t,
                       iterations=iterations, converged=converged, residual=residual,
                       conv=conv, method=method)


def _fista(op: TangentialOperator, prob: FrictionProblem, linear, q0, tol, callback, max_iter,
           check_every=10):
    """Accelerated projected gradient (FISTA) with adaptive restart on {discs} n {equilibrium}.

    Beck & Teboulle, SIAM J. Imaging Sci. 2 (2009) 183; restart when the momentum opposes the
    step (O'Donoghue & Candes, Found. Comput. Math. 15 (2015) 715). Step 1/L with L the largest
    eigenvalue of the operator's symbol. The multipliers of the exact projection, divided by the
    step, are the rigid motion. Convergence: relative duality gap
    sum g|s| - q.s over sum g|W| (zero iff Coulomb's law holds everywhere), every
    ``check_every`` iterations. Works on the contact cells only (gathered 1-D arrays).

    Returns (q_grid, iterations, converged, residual, y, slip_grid, convolutions).
    """
    contact = prob.g > 0
    g = prob.g[contact]
    cons = Constraints(prob.cons.X[contact], prob.cons.Y[contact], prob.cons.L)
    lin = linear[:, contact]
    grid = np.zeros((2, *prob.g.shape))

    def grad_of(qc):
        grid[:, contact] = qc
        return op(grid)[:, contact] - lin

    alpha = 1.0 / op.norm_bound
    lam = np.zeros(3)
    q, lam, _ = _project(q0[:, contact], g, cons, prob.target, lam, prob.rows)
    z, tk = q.copy(), 1.0
    conv, residual, yv, slip = 0, np.inf, np.zeros(3), np.zeros_like(q)
    converged, it = False, 0
    for it in range(1, max_iter + 1):
        gz = grad_of(z)
        conv += 1
        q_new, lam, _ = _project(z - alpha * gz, g, cons, prob.target, lam, prob.rows)
        yv = lam / alpha
        if it % check_every == 0 or it == max_iter:
            W = cons.adjoint(yv)
            slip = W - grad_of(q_new)
            conv += 1
            ns = np.hypot(slip[0], slip[1])
            work = np.sum(g * np.hypot(W[0], W[1]))
            residual = float(np.sum(g * ns - np.sum(q_new * slip, axis=0)) / work) if work else 0.0
            if callback is not None:
                callback(it, residual)
            if residual <= tol:
                q, converged = q_new, True
                break
        if np.sum((z - q_new) * (q_new - q)) > 0:
            z, tk = q_new.copy(), 1.0
        else:
            t_next = 0.5 * (1.0 + np.sqrt(1.0 + 4.0 * tk * tk))
            z = q_new + ((tk - 1.0) / t_next) * (q_new - q)
            tk = t_next
        q = q_new
    q_grid = np.zeros((2, *prob.g.shape))
    q_grid[:, contact] = q
    slip_grid = np.zeros_like(q_grid)
    slip_grid[:, contact] = slip
    return q_grid, it, converged, residual, yv, slip_grid, conv
