"""Atomic checkpoints of a time-stepping run: named arrays in one ``.npz`` file.

A checkpoint is written to a temporary file beside the target and moved over it with
:func:`os.replace`, so a run killed while writing leaves the previous checkpoint intact. Each
checkpoint carries a fingerprint of the run's inputs; resuming from a checkpoint of a
different run is refused.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

import numpy as np

from ..atomic import atomic_path
from ..errors import InputError

__all__ = ["Checkpointer", "fingerprint", "load_checkpoint", "save_checkpoint"]


def fingerprint(*parts) -> str:
    """SHA-256 of the inputs: arrays by dtype, shape and bytes, everything else by ``repr``."""
    digest = hashlib.sha256()
    for part in parts:
        if isinstance(part, np.ndarray):
            digest.update(f"{part.dtype}{part.shape}".encode())
            digest.update(np.ascontiguousarray(part).tobytes())
        else:
            digest.update(repr(part).encode())
    return digest.hexdigest()


def save_checkpoint(path, key: str, arrays: dict) -> Path:
    """Write ``arrays`` and the fingerprint ``key`` to ``path`` atomically; return the path."""
    path = Path(path)
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        np.savez(fh, fingerprint=np.array(key), **arrays)
        fh.flush()
        os.fsync(fh.fileno())
    return path


def load_checkpoint(path, key: str) -> dict | None:
    """The arrays of the checkpoint at ``path``, or None when there is none.

    Raises
    ------
    InputError
        When the checkpoint belongs to a run with other inputs (fingerprint mismatch).
    """
    path = Path(path)
    if not path.is_file():
        return None
    with np.load(path, allow_pickle=False) as data:
        arrays = {name: data[name] for name in data.files}
    if str(arrays.pop("fingerprint")) != key:
        raise InputError("checkpoint", f"a checkpoint of this same run ({path} was written by a "
                                       "run with other inputs; delete it to start afresh)")
    return arrays


class Checkpointer:
    """Checkpoints of one run every ``every`` steps and at its last step.

    Parameters
    ----------
    path : path or None
        The ``.npz`` file; None: no checkpoints (:meth:`load` gives None, :meth:`due` False).
    key : str
        Fingerprint of the run's inputs (:func:`fingerprint`).
    every : int
        Steps between checkpoints.
    """

    def __init__(self, path, key: str, every: int):
        self.path = None if path is None else Path(path)
        self.key = key
        self.every = every

    def load(self) -> dict | None:
        """The arrays of this run's checkpoint, or None (:func:`load_checkpoint`)."""
        return None if self.path is None else load_checkpoint(self.path, self.key)

    def due(self, step: int, total: int) -> bool:
        """Whether step ``step`` of ``total`` is checkpointed."""
        return self.path is not None and (step % self.every == 0 or step == total)

    def save(self, arrays: dict):
        """Write ``arrays`` atomically (:func:`save_checkpoint`)."""
        save_checkpoint(self.path, self.key, arrays)
