"""Allocator settings for long solver runs: keep freed memory in the process for reuse.

A step of the transient EHL solver creates and frees dozens of arrays of one to a few MB
(flow fields, far-field FFT spectra, the vectors of the Anderson mixer). glibc's ``malloc``
serves blocks of that size from the heap but returns the freed top of the heap to the kernel
once more than ``M_TRIM_THRESHOLD`` of it is free (a few MB by default), so a new temporary
page-faults on every page when it is first written. On the seed's gear case at its mesh
spacing (571 x 201 nodes) that cost 16 % of a timestep (0.49 s against 0.41 s per step,
median of 30 rough steps; docs/ehl-transient.md); measured again once the Anderson mixer no
longer woke OpenBLAS' threads, on the 801 x 201 paper case (10 steps from step 1,900, medians
of 5 runs alternated on a busy machine), 22.7 against 20.2 ms per sweep.

:func:`retain_freed_memory` raises the trim threshold and fixes the mmap threshold (so that
blocks up to it always come from the reusable heap). It changes the whole process, so the
library never calls it on import: the command line does, once, before it runs a case; a
script that runs long transient cases may call it too. Elsewhere than on glibc it does
nothing.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

__all__ = ["retain_freed_memory"]

_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3
_MMAP_THRESHOLD_MAX_MB = 32  # glibc's upper limit for M_MMAP_THRESHOLD on 64-bit systems


def retain_freed_memory(trim_mb: int = 256, mmap_mb: int = _MMAP_THRESHOLD_MAX_MB) -> bool:
    """Ask glibc to keep up to ``trim_mb`` MB of freed heap and to serve blocks below
    ``mmap_mb`` MB from the heap (``mallopt(M_TRIM_THRESHOLD)``, ``mallopt(M_MMAP_THRESHOLD)``).

    Parameters
    ----------
    trim_mb : int
        Free memory at the top of the heap, MB, that is kept instead of returned to the kernel.
    mmap_mb : int
        Blocks of at least this size, MB, are mapped and unmapped one by one (at most 32).

    Returns
    -------
    bool
        Whether both settings were applied (False off Linux/glibc).
    """
    if not sys.platform.startswith("linux"):
        return False
    name = ctypes.util.find_library("c")
    try:
        mallopt = ctypes.CDLL(name).mallopt
    except (OSError, AttributeError, TypeError):
        return False
    mmap_mb = min(int(mmap_mb), _MMAP_THRESHOLD_MAX_MB)
    ok_mmap = mallopt(_M_MMAP_THRESHOLD, mmap_mb << 20)
    ok_trim = mallopt(_M_TRIM_THRESHOLD, int(trim_mb) << 20)
    return bool(ok_mmap and ok_trim)
