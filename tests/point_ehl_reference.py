"""An independent steady point-contact EHL solution (pure rolling, Newtonian, incompressible).

Nothing here comes from :mod:`asperity.ehl`: it is a reference the steady solver is set
beside (tests/test_ehl_point_reference.py, tests/test_ehl_ellipse_reference.py,
docs/ehl-robustness.md, "An independent point contact at L = 0 (session 39)" and, for
k < 1, "Ellipses entrained along the major axis").

Equations, in Hertzian units (``X = x/a``, ``Y = y/a``, ``P = p/p_h``, ``H = h Rx/a^2``):

- Reynolds, with the Barus viscosity ``eta = eta0 exp(alpha p_h P)``::

      d/dX(eps dP/dX) + d/dY(eps dP/dY) = dH/dX,    eps = H^3 exp(-alpha p_h P) / lam,
      lam = 12 eta0 u_mean Rx^2 / (a^3 p_h)

- the film, with the half-space deflection of uniformly loaded rectangular panels (Love
  1929; Johnson 1985, eq. 3.25), a dense matrix ``K``::

      H = H0 + X^2/2 + (Rx/Ry) Y^2/2 + c sum_j K_ij P_j,   c = 2 p_h Rx / (pi E' a)

  where ``K_ij`` is the integral of ``1/r`` over the panel of node j seen from node i;

- the Reynolds exit (cavitation) condition as a complementarity problem: with
  ``F = -div(eps grad P) + dH/dX``, ``P >= 0, F >= 0, P F = 0``, written as the
  Fischer-Burmeister equation ``P + s F - sqrt(P^2 + (s F)^2) = 0`` (``s = dX`` a scale);
- the load balance ``int P dX dY = 2 pi k / 3`` (``k = b/a``) for the separation ``H0``.

Discretisation: nodes on a uniform grid over the domain with ``P = 0`` on its boundary,
symmetric about ``Y = 0`` (the half ``Y >= 0`` solved, the mirror panels added to ``K``);
finite volumes, the Poiseuille fluxes with the arithmetic mean of ``eps`` on a face, the
wedge flux ``H`` on a face from Leonard's upwind-biased quadratic (QUICK, ``kappa = 1/3``:
``H_{i+1/2} = (2 H_{i+1} + 5 H_i - H_{i-1}) / 6``, the mean next to the inlet). The load is
the nodal sum times ``dX dY``. All equations are solved at once by Newton's method on the
semismooth system with its dense Jacobian (LAPACK LU), a backtracking line search on the
squared residual, from Hertz's pressure on the coarsest mesh and from the interpolated
coarser solution on each finer one. A heavily loaded or piezoviscous contact, whose Hertz
start touches (``H = 0`` in the side lobes, where Newton stalls), is reached on the coarsest
mesh along a continuation: ``lam`` lowered from a thicker film, and ``alpha p_h`` raised in
steps from 0 (``solve_sequence``). The Hertz semi-axes and pressure of an ellipse are this
module's own too (``hertz_ellipse``).

References
----------
A. E. H. Love, Phil. Trans. R. Soc. A 228 (1929) 377-420; K. L. Johnson, *Contact Mechanics*,
Cambridge University Press, 1985, eq. (3.25).
B. P. Leonard, Comput. Methods Appl. Mech. Eng. 19 (1979) 59-98.
A. Fischer, Optimization 24 (1992) 269-284.
"""

import time
from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.sparse as sp
from scipy.interpolate import RegularGridInterpolator
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk


