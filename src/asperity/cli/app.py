"""Commands of ``asperity``: run, examples, example (and the sub-apps mounted below).

The command line only parses arguments, loads cases, calls runners and writers, and prints.
Bad input (a case file, an option, an output folder that cannot be written) ends with one line
``error: <field>: expected ...`` on stderr and exit code 2; a solver that did not converge ends
with exit code 3 after its files are written, on one line saying why (its own message: what
did not converge, and the key to change). Every warning of a run (``Outcome.warnings``: a
domain too small, a mesh too coarse, an inlet too short, ...) is one line ``warning: ...`` on
stderr; ``run --strict`` makes them exit code 3. Ctrl-C or SIGTERM during a run prints one line
saying where it stopped, where the partial results are and how to continue, and exits with
128 + the signal number. A command line that click cannot parse (an unknown option, a missing
argument, an unknown command) is an input error too: one line ``error: --bogus: no such
option``, exit code 2, and a second line naming the command's ``--help``.
"""

from __future__ import annotations

import math
import os
import shlex
import signal
import sys
import warnings
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from ..errors import InputError
from ..memory import retain_freed_memory

console = Console()
err_console = Console(stderr=True)

EXIT_BAD_INPUT = 2
EXIT_NOT_CONVERGED = 3
#: ``run --strict`` with warnings exits with this code too (the answer is not to be trusted).
EXIT_WARNINGS = 3
#: Largest case file read (a case file holds keys; measured data go in their own files).
MAX_CASE_BYTES = 4 * 2**20
#: An unexpected exception (a bug): one line instead of a traceback.
EXIT_INTERNAL = 1


def fail(message: str, code: int = EXIT_BAD_INPUT):
    """Print one error line on stderr and exit."""
    err_console.print(f"error: {message}", markup=False, highlight=False, soft_wrap=True)
    raise typer.Exit(code)


#: Click's exceptions, from the module typer's own ``BadParameter`` lives in: click itself with
#: an older typer, the copy of it that typer >= 0.24 ships (whose classes are not click's).
_CLICK_ERRORS = sys.modules[typer.BadParameter.__module__]
#: ``asperity`` alone prints the help (click >= 8.2 raises it as a usage error).
_NO_ARGS_IS_HELP = getattr(_CLICK_ERRORS, "NoArgsIsHelpError", ())


def usage_field(exc) -> str:
    """The option, argument or command a click usage error is about, as the user typed it
    (``--bogus``, ``case``); ``command`` where click names none."""
    name = getattr(exc, "option_name", None)
    param = getattr(exc, "param", None)
    if not name and param is not None:
        name = max(param.opts, key=len) if param.param_type_name == "option" else param.name
    return name or "command"


def usage_problem(exc, field: str) -> str:
    """Click's message without the option it names (the line names it first)."""
    if isinstance(exc, _CLICK_ERRORS.MissingParameter):
        return "missing (a value is required)"
    if isinstance(exc, _CLICK_ERRORS.NoSuchOption):
        text = "no such option" + exc.format_message().removeprefix(f"No such option: {field}")
    elif isinstance(exc, _CLICK_ERRORS.BadParameter):
        text = exc.message
    else:  # "Option '--out' requires an argument.", "No such command 'frob'."
        text = exc.format_message().removeprefix(f"Option '{field}' ")
    text = " ".join(text.split()).removesuffix(".")
    return text[:1].lower() + text[1:]


class OneLineUsageErrors(typer.core.TyperGroup):
    """The command group of ``asperity``: a usage error anywhere below it (an unknown option,
    a missing argument, an unknown command) is one ``error: <option>: ...`` line, exit code 2,
    and a line pointing to the command's ``--help``, instead of click's boxed panel."""

    def make_context(self, info_name, args, parent=None, **extra):
        """Parse the group's own options; a usage error becomes one line."""
        try:
            return super().make_context(info_name, args, parent=parent, **extra)
        except _NO_ARGS_IS_HELP:
            raise
        except _CLICK_ERRORS.UsageError as exc:
            usage_failure(exc)

    def invoke(self, ctx):
        """Run the subcommand; a usage error in parsing its command line becomes one line."""
        try:
            return super().invoke(ctx)
        except _NO_ARGS_IS_HELP:
            raise
        except _CLICK_ERRORS.UsageError as exc:
            usage_failure(exc)


