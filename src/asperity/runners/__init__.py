"""Runners: a validated case in, an :class:`asperity.results.Outcome` out.

Each analysis has one module with ``run(case, progress=None) -> Outcome``. Runners build the
bodies, surfaces and grids a case describes, call the solvers, and package fields, scalars,
figures and reference comparisons. They never read case files or write output files.
"""

from __future__ import annotations

import warnings
from importlib import import_module

__all__ = ["RUNNERS", "run_case"]

#: analysis key -> module holding its ``run`` function
RUNNERS = {
    "normal": "normal",
    "surface": "surface",
    "ehl-steady": "ehl_steady",
    "ehl-transient": "ehl_transient",
    "tangential": "tangential",
    "gear": "gear",
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

    Notes
    -----
    Warnings the library issues during the run (``warnings.warn``) join the Outcome's
    ``warnings``, so that they reach summary.json and the report; numpy's floating-point
    warnings are shown as usual.
    """
    module = import_module(f".{RUNNERS[case.analysis]}", __name__)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if getattr(module, "CHECKPOINTS", False):
            outcome = module.run(case, progress=progress, workdir=workdir, resume=resume)
        else:
            outcome = module.run(case, progress=progress)
    for w in caught:
        message = str(w.message)
        numeric = " encountered in " in message
        if issubclass(w.category, DeprecationWarning | FutureWarning) or numeric:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
        elif message not in outcome.warnings:
            outcome.warnings.append(message)
    outcome.case = case
    return outcome
