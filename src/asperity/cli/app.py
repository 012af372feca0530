"""Commands of ``asperity``: run, examples, example, surface, sweep, validate."""

from __future__ import annotations

import typer

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="Mechanics of rough, loaded, lubricated contacts.")


def main() -> None:
    """Entry point of the console script."""
    app()
