"""Seireg's modified linear-programming method for frictional contact (small grids).

Choi & Seireg (Seireg, *Friction and Lubrication in Mechanical Design*, 1998, sec. 3.4-3.5;
D. Choi, PhD thesis, Wisconsin 1986): the direction of the traction at every contact element is
predetermined by a trial rigid motion of body 1 relative to body 2, and only the magnitudes
``f_i`` are unknown. For a trial motion ``W_i = delta + omega z x (r_i - r_c)`` the traction
direction is ``t_i = W_i / |W_i|`` and, element by element,

    slip  s_i = lambda |W_i| - sum_j t_i.K_ij t_j f_j + t_i.c_i >= 0,
    0 <= f_i <= mu p_i,    s_i > 0  =>  f_i = mu p_i,     sum_i f_i |W_i| = b.y,

with ``lambda`` the amplitude of the rigid motion. The book enforces the complementarity with
a simplex whose basis entry is restricted; here the same condition is imposed with one binary
per element (``s_i <= S z_i``, ``f_i >= mu p_i z_i``) and the problem is solved by HiGHS
through :func:`scipy.optimize.milp`. The outer iteration of Figs. 3.22 (pure moment: the centre
of rotation is moved until the residual force vanishes) and 3.34 (force and moment) becomes a
root search on the two free parameters of the trial motion, which drives the residual load
(the components of the carried minus the applied load not fixed by the work condition) to zero.

The element directions are fixed in each linear program, so the solution is exact only where
the slip really is parallel to the trial motion (pure torsion about the true centre, pure
translation); elsewhere it is the book's approximation, which the FFT solver does not make.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy.optimize import Bounds, LinearConstraint, linprog, milp
from scipy.sparse import csr_matrix, eye, hstack, vstack

from ..elastic import tangential_influence
from ..materials import Material
from .friction import (
    FrictionProblem,
    TangentialResult,
    gross_slip_capacity,
    gross_slip_result,
    make_result,
)

__all__ = ["solve_lp"]


def _dense_blocks(Xc, Yc, dx, dy, body1, body2):
    """Dense influence matrices K_xx, K_xy, K_yy between the contact cells, m/Pa."""
    inf = tangential_influence(Xc[:, None] - Xc[None, :], Yc[:, None] - Yc[None, :], dx, dy,
                               body1, body2)
    return inf.xx, inf.xy, inf.yy


def _fixed_direction(Kxx, Kxy, Kyy, tx, ty, rho, g, c_along, work):
    """Magnitudes f, slip s and amplitude lambda for predetermined directions.

    First the linear program of the book: the smallest rigid-motion amplitude lambda such that
    no element's elastic displacement along its direction exceeds the rigid one
    (``K_t f - lambda rho <= c``, ``0 <= f <= mu p``, ``rho.f = work``). Its vertex solutions
    are complementary in practice (each element either sticks or carries mu p), which is
    checked; where they are not, the complementarity is imposed with binaries (HiGHS MILP).
    Returns (f, s, lambda) or None when infeasible.
    """
    Kt = (tx[:, None] * (Kxx * tx[None, :] + Kxy * ty[None, :])
          + ty[:, None] * (Kxy * tx[None, :] + Kyy * ty[None, :]))
    # scale tractions by max g, displacements by the largest full-slip displacement and the
    # rigid motion by its largest value, so that every row is of order one
    gs, rs = g.max(), rho.max()
    us = np.abs(Kt).sum(axis=1).max() * gs
    Kh, gh, ch = Kt * gs / us, g / gs, c_along / us
    rho, work = rho / rs, work / (gs * rs)
    n = g.size
    res = linprog(np.r_[np.zeros(n), 1.0], A_ub=np.hstack([Kh, -rho[:, None]]), b_ub=ch,
                  A_eq=np.r_[rho, 0.0][None, :], b_eq=[work],
                  bounds=np.c_[np.r_[np.zeros(n), 0.0], np.r_[gh, np.inf]], method="highs")
    if res.x is None:
        return None
    f, lam = res.x[:n], res.x[-1]
    s = lam * rho - Kh @ f + ch
    if np.max(np.minimum(gh - f, s)) > 1e-7 * max(lam, 1.0):
        out = _complementary_milp(Kh, gh, ch, rho, work, lam)
        if out is None:
            return None
        f, s, lam = out
    return f * gs, s * us, lam * us / rs


def _complementary_milp(Kh, gh, ch, rho, work, lam0, time_limit=5.0):
    """The fixed-direction problem with complementarity by binaries (scaled variables).

    Variables [f, s, z, lambda]: K f + s - lambda rho = c, s <= S z, f >= g z, rho.f = work;
    the bound S starts from the LP's amplitude and is enlarged while it binds. Branch and
    bound can be slow beyond a few hundred elements: None after ``time_limit`` seconds.
    """
    n = gh.size
    big = 4.0 * max(lam0 * rho.max(), np.abs(ch).max(), 1e-12)
    I_n, zero = eye(n, format="csr"), csr_matrix((n, n))
    for _ in range(8):
        A = vstack([
            hstack([csr_matrix(Kh), I_n, zero, csr_matrix(-rho[:, None])]),
            hstack([zero, I_n, -big * I_n, csr_matrix((n, 1))]),
            hstack([-I_n, zero, csr_matrix(np.diag(gh)), csr_matrix((n, 1))]),
            hstack([csr_matrix(rho[None, :]), csr_matrix((1, 2 * n + 1))]),
        ]).tocsr()
        lo = np.concatenate([ch, np.full(2 * n, -np.inf), [work]])
        hi = np.concatenate([ch, np.zeros(2 * n), [work]])
        res = milp(np.concatenate([np.zeros(n), np.ones(n), np.zeros(n + 1)]),
                   constraints=LinearConstraint(A, lo, hi),
                   integrality=np.concatenate([np.zeros(2 * n), np.ones(n), [0]]),
                   bounds=Bounds(np.zeros(3 * n + 1),
                                 np.concatenate([gh, np.full(n, big), np.ones(n), [np.inf]])),
                   options={"time_limit": time_limit})
        if res.x is None or not res.success:
            return None
        if res.x[n:2 * n].max() < 0.99 * big:
            return res.x[:n], res.x[n:2 * n], res.x[-1]
        big *= 4.0
    return None


def solve_lp(prob: FrictionProblem, linear, x, y, body1: Material, body2: Material,
             callback=None, tol=1e-9, max_iter=40) -> TangentialResult:
    """Solve with predetermined directions and HiGHS; see the module docstring.

    Called by :func:`asperity.contact.solve_tangential` with ``method="lp"`` (virgin loading
    only).

    Parameters
    ----------
    prob : FrictionProblem
        The problem from :func:`asperity.contact.friction.friction_problem`.
    linear : ndarray (2, nx, ny)
        Relative in-plane displacement caused by the pressure, m (zero for identical bodies).
    x, y : ndarray
        Cell-centre coordinates, m.
    body1, body2 : Material
        The two bodies.
    callback : callable, optional
        ``callback(trial, residual)`` after each trial motion.
    tol : float
        Tolerance on the residual: the largest unbalanced load component over the applied.
    max_iter : int
        Largest number of trial motions.

    Returns
    -------
    TangentialResult
        ``converged=False`` with ``reason`` when no trial motion balances the load.
    """
    t, y_cap = gross_slip_capacity(prob.g, prob.cons, prob.target, prob.rows)
    if t <= 1.0:
        return gross_slip_result(prob, t, y_cap, "lp")
    contact = prob.g > 0
    cons = prob.cons
    Xc, Yc, g = cons.X[contact], cons.Y[contact], prob.g[contact]
    dx, dy = x[1] - x[0], y[1] - y[0]
    Kxx, Kxy, Kyy = _dense_blocks(Xc, Yc, dx, dy, body1, body2)
    c = np.asarray(linear, dtype=float)[:, contact]
    # trial motions y = tn + N z with target.y = 1 (rotation fixed: y2 = 0, one parameter)
    rows = list(prob.rows)
    target = np.zeros(3)
    target[rows] = prob.target[rows]
    tn = target / (target @ target)
    N = np.zeros((3, len(rows) - 1))
    N[rows] = np.linalg.svd(target[rows][None, :])[2][1:].T
    state = {"it": 0, "infeasible": 0, "best": np.inf, "best_zz": None}
    cache = {}

    def solve_for(zz):
        key = tuple(zz)
        if key in cache:
            return cache[key]
        yv = tn + N @ zz
        Wx, Wy = yv[0] - yv[2] * Yc / cons.L, yv[1] + yv[2] * Xc / cons.L
        rho = np.hypot(Wx, Wy)
        rho_safe = np.where(rho > 0, rho, 1.0)
        tx, ty = Wx / rho_safe, Wy / rho_safe
        out = _fixed_direction(Kxx, Kxy, Kyy, tx, ty, rho, g, tx * c[0] + ty * c[1], 1.0)
        cache[key] = out, yv, tx, ty
        return cache[key]

    def residual(zz):
        out, yv, tx, ty = solve_for(zz)
        state["it"] += 1
        if out is None:  # no stick/slip split is consistent with these directions
            state["infeasible"] += 1
            return np.full(2, np.nan)
        f = out[0]
        q = np.stack([f * tx, f * ty])
        carried = np.array([q[0].sum(), q[1].sum(), (Xc * q[1] - Yc * q[0]).sum() / cons.L])
        r = N.T @ (carried - target) / np.abs(target).max()
        size = float(np.abs(r).max())
        if size < state["best"]:
            state["best"], state["best_zz"] = size, np.array(zz, dtype=float)
        if callback is not None:
            callback(state["it"], size)
        return r

    zz = np.zeros(N.shape[1])
    r = residual(zz)
    J, stalls = None, 0
    while np.all(np.isfinite(r)) and np.abs(r).max() > tol and state["it"] < max_iter:
        if J is None:  # finite-difference Jacobian, then Broyden updates
            h = 1e-4 * np.linalg.norm(tn)
            J = np.column_stack([(residual(zz + h * e) - r) / h for e in np.eye(zz.size)])
            if not np.all(np.isfinite(J)):
                break
        dz = -np.linalg.lstsq(J, r, rcond=None)[0]
        step = 1.0
        while True:  # damped: the residual must decrease (an infeasible trial does not)
            r_new = residual(zz + step * dz)
            if np.abs(r_new).max() < np.abs(r).max() or step < 0.1:
                break
            step *= 0.5
        if not np.all(np.isfinite(r_new)):
            break
        # the residual is piecewise constant in places (elements switch between stick and
        # slip): stop when two steps running gain less than 10 % (each trial may cost a MILP)
        stalls = stalls + 1 if np.abs(r_new).max() > 0.9 * np.abs(r).max() else 0
        J = J + np.outer(r_new - r - step * (J @ dz), dz) / (step * (dz @ dz))
        zz, r = zz + step * dz, r_new
        if stalls >= 2:
            break
    q = np.zeros((2, *prob.g.shape))
    res = state["best"]
    if state["best_zz"] is None:
        result = make_result(q, contact & False, q.copy(), np.zeros(3), prob, gross=False,
                             t=t, iterations=state["it"], converged=False, residual=np.inf,
                             conv=0, method="lp")
        return replace(result, reason=(
            "method lp: no stick/slip split is consistent with the traction directions of "
            "the trial rigid motion (the book's predetermined directions); use method = "
            "'fft', which does not predetermine them"))
    out, yv, tx, ty = solve_for(tuple(state["best_zz"]))
    f, s, lam = out
    q[0][contact], q[1][contact] = f * tx, f * ty
    slip = np.zeros_like(q)
    slip[0][contact], slip[1][contact] = s * tx, s * ty
    stick = np.zeros(prob.g.shape, dtype=bool)
    stick[contact] = f < g * (1.0 - 1e-9)
    result = make_result(q, stick, slip, lam * yv, prob, gross=False, t=t,
                         iterations=state["it"], converged=res <= tol, residual=res, conv=0,
                         method="lp")
    if res <= tol:
        return result
    return replace(result, reason=(
        f"method lp: no trial rigid motion balances the load with predetermined traction "
        f"directions: the best of {state['it']} leaves {res:.2g} of the applied load "
        f"unbalanced ({state['infeasible']} had no stick/slip split consistent with their "
        "directions; the carried load jumps as elements change between stick and slip); the "
        "traction shown is that best trial's; use method = 'fft', which does not "
        "predetermine the directions"))
