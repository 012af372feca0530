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

The dot products are compiled loops on the calling thread rather than ``np.dot``: numpy's
``np.dot`` of long vectors runs on OpenBLAS threads, which keep spinning for about 0.1 s after
each call. The mixer runs every few sweeps, so those threads kept one of the solver's cores
busy: on the 801 x 201 gear case on 2 cores the line sweep took 11.2 instead of 6.8 ms and the
flow field 7.8 instead of 4.7 ms, 26.1 instead of 17.9 ms per sweep in all.

References
----------
D. G. Anderson, J. ACM 12 (1965) 547-560.
H. F. Walker, P. Ni, SIAM J. Numer. Anal. 49 (2011) 1715-1735.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["AndersonMixer"]


@numba.njit(cache=True, fastmath={"reassoc"})
def _dot(u, v):
    """``u . v`` of two 1-D float arrays, on the calling thread (reassociated: vectorised)."""
    total = 0.0
    for i in range(u.size):
        total += u[i] * v[i]
    return total


class AndersonMixer:
    """Remembers the last ``memory`` differences of the pairs ``(x_i, g(x_i))`` and proposes
    the next iterate.

    Parameters
    ----------
    memory : int
        Number m of residual differences in the least-squares fit (>= 1).
    dot : callable, optional
        ``dot(u, v)``: the dot product of two iterate-sized vectors as a float. Default: the
        compiled loop for numpy arrays; vectors of another array library (a GPU's, as in
        ``benchmarks/ehl_sweep_gpu.py``) need that library's.
    """

    def __init__(self, memory: int, dot=None):
        self.memory = int(memory)
        self.dot = _dot if dot is None else dot
        self.reset()

    def reset(self):
        """Forget the history (the next :meth:`mix` returns ``g`` unchanged)."""
        self._last = None
        self._d_f: list[np.ndarray] = []
        self._d_g: list[np.ndarray] = []
        self._gram = np.zeros((0, 0))

    def mix(self, x: np.ndarray, g: np.ndarray) -> np.ndarray:
        """Record the pair (x, g(x)) and return the accelerated next iterate.

        With a single pair in the history this is the plain fixed-point step ``g``. The
        least-squares problem is solved through its m x m normal equations (the vectors are
        long, m is small), whose Gram matrix gains one row of dot products per call.
        """
        if self.dot is _dot:
            x, g = np.asarray(x, dtype=float), np.asarray(g, dtype=float)
        f = g - x
        if self._last is not None:
            self._d_f.append(f - self._last[0])
            self._d_g.append(g - self._last[1])
            gram = self._gram
            if len(self._d_f) > self.memory:
                self._d_f.pop(0)
                self._d_g.pop(0)
                gram = gram[1:, 1:]
            row = np.array([self.dot(u, self._d_f[-1]) for u in self._d_f])
            self._gram = np.empty((row.size, row.size))
            self._gram[:-1, :-1] = gram
            self._gram[-1] = self._gram[:, -1] = row
        self._last = (f, g)
        if not self._d_f:
            return g.copy()
        rhs = np.array([self.dot(u, f) for u in self._d_f])
        gamma = np.linalg.lstsq(self._gram, rhs, rcond=1e-12)[0]
        out = g.copy()
        for gk, d_g in zip(gamma, self._d_g, strict=True):
            out -= gk * d_g
        return out
