"""Runners: a validated case in, an :class:`asperity.results.Outcome` out.

Each analysis has one module with ``run(case, progress=None) -> Outcome``. Runners build the
bodies, surfaces and grids a case describes, call the solvers, and package fields, scalars,
figures and reference comparisons. They never read case files or write output files.
"""

from __future__ import annotations

from importlib import import_module

__all__ = ["RUNNERS", "run_case"]

#: analysis key -> module holding its ``run`` function
RUNNERS = {
    "normal": "normal",
    "surface": "surface",
    "ehl-steady": "ehl_steady",
    "ehl-transient": "ehl_transient",
    "tangential": "tangential",
}


def run_case(case, progress=None, *, workdir=None, resume=False):
    """Run a validated case and return its Outcome.

    Parameters
    ----------
    case : pydantic model
        From :func:`asperity.cases.load_case`.
    progress : callable, optional
        ``progress(done, total, description)`` for progress bars.
    workdir : path, optional
        Folder for checkpoints and streamed partial results of long runs (runners whose
        module sets ``CHECKPOINTS = True``); others ignore it.
    resume : bool
        Continue a checkpointed run from ``workdir``.
    """
    module = import_module(f".{RUNNERS[case.analysis]}", __name__)
    if getattr(module, "CHECKPOINTS", False):
        return module.run(case, progress=progress, workdir=workdir, resume=resume)
    return module.run(case, progress=progress)