def hertz_ellipse(*, rx, ry, load, reduced_modulus):
    """Hertz's elliptical contact with the semi-axis ``a`` along x (Johnson 1985, eq. 3.39).

    With ``k = b/a`` and ``e^2 = 1 - k^2`` (``a`` the major semi-axis, ``rx >= ry``; for
    ``rx < ry`` the roles swap and ``k > 1``), ``rx/ry = (E(e)/k^2 - K(e)) / (K(e) - E(e))``
    fixes ``k``, and ``1/(2 rx) = 3 W (K - E) / (pi E* e^2 a^3)`` with ``E* = E'/2`` fixes
    ``a``; ``p_h = 3 W / (2 pi a b)``.

    Parameters
    ----------
    rx, ry : float
        Reduced radii along and across the rolling direction x (m).
    load : float
        Normal load (N).
    reduced_modulus : float
        ``E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)`` (Pa).

    Returns
    -------
    tuple
        ``(k, a, p_h)``: ``b/a``, the semi-axis along x (m), the peak pressure (Pa).
    """
    major, minor = max(rx, ry), min(rx, ry)

    def ratio(k):
        e2 = 1.0 - k * k
        return (ellipe(e2) / k**2 - ellipk(e2)) / (ellipk(e2) - ellipe(e2))

    k = 1.0 if major == minor else brentq(lambda k: ratio(k) - major / minor, 1e-3,
                                          1.0 - 1e-12, xtol=1e-15)
    e2 = 1.0 - k * k
    factor = 0.25 if k == 1.0 else (ellipk(e2) - ellipe(e2)) / (np.pi * e2)
    major_axis = (6.0 * load * major * factor / reduced_modulus) ** (1.0 / 3.0)
    a = major_axis if rx >= ry else k * major_axis
    k = k if rx >= ry else 1.0 / k
    return k, a, 3.0 * load / (2.0 * np.pi * a * a * k)


def love_panel(x, y, half_x, half_y):
    """Integral of ``1/r`` over the rectangle ``|s| <= half_x, |t| <= half_y`` seen from
    ``(x, y)`` (Love 1929; Johnson 1985, eq. 3.25 without its factor ``(1 - nu^2) p/(pi E)``).

    Parameters
    ----------
    x, y : array_like
        Field point relative to the rectangle's centre (any length unit).
    half_x, half_y : float
        Half-sides of the rectangle (the same unit).

    Returns
    -------
    numpy.ndarray
        The integral (the same length unit).
    """
    x, y = np.asarray(x, float), np.asarray(y, float)
    xp, xm, yp, ym = x + half_x, x - half_x, y + half_y, y - half_y

    def log_ratio(num_s, num_t, den_s, den_t):
        return np.log((num_t + np.hypot(num_s, num_t)) / (den_t + np.hypot(den_s, den_t)))

    # each log argument is positive: t + sqrt(s^2 + t^2) with the larger t on top; the
    # term multiplying a vanishing length is 0 (its log stays finite or the product -> 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        terms = (xp * log_ratio(xp, yp, xp, ym)
                 + yp * log_ratio(yp, xp, yp, xm)
                 + xm * log_ratio(xm, ym, xm, yp)
                 + ym * log_ratio(ym, xm, ym, xp))
    return np.nan_to_num(terms)


@dataclass(frozen=True)
class PointSolution:
    """A converged (or not) reference solution on one mesh.

    Attributes
    ----------
    X, Y : numpy.ndarray
        Node coordinates (Y from 0, the symmetry line).
    P, H : numpy.ndarray
        Pressure and film at the nodes, ``[ix, iy]``.
    H0 : float
        Rigid separation.
    central : float
        ``H`` at (0, 0) (linear between nodes along X).
    minimum : float
        Least nodal ``H``.
    iterations : int
        Newton steps on this mesh.
    residual : float
        Largest absolute residual of the semismooth equations and the load.
    converged : bool
        Whether the residual fell below the tolerance.
    seconds : float
        Wall time of the solve on this mesh.
    """

    X: np.ndarray
    Y: np.ndarray
    P: np.ndarray
    H: np.ndarray
    H0: float
    central: float
    minimum: float
    iterations: int
    residual: float
    converged: bool
    seconds: float


