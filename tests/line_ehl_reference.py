"""An independent steady line-contact EHL solution (Newtonian, Barus, incompressible).

Nothing here comes from :mod:`asperity.ehl`: it is a reference the steady line solver is set
beside (tests/test_ehl_line_reference.py; docs/ehl-robustness.md, "Moes' line fit at low M,
an independent reference (session 41)").

Equations, in Hertzian units (``X = x/a``, ``P = p/p_h``, ``H = h R/a^2``, ``a`` the Hertz
half-width and ``p_h`` its peak pressure):

- Reynolds once integrated, with the Reynolds exit condition ``P = dP/dX = 0`` at the
  cavitation point ``X_e`` (an unknown) and the Barus viscosity taken exactly by Grubin's
  reduced pressure ``Q = (1 - exp(-alpha p_h P)) / (alpha p_h)``::

      H^3 dQ/dX = lam (H - H_e),    H_e = H(X_e),    lam = 12 eta0 u_mean R^2 / (a^3 p_h)

  (``Q = P`` when ``alpha = 0``: Herrebrugh's isoviscous form);
- the film with the half-space line deflection of piecewise-constant pressure panels::

      H = H0 + X^2 / 2 - (1/pi) sum_j P_j int_{panel j} ln|X - S| dS

  (the plane-strain displacement of both bodies, ``-(4/(pi E')) int p ln|x - s| ds``, in
  these units; its constant goes into ``H0``);
- the load ``int P dX = pi/2`` (trapezoidal rule).

Discretisation: ``n`` uniform cells from the inlet ``X_in`` to ``X_e``, ``P = 0`` at both
ends; on each cell ``H_m^3 (Q_{i+1} - Q_i)/dX = lam (H_m - H_e)`` with ``H_m`` the mean of the
cell's two nodal films. Unknowns: the ``n - 1`` inner pressures, ``H0`` and ``X_e``; they are
solved together with the load by Newton's method with a dense Jacobian and a line search,
from Hertz's pressure on the first mesh and from the interpolated coarser solution on each
finer one; a piezoviscous contact is reached along ``alpha p_h`` raised in steps from 0.

References
----------
H. Herrebrugh, J. Lubr. Technol. 90 (1968) 262-270 (the isoviscous-elastic line contact).
A. N. Grubin, in Investigation of the Contact of Machine Components, Central Scientific
Research Institute for Technology and Mechanical Engineering, Moscow, book 30 (1949) (the
reduced pressure).
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, eq. (2.25).
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LineSolution:
    """A reference solution on one mesh (Hertzian units).

    Attributes
    ----------
    X, P, H : numpy.ndarray
        Nodes from the inlet to the exit point, pressure and film.
    central, minimum : float
        ``H`` at ``X = 0`` (linear between nodes) and the least nodal ``H``.
    exit : float
        The cavitation point ``X_e``.
    residual : float
        Largest absolute residual.
    """

    X: np.ndarray
    P: np.ndarray
    H: np.ndarray
    central: float
    minimum: float
    exit: float
    residual: float


def _antiderivative(t):
    """``t ln|t| - t`` (0 at t = 0), the integral of ``ln|t|``."""
    safe = np.where(t == 0.0, 1.0, np.abs(t))
    return np.where(t == 0.0, 0.0, t * np.log(safe) - t)


def hertz_groups(*, radius, load_per_length, reduced_modulus, eta0, mean_speed):
    """Hertz's half-width ``a = sqrt(8 w R / (pi E'))``, peak pressure ``p_h = 2 w/(pi a)``
    and ``lam = 12 eta0 u_mean R^2 / (a^3 p_h)`` of a line contact (Johnson 1985, eq. 4.45)."""
    a = np.sqrt(8.0 * load_per_length * radius / (np.pi * reduced_modulus))
    p_h = 2.0 * load_per_length / (np.pi * a)
    return a, p_h, 12.0 * eta0 * mean_speed * radius**2 / (a**3 * p_h)


class LineReference:
    """The discrete equations of the module docstring.

    Parameters
    ----------
    lam : float
        ``12 eta0 u_mean R^2 / (a^3 p_h)``.
    alpha_p : float
        ``alpha p_h`` (0: isoviscous).
    inlet : float
        ``X_in`` in units of a.
    """

    def __init__(self, *, lam, alpha_p=0.0, inlet=-4.0):
        self.lam, self.alpha_p, self.inlet = lam, alpha_p, inlet

    def reduced(self, P):
        """Grubin's reduced pressure ``(1 - exp(-alpha p_h P)) / (alpha p_h)``."""
        if self.alpha_p == 0.0:
            return P
        return -np.expm1(-self.alpha_p * P) / self.alpha_p

    def fields(self, z, n):
        """Nodes, pressures, films and the panel integrals of the unknowns
        ``z = (P_1..P_{n-1}, H0, X_e)``."""
        X = np.linspace(self.inlet, z[-1], n + 1)
        P = np.r_[0.0, z[:n - 1], 0.0]
        edges = np.r_[X[0], 0.5 * (X[1:] + X[:-1]), X[-1]]
        d = X[:, None] - edges[None, :]
        panels = _antiderivative(d[:, :-1]) - _antiderivative(d[:, 1:])
        return X, P, z[n - 1] + X**2 / 2.0 - panels @ P / np.pi, panels

    def residual(self, z, n):
        """Each cell's integrated Reynolds equation over ``lam``, and the load error."""
        X, P, H, _ = self.fields(z, n)
        Hm = 0.5 * (H[1:] + H[:-1])
        flow = Hm**3 * np.diff(self.reduced(P)) / np.diff(X) - self.lam * (Hm - H[-1])
        return np.r_[flow / self.lam, np.trapezoid(P, X) - np.pi / 2.0]

    def jacobian(self, z, n):
        """The residual's Jacobian: exact in the pressures and ``H0``, a forward difference
        in ``X_e`` (which moves every node)."""
        X, P, H, panels = self.fields(z, n)
        dX = X[1] - X[0]
        Hm = 0.5 * (H[1:] + H[:-1])
        dQ = np.diff(self.reduced(P))
        dH = np.c_[-panels[:, 1:-1] / np.pi, np.ones(n + 1)]  # d H_k / d (P_inner, H0)
        dHm = 0.5 * (dH[1:] + dH[:-1])
        J = np.empty((n + 1, n + 1))
        J[:n, :n] = (3.0 * Hm**2 * dQ / (dX * self.lam))[:, None] * dHm - (dHm - dH[-1])
        slope = np.exp(-self.alpha_p * P[1:-1]) / (dX * self.lam)  # dQ/dP over dX lam
        inner = np.arange(n - 1)
        J[inner, inner] += slope * Hm[:-1] ** 3  # node j + 1 ends cell j
        J[inner + 1, inner] -= slope * Hm[1:] ** 3  # and starts cell j + 1
        J[n, :n - 1], J[n, n - 1] = dX, 0.0
        step = 1e-7 * max(1.0, abs(z[-1]))
        shifted = z.copy()
        shifted[-1] += step
        J[:, n] = (self.residual(shifted, n) - self.residual(z, n)) / step
        return J

    def solve(self, z, n, tol=1e-10, max_iter=80):
        """Newton's method from ``z`` with a backtracking line search on the squared residual
        (films kept positive); raises where the largest residual stays above ``tol``."""
        res = self.residual(z, n)
        for _ in range(max_iter):
            if np.abs(res).max() < tol:
                break
            step = np.linalg.solve(self.jacobian(z, n), -res)
            merit, t = res @ res, 1.0
            while True:
                trial = z + t * step
                if trial[-1] > 0.5 and self.fields(trial, n)[2].min() > 0.0:
                    new = self.residual(trial, n)
                    if new @ new <= (1.0 - 1e-4 * t) * merit:
                        break
                t *= 0.5
                if t < 1e-10:
                    raise RuntimeError(f"line reference: the line search stalled on {n} cells "
                                       f"({np.abs(res).max():.2e})")
            z, res = trial, new
        worst = float(np.abs(res).max())
        if worst > tol:
            raise RuntimeError(f"line reference: no convergence on {n} cells ({worst:.2e})")
        X, P, H, _ = self.fields(z, n)
        return z, LineSolution(X, P, H, float(np.interp(0.0, X, H)), float(H.min()),
                               float(z[-1]), worst)

    def hertz_start(self, n, film):
        """Hertz's pressure (scaled to the load), separation ``film``, exit at 1.05."""
        X = np.linspace(self.inlet, 1.05, n + 1)
        P = np.sqrt(np.clip(1.0 - X**2, 0.0, None))
        P *= np.pi / 2.0 / np.trapezoid(P, X)
        return np.r_[P[1:-1], film, 1.05]


def solve_line(*, lam, alpha_p, cells, inlet=-4.0, film=0.5, stages=8):
    """Reference solutions on meshes of ``cells`` cells, the first from Hertz (separation
    ``film``) with ``alpha p_h`` raised from 0 in ``stages`` steps, each finer one from the
    coarser solution.

    Returns
    -------
    list of LineSolution
    """
    ref = LineReference(lam=lam, inlet=inlet)
    z = ref.hertz_start(cells[0], film)
    for value in alpha_p * np.arange(1, stages + 1) / stages if alpha_p else [0.0]:
        ref.alpha_p = value
        z, _ = ref.solve(z, cells[0])
    out = []
    for i, n in enumerate(cells):
        if i:
            X, P, _, _ = ref.fields(z, cells[i - 1])
            finer = np.linspace(inlet, z[-1], n + 1)
            z = np.r_[np.interp(finer, X, P)[1:-1], z[cells[i - 1] - 1], z[-1]]
        z, sol = ref.solve(z, n)
        out.append(sol)
    return out
