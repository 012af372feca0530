"""One self-contained HTML report per run, and one per parameter study.

A run's report puts the headline results first, then the key results in words with readable
units (:mod:`asperity.formatting`; imperial beside SI for a case written in imperial units),
the comparison with references, the figures and the case's parameters. A study's report plots
the swept results against the axes and lists the cases. Figures are embedded as base64 PNG, so
a file can be mailed or archived alone. The reports only format what the runners computed; they
never compute physics.
"""

from __future__ import annotations

import base64
import html
import math
import re
from pathlib import Path

from .formatting import (
    NOISE,
    STANDARD_ERROR,
    SummaryRow,
    coordinate_unit,
    describe_key,
    format_number,
    format_quantity,
    result_unit,
    summary_rows,
)
from .results import Outcome, atomic_path

__all__ = ["MESH_ERROR", "NOT_CONVERGED", "REFERENCES", "WARNED", "render_report",
           "render_study_report", "study_case_marks", "study_references", "study_status",
           "study_variables", "write_report", "write_study_report"]

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2rem auto;
max-width:1100px;color:#1b1f24;line-height:1.45;padding:0 1rem}
h1{font-size:1.6rem;margin-bottom:.2rem} h2{font-size:1.2rem;border-bottom:1px solid #d0d7de;
padding-bottom:.2rem;margin-top:2rem} .sub{color:#57606a;margin-top:0}
table{border-collapse:collapse;margin:.5rem 0;font-size:.92rem}
td,th{border:1px solid #d0d7de;padding:.25rem .6rem;text-align:right}
th{background:#f6f8fa} td.l,th.l{text-align:left}
.pass{color:#1a7f37;font-weight:600} .fail{color:#cf222e;font-weight:600}
.caution{color:#bc4c00;font-weight:600}
.info{color:#57606a} figure{margin:1rem 0;display:inline-block;vertical-align:top;max-width:100%}
figure img{max-width:520px;border:1px solid #d0d7de} figcaption{font-size:.85rem;color:#57606a;
max-width:520px} .note{background:#f6f8fa;border:1px solid #d0d7de;padding:.5rem .8rem;
border-radius:4px} .bad{background:#ffebe9;border-color:#cf222e}
.ok{background:#dafbe1;border-color:#1a7f37}
.warn{background:#fff1e5;border:2px solid #bc4c00;color:#762c00;padding:.5rem .8rem;
border-radius:4px} .warn ul{margin:.3rem 0 0 0}
td{white-space:nowrap} td.l{white-space:normal}
h3{font-size:1rem;margin:1rem 0 .2rem;color:#57606a}
.headline{display:flex;flex-wrap:wrap;gap:.8rem;margin:1rem 0}
.card{border:1px solid #d0d7de;border-radius:6px;padding:.6rem 1rem;min-width:11rem;
background:#f6f8fa} .cv{font-size:1.45rem;font-weight:600} .cl{color:#57606a;font-size:.9rem}
code{font-size:.85rem}
figure.wide img{max-width:min(100%,1000px)} figure.wide figcaption{max-width:1000px}
.scroll{overflow-x:auto}
"""


#: Summary keys shown as the headline, in this order of preference (the first four present).
HEADLINE_KEYS = (
    "contact_time_percent", "contact_time_fraction", "central_film_thickness_m",
    "minimum_film_thickness_m", "max_pressure_pa", "contact_area_m2", "approach_m",
    "max_contact_count_rate_per_ms", "gross_slip", "path_gross_slip", "stick_fraction",
    "shift_m", "rotation_rad", "friction_capacity_n", "mean_contact_pressure_pa",
    "friction_coefficient", "ra_m", "rq_m", "rz_m", "correlation_length_m", "kinematic_rt_m",
    "minimum_lambda", "minimum_film_m",
    "maximum_flash_temperature_k", "maximum_hertz_pressure_pa",
)

#: A study's figure draws these after the headline keys, before the other results: the film
#: and lambda at the pitch point of a gear, which show how the mesh's middle changes.
_STUDY_FIRST = ("pitch_minimum_film_m", "pitch_lambda")

#: A study's figure draws these last, where panels are left: forces that follow the swept
#: torque by statics (the normal force and ISO's F_t are the torque over a radius).
_STUDY_LAST = ("normal_force_n", "iso_nominal_tangential_force_n")

#: The mark of a study's case that ran to the end without converging: its numbers are not a
#: solution (red crosses in the figure, apart from the line).
NOT_CONVERGED = "not converged"

#: The mark of a case with a warning that its minimum film is not resolved by the mesh, its
#: estimated error over 100 % (:mod:`asperity.diagnostics`): a hollow square in the figure.
MESH_ERROR = "mesh error over 100 %"

#: The mark of a case with other warnings: a hollow circle in the figure.
WARNED = "with warnings"

_MESH_OVER_100 = re.compile(r"estimated error over 100 %")

#: Bookkeeping of the solver, listed after the physical results (where a load path reaches
#: gross slip, path_gross_slip and path_gross_slip_step, is a result: it stays with them).
_SOLVER_KEYS = ("converged", "iterations", "residual", "sweeps", "total_sweeps", "steps",
                "mean_sweeps_per_step", "steps_converged_fraction", "load_error", "path_steps",
                "path_iterations", "path_converged", "points",
                "fixed_point_distance_pressure_fraction", "fixed_point_distance_film_fraction",
                "ehl_solves_converged", "ehl_wall_time_s", "status")


#: The closed-form references of a result (summary keys, as the runners write them): drawn
#: beside it, dashed, in its panel of a study's figure (:func:`study_references`), each with
#: the name of its formula in the legend. Only the same quantity: a central film beside the
#: central-film formulas (:func:`asperity.references.film_formulas`), a minimum film beside
#: the minimum-film ones, a dry contact's maximum pressure and approach beside Hertz's (an EHL
#: contact's maximum pressure beside its Hertz pressure), a rough sphere's real area and load
#: radius beside Greenwood & Tripp's, a tangential contact's shift, twist and stick radius
#: beside Cattaneo-Mindlin's or Lubkin's.
REFERENCES = {
    "central_film_thickness_m": (
        ("hamrock_dowson_central_film_m", "Hamrock-Dowson (1977)"),
        ("hamrock_dowson_soft_central_film_m", "Hamrock-Dowson, soft EHL (1978)"),
        ("nijenbanning_central_film_m", "Nijenbanning et al. (1994)"),
        ("chittenden_central_film_m", "Chittenden et al. (1985)"),
        ("moes_central_film_m", "Moes (1992)")),
    "minimum_film_thickness_m": (
        ("hamrock_dowson_minimum_film_m", "Hamrock-Dowson (1977)"),
        ("hamrock_dowson_soft_minimum_film_m", "Hamrock-Dowson, soft EHL (1978)"),
        ("chittenden_minimum_film_m", "Chittenden et al. (1985)"),
        ("dowson_higginson_minimum_film_m", "Dowson-Higginson (1977)"),
        ("martin_minimum_film_m", "Martin (1916)"),
        ("brewe_hamrock_taylor_minimum_film_m", "Brewe-Hamrock-Taylor (1979)")),
    "max_pressure_pa": (("hertz_max_pressure_pa", "Hertz"),),
    "approach_m": (("hertz_approach_m", "Hertz"),),
    "shift_m": (("cattaneo_mindlin_shift_m", "Cattaneo-Mindlin"),),
    "rotation_rad": (("lubkin_rotation_rad", "Lubkin (1951)"),),
    "stick_radius_m": (("cattaneo_mindlin_stick_radius_m", "Cattaneo-Mindlin"),
                       ("lubkin_stick_radius_m", "Lubkin (1951)")),
    "contact_area_m2": (("greenwood_tripp_real_area_m2", "Greenwood-Tripp (1967)"),),
    "load_rms_radius_m": (("greenwood_tripp_rms_radius_m", "Greenwood-Tripp (1967)"),),
}


def _unique(rows: list[SummaryRow]) -> list[SummaryRow]:
    """The rows without repeats of the same quantity and value (a fraction and its percent)."""
    seen, kept = set(), []
    for r in rows:
        if (r.label, r.text) not in seen:
            seen.add((r.label, r.text))
            kept.append(r)
    return kept


def _headline(rows: list[SummaryRow]) -> str:
    rows = _unique(rows)
    by_key = {r.key: r for r in rows}
    chosen = [by_key[k] for k in HEADLINE_KEYS if k in by_key][:4]
    if not chosen:
        chosen = [r for r in rows if r.key not in _SOLVER_KEYS][:3]
    cards = "".join(f"<div class=card><div class=cv>{html.escape(r.text)}</div>"
                    f"<div class=cl>{html.escape(r.label)}</div></div>" for r in chosen)
    return f"<div class=headline>{cards}</div>" if cards else ""


def _summary_table(rows: list[SummaryRow]) -> str:
    rows = _unique(rows)
    physics = [r for r in rows if r.key not in _SOLVER_KEYS]
    solver = [r for r in rows if r.key in _SOLVER_KEYS]

    def body(items):
        return "".join(f"<tr><td class=l>{html.escape(r.label)}</td>"
                       f"<td>{html.escape(r.text)}</td></tr>" for r in items)

    table = f"<table><tr><th class=l>quantity</th><th>value</th></tr>{body(physics)}</table>"
    if solver:
        table += ("<h3>Solver</h3><table><tr><th class=l>quantity</th><th>value</th></tr>"
                  f"{body(solver)}</table>")
    return table


def _difference(relative_error: float) -> str:
    """A relative difference in percent: ``+0.63 %``, ``0 %`` when exact, ``< 0.01 %``."""
    if not math.isfinite(relative_error):
        return "n/a"
    percent = 100.0 * relative_error
    if percent == 0.0:
        return "0 %"
    if abs(percent) < 0.005:
        return "&lt; 0.01 %"
    return f"{percent:+.2f} %".replace("-", "\u2212")


def _comparison_table(comparisons, imperial: bool = False) -> str:
    if not comparisons:
        return "<p class=info>No closed-form or published reference applies to this case.</p>"
    rows = []
    for c in comparisons:
        status = c.passed
        badge = ("<span class=info>info</span>" if status is None else
                 "<span class=pass>pass</span>" if status else "<span class=fail>differs</span>")
        tol = "" if c.tolerance is None else f"{format_number(100 * c.tolerance, 3)} %"
        value = format_quantity(c.value, c.unit, imperial=imperial)
        reference = format_quantity(c.reference, c.unit, imperial=imperial)
        rows.append(
            f"<tr><td class=l>{html.escape(c.quantity)}</td><td>{html.escape(value)}</td>"
            f"<td>{html.escape(reference)}</td><td>{_difference(c.relative_error)}</td>"
            f"<td>{tol}</td><td>{badge}</td>"
            f"<td class=l>{html.escape(c.source)}{(': ' + html.escape(c.note)) if c.note else ''}"
            "</td></tr>")
    head = ("<tr><th class=l>quantity</th><th>asperity</th><th>reference</th>"
            "<th>difference</th><th>tolerance</th><th></th><th class=l>source</th></tr>")
    return f"<table>{head}{''.join(rows)}</table>"


def _flatten(data, prefix: str = ""):
    """(dotted key, value) of a nested case dict; lists of tables as ``key[i].field``."""
    for key, value in data.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict):
            yield from _flatten(value, path + ".")
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, item in enumerate(value):
                yield from _flatten(item, f"{path}[{i}].")
        else:
            yield path, value


def _parameters_table(case: dict, imperial: bool = False, chosen: dict | None = None) -> str:
    """The case's keys and values, quantities in readable units (SI as validated); the values
    in ``chosen`` (:attr:`Outcome.chosen`) replace the case's defaults, marked as chosen; a
    chosen key the case leaves out (an EHL domain bound left to the contact) follows its
    table's other keys.

    A key that takes a number or a quantity (an EHL domain bound) shows a number in Hertz
    semi-axes, as the case file means it. A key chosen as None does not apply to the run and
    is left out.
    """
    from .cases import ANALYSES
    from .cases.keys import case_keys

    chosen = chosen or {}
    model = ANALYSES.get(case.get("analysis"))
    keys = {k.key: k for k in case_keys(model)} if model is not None else {}
    items = list(_flatten(case))
    for key, value in chosen.items():  # a key the case leaves out: after its table's others
        if value is not None and key not in dict(items):
            table = key.rsplit(".", 1)[0] + "."
            at = max((i for i, (k, _) in enumerate(items) if k.startswith(table)),
                     default=len(items) - 1)
            items.insert(at + 1, (key, value))
    rows = []
    for key, value in items:
        if key in ("title", "description", "source"):
            continue
        spec = keys.get(re.sub(r"\[\d+\]", "[]", key))
        unit = spec.unit if spec is not None else ""
        mark = ""
        if key in chosen:
            if chosen[key] is None:
                continue
            value, mark = chosen[key], " (chosen for the contact)"

        def shown(v, unit=unit):
            if unit == "rad":  # case angles (pressure angle, force direction) in degrees
                return f"{format_number(math.degrees(v))} deg"
            return format_quantity(v, unit, imperial=imperial)

        if spec is not None and spec.type == "number or quantity" \
                and isinstance(value, int | float):
            text = f"{format_number(value)} Hertz semi-axes"
        elif isinstance(value, list | tuple):
            text = ", ".join(shown(v) if isinstance(v, int | float) and not isinstance(v, bool)
                             else str(v) for v in value)
        elif isinstance(value, float) or (isinstance(value, int) and unit):
            text = shown(value)
        elif isinstance(value, bool):
            text = "true" if value else "false"
        else:
            text = str(value)
        rows.append(f"<tr><td class=l><code>{html.escape(key)}</code></td>"
                    f"<td class=l>{html.escape(text + mark)}</td></tr>")
    return ("<table><tr><th class=l>key</th><th class=l>value</th></tr>"
            f"{''.join(rows)}</table>")


def _figures(outcome: Outcome, files: dict) -> str:
    parts = []
    for stem, (_fig, caption) in outcome.figures.items():
        path = files.get(stem)
        if path is None or not Path(path).is_file():
            continue
        png = Path(path).read_bytes()
        data = base64.b64encode(png).decode("ascii")
        width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
        wide = " class=wide" if height and width > 1.7 * height else ""  # PNG IHDR size
        parts.append(f'<figure{wide}><img alt="{html.escape(stem)}" '
                     f'src="data:image/png;base64,{data}">'
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
                  extra_html: str = "", *, imperial: bool = False) -> str:
    """The report as an HTML string.

    The headline results come first, then the key results in words with their units, the
    comparison with references, the figures and the case's parameters.

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
    imperial : bool
        Show imperial values beside SI (for a case given in imperial units; see
        :func:`asperity.formatting.given_in_imperial`).
    """
    status = _status_banner(outcome)
    notes = "".join(f"<p class=note>{html.escape(n)}</p>" for n in outcome.notes)
    rows = summary_rows(outcome.summary, imperial=imperial)
    units = "SI and imperial" if imperial else "SI"
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)} - asperity</title>
<style>{_CSS}</style></head><body>
<h1>{html.escape(title)}</h1>
<p class=sub>{html.escape(str(case.get('description', '')))}
{('<br>Source: ' + html.escape(str(case['source']))) if case.get('source') else ''}</p>
{status}{_headline(rows)}{notes}
<h2>Key results</h2>{_summary_table(rows)}
<h2>Comparison with references</h2>{_comparison_table(outcome.comparisons, imperial)}
{extra_html}
<h2>Figures</h2>{_figures(outcome, files)}
<h2>Case parameters ({units})</h2>{_parameters_table(case, imperial, outcome.chosen)}
<p class=info>Written by asperity. Files: {', '.join(html.escape(Path(p).name)
                                             for p in files.values())}.</p>
</body></html>
"""


def write_report(title: str, case: dict, outcome: Outcome, files: dict, path, *,
                 imperial: bool = False) -> Path:
    """Render the report (:func:`render_report`) and write it atomically to ``path``."""
    text = render_report(title, case, outcome, files, imperial=imperial)
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def study_variables(ds, limit: int = 9) -> list[str]:
    """The numeric results of a study that vary from case to case: headline quantities first
    (then a gear's pitch film and lambda; its normal force and F_t, which follow the torque,
    last), solver bookkeeping, repeats of a swept value and second copies of a quantity (the same
    long name: a fraction and its percent) left out, and so are the closed-form references
    drawn beside a result in its panel (:func:`study_references`: Hertz's maximum pressure
    beside the maximum pressure, not a panel of its own).

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).
    limit : int
        Most variables returned.

    Returns
    -------
    list of str
    """
    import numpy as np

    axes = [a for a in ds.attrs.get("axes", "").split(",") if a]
    numeric = []
    for name, var in ds.data_vars.items():
        if name in _SOLVER_KEYS or not np.issubdtype(var.dtype, np.number):
            continue
        if name.endswith(STANDARD_ERROR) and name.removesuffix(STANDARD_ERROR) in ds:
            continue  # shown beside its value (_cases_table)
        values = var.values.astype(float)
        finite = values[np.isfinite(values)]
        if finite.size and np.ptp(finite) > 1e-12 * max(np.max(np.abs(finite)), 1e-300) and \
                not any(_repeats_axis(var, ds[a]) for a in axes):
            numeric.append(str(name))
    first = [k for k in (*HEADLINE_KEYS, *_STUDY_FIRST) if k in numeric]
    ranked = first + [k for k in numeric if k not in first and k not in _STUDY_LAST] + [
        k for k in _STUDY_LAST if k in numeric]
    # one of a quantity stored twice (a fraction and its percent): the first by rank
    seen, kept = set(), []
    for k in ranked:
        label = ds[k].attrs.get("long_name", k)
        if label not in seen:
            seen.add(label)
            kept.append(k)
    # a reference drawn in its result's panel (study_references) has no panel of its own
    drawn = {ref for refs in study_references(ds, kept).values() for ref, _ in refs}
    return [k for k in kept if k not in drawn][:limit]


def study_references(ds, variables) -> dict[str, list[tuple[str, str]]]:
    """The closed-form references that ``study.nc`` carries for each of ``variables``
    (:data:`REFERENCES`): those in the dataset, numeric, in the result's unit and with a
    value somewhere, whether or not they vary over the study (Hertz's pressure beside the
    maximum pressure of an EHL speed sweep).

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).
    variables : list of str
        The results plotted (:func:`study_variables`).

    Returns
    -------
    dict
        Result key -> list of (reference key, formula's name), for the results that have any.
    """
    import numpy as np

    found = {}
    for key in variables:
        if key not in ds:
            continue
        refs = [(ref, name) for ref, name in REFERENCES.get(key, ())
                if ref in ds and np.issubdtype(ds[ref].dtype, np.number)
                and ds[ref].attrs.get("units") == ds[key].attrs.get("units")
                and np.isfinite(ds[ref].values.astype(float)).any()]
        if refs:
            found[key] = refs
    return found


def _repeats_axis(var, coord) -> bool:
    """Whether a result only repeats a swept value (the load of a load sweep)."""
    import numpy as np

    if not np.issubdtype(coord.dtype, np.number) or coord.attrs.get("units") != var.attrs.get(
            "units"):
        return False
    import xarray as xr

    values, axis = xr.broadcast(var.astype(float), coord.astype(float))
    return bool(np.allclose(values.values, axis.values, rtol=1e-9, equal_nan=True))


def _header(text: str, unit: str) -> str:
    """A column heading (HTML already escaped) with its unit, if any, once: ``contact area
    (mm²)``."""
    return f"<th>{text} ({html.escape(unit)})</th>" if unit else f"<th>{text}</th>"


def _cases_table(ds, variables) -> str:
    """The table of cases: the axis values, the results ``variables``, state and errors.

    Each quantity column is in one unit, chosen from its largest magnitude
    (:func:`asperity.formatting.result_unit`, as the figure's axes) and named once in its
    heading; the cells are numbers with 4 significant digits (a standard error with 2).
    Formatted cell by cell, a column of contact areas read "4608 µm²" in one row and
    "0.01053 mm²" in the next. Labels, yes/no flags, states and errors stay text.
    """
    import numpy as np

    axes = [a for a in ds.attrs.get("axes", "").split(",") if a]
    dims = list(ds["state"].dims)
    scale = {v: float(np.nanmax(np.abs(ds[v].values))) for v in variables}
    axis_units = {a: coordinate_unit(ds[a].values, ds[a].attrs.get("units", "1"))
                  if np.issubdtype(ds[a].dtype, np.number) else None for a in axes}
    flags = {v for v in variables if ds[v].attrs.get("flag_meanings") == "no yes"
             and np.all(np.isin(ds[v].values[np.isfinite(ds[v].values)], (0.0, 1.0)))}
    units = {v: (1.0, "") if v in flags else result_unit(v, scale[v]) for v in variables}
    head = "".join(_header(_breakable(ds[a].attrs.get("long_name", a)),
                           axis_units[a][1] if axis_units[a] else "") for a in axes)
    head += "".join(_header(html.escape(describe_key(v)[0]), units[v][1]) for v in variables)
    rows = []
    marks = study_case_marks(ds)
    for n, index in enumerate(np.ndindex(*ds["state"].shape)):
        sel = dict(zip(dims, index, strict=True))
        cells = []
        for a in axes:
            coord = ds[a].isel({d: i for d, i in sel.items() if d in ds[a].dims})
            value = coord.values.item()
            cells.append(str(value) if axis_units[a] is None
                         else format_number(float(value) * axis_units[a][0]))
        for v in variables:
            value = float(ds[v].isel(sel).values)
            if v in flags:
                cells.append("n/a" if math.isnan(value) else "yes" if value else "no")
                continue
            if describe_key(v)[1] and math.isfinite(value) and abs(value) <= NOISE * scale[v]:
                value = 0.0  # round-off of a quantity that is zero (as in a run's report)
            text = format_number(value * units[v][0])
            spread = (float(ds[v + STANDARD_ERROR].isel(sel).values)
                      if v + STANDARD_ERROR in ds else math.nan)
            if math.isfinite(spread):  # its standard error, in the column's unit
                text += f" ± {format_number(spread * units[v][0], 2)}"
            cells.append(text)
        state, error, badge = _case_state(ds, sel, str(marks.values[index]))
        rows.append(f"<tr><td>{n:04d}</td>" + "".join(f"<td>{html.escape(c)}</td>"
                                                       for c in cells)
                    + f"<td>{badge}</td><td class=l>{html.escape(error)}</td></tr>")
    return (f"<table><tr><th>case</th>{head}<th>state</th><th class=l>error or warnings</th>"
            "</tr>"
            f"{''.join(rows)}</table>")


def _case_state(ds, sel, mark: str) -> tuple[str, str, str]:
    """(state, error or warnings, badge in HTML) of the case at ``sel`` in the table of
    cases, its ``mark`` (:func:`study_case_marks`) as the figure draws it: ``not converged``
    with its run's reason, ``done, mesh error over 100 %`` or ``done, with warnings`` with
    their count."""
    state = str(ds["state"].isel(sel).values)
    error = str(ds["error"].isel(sel).values)
    if mark == NOT_CONVERGED:
        state = NOT_CONVERGED
        if "convergence" in ds:  # the case's own reason (its run's message)
            error = str(ds["convergence"].isel(sel).values)
    elif mark:
        state = f"done, {mark}"
    if "warnings" in ds and str(ds["warnings"].isel(sel).values):
        count = len(str(ds["warnings"].isel(sel).values).split("\n"))
        more = f"{count} warning{'s' * (count > 1)} (below)"
        error = f"{error} ({more})" if error else more
    kind = ("pass" if state == "done" else "caution" if state.startswith("done, ")
            else "fail")
    return state, error, f"<span class={kind}>{html.escape(state)}</span>"


def _breakable(key: str) -> str:
    """A dotted case-file key as HTML that may wrap after each dot and underscore
    (``body2.youngs_modulus``), so that a study's table of cases fits the page."""
    return re.sub(r"([._])", r"\1<wbr>", html.escape(key))


def _not_converged(ds, sel) -> bool:
    """Whether the case at ``sel`` ran to the end without converging (False where the study
    file predates the ``converged`` record)."""
    return "converged" in ds and float(ds["converged"].isel(sel).values) == 0.0


def study_case_marks(ds):
    """The mark of each case of a study, as its figure draws it and its table names it.

    :data:`NOT_CONVERGED` for a case that ran to the end without converging, else
    :data:`MESH_ERROR` for one warned that its minimum film's estimated mesh error is over
    100 %, else :data:`WARNED` for one with any other warning, else ``""`` (a clean case, and
    a failed or missing one, which has no numbers to draw).

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).

    Returns
    -------
    xarray.DataArray
        Strings, on the dimensions of ``ds["state"]``.
    """
    import numpy as np

    marks = np.full(ds["state"].shape, "", dtype=object)
    dims = list(ds["state"].dims)
    for index in np.ndindex(*ds["state"].shape):
        marks[index] = _case_mark(ds, dict(zip(dims, index, strict=True)))
    return ds["state"].copy(data=marks.astype(str))


def _case_mark(ds, sel) -> str:
    """The mark of the case at ``sel`` (:func:`study_case_marks`)."""
    if str(ds["state"].isel(sel).values) != "done":
        return ""
    if _not_converged(ds, sel):
        return NOT_CONVERGED
    text = str(ds["warnings"].isel(sel).values) if "warnings" in ds else ""
    if _MESH_OVER_100.search(text):
        return MESH_ERROR
    return WARNED if text else ""


def _case_warnings(ds) -> list[tuple[str, list[str]]]:
    """(case id, warning lines) of the cases with warnings, in case order."""
    import numpy as np

    if "warnings" not in ds:
        return []
    dims = list(ds["state"].dims)
    found = []
    for n, index in enumerate(np.ndindex(*ds["state"].shape)):
        text = str(ds["warnings"].isel(dict(zip(dims, index, strict=True))).values)
        if text:
            found.append((f"{n:04d}", text.split("\n")))
    return found


def study_status(ds) -> tuple[bool, str]:
    """Whether every case is done, converged and free of warnings, and one line that says
    how many are not (the study report's banner and the command line's last line).

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).
    """
    states = ds["state"].values.ravel()
    done, failed = int((states == "done").sum()), int((states == "failed").sum())
    ids = [f"{n:04d}" for n in range(states.size)]
    unconverged = [] if "converged" not in ds else [
        c for c, s, v in zip(ids, states, ds["converged"].values.ravel(), strict=True)
        if s == "done" and v == 0.0]
    warned = [c for c, _ in _case_warnings(ds)]
    parts = [f"{done} of {states.size} cases done"]
    if unconverged:
        parts.append(f"{len(unconverged)} not converged ({_ids(unconverged)})")
    if warned:
        parts.append(f"{len(warned)} with warnings ({_ids(warned)})")
    if failed:
        failed_ids = [c for c, st in zip(ids, states, strict=True) if st == "failed"]
        parts.append(f"{failed} failed ({_ids(failed_ids)})")
    missing = [c for c, st in zip(ids, states, strict=True) if st == "missing"]
    if missing:
        parts.append(f"{len(missing)} missing ({_ids(missing)})")
    return done == states.size and not unconverged and not warned, ", ".join(parts)


def _ids(chosen: list[str], limit: int = 12) -> str:
    """Case ids as listed on a line: the first ``limit`` of them and a count of the rest."""
    shown = ", ".join(chosen[:limit])
    return shown + (f" and {len(chosen) - limit} more" if len(chosen) > limit else "")


def render_study_report(ds, figure_png: bytes | None = None) -> str:
    """The HTML report of a parameter study: the swept results against the axes (a figure)
    and the table of cases.

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).
    figure_png : bytes, optional
        The figure of :func:`asperity.plotting.study.plot_study`, embedded as PNG.
    """
    title = str(ds.attrs.get("title", "Parameter study"))
    states = ds["state"].values.ravel()
    clean, line = study_status(ds)
    warned = _case_warnings(ds)
    where = [w for w, shown in (("errors in the table", (states == "failed").any()),
                                ("warnings below it", warned)) if shown]
    status = (f"<p class='note ok'>{html.escape(line)}.</p>" if clean
              else f"<p class='note bad'><b>{html.escape(line)}</b>"
                   f"{' (' + ', '.join(where) + ')' if where else ''}.</p>")
    warning_list = "" if not warned else (
        "<h2>Warnings</h2><ul>" + "".join(
            f"<li>case {cid}: {html.escape(w)}</li>" for cid, lines in warned for w in lines)
        + "</ul>")
    variables = study_variables(ds)
    figure = ("<p class=info>No result varies from case to case.</p>" if figure_png is None else
              '<figure><img style="max-width:100%" alt="study" src="data:image/png;base64,'
              f'{base64.b64encode(figure_png).decode("ascii")}"><figcaption>Each result '
              "against the first axis (one line per value of the other axes). Red crosses, "
              "apart from the line: cases that did not converge (not a solution); hollow "
              "squares: a mesh error over 100 % of the minimum film; hollow circles: other "
              "warnings (as the table of cases says).</figcaption></figure>")
    axes = ", ".join(html.escape(ds[a].attrs.get("long_name", a))
                     for a in ds.attrs.get("axes", "").split(",") if a)
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)} - asperity study</title>
<style>{_CSS}</style></head><body>
<h1>{html.escape(title)}</h1>
<p class=sub>Parameter study ({html.escape(str(ds.attrs.get('mode', 'cross')))}) over {axes};
{states.size} cases.</p>
{status}
<h2>Results against the axes</h2>{figure}
<h2>Cases</h2><div class=scroll>{_cases_table(ds, variables[:6])}</div>
{warning_list}
<p class=info>Written by asperity. Every case's files are in cases/NNNN; all scalars, with
units, in study.nc.</p>
</body></html>
"""


def _in_axis_order(ds):
    """The study with its cases in increasing order of the first axis, for the figure.

    The figure joins the points in the order of the cases: a load axis written
    ``["10 N", 20, "0.03 kN", "5 lbf"]`` (10, 20, 30, 22.2 N) drew every result as a loop
    back from 30 N to 22.2 N, as if it were not single valued. Labelled axes keep their order;
    the table of cases keeps the study's.
    """
    import numpy as np

    names = [n for n in ds.attrs.get("axes", "").split(",") if n]
    if not names or names[0] not in ds.coords:
        return ds
    values = ds[names[0]].values
    if not np.issubdtype(values.dtype, np.number) or np.all(np.diff(values) >= 0):
        return ds
    return ds.sortby(names[0])


def write_study_report(ds, out_dir) -> Path:
    """Draw the study figure (``study.png``) and write ``report.html`` into ``out_dir``.

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` (:func:`asperity.sweep.combine`).
    out_dir : path
        The study's output folder.

    Returns
    -------
    pathlib.Path
        The report's path.
    """
    import matplotlib.pyplot as plt

    from .plotting.study import plot_study

    out = Path(out_dir)
    variables = study_variables(ds)
    png = None
    if variables:
        ordered = _in_axis_order(ds)
        fig = plot_study(ordered, variables, references=study_references(ordered, variables))
        with atomic_path(out / "study.png") as tmp:
            fig.savefig(tmp, format="png", dpi=110, bbox_inches="tight")
        plt.close(fig)
        png = (out / "study.png").read_bytes()
    path = out / "report.html"
    with atomic_path(path) as tmp:
        tmp.write_text(render_study_report(ds, png), encoding="utf-8")
    return path
