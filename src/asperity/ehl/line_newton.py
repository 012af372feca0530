"""Newton solution of a steady line contact's discrete equations, where the point update stalls.

The fixed point of the line contact's point update (:func:`asperity.ehl.kernels.point_sweep`,
steady: ``theta = 1``, no time terms) satisfies at every interior node ``i``

    r_i = xi_e (p_{i+1} - p_i) + xi_w (p_{i-1} - p_i)
          - lam (c0 (rho h)_i - c1 (rho h)_{i-1} + c2 (rho h)_{i-2}) / dX = 0    (p_i > 0)

with the face conductances ``xi = (eps_i + eps_nb) / (2 dX^2)`` and the upwind weights of
:mod:`asperity.ehl.kernels`, or ``p_i = 0`` where ``r_i <= 0`` at ``p_i = 0`` (cavitated),
and ``H = H0 + X^2/2 + phi + c D*P`` at every node: the differential deflection rows with
the far field refreshed and the Dirichlet edge films hold exactly that film, since the
coefficients ``f`` are the 3-point second difference of the strip kernel ``D``
(:func:`asperity.elastic.differential.line_differential_coefficients`). With the load
``sum P dX`` this is the system :func:`solve_line_newton` solves, unknowns the interior
pressures and ``H0``, by semismooth Newton on ``min(p_i, -r_i / (xi_e + xi_w)) = 0``
(the cavitation complementarity; Hintermueller, Ito & Kunisch 2002) with a backtracking line
search. The Jacobian is ``dr/dP + dr/dH (c D)`` with the banded ``dr/dP``, ``dr/dH`` by
coloured finite differences of the residual (five colours cover the stencil ``i-2..i+1``)
and the dense influence matrix ``D``; each step is one dense LU solve (``nx`` nodes:
``nx^3/3`` operations, 0.1-0.5 s at 2049).

Why: with the viscosity constant (an isoviscous contact, ``alpha p_h`` near 0) the Reynolds
rows are elliptic through the whole contact and the point update relaxes their smooth
pressure error only over about ``nx^2`` sweeps, under a load loop that then cycles: rubber
and polymer rollers in water at Moes M = 30-117 did not converge on 513-2049 nodes in
40,000 sweeps per grid (docs/ehl-robustness.md, "Isoviscous line contacts at M >= 30" and
"Session 38: line contacts"). The discretisation is not changed: the Newton solution is
handed back to the relaxation, whose own convergence test decides
(:func:`asperity.ehl.solver.solve_steady`).

References
----------
M. Hintermueller, K. Ito, K. Kunisch, SIAM J. Optim. 13 (2002) 865-888 (semismooth Newton
for complementarity, primal-dual active sets).
"""

from __future__ import annotations

import warnings

import numpy as np
import scipy.linalg
import scipy.sparse

from ..elastic.differential import strip_integral

__all__ = ["MAX_NODES", "solve_line_newton"]

#: Most nodes of a grid solved by Newton: the dense influence and Jacobian matrices take
#: ``8 nx^2`` bytes each (34 MB at 2049 nodes) and the LU ``nx^3/3`` operations.
MAX_NODES = 2049

#: Colours of the finite-difference Jacobian: node i's residual depends on the pressures of
#: i-1..i+1 and the films of i-2..i+1, so nodes five apart never share a row.
_COLOURS = 5


def _residual(state, P, H):
    """Reynolds residual r_i and the scale ``xi_e + xi_w`` at the interior nodes."""
    prob = state.problem
    ex, _, rho = prob.lubricant.flow_field(P[:, None], H[:, None], prob.sliding_speed,
                                           units=state.flow_units)
    eps, q = ex[:, 0], rho[:, 0] * H
    dx2 = state.dX**2
    xe = 0.5 * (eps[1:-1] + eps[2:]) / dx2
    xw = 0.5 * (eps[1:-1] + eps[:-2]) / dx2
    wedge = 1.5 * q[1:-1] - 2.0 * q[:-2]
    wedge[1:] += 0.5 * q[:-3]
    wedge[0] = q[1] - q[0]  # first order next to the inlet, as in the sweeps
    r = xe * (P[2:] - P[1:-1]) + xw * (P[:-2] - P[1:-1]) - state.lam * wedge / state.dX
    return r, xe + xw


