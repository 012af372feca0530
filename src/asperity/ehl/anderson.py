"""Anderson acceleration of a fixed-point iteration ``x -> g(x)``.

Used by the transient EHL step (:mod:`asperity.ehl.transient`) on its refresh cycles: after the
local (asperity-scale) errors have been relaxed, what is left decays slowly and smoothly (the
lagged far-field deflection and the load balance through the rigid separation), and a few
remembered cycles span it well enough to extrapolate. ``scipy.optimize.anderson`` drives its
own loop on a residual function; here the iteration stays the solver's own (the relaxation
sweeps with their active set, the convergence test on a sweep), and the mixer only proposes
the next iterate.

Type II (Walker & Ni 2011, Eq. 2.2 with mixing parameter 1): with residuals ``f_i = g_i -
x_i`` and the differences ``dF``, ``dG`` of the last ``m + 1`` pairs,

    gamma = argmin || f_k - dF gamma ||_2,      x_{k+1} = g_k - dG gamma.

References
----------
D. G. Anderson, J. ACM 12 (1965) 547-560.
H. F. Walker, P. Ni, SIAM J. Numer. Anal. 49 (2011) 1715-1735.
"""

from __future__ import annotations

import numpy as np

__all__ = ["AndersonMixer"]


class AndersonMixer:
    """Remembers the last ``memory + 1`` pairs ``(x_i, g(x_i))`` and proposes the next iterate.

    Parameters
    ----------
    memory : int
        Number m of residual differences in the least-squares fit (>= 1).
    """

    def __init__(self, memory: int):
        self.memory = int(memory)
        self._g: list[np.ndarray] = []
        self._f: list[np.ndarray] = []

    def reset(self):
        """Forget the history (the next :meth:`mix` returns ``g`` unchanged)."""
        self._g.clear()
        self._f.clear()

    def mix(self, x: np.ndarray, g: np.ndarray) -> np.ndarray:
        """Record the pair (x, g(x)) and return the accelerated next iterate.

        With a single pair in the history this is the plain fixed-point step ``g``. The
        least-squares problem is solved through its m x m normal equations (the vectors are
        long, m is small).
        """
        g = np.asarray(g, dtype=float)
        self._g.append(g)
        self._f.append(g - np.asarray(x, dtype=float))
        if len(self._g) > self.memory + 1:
            self._g.pop(0)
            self._f.pop(0)
        if len(self._g) < 2:
            return g.copy()
        d_f = [b - a for a, b in zip(self._f[:-1], self._f[1:], strict=True)]
        gram = np.array([[np.dot(u, v) for v in d_f] for u in d_f])
        rhs = np.array([np.dot(u, self._f[-1]) for u in d_f])
        gamma = np.linalg.lstsq(gram, rhs, rcond=1e-12)[0]
        out = g.copy()
        for k, gk in enumerate(gamma):
            out -= gk * (self._g[k + 1] - self._g[k])
        return out