class PointReference:
    """The discrete equations of the module docstring on one uniform mesh.

    Parameters
    ----------
    lam : float
        ``12 eta0 u_mean Rx^2 / (a^3 p_h)``.
    c : float
        ``2 p_h Rx / (pi E' a)``.
    k : float
        ``b/a`` (the load integral is ``2 pi k / 3``).
    ratio : float
        ``Rx/Ry``.
    domain : tuple
        ``(x_min, x_max, y_max)`` in units of a (the half domain ``0 <= Y <= y_max``).
    dx, dy : float
        Node spacings in units of a; the bounds must be whole multiples of them.
    alpha_p : float
        ``alpha p_h`` (0: isoviscous).
    """

    def __init__(self, *, lam, c, k, ratio, domain, dx, dy, alpha_p=0.0):
        x0, x1, y1 = domain
        nx, ny = round((x1 - x0) / dx) + 1, round(y1 / dy) + 1
        if abs((nx - 1) * dx - (x1 - x0)) > 1e-9 or abs((ny - 1) * dy - y1) > 1e-9:
            raise ValueError("domain bounds must be whole multiples of dx and dy")
        self.lam, self.c, self.k, self.alpha_p = lam, c, k, alpha_p
        self.dx, self.dy, self.nx, self.ny = dx, dy, nx, ny
        self.X = x0 + dx * np.arange(nx)
        self.Y = dy * np.arange(ny)
        gx, gy = np.meshgrid(self.X, self.Y, indexing="ij")
        self.rigid = (gx**2 + ratio * gy**2).ravel() / 2.0
        inner = np.zeros((nx, ny), bool)
        inner[1:-1, :-1] = True
        self.inner = inner.ravel()
        self.nodes = np.flatnonzero(self.inner)
        self.kernel = c * self._kernel()
        self._faces()
        self._wedge()

    def _kernel(self):
        """``K`` from every node (rows) to every unknown (columns), mirror panels added."""
        nx, ny, dx, dy = self.nx, self.ny, self.dx, self.dy
        di = np.arange(-(nx - 1), nx)
        dj = np.arange(-(ny - 1), 2 * ny - 1)
        table = love_panel(di[:, None] * dx, dj[None, :] * dy, dx / 2, dy / 2)
        i, j = np.divmod(np.arange(nx * ny), ny)
        p, q = i[self.nodes], j[self.nodes]
        direct = table[i[:, None] - p[None, :] + nx - 1, j[:, None] - q[None, :] + ny - 1]
        mirror = table[i[:, None] - p[None, :] + nx - 1, j[:, None] + q[None, :] + ny - 1]
        return direct + np.where(q[None, :] > 0, mirror, 0.0)

    def _faces(self):
        """Neighbour lists of every unknown: (row, neighbour node, weight) per direction; the
        neighbour below ``Y = 0`` is the mirror node above it."""
        ny = self.ny
        i, j = np.divmod(self.nodes, ny)
        rows, nbs, weights = [], [], []
        for di, dj, w in ((1, 0, self.dx**-2), (-1, 0, self.dx**-2),
                          (0, 1, self.dy**-2), (0, -1, self.dy**-2)):
            jj = np.abs(j + dj)
            rows.append(np.arange(self.nodes.size))
            nbs.append((i + di) * ny + jj)
            weights.append(np.full(self.nodes.size, w))
        self.face_row = np.concatenate(rows)
        self.face_nb = np.concatenate(nbs)
        self.face_w = np.concatenate(weights)

    def _wedge(self):
        """Sparse matrix of ``d(H)/dX`` by face values (QUICK; the mean at the inlet face)."""
        ny, n = self.ny, self.nodes.size
        i, j = np.divmod(self.nodes, ny)
        rows, cols, vals = [], [], []

        def face(left, row_sign):
            # face between node `left` and `left + 1` along x
            quick = left >= 1
            for shift, (wq, wm) in ((1, (2 / 6, 0.5)), (0, (5 / 6, 0.5)), (-1, (-1 / 6, 0.0))):
                w = np.where(quick, wq, wm)
                keep = w != 0
                rows.append(np.arange(n)[keep])
                cols.append(((left + shift) * ny + j)[keep])
                vals.append(row_sign * w[keep] / self.dx)

        face(i, 1.0)
        face(i - 1, -1.0)
        self.wedge = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                            np.concatenate(cols))),
                                   shape=(n, self.nx * self.ny))

    def film(self, P, H0):
        """Nodal film of the unknown pressures ``P`` (every node, flattened)."""
        return H0 + self.rigid + self.kernel @ P

    def equations(self, P, H0):
        """Residuals ``F`` (scaled by dX), the load error, and their Jacobian blocks."""
        H = self.film(P, H0)
        full = np.zeros(self.nx * self.ny)
        full[self.nodes] = P
        eps = H**3 * np.exp(-self.alpha_p * full) / self.lam
        r, s, w = self.face_row, self.face_nb, self.face_w
        node = self.nodes[r]
        mean = 0.5 * (eps[node] + eps[s])
        jump = full[s] - full[node]
        n, m = self.nodes.size, self.nx * self.ny
        F = -np.bincount(r, w * mean * jump, n) + self.wedge @ H
        # d F / d eps, then through eps(H, P)
        deps = sp.csr_matrix((np.r_[-0.5 * w * jump, -0.5 * w * jump],
                              (np.r_[r, r], np.r_[node, s])), shape=(n, m))
        dF_dH = deps @ sp.diags(3.0 * eps / H) + self.wedge
        dF_dP = sp.csr_matrix((np.r_[w * mean, -w * mean], (np.r_[r, r], np.r_[node, s])),
                              shape=(n, m))
        dF_dP = (dF_dP - deps @ sp.diags(self.alpha_p * eps))[:, self.nodes]
        jac = dF_dP.toarray() + dF_dH @ self.kernel
        dH0 = np.asarray(dF_dH.sum(axis=1)).ravel()
        weights = np.where(self.nodes % self.ny == 0, 1.0, 2.0) * self.dx * self.dy
        load = weights @ P / (2.0 * np.pi * self.k / 3.0) - 1.0
        s_ = self.dx
        return s_ * F, load, s_ * jac, s_ * dH0, weights / (2.0 * np.pi * self.k / 3.0), H

    def hertz_start(self, film):
        """Hertz's pressure and the separation giving a least film ``film``."""
        gx, gy = np.meshgrid(self.X, self.Y, indexing="ij")
        P = np.sqrt(np.clip(1.0 - gx**2 - (gy / self.k) ** 2, 0.0, None)).ravel()[self.nodes]
        return P, film - np.min(self.rigid + self.kernel @ P)

    def interpolate(self, coarse: PointSolution):
        """Start from a coarser solution (bilinear in P, the same H0)."""
        f = RegularGridInterpolator((coarse.X, coarse.Y), coarse.P)
        gx, gy = np.meshgrid(self.X, self.Y, indexing="ij")
        # the same bounds up to rounding (0.15 * 50 > 0.25 * 30): clipped onto the coarse grid
        points = np.stack([np.clip(gx.ravel(), coarse.X[0], coarse.X[-1]),
                           np.clip(gy.ravel(), coarse.Y[0], coarse.Y[-1])], axis=1)
        P = f(points)[self.nodes]
        return P, coarse.H0

    def solve(self, P, H0, *, tol=1e-10, max_iter=60) -> PointSolution:
        """Semismooth Newton (Fischer-Burmeister) with a backtracking line search."""

        def system(P, H0):
            F, load, jF, jH0, wl, H = self.equations(P, H0)
            root = np.hypot(P, F)
            phi = P + F - root
            return np.r_[phi, load], (F, jF, jH0, wl, root, H)

        started = time.perf_counter()
        res, parts = system(P, H0)
        it = 0
        for it in range(1, max_iter + 1):
            F, jF, jH0, wl, root, _ = parts
            safe = np.where(root > 1e-14, root, 1.0)
            da = np.where(root > 1e-14, 1.0 - P / safe, 1.0 - 1.0 / np.sqrt(2.0))
            db = np.where(root > 1e-14, 1.0 - F / safe, 1.0 - 1.0 / np.sqrt(2.0))
            n = P.size
            J = np.empty((n + 1, n + 1))
            J[:n, :n] = db[:, None] * jF
            J[np.arange(n), np.arange(n)] += da
            J[:n, n] = db * jH0
            J[n, :n], J[n, n] = wl, 0.0
            step = scipy.linalg.lu_solve(scipy.linalg.lu_factor(J, overwrite_a=True,
                                                                check_finite=False), -res)
            merit, t = res @ res, 1.0
            while True:
                Pn, H0n = P + t * step[:n], H0 + t * step[n]
                if np.min(self.film(Pn, H0n)) > 0.0:
                    resn, partsn = system(Pn, H0n)
                    if resn @ resn <= (1.0 - 1e-4 * t) * merit:
                        break
                if t < 1e-8:
                    return self._result(P, H0, res, parts, it, started, converged=False)
                t *= 0.5
            P, H0, res, parts = Pn, H0n, resn, partsn
            if np.abs(res).max() < tol:
                break
        return self._result(P, H0, res, parts, it, started,
                            converged=bool(np.abs(res).max() < tol))

    def _result(self, P, H0, res, parts, iterations, started, *, converged):
        H = parts[-1].reshape(self.nx, self.ny)
        full = np.zeros(self.nx * self.ny)
        full[self.nodes] = P
        return PointSolution(self.X, self.Y, full.reshape(self.nx, self.ny), H, float(H0),
                             float(np.interp(0.0, self.X, H[:, 0])), float(H.min()),
                             iterations, float(np.abs(res).max()), converged,
                             time.perf_counter() - started)


