"""Commands of ``asperity``: run, examples, example (and the sub-apps mounted below).

The command line only parses arguments, loads cases, calls runners and writers, and prints.
Bad input ends with one line ``error: <field>: expected ...`` on stderr and exit code 2; a solver
that did not converge ends with exit code 3 after its files are written.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from ..errors import InputError

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Mechanics of rough, loaded, lubricated contacts.")
console = Console()
err_console = Console(stderr=True)

EXIT_BAD_INPUT = 2
EXIT_NOT_CONVERGED = 3


def fail(message: str, code: int = EXIT_BAD_INPUT):
    """Print one error line on stderr and exit."""
    err_console.print(f"error: {message}", markup=False, highlight=False, soft_wrap=True)
    raise typer.Exit(code)


def guarded(fn):
    """Run ``fn``; turn an InputError into one line and exit code 2."""
    import functools

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except InputError as exc:
            fail(str(exc))

    return wrapper


@app.command()
@guarded
def run(
    case: Annotated[str | None, typer.Argument(help="Case file (TOML) or built-in example name; "
                                               "the default example when omitted.")] = None,
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder.")] = Path(
        "asperity-out"),
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False,
):
    """Run a case: write result.nc, summary.json, figures and report.html to OUT."""
    from ..cases import load_case
    from ..examples import DEFAULT_EXAMPLE, example_text
    from ..report import write_report
    from ..results import write_outcome
    from ..runners import run_case
    from .progress import progress_bar

    if case is None:
        case = DEFAULT_EXAMPLE
    is_file = case.endswith(".toml") or Path(case).is_file()
    model = load_case(Path(case) if is_file else example_text(case))
    console.print(f"[bold]{model.title}[/bold] ({model.analysis})")
    with progress_bar(console, disable=quiet) as progress:
        outcome = run_case(model, progress=progress)
    files = write_outcome(outcome, out)
    files["report"] = write_report(model.title, model.model_dump(mode="json"), outcome, files,
                                   Path(out) / "report.html")
    _print_summary(outcome.summary)
    console.print(f"wrote {len(files)} files to {out}/ (report: {files['report']})")
    if not outcome.converged:
        fail("the solver did not converge; see report.html", EXIT_NOT_CONVERGED)


def _print_summary(summary: dict) -> None:
    table = Table(show_header=False, box=None)
    for key, value in summary.items():
        if isinstance(value, float):
            value = f"{value:.6g}"
        table.add_row(key, str(value))
    console.print(table)


@app.command()
@guarded
def examples():
    """List the built-in examples."""
    from ..examples import DEFAULT_EXAMPLE, list_examples

    table = Table(title="asperity examples (asperity example NAME prints one)")
    for col in ("name", "analysis", "description", "source"):
        table.add_column(col, overflow="fold")
    for ex in list_examples():
        name = ex.name + (" (default)" if ex.name == DEFAULT_EXAMPLE else "")
        name += " [long]" if ex.long_running else ""
        table.add_row(name, ex.analysis, ex.description or ex.title, ex.source)
    console.print(table)


@app.command()
@guarded
def example(name: Annotated[str, typer.Argument(help="Example name (see asperity examples).")]):
    """Print a built-in example as TOML (save it, edit it, run it)."""
    from ..examples import example_text

    sys.stdout.write(example_text(name))


def main() -> None:
    """Entry point of the console script."""
    app()