def usage_failure(exc):
    """Print a click usage error as the one ``error:`` line of bad input, the command's
    ``--help`` on a second line, and exit with code 2."""
    field = usage_field(exc)
    err_console.print(f"error: {field}: {usage_problem(exc, field)}", markup=False,
                      highlight=False, soft_wrap=True)
    if exc.ctx is not None:
        err_console.print(f"(see '{exc.ctx.command_path} --help')", markup=False,
                          highlight=False, soft_wrap=True)
    raise typer.Exit(EXIT_BAD_INPUT)


app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  cls=OneLineUsageErrors, help="Mechanics of rough, loaded, lubricated contacts.")


def guarded(fn):
    """Run ``fn``; turn bad input, an unreadable or unwritable file, or exhausted memory into
    one line and exit code 2, and any other exception (a bug) into one line and exit code 1
    (the traceback with ``ASPERITY_DEBUG=1``)."""
    import functools

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except InputError as exc:
            fail(str(exc))
        except OSError as exc:
            name = exc.filename if exc.filename is not None else "file"
            fail(f"{name}: {exc.strerror or exc}")
        except MemoryError:
            fail("memory: the case needs more memory than this machine has; use fewer cells")
        except (typer.Exit, typer.Abort):
            raise
        except KeyboardInterrupt:
            err_console.print("stopped: SIGINT; run the same command again (a sweep resumes "
                              "from its records)", markup=False, highlight=False)
            raise typer.Exit(128 + signal.SIGINT) from None
        except Exception as exc:  # a bug: still one line, unless asked for the traceback
            if os.environ.get("ASPERITY_DEBUG"):
                raise
            detail = " ".join(str(exc).split())
            fail(f"internal: {type(exc).__name__}: {detail} (a bug in asperity: please report "
                 "it with the case file; ASPERITY_DEBUG=1 shows the traceback)", EXIT_INTERNAL)

    return wrapper


class Interrupted(Exception):
    """Raised in the main thread by SIGINT or SIGTERM during a run."""

    def __init__(self, signum: int):
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


def _check_case_file(path: Path) -> None:
    """Fail unless ``path`` is a readable UTF-8 text file (binary, UTF-16, a folder: no)."""
    if path.is_dir():
        raise InputError("case", "a TOML case file, not a folder", str(path))
    if not path.is_file():
        return  # load_case names the missing file
    if path.stat().st_size > MAX_CASE_BYTES:
        raise InputError("case", f"a TOML case file of at most {MAX_CASE_BYTES // 2**20} MiB "
                         "(data belong in a separate file named by path)", str(path))
    data = path.read_bytes()
    if b"\x00" in data:
        raise InputError("case", "a UTF-8 TOML text file (this one is binary or UTF-16)",
                         str(path))
    try:
        data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError("case", f"a UTF-8 TOML text file (byte {exc.start} is not UTF-8)",
                         str(path)) from None


def _check_out_dir(out: Path) -> None:
    """Fail unless ``out`` is (or can be made) a folder this process can write into."""
    if out.exists() and not out.is_dir():
        raise InputError("--out", "a folder (this is an existing file)", str(out))
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("--out", f"a folder that can be created ({exc.strerror})",
                         str(out)) from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise InputError("--out", "a folder this user can write into", str(out))