def solve_sequence(*, spacings, aspect=1.0, film, lam, lam_start=None, alpha_p=0.0,
                   path=(), **kwargs):
    """Reference solutions on meshes of the given ``dX`` (``dY = aspect dX``), each started
    from the previous one, the first from Hertz with least film ``film``.

    ``lam_start`` (> ``lam``): on the first mesh, march from it down to ``lam`` in steps of
    a factor of at most 3 (a heavily loaded contact, whose Hertz start on a coarse mesh
    touches, reached from a thicker film).

    ``path``: pairs ``(lam, alpha_p)`` solved in turn on the first mesh before the case's
    own ``(lam, alpha_p)``, each started from the one before (after the ``lam_start``
    march, which runs isoviscous when ``path`` is given): a piezoviscous contact reached
    from an isoviscous one (``alpha p_h`` raised in steps from 0) and a thick film.

    Returns
    -------
    list of PointSolution
        One per mesh; a stage of the path that does not converge ends the list there (its
        unconverged solution last).
    """
    out = []
    for dx in spacings:
        ref = PointReference(dx=dx, dy=aspect * dx, lam=lam, alpha_p=alpha_p, **kwargs)
        if out:
            out.append(ref.solve(*ref.interpolate(out[-1])))
            if not out[-1].converged:
                return out
            continue
        start = ref.hertz_start(film)
        first_alpha = path[0][1] if path else alpha_p
        steps = int(np.ceil(np.log(lam_start / lam) / np.log(3.0))) if lam_start else 0
        marched = lam * ((lam_start or lam) / lam) ** (np.arange(steps, 0, -1) / max(steps, 1))
        for stage in [(value, first_alpha) for value in marched] + list(path):
            ref.lam, ref.alpha_p = stage
            sol = ref.solve(*start)
            if not sol.converged:
                return [sol]
            start = (sol.P.ravel()[ref.nodes], sol.H0)
        ref.lam, ref.alpha_p = lam, alpha_p
        out.append(ref.solve(*start))
        if not out[-1].converged:
            return out
    return out


def richardson(coarse, fine, ratio, order=2.0):
    """Richardson's extrapolation of two values on spacings ``ratio`` apart.

    Returns
    -------
    float
        ``fine + (fine - coarse) / (ratio^order - 1)``.
    """
    return fine + (fine - coarse) / (ratio**order - 1.0)
