"""Files written atomically: a temporary file beside the target, renamed onto it.

Shared by the output layer (:mod:`asperity.results`, :mod:`asperity.report`, the sweeps) and
the solvers' checkpoints (:mod:`asperity.ehl.checkpoint`), so that a solver does not import
the output layer. :func:`os.replace` within one folder is atomic on POSIX and Windows: a run
killed while writing leaves the previous file intact.
"""

from __future__ import annotations

import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

__all__ = ["atomic_path"]


@contextmanager
def atomic_path(path: str | Path):
    """Yield a temporary path next to ``path``; rename it onto ``path`` if the block succeeds."""
    path = Path(path)
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