@app.command()
@guarded
def run(
    case: Annotated[str | None, typer.Argument(help="Case file (TOML) or built-in example name; "
                                               "the default example when omitted.")] = None,
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder.")] = Path(
        "asperity-out"),
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False,
    resume: Annotated[bool, typer.Option("--resume", help="Continue a checkpointed long run "
                                                          "(transient EHL) in OUT.")] = False,
    strict: Annotated[bool, typer.Option("--strict", help="Exit with code 3 when the run has "
                                                          "warnings.")] = False,
):
    """Run a case: write result.nc, summary.json, figures and report.html to OUT."""
    from ..cases import load_case
    from ..cases.doubts import unit_doubts
    from ..examples import DEFAULT_EXAMPLE, example_text
    from ..runners import run_case
    from .progress import progress_bar

    if case is None:
        case = DEFAULT_EXAMPLE
    is_file = case.endswith(".toml") or Path(case).is_file()
    if is_file:
        _check_case_file(Path(case))
    model = load_case(Path(case) if is_file else example_text(case))
    _check_out_dir(out)
    console.print(f"[bold]{model.title}[/bold] ({model.analysis})")
    # the doubts on the units need no solve: said before it (a bare 210000 modulus, read as
    # 210 kPa, was said after a 163 s solve), and not again after it
    early = unit_doubts(model)
    for line in early:
        err_console.print(f"warning: {line}", markup=False, highlight=False, soft_wrap=True)
    where = {"description": "the start"}
    pending = []  # a signal whose exception landed where Python ignores it (a weakref callback)

    def interrupt(signum, _frame):
        pending.append(signum)
        raise Interrupted(signum)

    previous_hook = sys.unraisablehook

    def unraisable(info):
        if not isinstance(info.exc_value, Interrupted):  # that one is taken up from pending
            previous_hook(info)

    handlers = {sig: signal.signal(sig, interrupt) for sig in (signal.SIGINT, signal.SIGTERM)}
    sys.unraisablehook = unraisable
    try:
        with progress_bar(console, disable=quiet) as progress, warnings.catch_warnings():
            warnings.showwarning = _warning_line  # numpy's, also when not started by main()

            def tracked(done, total=None, description=None):
                if pending:
                    raise Interrupted(pending[0])
                where["description"] = description or f"step {done}"
                progress(done, total, description)

            outcome = run_case(model, progress=tracked, workdir=out, resume=resume)
        if pending:
            raise Interrupted(pending[0])
        where["description"] = "writing the results"
        imperial = _in_imperial(case, is_file)
        files = outcome.write(out, imperial=imperial)  # outcome.case is the model
    except Interrupted as exc:
        _stopped(exc, where["description"], case, out, quiet)
    finally:
        for sig, handler in handlers.items():
            signal.signal(sig, handler)
        sys.unraisablehook = previous_hook
    _print_summary(outcome.summary, imperial)
    _print_differences(outcome.comparisons, imperial)
    console.print(f"wrote {len(files)} files to {out}/ (report: {files['report']})")
    for line in outcome.warnings:
        if line not in early:
            err_console.print(f"warning: {line}", markup=False, highlight=False,
                              soft_wrap=True)
    if not outcome.converged:  # the run's own reason, with the key to change where it has one
        from ..sweep import convergence_message

        fail(f"{convergence_message(outcome)} (report: {files['report']})", EXIT_NOT_CONVERGED)
    if outcome.warnings and strict:
        fail(f"{len(outcome.warnings)} warning(s) and --strict; see report.html", EXIT_WARNINGS)
    if not outcome.warnings:
        console.print("Converged.")


def _in_imperial(case: str, is_file: bool) -> bool:
    """Whether the case file (or built-in example) gives quantities in imperial units."""
    from ..cases import parse_toml
    from ..examples import example_text
    from ..formatting import given_in_imperial

    text = Path(case).read_text(encoding="utf-8") if is_file else example_text(case)
    return given_in_imperial(parse_toml(text, case))


def _stopped(exc: Interrupted, where: str, case: str, out: Path, quiet: bool):
    """Say where an interrupted run stopped and how to go on; mark its files partial; exit."""
    from ..results import mark_partial

    again = ["asperity", "run", case, "--out", str(out)] + (["--quiet"] if quiet else [])
    steps = mark_partial(out, where, " ".join(map(shlex.quote, again + ["--resume"])))
    if steps is None:
        message = (f"{exc} at {where}: no partial results were saved yet; start again with: "
                   f"{shlex.join(again)}")
    else:
        message = (f"{exc} at {where}: partial results (up to step {steps}) are in {out}/; "
                   f"continue with: {shlex.join(again + ['--resume'])}")
    err_console.print(f"stopped: {message}", markup=False, highlight=False, soft_wrap=True)
    raise typer.Exit(128 + exc.signum)


def _print_differences(comparisons, imperial: bool = False) -> None:
    """One line per comparison beyond its tolerance (the report's "differs" rows): a user's
    own reference 20 % off was in report.html alone."""
    from ..formatting import format_quantity

    for c in comparisons:
        if c.passed is False:
            console.print(
                f"differs: {c.quantity} {format_quantity(c.value, c.unit, imperial=imperial)} "
                f"against {format_quantity(c.reference, c.unit, imperial=imperial)} "
                f"({c.source}): {_percent(c.relative_error)}, beyond the "
                f"{100 * c.tolerance:.3g} % tolerance", markup=False, highlight=False,
                soft_wrap=True)


