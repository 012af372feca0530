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

The history's products and the proposal are compiled loops on the calling thread (two
passes over the vectors per mix), not ``np.dot``: numpy's ``np.dot`` of long vectors runs on
OpenBLAS threads, which keep spinning for about 0.1 s after each call. The mixer runs every
few sweeps, so those threads kept one of the solver's cores busy: on the 801 x 201 gear case
on 2 cores the line sweep took 11.2 instead of 6.8 ms and the flow field 7.8 instead of
4.7 ms, 26.1 instead of 17.9 ms per sweep in all.

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
def _record(x, g, last_f, last_g, d_f, d_g, slot, slots, gram_row, rhs):
    """Record the pair (x, g) in one pass over the vectors: with ``f = g - x``, the new
    differences ``d_f[slot] = f - last_f`` and ``d_g[slot] = g - last_g`` (replacing the
    slot's old ones), the Gram row ``gram_row[k] = d_f[slots[k]] . d_f[slot]`` and
    ``rhs[k] = d_f[slots[k]] . f`` over the remembered slots (``slot`` among them), and
    ``last_f, last_g = f, g``."""
    m = slots.size
    gram_row[:] = 0.0
    rhs[:] = 0.0
    for i in range(x.size):
        fi = g[i] - x[i]
        d_f[slot, i] = fi - last_f[i]
        d_g[slot, i] = g[i] - last_g[i]
        last_f[i] = fi
        last_g[i] = g[i]
        for k in range(m):
            u = d_f[slots[k], i]
            gram_row[k] += u * d_f[slot, i]
            rhs[k] += u * fi


@numba.njit(cache=True)
def _propose(g, d_g, slots, gamma, out):
    """``out = g - sum_k gamma[k] d_g[slots[k]]`` in one pass."""
    for i in range(g.size):
        total = g[i]
        for k in range(slots.size):
            total -= gamma[k] * d_g[slots[k], i]
        out[i] = total


class AndersonMixer:
    """Remembers the last ``memory`` differences of the pairs ``(x_i, g(x_i))`` and proposes
    the next iterate.

    Parameters
    ----------
    memory : int
        Number m of residual differences in the least-squares fit (>= 1).
    dot : callable, optional
        ``dot(u, v)``: the dot product of two iterate-sized vectors as a float, for vectors of
        another array library (a GPU's, as in ``benchmarks/ehl_sweep_gpu.py``), which the
        mixer then handles with that library's array operations. Default: numpy vectors,
        whose history the mixer keeps in ring buffers and records and mixes in two compiled
        passes (:func:`_record`, :func:`_propose`) instead of about twenty numpy operations
        that each write a new vector: 2.5 -> 1.4 ms per mix of 230,000 entries (the gear
        case at the seed's spacing, 571 x 201 nodes).
    """

    def __init__(self, memory: int, dot=None):
        self.memory = int(memory)
        self.dot = dot
        self._buffers = None
        self.reset()

    def reset(self):
        """Forget the history (the next :meth:`mix` returns ``g`` unchanged)."""
        self._last = None
        self._d_f: list = []
        self._d_g: list = []
        self._slots: list[int] = []
        self._gram = np.zeros((self.memory, self.memory))

    def mix(self, x, g):
        """Record the pair (x, g(x)) and return the accelerated next iterate.

        With a single pair in the history this is the plain fixed-point step ``g``. The
        least-squares problem is solved through its m x m normal equations (the vectors are
        long, m is small), whose Gram matrix gains one row of dot products per call.
        """
        if self.dot is not None:
            return self._mix_arrays(x, g)
        x, g = np.asarray(x, dtype=float), np.asarray(g, dtype=float)
        if self._buffers is None or self._buffers[0].size != x.size:
            self._buffers = (np.empty(x.size), np.empty(x.size),
                             np.empty((self.memory, x.size)), np.empty((self.memory, x.size)))
        last_f, last_g, d_f, d_g = self._buffers
        if self._last is None:
            np.subtract(g, x, out=last_f)
            last_g[:] = g
            self._last = True
            return g.copy()
        slots = self._slots
        slot = slots.pop(0) if len(slots) == self.memory else len(slots)
        slots.append(slot)
        order = np.array(slots)
        gram_row, rhs = np.empty(order.size), np.empty(order.size)
        _record(x, g, last_f, last_g, d_f, d_g, slot, order, gram_row, rhs)
        self._gram[order, slot] = self._gram[slot, order] = gram_row
        gamma = np.linalg.lstsq(self._gram[np.ix_(order, order)], rhs, rcond=1e-12)[0]
        out = np.empty(x.size)
        _propose(g, d_g, order, gamma, out)
        return out

    def _mix_arrays(self, x, g):
        """:meth:`mix` with the caller's dot product and its array library's operations."""
        f = g - x
        if self._last is not None:
            self._d_f.append(f - self._last[0])
            self._d_g.append(g - self._last[1])
            gram = self._gram[:len(self._d_f) - 1, :len(self._d_f) - 1]
            if len(self._d_f) > self.memory:
                self._d_f.pop(0)
                self._d_g.pop(0)
                gram = gram[1:, 1:]
            m = len(self._d_f)
            self._gram[:m - 1, :m - 1] = gram.copy()
            self._gram[m - 1, :m] = self._gram[:m, m - 1] = [self.dot(u, self._d_f[-1])
                                                            for u in self._d_f]
        self._last = (f, g)
        if not self._d_f:
            return g.copy()
        m = len(self._d_f)
        rhs = np.array([self.dot(u, f) for u in self._d_f])
        gamma = np.linalg.lstsq(self._gram[:m, :m], rhs, rcond=1e-12)[0]
        out = g.copy()
        for gk, d_g in zip(gamma, self._d_g, strict=True):
            out -= gk * d_g
        return out
