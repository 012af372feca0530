"""A rich progress bar fed by runners' ``progress(done, total, description)`` callbacks."""

from __future__ import annotations

from contextlib import contextmanager

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    SpinnerColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

__all__ = ["progress_bar"]


@contextmanager
def progress_bar(console, disable: bool = False):
    """Yield a ``progress(done, total, description)`` callable that drives one rich bar."""
    with Progress(SpinnerColumn(), TextColumn("{task.description}"), BarColumn(),
                  MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("ETA"),
                  TimeRemainingColumn(), console=console, disable=disable,
                  transient=False) as bar:
        task = bar.add_task("starting", total=None)

        def update(done, total=None, description=None):
            bar.update(task, completed=done, total=total,
                       description=description or bar.tasks[0].description)

        yield update