def _percent(relative: float) -> str:
    """A relative difference in percent, ``n/a`` where it is not a number (a zero
    reference), as the report's comparison table writes it."""
    return f"{100 * relative:+.1f} %" if math.isfinite(relative) else "n/a"


def _print_summary(summary: dict, imperial: bool = False) -> None:
    """The key results as in the report: in words, readable units (imperial beside SI)."""
    from ..formatting import summary_rows

    table = Table(show_header=False, box=None)
    table.add_column(overflow="fold")
    table.add_column(justify="right", overflow="fold")
    for row in summary_rows(summary, imperial=imperial):
        table.add_row(row.label, row.text)
    console.print(table, highlight=False)


@app.command()
@guarded
def examples():
    """List the built-in examples and parameter studies."""
    show_examples(console)


def show_examples(out: Console) -> None:
    """Print the built-in examples grouped by analysis, then the studies, on ``out``.

    Each name stands on its own line with its description and source indented below, so the
    list reads at any width down to 80 columns (no table columns squeezed to a letter).
    """
    from rich.padding import Padding
    from rich.text import Text

    from ..examples import DEFAULT_EXAMPLE, list_examples, list_studies

    out.print("[bold]asperity examples[/] (asperity example NAME prints one, asperity run NAME "
              "runs it)", highlight=False)
    by_analysis: dict[str, list] = {}
    for ex in list_examples():
        by_analysis.setdefault(ex.analysis, []).append(ex)
    for analysis, items in by_analysis.items():
        out.print(f"\n[bold underline]{analysis}[/]", highlight=False)
        for ex in items:
            name = Text(ex.name, style="bold cyan")
            if ex.name == DEFAULT_EXAMPLE:
                name.append(" (default)", style="green")
            if ex.long_running:
                name.append(" (long run)", style="yellow")
            out.print(Padding(name, (0, 0, 0, 2)), highlight=False)
            text = Text(ex.description or ex.title)
            if ex.source:
                text.append(f"\nSource: {ex.source}", style="dim")
            out.print(Padding(text, (0, 0, 0, 6)), highlight=False)
    out.print("\n[bold]parameter studies[/] (asperity example NAME prints one, asperity sweep "
              "NAME runs it)", highlight=False)
    for name, description in list_studies():
        out.print(Padding(Text(name, style="bold cyan"), (0, 0, 0, 2)), highlight=False)
        out.print(Padding(Text(description), (0, 0, 0, 6)), highlight=False)


@app.command()
@guarded
def example(
    name: Annotated[str, typer.Argument(help="Example or study name (see asperity examples).")],
    out: Annotated[Path | None, typer.Option(
        "--out", help="Write NAME.toml and the data it names into this folder.")] = None,
):
    """Print a built-in example or parameter study as TOML, or write it to --out.

    Save it, edit it, then run it: asperity run (an example) or asperity sweep (a study).
    """
    from ..examples import builtin_text, write_example

    if out is None:
        sys.stdout.write(builtin_text(name)[1])
        return
    for path in write_example(name, out):
        console.print(f"wrote {path}")


