"""Results of a run: an xarray Dataset, a summary of scalars, files written atomically.

Every analysis' runner returns an :class:`Outcome`; :func:`write_outcome` writes
``result.nc`` (CF-style: units and long names on every variable, coordinates in m),
``summary.json`` (scalars with unit-suffixed keys) and the figures as PNG. Each file is written
to a temporary name in the same folder and renamed, so a killed run never leaves half a file.
Both data files carry ``status``: ``"complete"``, or ``"partial"`` for the streamed results of
a long run that was stopped (:func:`mark_partial`), and the run's warnings.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import xarray as xr

from .atomic import atomic_path

__all__ = ["Comparison", "Outcome", "atomic_path", "mark_partial", "write_outcome", "write_json",
           "variable"]


@dataclass(frozen=True)
class Comparison:
    """One asperity number next to its reference (closed form, book or paper)."""

    quantity: str
    value: float
    reference: float
    source: str
    unit: str = ""
    tolerance: float | None = None
    note: str = ""

    @property
    def relative_error(self) -> float:
        """(value - reference) / |reference| (NaN when the reference is 0)."""
        return (self.value - self.reference) / abs(self.reference) if self.reference else math.nan

    @property
    def passed(self) -> bool | None:
        """Whether |relative error| <= tolerance; None when no tolerance applies."""
        if self.tolerance is None:
            return None
        return bool(abs(self.relative_error) <= self.tolerance)


@dataclass
class Outcome:
    """What a runner hands to the writers: data, scalars, figures, references.

    Attributes
    ----------
    dataset : xarray.Dataset
        Fields on their coordinates, with ``units`` and ``long_name`` attributes.
    summary : dict
        Scalars with unit-suffixed keys (``max_pressure_pa``) plus ``converged``.
    figures : dict
        File stem -> (callable returning a matplotlib Figure, caption). Figures are drawn only
        when written, so parameter studies that skip them pay nothing.
    comparisons : list of Comparison
        Side-by-side checks against references, shown in the report.
    converged : bool
        False when a solver did not converge; the command line then exits non-zero.
    notes : list of str
        Remarks for the report (assumptions, discrepancies explained).
    warnings : list of str
        One line each for anything that makes the answer untrustworthy or dependent on a
        choice of the user (a domain too small, a mesh too coarse, an inlet too short, a value
        clipped): the quantity, its value, the limit and what to change. Written to
        ``summary.json["warnings"]``, printed by the command line, shown in the report.
    case : pydantic model, optional
        The validated case the outcome came from (set by :func:`asperity.runners.run_case`);
        its title and parameters head the report.
    chosen : dict
        Dotted case key -> the value the run used where the analysis chose it instead of the
        case's default (an EHL mesh and domain chosen for the contact: ``grid.nx``,
        ``grid.x_min`` in Hertz semi-axes, ...); the report's parameters show these. None: the
        key does not apply to the run (a line contact's y bounds), left out of the report.
    """

    dataset: xr.Dataset
    summary: dict
    figures: dict = field(default_factory=dict)
    comparisons: list = field(default_factory=list)
    converged: bool = True
    notes: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    case: object = None
    chosen: dict = field(default_factory=dict)

    def write(self, out_dir: str | Path, figures: bool = True, *, imperial: bool = False) -> dict:
        """Write what ``asperity run`` writes: result.nc, summary.json, figures, report.html.

        ``imperial`` puts imperial values beside SI in the report (``asperity run`` sets it for
        a case given in imperial units).

        Returns
        -------
        dict
            Name -> path of every file written (``"report"``: the HTML report).
        """
        from .report import write_report  # the report renders Outcomes: imported on use

        files = write_outcome(self, out_dir, figures=figures)
        title = getattr(self.case, "title", None) or self.dataset.attrs.get("title", "asperity")
        case = {} if self.case is None else self.case.model_dump(mode="json", exclude_none=True,
                                                                  by_alias=True)
        files["report"] = write_report(title, case, self, files, Path(out_dir) / "report.html",
                                       imperial=imperial)
        return files


def variable(dims, values, units: str, long_name: str, **attrs) -> xr.Variable:
    """An xarray Variable with CF ``units`` and ``long_name`` attributes."""
    return xr.Variable(dims, np.asarray(values), attrs={"units": units, "long_name": long_name,
                                                         **attrs})


def _jsonable(value):
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_jsonable(v) for v in value]
    return value


def write_json(data: dict, path: str | Path) -> None:
    """Write ``data`` as indented JSON, atomically (NaN/inf become null)."""
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(_jsonable(data), indent=2) + "\n", encoding="utf-8")


def write_netcdf(dataset: xr.Dataset, path: str | Path) -> None:
    """Write a Dataset to netCDF-4 (h5netcdf engine), atomically."""
    with atomic_path(path) as tmp:
        dataset.to_netcdf(tmp, engine="h5netcdf")


def write_outcome(outcome: Outcome, out_dir: str | Path, figures: bool = True) -> dict:
    """Write ``result.nc``, ``summary.json`` and (unless ``figures=False``) the PNG figures.

    Returns
    -------
    dict
        Name -> path of every file written.
    """
    import matplotlib.pyplot as plt

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = {"result": out / "result.nc", "summary": out / "summary.json"}
    status = {"status": "complete", "warnings": list(outcome.warnings)}
    write_netcdf(outcome.dataset.assign_attrs(status="complete",
                                              warnings="\n".join(outcome.warnings)),
                 written["result"])
    write_json({**outcome.summary, **status}, written["summary"])
    for stem, (draw, _caption) in (outcome.figures.items() if figures else ()):
        fig = draw()
        path = out / f"{stem}.png"
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format="png", dpi=120, bbox_inches="tight")
        plt.close(fig)
        written[stem] = path
    return written


def mark_partial(out_dir: str | Path, stopped_at: str, command: str) -> int | None:
    """Record in ``summary.json`` that a run was stopped; return the steps its results hold.

    Long runs stream their statistics to ``result.nc`` with ``status = "partial"`` and the
    ``steps_done`` they cover. This writes ``summary.json`` with ``status = "partial"``, where
    the run stopped and the ``command`` that continues it. Without a partial ``result.nc``
    nothing was saved: the summary then says ``status = "interrupted"``.

    Parameters
    ----------
    out_dir : path
        The run's output folder.
    stopped_at : str
        Where the run was when it stopped (the progress description, e.g. a step).
    command : str
        The command line that continues the run (or starts it again).

    Returns
    -------
    int or None
        The steps the partial results cover, or None when there are none.
    """
    out = Path(out_dir)
    steps = None
    try:
        with xr.open_dataset(out / "result.nc", engine="h5netcdf") as ds:
            if ds.attrs.get("status") == "partial":
                steps = int(ds.attrs.get("steps_done", 0))
    except (OSError, ValueError):
        steps = None
    summary = {"status": "interrupted" if steps is None else "partial", "stopped_at": stopped_at,
               "steps_done": steps, "continue_with": command, "warnings": [
                   f"the run was stopped at {stopped_at}; "
                   + ("nothing was saved" if steps is None else
                      f"result.nc holds the statistics of the first {steps} steps only")]}
    write_json(summary, out / "summary.json")
    return steps
