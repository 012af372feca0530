"""Files written atomically: a temporary file beside the target, renamed onto it.

Shared by the output layer (:mod:`asperity.results`, :mod:`asperity.report`, the sweeps) and
the solvers' checkpoints (:mod:`asperity.ehl.checkpoint`), so that a solver does not import
the output layer. :func:`os.replace` within one folder is atomic on POSIX and Windows: a run
killed while writing leaves the previous file intact. SIGINT and SIGTERM are held back while
the file is written and delivered once it is in place, so that an interrupt does not leave an
open netCDF/HDF5 handle behind to be closed, and fail, at exit.
"""

from __future__ import annotations

import os
import signal
import tempfile
import threading
from contextlib import contextmanager
from pathlib import Path

__all__ = ["atomic_path"]


INTERRUPTS = (signal.SIGINT, signal.SIGTERM)


@contextmanager
def interrupts_held():
    """Hold SIGINT and SIGTERM back for the duration of the block, then deliver them.

    A signal that arrives in the block is recorded; on leaving, the previous handlers are put
    back and each recorded signal is raised again, so it acts as if it had come just after the
    block. Only the main thread can set handlers; elsewhere, and for a signal whose handler was
    not set from Python, the block runs unchanged.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught = []
    held = {sig: signal.getsignal(sig) for sig in INTERRUPTS}
    held = {sig: handler for sig, handler in held.items() if handler is not None}
    for sig in held:
        signal.signal(sig, lambda signum, _frame: caught.append(signum))
    try:
        yield
    finally:
        for sig, handler in held.items():
            signal.signal(sig, handler)
        for sig in dict.fromkeys(caught):
            signal.raise_signal(sig)


@contextmanager
def atomic_path(path: str | Path):
    """Yield a temporary path next to ``path``; rename it onto ``path`` if the block succeeds.

    SIGINT and SIGTERM are held back until the file is in place (:func:`interrupts_held`).
    """
    with interrupts_held(), _replaced_on_success(Path(path)) as tmp:
        yield tmp


@contextmanager
def _replaced_on_success(path: Path):
    """Yield a temporary path next to ``path``; rename it onto ``path`` if the block succeeds."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; give the usual permissions
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
