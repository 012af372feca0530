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

#: Blocks of the parallel passes: partial dot products are summed per block, then over the
#: blocks in a fixed order, so a mix does not depend on the number of threads.
_BLOCKS = 64


@numba.njit(parallel=True, cache=True)
def _record(x, g, last, df, dg, slot, slots, dots):
    """Record the pair (x, g) in history slot ``slot`` and return its dot products.

    With ``f = g - x`` and ``last = (f, g)`` of the previous pair: ``df[slot] = f - last[0]``,
    ``dg[slot] = g - last[1]``, then ``last = (f, g)``; ``dots[0, a] = df[slots[a]] .
    df[slot]`` (the new row of the Gram matrix) and ``dots[1, a] = df[slots[a]] . f`` (the
    right-hand side), ``slots`` holding ``slot``. One pass, in ``_BLOCKS`` blocks.
    """
    n = x.size
    m = slots.size
    size = (n + _BLOCKS - 1) // _BLOCKS
    partial = np.zeros((_BLOCKS, 2, m))
    for block in numba.prange(_BLOCKS):
        for i in range(block * size, min(n, (block + 1) * size)):
            f = g[i] - x[i]
            d = f - last[0, i]
            df[slot, i] = d
            dg[slot, i] = g[i] - last[1, i]
            last[0, i] = f
            last[1, i] = g[i]
            for a in range(m):
                u = df[slots[a], i]
                partial[block, 0, a] += u * d
                partial[block, 1, a] += u * f
    dots[:] = 0.0
    for block in range(_BLOCKS):
        dots += partial[block]


@numba.njit(parallel=True, cache=True)
def _combine(g, dg, slots, gamma, out):
    """``out = g - sum_a gamma[a] dg[slots[a]]``, the mixer's proposal."""
    m = slots.size
    for i in numba.prange(g.size):
        v = g[i]
        for a in range(m):
            v -= gamma[a] * dg[slots[a], i]
        out[i] = v


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
        mixed by the compiled passes :func:`_record` and :func:`_combine`.
    """

    def __init__(self, memory: int, dot=None):
        self.memory = int(memory)
        self.dot = dot
        self._df = self._dg = self._last = None
        self._size = -1
        self.reset()

    def reset(self):
        """Forget the history (the next :meth:`mix` returns ``g`` unchanged)."""
        self._pairs = 0
        self._slots: list[int] = []
        self._gram = np.zeros((0, 0))

    def mix(self, x, g):
        """Record the pair (x, g(x)) and return the accelerated next iterate (a new vector).

        With a single pair in the history this is the plain fixed-point step ``g``. The
        least-squares problem is solved through its m x m normal equations (the vectors are
        long, m is small), whose Gram matrix gains one row of dot products per call; the
        oldest difference is dropped once there are ``memory`` of them.
        """
        if self.dot is None:
            x, g = np.asarray(x, dtype=float), np.asarray(g, dtype=float)
        self._allocate(g)
        if self._pairs == 0:
            self._pairs = 1
            self._last[0] = g - x
            self._last[1] = g
            return g.copy()
        slots = self._slots
        gram = self._gram
        if len(slots) == self.memory:
            slot = slots.pop(0)
            gram = gram[1:, 1:]
        else:
            slot = min(set(range(self.memory)) - set(slots))
        slots.append(slot)
        dots = self._record(x, g, slot)
        self._gram = np.empty((len(slots), len(slots)))
        self._gram[:-1, :-1] = gram
        self._gram[-1] = self._gram[:, -1] = dots[0]
        gamma = np.linalg.lstsq(self._gram, dots[1], rcond=1e-12)[0]
        if self.dot is None:
            out = np.empty_like(g)
            _combine(g, self._dg, np.array(slots), gamma, out)
            return out
        out = g.copy()
        for gk, slot in zip(gamma, slots, strict=True):
            out -= gk * self._dg[slot]
        return out

    def _allocate(self, g):
        """The history buffers, for vectors like ``g`` (kept while the size stays)."""
        if g.size == self._size:
            return
        self._size = g.size
        if self.dot is None:
            self._df = np.empty((self.memory, g.size))
            self._dg = np.empty((self.memory, g.size))
            self._last = np.empty((2, g.size))
        else:
            self._df = [None] * self.memory
            self._dg = [None] * self.memory
            self._last = [None, None]

    def _record(self, x, g, slot):
        """Store the differences of the new pair in ``slot``; its Gram row and right-hand
        side, ``(2, len(slots))``, in the order of the history."""
        slots = self._slots
        if self.dot is None:
            dots = np.empty((2, len(slots)))
            _record(x, g, self._last, self._df, self._dg, slot, np.array(slots), dots)
            return dots
        f = g - x
        self._df[slot] = f - self._last[0]
        self._dg[slot] = g - self._last[1]
        self._last = [f, g]
        return np.array([[self.dot(self._df[a], self._df[slot]) for a in slots],
                         [self.dot(self._df[a], f) for a in slots]])