@app.command()
@guarded
def validate(
    select: Annotated[str | None, typer.Option(
        "--select", "-k", help="Only checks whose name contains this.")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Machine-readable output.")] = False,
    slow: Annotated[bool, typer.Option("--slow", help="Include the paper-mesh checks "
                                                      "(minutes).")] = False,
):
    """Run the analytical and published-number checks; print the validation table."""
    import json

    from ..validation import run_checks

    rows = run_checks(select, slow=slow)
    if not rows:
        hint = "" if slow else " (the paper-mesh checks need --slow)"
        raise InputError("--select", "", select,
                         problem=f"no check name contains it{hint}; 0 checks run")
    failed = [r for _, r in rows if r.passed is False]
    if as_json:
        sys.stdout.write(json.dumps([
            {"case": name, "quantity": r.quantity, "reference": r.reference, "asperity": r.value,
             "unit": r.unit, "relative_error": r.relative_error, "tolerance": r.tolerance,
             "passed": r.passed, "source": r.source} for name, r in rows], indent=2) + "\n")
    else:
        table = Table(title=f"asperity validation: {len(rows) - len(failed)} of {len(rows)} pass")
        for col in ("case", "quantity", "reference", "asperity", "unit", "rel. error",
                    "tolerance", ""):
            table.add_column(col)
        for name, r in rows:
            mark = "[green]pass[/]" if r.passed else "[red]FAIL[/]" if r.passed is False else "-"
            table.add_row(name, r.quantity, f"{r.reference:.6g}", f"{r.value:.6g}", r.unit,
                          f"{r.relative_error:+.2e}",
                          "" if r.tolerance is None else f"{r.tolerance:.1e}", mark)
        Console(width=max(console.width, 140)).print(table)
    if failed:
        raise typer.Exit(1)


#: ``asperity sweep --help``: a first line for the command list, then one paragraph (help
#: text without line breaks inside a paragraph, which the help screen would keep).
SWEEP_HELP = (
    "Run a parameter study on Dask (or resume one): write OUT/study.nc and OUT/report.html."
    "\n\nExits 3 when a case failed or did not converge; cases with warnings are counted on "
    "the last line and listed in the report. Before it starts it says how many cases it runs "
    "and, for transient EHL cases, about how long they take; Ctrl-C or SIGTERM stops it with "
    "one line (the finished cases are kept; the same command goes on).")


@app.command(help=SWEEP_HELP)
@guarded
def sweep(
    study: Annotated[Path, typer.Argument(help="Study file (TOML): base case + axes, or the "
                                          "name of a built-in study.")],
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder.")] = Path(
        "asperity-sweep"),
    scheduler: Annotated[str | None, typer.Option(
        "--scheduler", help="Address of a running Dask scheduler (default: a local cluster).")
    ] = None,
    workers: Annotated[int, typer.Option(help="Workers of the local cluster.")] = 2,
    serial: Annotated[bool, typer.Option("--serial", help="Run in this process, no Dask.")
                      ] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False,
):
    """Run a parameter study (the help text: :data:`SWEEP_HELP`)."""
    from ..report import study_status
    from ..sweep import load_study, local_cluster, run_study

    spec = load_study(study)
    _check_out_dir(out)
    again = ["asperity", "sweep", str(study), "--out", str(out)] + (
        ["--serial"] if serial else ["--scheduler", scheduler] if scheduler else
        ["--workers", str(workers)] if workers != 2 else []) + (["--quiet"] if quiet else [])
    console.print(_sweep_plan(spec, out), markup=False, highlight=False, soft_wrap=True)
    stop = []

    def interrupt(signum, _frame):  # a KeyboardInterrupt: no case records it as its error
        stop.append(signum)
        raise KeyboardInterrupt

    handlers = {sig: signal.signal(sig, interrupt) for sig in (signal.SIGINT, signal.SIGTERM)}
    try:
        ds = _run_sweep(spec, out, serial, scheduler, workers, quiet, run_study, local_cluster)
    except KeyboardInterrupt:
        _sweep_stopped(stop[0] if stop else signal.SIGINT, spec, out, again)
    finally:
        for sig, handler in handlers.items():
            signal.signal(sig, handler)
    _, line = study_status(ds)
    for text in _case_problems(ds):
        err_console.print(text, markup=False, highlight=False, soft_wrap=True)
    console.print(f"wrote {out / 'study.nc'}: {line} (report: {out / 'report.html'})",
                  markup=False, highlight=False, soft_wrap=True)
    if (ds["state"] != "done").any() or (ds["converged"] == 0).any():
        raise typer.Exit(EXIT_NOT_CONVERGED)


def _run_sweep(spec, out, serial, scheduler, workers, quiet, run_study, local_cluster):
    """Run the study in this process, on a scheduler or on a local cluster, with a bar."""
    from .progress import progress_bar

    with progress_bar(console, disable=quiet) as progress:
        if serial:
            return run_study(spec, out, progress=progress)
        import logging

        from dask.distributed import Client

        logging.getLogger("distributed").setLevel(logging.ERROR)  # after its own set-up
        if scheduler:
            with _connect(scheduler) as client:
                return run_study(spec, out, client=client, progress=progress)
        with local_cluster(workers) as cluster, Client(cluster) as client:
            return run_study(spec, out, client=client, progress=progress)


