"""``asperity gear``: a gear pair along its path of contact, with the transient hand-off.

``asperity gear CASE --out DIR`` runs an ``analysis = "gear"`` case like ``asperity run``;
``--emit-transient DIR2`` also writes the ``ehl-transient`` case of one position of the path
(``--at pitch``, ``min-lambda``, ``max-flash`` or a roll angle such as ``"24 deg"``; default the
case's ``[handoff] at``) to ``DIR2/transient.toml``, ready for ``asperity run``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError

__all__ = ["gear"]


def gear(
    case: Annotated[str, typer.Argument(help="Gear case file (TOML) or built-in example.")],
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder.")] = Path(
        "asperity-gear"),
    emit_transient: Annotated[Path | None, typer.Option(
        "--emit-transient", help="Write the ehl-transient case of one path position to "
                                 "DIR/transient.toml.")] = None,
    at: Annotated[str | None, typer.Option(
        "--at", help='Position: pitch, min-lambda, max-flash or a roll angle ("24 deg"); '
                     "default the case's \\[handoff] at.")] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False,
):
    """Film, lambda, friction and flash temperature along the path of contact."""
    from ..cases import load_case
    from ..examples import example_text
    from ..runners.gear import handoff, outcome, solve
    from .app import EXIT_NOT_CONVERGED, console, err_console, fail
    from .progress import progress_bar

    is_file = case.endswith(".toml") or Path(case).is_file()
    model = load_case(Path(case) if is_file else example_text(case))
    if model.analysis != "gear":
        raise InputError("analysis", '"gear" for asperity gear (use asperity run)',
                         model.analysis)
    for folder, option in ((out, "--out"), (emit_transient, "--emit-transient")):
        if folder is not None and folder.exists() and not folder.is_dir():
            raise InputError(option, "a folder (this is an existing file)", str(folder))
        if folder is not None:
            folder.mkdir(parents=True, exist_ok=True)
    console.print(f"[bold]{model.title}[/bold] (gear)")
    with progress_bar(console, disable=quiet) as progress:
        result, seconds = solve(model, progress)
    done = outcome(model, result, seconds)
    done.case = model
    files = done.write(out)
    for key in ("transverse_contact_ratio", "overlap_ratio", "minimum_lambda",
                "maximum_flash_temperature_k", "maximum_hertz_pressure_pa",
                "pitch_hertz_pressure_pa", "iso_nominal_contact_stress_pa", "ehl_wall_time_s"):
        console.print(f"{key:32s} {done.summary[key]:.4g}")
    console.print(f"wrote {len(files)} files to {out}/ (report: {files['report']})")
    if emit_transient is not None:
        data, text = handoff(model, result, at)
        load_case(data)  # the emitted case must validate as it is written
        target = Path(emit_transient) / "transient.toml"
        target.write_text(text, encoding="utf-8")
        console.print(f"wrote the transient case {target} (asperity run {target})")
    for line in done.warnings:
        err_console.print(f"warning: {line}", markup=False, highlight=False, soft_wrap=True)
    if not done.converged:
        fail("the EHL solver did not converge at every path point; see report.html",
             EXIT_NOT_CONVERGED)
