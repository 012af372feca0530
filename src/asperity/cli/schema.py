"""``asperity schema [ANALYSIS]``: every case-file key with its type, unit, default and meaning.

The same reference is written to ``docs/cases.md`` by ``asperity schema --markdown`` (a test
checks that the file is up to date with the case models).
"""

from __future__ import annotations

from typing import Annotated

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

__all__ = ["markdown", "schema"]

_INTRO = """\
# Case-file keys

Every key of an asperity case file, by analysis, generated from the case models
(`asperity schema --markdown > docs/cases.md`; `asperity schema ANALYSIS` prints one analysis).

A **quantity** is a number in the SI unit shown or a string with any unit of the same
dimension (`"2160 lbf"`, `"0.6 in"`, `"30e6 psi"`, `"25 um"`). A bare number whose SI reading
is unlikely for what the key holds runs with a warning that gives both readings and what to
write (`youngs_modulus = 30e6`: 30 MPa, or 206.8 GPa in psi; `rx = 9.525`: 9.525 m, or mm?;
`eta0 = 100`: 100 Pa s, or mPa s?; a slide/roll ratio beyond 2 however written);
one out of a key's bounds is refused with the bound in a unit. An **integer** (a mesh size,
a count, a seed) is a TOML integer (`nx = 128`; `128.0`, a float without a fraction, is the same
count), not a quoted one (`"128"`); `true`/`false` is neither an integer nor a **number**
(`poisson_ratio = 0.3`). A key a table does not have is refused, with the table's key that
reads like it (`loading.lod: unknown key; did you mean 'load'?`). A default `-` means the key is
optional and has no value unless given (the analysis chooses, or the table is absent).
Keys under `name[].` belong to each entry of an array of tables (`[[name]]`).
"""


def _escape(text: str) -> str:
    return text.replace("|", "\\|")


def markdown() -> str:
    """The reference of every analysis' keys as Markdown (the text of ``docs/cases.md``)."""
    from ..cases import ANALYSES
    from ..cases.keys import case_keys

    parts = [_INTRO]
    for analysis, model in ANALYSES.items():
        parts.append(f"\n## analysis = \"{analysis}\"\n\n")
        doc = (model.__doc__ or "").strip().split("\n\n")[0].replace("``", "`")
        if doc:
            parts.append(" ".join(doc.split()) + "\n")
        parts.append("\n| key | type | unit | default | meaning |\n|---|---|---|---|---|\n")
        for k in case_keys(model):
            parts.append(f"| `{k.key}` | {_escape(k.type)} | {k.unit} | {_escape(k.default)} "
                         f"| {_escape(k.meaning)} |\n")
    return "".join(parts)


def schema(
    analysis: Annotated[str | None, typer.Argument(
        help="Analysis (normal, surface, ehl-steady, ehl-transient, tangential, gear); all when "
             "omitted.")] = None,
    as_markdown: Annotated[bool, typer.Option(
        "--markdown", help="Print Markdown (the text of docs/cases.md).")] = False,
):
    """List every case-file key: type, unit, default and meaning."""
    import sys

    from ..cases import ANALYSES
    from ..cases.keys import case_keys
    from ..errors import InputError

    if as_markdown:
        sys.stdout.write(markdown())
        return
    if analysis is not None and analysis not in ANALYSES:
        raise InputError("analysis", "one of " + ", ".join(f'"{a}"' for a in ANALYSES),
                         analysis)
    console = Console()
    for name in [analysis] if analysis else list(ANALYSES):
        table = Table(title=f'analysis = "{name}"', title_justify="left", box=None,
                      show_header=True, padding=(0, 1), pad_edge=False)
        table.add_column("key", no_wrap=True, style="bold")
        table.add_column("type, unit, default; meaning", overflow="fold")
        for k in case_keys(ANALYSES[name]):
            default = {"required": "required", "-": "optional"}.get(k.default,
                                                                    f"default {k.default}")
            what = f"{k.type} in {k.unit}, {default}" if k.unit else f"{k.type}, {default}"
            table.add_row(k.key, escape(what) + (f"\n[dim]{escape(k.meaning)}[/]" if k.meaning
                                                  else ""))
        console.print(table)
        console.print()