def _banded_jacobian(state, P, H, r0, wrt_pressure):
    """``dr/dP`` or ``dr/dH`` (sparse, interior rows by all nodes) by coloured differences."""
    n = P.size
    rows, cols, vals = [], [], []
    base = P if wrt_pressure else H
    step = 1e-7 * np.maximum(np.abs(base), 1e-3 * max(np.abs(base).max(), 1e-12))
    interior = np.arange(1, n - 1)
    for colour in range(_COLOURS):
        nodes = np.arange(colour, n, _COLOURS)
        if wrt_pressure:
            nodes = nodes[(nodes > 0) & (nodes < n - 1)]
        shifted = base.copy()
        shifted[nodes] += step[nodes]
        r = _residual(state, shifted, H)[0] if wrt_pressure else _residual(state, P, shifted)[0]
        change = r - r0
        # the perturbed node in each row's stencil i-2..i+2 of this colour
        owner = np.full(n, -1)
        owner[nodes] = nodes
        for offset in range(-2, 3):
            j = interior + offset
            ok = (j >= 0) & (j < n)
            j = j[ok]
            hit = owner[j] >= 0
            rows.append(interior[ok][hit] - 1)
            cols.append(j[hit])
            vals.append(change[ok][hit] / step[j[hit]])
    return scipy.sparse.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n - 2, n))


def solve_line_newton(state, target, *, tol: float = 1e-10, max_steps: int = 40) -> bool:
    """Solve a line contact's steady discrete equations by Newton from ``state`` (in place).

    The complementarity rows are ``min(p_i, -r_i / s_i)`` with ``s_i = xi_e + xi_w`` at the
    start, held fixed through the solve (any positive row scale gives the same solution; one
    that follows the iterate left the Newton step without descent: a polyurethane roller at
    M = 62 on 129 nodes stalled at 0.046 with it and converged in 7 steps without it).

    Parameters
    ----------
    state : asperity.ehl.solver.EHLState
        A line contact's state (one row, steady), its pressure and separation the start
        (its film is not used: the film is the integral one of the pressure); on success
        replaced by the solution (``H`` the integral film, ``P >= 0``, the active set),
        otherwise left as it was.
    target : float
        The dimensionless load ``int P dX`` to carry.
    tol : float
        Largest complementarity residual and relative load error at which the system counts
        as solved.
    max_steps : int
        Newton steps at most.

    Returns
    -------
    bool
        Whether the system was solved, with a positive film at every node on the way (a dry
        contact is not in this formulation) and no non-finite value. A grid finer than
        :data:`MAX_NODES` is not tried.
    """
    n = state.X.size
    if n > MAX_NODES:
        return False
    dX = state.dX
    influence = state.c * strip_integral(np.subtract.outer(state.X, state.X), dX)
    rigid = state.geometry[:, 0] + state.roughness[:, 0]

    def evaluate(z, scale):
        """(rows, P, H, r) at the unknowns z = (interior P, H0); None where the film
        closes or a value is not finite."""
        P = np.r_[0.0, z[:-1], 0.0]
        H = z[-1] + rigid + influence @ P
        if not np.all(H > 0.0):
            return None
        r = _residual(state, P, H)[0]
        rows = np.r_[np.minimum(P[1:-1], -r / scale), (P.sum() * dX - target) / target]
        return (rows, P, H, r) if np.all(np.isfinite(rows)) else None

    z = np.r_[np.maximum(state.P[1:-1, 0], 0.0), state.H0]
    P = np.r_[0.0, z[:-1], 0.0]
    H = z[-1] + rigid + influence @ P
    if not np.all(H > 0.0):
        return False
    scale = _residual(state, P, H)[1]
    current = evaluate(z, scale)
    if current is None:
        return False
    for _ in range(max_steps):
        rows, P, H, r = current
        if np.abs(rows).max() < tol:
            break
        jp = _banded_jacobian(state, P, H, r, True)
        jh = _banded_jacobian(state, P, H, r, False)
        jac = np.zeros((n - 1, n - 1))
        jac[:-1, :-1] = -(jp.toarray() + jh @ influence)[:, 1:-1] / scale[:, None]
        jac[:-1, -1] = -np.asarray(jh.sum(axis=1)).ravel() / scale
        cavitated = np.flatnonzero(P[1:-1] <= -r / scale)
        jac[cavitated] = 0.0
        jac[cavitated, cavitated] = 1.0
        jac[-1, :-1] = dX / target
        try:
            with warnings.catch_warnings():  # ill-conditioned in a stiff Hertz zone (rcond
                # 1e-20 at M = 100, L = 10): the line search judges the step
                warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)
                dz = scipy.linalg.solve(jac, -rows)
        except (scipy.linalg.LinAlgError, ValueError):
            return False
        size = np.linalg.norm(rows)
        step = 1.0
        for _ in range(20):  # backtracking on the 2-norm of the rows (Armijo, 1e-4)
            trial = evaluate(z + step * dz, scale)
            if trial is not None and np.linalg.norm(trial[0]) < (1.0 - 1e-4 * step) * size:
                break
            step *= 0.5
        else:
            return False
        z = z + step * dz
        current = trial
    else:
        return False
    _, P, H, _ = current
    state.P = np.maximum(P, 0.0)[:, None]
    state.H = H[:, None]
    state.H0 = float(z[-1])
    state.kind[:] = 0
    state.kind[state.P <= 0.0] = 1
    return True