def _connect(scheduler: str):
    """A Dask client of the scheduler at ``scheduler``; an address that is none, or a TCP
    scheduler that does not answer, is bad input naming --scheduler (it read "error: file:
    Timed out trying to connect ... after 30 s"). The address is checked before a client is
    made: a client that fails to connect stays dask's scheduler and, collected at exit,
    waits a minute for its own close."""
    import socket

    from dask.distributed import Client
    from distributed.comm.addressing import parse_address, parse_host_port

    def refused(detail):
        return InputError("--scheduler", "", problem=f"could not connect to a Dask scheduler "
                          f"at {scheduler} ({detail}); give the address of a running one "
                          "(tcp://HOST:8786) or leave --scheduler out for a local cluster")

    try:
        protocol, location = parse_address(scheduler)
        if protocol in ("tcp", "tls"):
            host, port = parse_host_port(location)
            socket.create_connection((host, port), timeout=SCHEDULER_TIMEOUT).close()
    except (OSError, ValueError, TypeError) as exc:
        raise refused(" ".join(str(exc).split()) or type(exc).__name__) from None
    return Client(scheduler)


#: Seconds --scheduler's address is given to answer (:func:`_connect`).
SCHEDULER_TIMEOUT = 5.0


def _sweep_plan(spec, out: Path) -> str:
    """The line said before a study starts: its cases, those left to run, and where the
    analysis estimates it, their expected time on 2 cores (a line, not a question: CI has no
    stdin)."""
    from ..formatting import format_duration
    from ..sweep import estimated_seconds, resume_plan

    plan = resume_plan(spec, out)  # refuses another study's folder before anything starts
    cases = {cid: case for cid, case, _ in spec.cases}
    todo = [cases[cid] for cid in plan.todo]
    total = len(spec.cases)
    line = f"{spec.title}: {total} case{'s' * (total != 1)} ({spec.mode})" + plan.line()
    seconds = [estimated_seconds(case) for case in todo]
    known = [t for t in seconds if t is not None]
    if known:
        line += (f"; estimated {format_duration(sum(known))} on 2 cores in all (within a "
                 f"factor of 2; {format_duration(max(known))} for the longest case)")
    return line


def _case_problems(ds, limit: int = 5) -> list[str]:
    """One line per failed or unconverged case (at most ``limit`` of each), with its reason."""
    lines = []
    states = ds["state"].values.ravel()
    errors = ds["error"].values.ravel()
    converged = ds["converged"].values.ravel()
    why = ds["convergence"].values.ravel() if "convergence" in ds else [""] * states.size
    failed = [(n, e) for n, (st, e) in enumerate(zip(states, errors, strict=True))
              if st == "failed"]
    stalled = [(n, w) for n, (st, c, w) in enumerate(zip(states, converged, why, strict=True))
               if st == "done" and c == 0.0]
    for kind, found in (("failed", failed), ("did not converge", stalled)):
        for n, reason in found[:limit]:
            lines.append(f"case {n:04d} {kind}: {' '.join(str(reason).split()) or 'no reason'}")
        if len(found) > limit:
            lines.append(f"... and {len(found) - limit} more that {kind} (report.html lists "
                         "them)")
    return lines


def _sweep_stopped(signum: int, spec, out: Path, again: list[str]):
    """Say where a stopped study is and how to go on; exit with 128 + the signal number."""
    from ..sweep import case_status

    done = sum((case_status(out / "cases" / cid) or {}).get("state") in ("done", "failed")
               for cid, _, _ in spec.cases)
    err_console.print(f"stopped: {signal.Signals(signum).name} with {done} of "
                      f"{len(spec.cases)} cases finished (kept in {out}/cases); run the same "
                      f"command again to go on: {shlex.join(again)}", markup=False,
                      highlight=False, soft_wrap=True)
    raise typer.Exit(128 + signum)


def _mount_sub_apps() -> None:
    from .schema import schema
    from .surface import surface_app

    app.add_typer(surface_app, name="surface",
                  help="Roughness of measured or generated surfaces: stats, generate, plot.")
    app.command()(guarded(schema))
    from .gear import gear

    app.command(name="gear")(guarded(gear))


_mount_sub_apps()


def _warning_line(message, category, filename, lineno, file=None, line=None):
    """Show a library warning as one line on stderr (replaces ``warnings.showwarning``)."""
    err_console.print(f"warning: {message}", markup=False, highlight=False, soft_wrap=True)


def main() -> None:
    """Entry point of the console script (keeps freed memory for reuse: :mod:`asperity.memory`)."""
    warnings.showwarning = _warning_line
    retain_freed_memory()
    app()
