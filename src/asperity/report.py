"""One self-contained HTML report per run: parameters, results, figures, references.

Figures are embedded as base64 PNG, so the file can be mailed or archived alone. The report
only formats what the runner computed; it never computes physics.
"""

from __future__ import annotations

import base64
import html
import json
import math
from pathlib import Path

from .results import Outcome, atomic_path

__all__ = ["render_report", "write_report"]

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2rem auto;
max-width:1100px;color:#1b1f24;line-height:1.45;padding:0 1rem}
h1{font-size:1.6rem;margin-bottom:.2rem} h2{font-size:1.2rem;border-bottom:1px solid #d0d7de;
padding-bottom:.2rem;margin-top:2rem} .sub{color:#57606a;margin-top:0}
table{border-collapse:collapse;margin:.5rem 0;font-size:.92rem}
td,th{border:1px solid #d0d7de;padding:.25rem .6rem;text-align:right}
th{background:#f6f8fa} td.l,th.l{text-align:left}
.pass{color:#1a7f37;font-weight:600} .fail{color:#cf222e;font-weight:600}
.info{color:#57606a} figure{margin:1rem 0;display:inline-block;vertical-align:top;max-width:100%}
figure img{max-width:520px;border:1px solid #d0d7de} figcaption{font-size:.85rem;color:#57606a;
max-width:520px} .note{background:#f6f8fa;border:1px solid #d0d7de;padding:.5rem .8rem;
border-radius:4px} .bad{background:#ffebe9;border-color:#cf222e}
.ok{background:#dafbe1;border-color:#1a7f37}
.warn{background:#fff1e5;border:2px solid #bc4c00;color:#762c00;padding:.5rem .8rem;
border-radius:4px} .warn ul{margin:.3rem 0 0 0}
pre{background:#f6f8fa;padding:.6rem;overflow:auto;font-size:.85rem}
"""


def _fmt(value) -> str:
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return "n/a"
        return f"{value:.5g}"
    return html.escape(str(value))


def _summary_table(summary: dict) -> str:
    rows = "".join(
        f"<tr><td class=l>{html.escape(k)}</td><td>{_fmt(v)}</td></tr>"
        for k, v in summary.items() if not isinstance(v, dict | list)
    )
    return f"<table><tr><th class=l>quantity</th><th>value</th></tr>{rows}</table>"


def _comparison_table(comparisons) -> str:
    if not comparisons:
        return "<p class=info>No closed-form or published reference applies to this case.</p>"
    rows = []
    for c in comparisons:
        status = c.passed
        badge = ("<span class=info>info</span>" if status is None else
                 "<span class=pass>pass</span>" if status else "<span class=fail>differs</span>")
        tol = "" if c.tolerance is None else f"{100 * c.tolerance:.3g} %"
        rows.append(
            f"<tr><td class=l>{html.escape(c.quantity)}</td><td>{_fmt(c.value)}</td>"
            f"<td>{_fmt(c.reference)}</td><td class=l>{html.escape(c.unit)}</td>"
            f"<td>{100 * c.relative_error:+.2f} %</td><td>{tol}</td><td>{badge}</td>"
            f"<td class=l>{html.escape(c.source)}{(': ' + html.escape(c.note)) if c.note else ''}"
            "</td></tr>")
    head = ("<tr><th class=l>quantity</th><th>asperity</th><th>reference</th><th class=l>unit"
            "</th><th>difference</th><th>tolerance</th><th></th><th class=l>source</th></tr>")
    return f"<table>{head}{''.join(rows)}</table>"


def _figures(outcome: Outcome, files: dict) -> str:
    parts = []
    for stem, (_fig, caption) in outcome.figures.items():
        path = files.get(stem)
        if path is None or not Path(path).is_file():
            continue
        data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
        parts.append(f'<figure><img alt="{html.escape(stem)}" src="data:image/png;base64,{data}">'
                     f"<figcaption>{html.escape(caption)}</figcaption></figure>")
    return "".join(parts) or "<p class=info>No figures.</p>"


def _status_banner(outcome: Outcome) -> str:
    """"Converged." only when there is nothing to warn about; else the warnings, in a banner."""
    parts = []
    if not outcome.converged:
        parts.append("<p class='note bad'><b>Not converged</b>: the results below are not "
                     "trustworthy.</p>")
    if outcome.warnings:
        items = "".join(f"<li>{html.escape(w)}</li>" for w in outcome.warnings)
        count = len(outcome.warnings)
        parts.append(f"<div class=warn role=alert><b>{count} warning{'s' * (count > 1)}</b>: "
                     f"the results below depend on choices of the case and may be wrong."
                     f"<ul>{items}</ul></div>")
    if not parts:
        parts.append("<p class='note ok'>Converged.</p>")
    return "".join(parts)


def render_report(title: str, case: dict, outcome: Outcome, files: dict,
                  extra_html: str = "") -> str:
    """The report as an HTML string.

    Parameters
    ----------
    title : str
        Heading.
    case : dict
        The case as validated (SI values), shown as parameters.
    outcome : Outcome
        What the runner returned.
    files : dict
        Name -> path of the files written (figures are read from here and embedded).
    extra_html : str, optional
        Additional sections (already escaped HTML), e.g. a contact-time table.
    """
    status = _status_banner(outcome)
    notes = "".join(f"<p class=note>{html.escape(n)}</p>" for n in outcome.notes)
    params = html.escape(json.dumps(case, indent=2, default=str))
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)} - asperity</title>
<style>{_CSS}</style></head><body>
<h1>{html.escape(title)}</h1>
<p class=sub>{html.escape(str(case.get('description', '')))}
{('<br>Source: ' + html.escape(str(case['source']))) if case.get('source') else ''}</p>
{status}{notes}
<h2>Key results</h2>{_summary_table(outcome.summary)}
<h2>Comparison with references</h2>{_comparison_table(outcome.comparisons)}
{extra_html}
<h2>Figures</h2>{_figures(outcome, files)}
<h2>Case parameters (SI)</h2><pre>{params}</pre>
<p class=info>Written by asperity. Files: {', '.join(html.escape(Path(p).name)
                                             for p in files.values())}.</p>
</body></html>
"""


def write_report(title: str, case: dict, outcome: Outcome, files: dict, path) -> Path:
    """Render the report and write it atomically to ``path``."""
    text = render_report(title, case, outcome, files)
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)
