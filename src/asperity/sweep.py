"""Parameter studies: a base case, parameter axes, the cases run on Dask, one combined netCDF.

A study file (TOML)::

    title = "Contact area vs load"
    base = "rough-flat-normal"          # a built-in example or a case file (relative path)
    mode = "cross"                      # every combination; "zip" pairs the axes element-wise

    [[axis]]
    key = "loading.load"                # dotted path into the case
    values = ["5 N", "10 N", "20 N"]    # or: range = {start = 5, stop = 20, num = 4, unit = "N"}

A bare number on an axis is in the key's SI unit, as in a case file (``[0.1, "50 cm/s"]`` on
``speeds.u``); a ``range`` with ``scale = "log"`` starts and stops above zero. A key is swept by
one axis only, names a key rather than a table, and in ``mode = "cross"`` takes each value once;
the file format in full: docs/studies.md.

``unset = ["paper_contact_time_percent"]`` removes keys of the base case from every case (a
value that holds for the base only). An axis may also set several keys together (one
dimension, labelled points)::

    [[axis]]
    name = "surfaces"
    keys = ["surface1.profile", "surface2.profile"]
    values = [["C", "C"], ["A", "A"]]
    labels = ["C-C", "A-A"]            # optional; default the values joined by "-"

Each case runs in its own folder ``OUT/cases/NNNN`` (``input.json``, written first, then
``summary.json`` and ``result.nc``) and is marked done by ``status.json`` written last; both
record the case's input fingerprint (:func:`case_fingerprint`, the SHA-256 of the merged case)
and the asperity version. Run again, a study reuses a finished case only where its folder holds
a run of the same input, runs again the cases whose input changed (a warning says how many),
and refuses an output folder of another study, or one whose cases record no input. A failing
case is recorded with its error and does not stop the others. The scalars of all cases are combined
into ``OUT/study.nc`` with the swept parameters as dimensions (``mode = "cross"``) or along a
``case`` dimension (``mode = "zip"``), units and long names on every variable; ``OUT/report.html``
plots the results against the axes (``OUT/study.png``) and lists the cases.
"""

from __future__ import annotations

import copy
import difflib
import hashlib
import itertools
import json
import math
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from .errors import InputError
from .formatting import cf_units, describe_key
from .report import write_study_report
from .results import write_json, write_netcdf
from .units import DIMENSIONS, is_bare, to_si, unit_of

__all__ = ["CASE_FILES", "INPUT_FILE", "NAMING_KEYS", "RANGE_KEYS", "THREAD_VARIABLES",
           "ResumePlan", "Study", "case_fingerprint", "case_status", "combine",
           "convergence_message", "discard_case", "estimated_seconds", "input_record",
           "load_study", "local_cluster", "recorded_input", "resume_plan", "run_one",
           "run_study"]

#: The keys of an axis's ``range`` table.
RANGE_KEYS = ("start", "stop", "num", "unit", "scale")


@dataclass(frozen=True)
class Study:
    """A validated study: its cases (dicts, ready for ``load_case``) and axis coordinates.

    Attributes
    ----------
    title, mode : str
    axes : tuple
        Of (dimension name, keys, values as given, labels or None).
    cases : tuple
        Of (case id, case dict, {axis name: value}).
    base : str
        The base case: a built-in example's name, or the case file's absolute path.
    units : tuple
        Per axis, the SI unit of its key where the key is a quantity (a bare number on the
        axis is in that unit, as in a case file), else None.
    scales : tuple
        Per axis, ``"log"`` for a range with ``scale = "log"``, else ``"linear"`` (the study
        figure's x axis).
    """

    title: str
    mode: str
    axes: tuple
    cases: tuple
    base: str = ""
    units: tuple = ()
    scales: tuple = ()


def _set_path(data: dict, dotted: str, value) -> None:
    keys = dotted.split(".")
    node = data
    for k in keys[:-1]:
        if not isinstance(node.get(k), dict):
            node[k] = {}
        node = node[k]
    node[keys[-1]] = value


def _get_path(data: dict, dotted: str):
    """The value at a dotted key of a case, or None where it is not set."""
    node = data
    for k in dotted.split("."):
        node = node.get(k) if isinstance(node, dict) else None
    return node


def _unset(data: dict, keys) -> None:
    """Remove the dotted ``keys`` of the study's ``unset`` list from the base case.

    For a base key that does not hold for the swept cases, e.g. the paper's value of the base
    case (``paper_contact_time_percent``), which a study of other cases must not compare with.
    """
    if not (isinstance(keys, list) and all(isinstance(k, str) for k in keys)):
        raise InputError("unset", "a list of dotted keys of the base case", keys)
    for i, dotted in enumerate(keys):
        head, _, last = dotted.rpartition(".")
        node = _get_path(data, head) if head else data
        if not isinstance(node, dict) or last not in node:
            raise InputError(f"unset[{i}]", "a key the base case sets", dotted)
        del node[last]


def _axis_values(axis: dict, index: int) -> list:
    where = f"axis[{index}]"
    if "values" in axis and "range" in axis:
        raise InputError(where, "either values or range, not both")
    if "values" in axis:
        values = axis["values"]
        if not isinstance(values, list) or not values:
            raise InputError(f"{where}.values", "a non-empty list", values)
        return values
    if "range" in axis:
        r = axis["range"]
        if not isinstance(r, dict) or not {"start", "stop", "num"} <= set(r):
            raise InputError(f"{where}.range", "a table {start, stop, num[, unit, scale]}",
                             r)
        start, stop, num = (_range_end(r, "start", where), _range_end(r, "stop", where),
                            r["num"])
        unknown = sorted(set(r) - set(RANGE_KEYS))
        if unknown:
            raise InputError(f"{where}.range.{unknown[0]}",
                             f"one of {', '.join(RANGE_KEYS)} (check the spelling)", r[unknown[0]])
        if isinstance(num, bool) or not isinstance(num, int) or num < 2:
            raise InputError(f"{where}.range.num", "an integer >= 2 (one case: values = [...])",
                             num)
        scale = r.get("scale", "linear")
        if scale not in ("linear", "log"):
            raise InputError(f"{where}.range.scale", '"linear" or "log"', scale)
        if scale == "log":  # a geometric sequence of positive numbers
            for end, value in (("start", start), ("stop", stop)):
                if not (math.isfinite(value) and value > 0):
                    raise InputError(f"{where}.range.{end}", 'a number > 0 for scale = "log" '
                                     '(or scale = "linear")', r[end])
        vals = (np.geomspace(start, stop, num) if scale == "log" else np.linspace(start, stop, num))
        unit = r.get("unit")
        return [f"{v:.12g} {unit}" if unit else float(v) for v in vals]
    raise InputError(where, "a values list or a range table")


def _range_end(r: dict, end: str, where: str) -> float:
    """The ``start`` or ``stop`` of an axis's range as a finite number.

    A quantity (``start = "10 N"``) is refused with where its unit goes (the table's ``unit``,
    for both ends), and an infinite end, which had made a range of repeated infinities refused
    as "the same case" after a numpy warning.
    """
    value = r[end]
    if isinstance(value, str) and not is_bare(value):
        raise InputError(f"{where}.range.{end}", "a number (give the unit once for both ends: "
                         "start = 10, stop = 50, unit = \"N\")", value)
    try:
        number = float(value) if not isinstance(value, bool) else math.nan
    except (TypeError, ValueError):
        number = math.nan
    if not math.isfinite(number):
        raise InputError(f"{where}.range.{end}", "a finite number", value)
    return number


def _axis(ax, i: int) -> tuple:
    """(dimension name, keys, values, labels) of one [[axis]] table."""
    if not isinstance(ax, dict):
        raise InputError(f"axis[{i}]", "a table with key (or keys) and values")
    unknown = set(ax) - {"key", "keys", "values", "range", "name", "labels"}
    if unknown:
        raise InputError(f"axis[{i}].{sorted(unknown)[0]}", "",
                         problem="unknown key (check the spelling)")
    if "key" in ax and "keys" in ax:
        raise InputError(f"axis[{i}]", "", problem="give key (one swept key) or keys (several "
                         "swept together), not both")
    if isinstance(ax.get("key"), str) and "keys" not in ax:
        return ax.get("name", ax["key"]).replace(".", "__"), (ax["key"],), _axis_values(ax, i), \
            None
    keys = ax.get("keys")
    if not (isinstance(keys, list) and keys and all(isinstance(k, str) for k in keys)):
        raise InputError(f"axis[{i}].key", "a dotted key path such as 'loading.load' (or a "
                                           "keys list)")
    values = _axis_values(ax, i)
    if not all(isinstance(v, list) and len(v) == len(keys) for v in values):
        raise InputError(f"axis[{i}].values", f"lists of {len(keys)} values, one per key")
    labels = ax.get("labels", ["-".join(str(x) for x in v) for v in values])
    if not (isinstance(labels, list) and len(labels) == len(values)):
        raise InputError(f"axis[{i}].labels", "one label per value")
    name = ax.get("name", "__".join(k.replace(".", "__") for k in keys))
    return str(name), tuple(keys), values, [str(label) for label in labels]


def _name_case(case: dict, base: str, title: str, axes: list, position: tuple) -> None:
    """Title and describe one case by the values its axes set, unless an axis sets them.

    Without this every case would carry the base example's title and description, which name
    the base's own values (a C-C study case titled "C against C, xi = 0.25" whatever it runs).
    """
    set_keys = {key for _, keys, _, _ in axes for key in keys}
    parts = []
    for (name, _, values, labels), i in zip(axes, position, strict=True):
        shown = labels[i] if labels is not None else values[i]
        parts.append(f"{name.replace('__', '.')} = {shown}")
    if "title" not in set_keys:
        case["title"] = f"{title}: {', '.join(parts)}"
    if "description" not in set_keys:
        case["description"] = (f"Case of the study \"{title}\" on the example or case file "
                               f"{base}, with {'; '.join(parts)}.")


def _read_base(path: Path, base) -> tuple[dict, str]:
    """The base case's TOML (a case file beside the study, else a built-in example) and the
    name it is recorded under in study.nc."""
    from .cases import parse_toml
    from .examples import example_text

    if not isinstance(base, str):
        raise InputError("base", "a built-in example name or a case file path", base)
    base_path = path.parent / base
    if base_path.is_file():
        return parse_toml(base_path.read_text(encoding="utf-8"), base), str(base_path.resolve())
    try:
        text = example_text(base)
    except InputError:
        raise InputError("base", "", problem=f"no file {base_path.resolve()} and no built-in "
                         "example of that name (asperity examples lists them)") from None
    return parse_toml(text, base), base


def _base_keys(base_case: dict) -> dict:
    """The keys of the base case's analysis (:func:`~asperity.cases.keys.case_keys`) by
    dotted path; empty where the analysis is not known (the case's own check says so)."""
    from .cases import ANALYSES
    from .cases.keys import case_keys

    model = ANALYSES.get(base_case.get("analysis")) if isinstance(
        base_case.get("analysis"), str) else None
    return {} if model is None else {k.key: k for k in case_keys(model)}


def _check_axes(axes: list, keys: dict, mode: str, base_case: dict | None = None) -> tuple:
    """Refuse what would run but not answer the question; return each axis' SI unit.

    A key swept by two axes (the second overrode the first in every case and the combination
    failed after all cases had run), a key that names a table given values that are not tables,
    bare numbers beside quantities where a bare number is not in the key's SI unit, bare
    numbers meant in the unit the base writes the key in (:func:`_check_bare_scale`), the
    ``analysis`` key (a study runs its base's analysis), and one value twice on an axis of a
    cross study (the same case run twice, a coordinate that selects two rows).
    """
    base_case = base_case or {}
    seen: dict[str, int] = {}
    names: dict[str, int] = {}
    units = []
    for i, (name, axis_keys, values, _) in enumerate(axes):
        field = f"axis[{i}].key" if len(axis_keys) == 1 else f"axis[{i}].keys"
        for k, key in enumerate(axis_keys):
            if key == "analysis":
                raise InputError(field, "", problem="analysis is not swept: a study runs the "
                                 f"analysis of its base ({base_case.get('analysis')!r}); write "
                                 "one study per analysis")
            if key in seen:
                raise InputError(field, "", problem=f"{key} is already swept by "
                                 f"axis[{seen[key]}]")
            clash = next((other for other in seen if other.startswith(key + ".")
                          or key.startswith(other + ".")), None)
            if clash is not None:
                raise InputError(field, "", problem=f"{key} overlaps {clash}, which "
                                 f"axis[{seen[clash]}] sweeps")
            seen[key] = i
            column = [v if len(axis_keys) == 1 else v[k] for v in values]
            spec = keys.get(key)
            if spec is not None and spec.type == "table" and not all(
                    isinstance(v, dict) for v in column):
                inside = [c.split(".", 1)[1] for c in keys if c.startswith(key + ".")
                          and "." not in c.split(".", 1)[1]]
                raise InputError(field, "", problem=f"{key} names a table, not a key; name a "
                                 f"key in it ({', '.join(f'{key}.{c}' for c in inside)})")
            if spec is not None and spec.type == "number or quantity" and \
                    0 < sum(is_bare(v) for v in column) < len(column):
                raise InputError(f"axis[{i}].values", "", problem=f"bare numbers beside "
                                 f"quantities for {key}, where a bare number is not in "
                                 f"{spec.unit}; give every value with its unit, or none")
            if spec is not None and spec.type == "quantity" and spec.unit:
                _check_bare_scale(f"axis[{i}].values", key, column, spec.unit,
                                  _get_path(base_case, key))
        if name in names:
            raise InputError(f"axis[{i}].name", "", problem=f"{name.replace('__', '.')} is "
                             f"already the name of axis[{names[name]}]; give each axis its own "
                             "name")
        names[name] = i
        unit = None
        if len(axis_keys) == 1 and (spec := keys.get(axis_keys[0])) is not None:
            unit = spec.unit if spec.type == "quantity" and spec.unit else None
        units.append(unit)
        if mode == "cross":
            _check_distinct(i, axis_keys, values, unit, keys)
    return tuple(units)


def _dimension_of(si_unit: str) -> str | None:
    """The :data:`~asperity.units.DIMENSIONS` name of an SI unit (``"m"``: ``"length"``)."""
    return next((d for d, u in DIMENSIONS.items() if u and u == si_unit), None)


def _written_unit(value, dimension: str) -> tuple[str, float] | None:
    """The unit a case value is written in and its size in SI (``"9.525 mm"``:
    ``("mm", 0.001)``), or None for a bare number or a value that is not a quantity."""
    unit = unit_of(value)
    if unit is None:
        return None
    try:
        return unit, to_si(f"1 {unit}", dimension, "base")
    except InputError:
        return None


def _check_bare_scale(field: str, key: str, column: list, si_unit: str, base_value) -> None:
    """Refuse bare numbers that read as the base's unit but are taken in SI.

    A base written ``rx = "9.525 mm"`` swept with ``values = [9.525, 12.7]`` ran radii of
    9.5 and 12.7 m (a bare number is in the key's SI unit), and a tangential case answered for
    them without a word. Refused where the base is written in a unit at least 100 times the SI
    one or smaller, and every bare value is at least 100 times off the base in SI but within a
    factor 10 of it read in the base's unit.
    """
    dimension = _dimension_of(si_unit)
    written = None if dimension is None else _written_unit(base_value, dimension)
    bare = [float(v) for v in column if is_bare(v)]
    if written is None or not bare or abs(math.log10(written[1])) < 2:
        return
    try:
        base_si = abs(to_si(base_value, dimension, key))
    except InputError:  # the base's own check says what is wrong with it
        return
    if base_si == 0 or not all(math.isfinite(v) and v != 0 for v in bare):
        return
    if all(abs(math.log10(abs(v) / base_si)) >= 2
           and abs(math.log10(abs(v) * written[1] / base_si)) <= 1 for v in bare):
        v = bare[0]
        raise InputError(field, "", problem=f"{v:g} on {key} is {v:g} {si_unit} (a bare "
                         f"number is in {si_unit}), {abs(v) / base_si:.4g} times the base's "
                         f"{base_value!r}; give the unit (\"{v:g} {written[0]}\"), or write "
                         f"\"{v:g} {si_unit}\" if that is meant")


def _check_distinct(i: int, axis_keys, values, unit, keys) -> None:
    """Refuse a value given twice on an axis of a cross study (``1.0`` and ``"3.6 km/h"``
    for a speed: both 1 m/s)."""
    def quantity_unit(key):
        spec = keys.get(key)
        return spec.unit if spec is not None and spec.type == "quantity" and spec.unit else None

    if len(axis_keys) == 1:
        columns = [_normal_values(values, unit)]
    else:
        columns = [_normal_values([v[k] for v in values], quantity_unit(key))
                   for k, key in enumerate(axis_keys)]
    rows = list(zip(*columns, strict=True))
    for n, row in enumerate(rows):
        first = rows.index(row)
        if first < n:
            same = f" (both {row[0]:.6g} {unit})" if len(row) == 1 and unit and \
                isinstance(row[0], float) else ""
            raise InputError(f"axis[{i}].values", "", problem=f"values {first} and {n} are the "
                             f"same case: {values[first]!r} and {values[n]!r}{same}; give each "
                             "value once")


def _normal_values(values: list, unit) -> list:
    """Axis values as compared for repeats: SI numbers rounded to 12 digits where they are
    quantities, else their text."""
    numbers, _ = _coordinate(values, unit)
    if np.issubdtype(numbers.dtype, np.number):
        return [float(f"{v:.12g}") for v in numbers]
    return [json.dumps(v, sort_keys=True, default=str) for v in values]


def _unknown_axis_key(exc: InputError, axes: list, base_case: dict) -> None:
    """Name the axis whose key the case refused as unknown, with the analysis and the nearest
    key it has (``loading.load`` on an EHL base: ``contact.load``).

    The case's own line named the first unknown part only (``case 0 (loading): unknown key
    (check the spelling)``) though the key is the study's and may be a key of another analysis.
    """
    if not exc.problem.startswith("unknown key"):
        return
    for i, (_, axis_keys, _, _) in enumerate(axes):
        for key in axis_keys:
            if key != exc.field and not key.startswith(exc.field + "."):
                continue
            known = list(_base_keys(base_case))
            last = key.rsplit(".", 1)[-1]
            near = [k for k in known if k.rsplit(".", 1)[-1] == last] or \
                difflib.get_close_matches(key, known, n=1, cutoff=0.6)
            analysis = base_case.get("analysis")
            field = f"axis[{i}].key" if len(axis_keys) == 1 else f"axis[{i}].keys"
            raise InputError(field, "", problem=f"{key} is not a key of analysis = "
                             f"\"{analysis}\""
                             + (f" (did you mean {near[0]}?)" if near else "")
                             + f"; asperity schema {analysis} lists them") from None


def load_study(path: str | Path) -> Study:
    """Read and validate a study file (or a built-in study by name); every case is validated
    before anything runs.

    Parameters
    ----------
    path : str or path
        A study file (TOML), or the name of a built-in study.

    Returns
    -------
    Study

    Raises
    ------
    InputError
        For a bad study (naming its key: ``axis[1].key``, ``base``, ...) or a case that would
        not run (``case 3 (speeds.u): ...``).
    """
    from .cases import load_case, parse_toml
    from .examples import study_text

    path = Path(path)
    text = path.read_text(encoding="utf-8") if path.is_file() else study_text(str(path))
    spec = parse_toml(text, str(path))
    unknown = set(spec) - {"title", "base", "mode", "axis", "description", "unset"}
    if unknown:
        raise InputError(sorted(unknown)[0], "", problem="unknown key (check the spelling)")
    base = spec.get("base")
    base_case, base_name = _read_base(path, base)
    _unset(base_case, spec.get("unset", []))
    mode = spec.get("mode", "cross")
    if mode not in ("cross", "zip"):
        raise InputError("mode", '"cross" or "zip"', mode)
    axes_spec = spec.get("axis")
    if not isinstance(axes_spec, list) or not axes_spec:
        raise InputError("axis", "at least one [[axis]] table with key and values")
    axes = [_axis(ax, i) for i, ax in enumerate(axes_spec)]
    if mode == "zip" and len({len(ax[2]) for ax in axes}) != 1:
        lengths = ", ".join(f"{'/'.join(ax[1])}: {len(ax[2])}" for ax in axes)
        raise InputError("axis", "axes of equal length for mode = \"zip\" (one case per "
                         "position along them)", lengths)
    units = _check_axes(axes, _base_keys(base_case), mode, base_case)
    positions = (zip(*(range(len(ax[2])) for ax in axes), strict=True) if mode == "zip"
                 else itertools.product(*(range(len(ax[2])) for ax in axes)))
    title = spec.get("title", path.stem)
    cases = []
    for n, position in enumerate(positions):
        combo = tuple(ax[2][i] for ax, i in zip(axes, position, strict=True))
        case = copy.deepcopy(base_case)
        for (_, keys, _, _), value in zip(axes, combo, strict=True):
            for key, v in zip(keys, value if len(keys) > 1 else (value,), strict=True):
                _set_path(case, key, v)
        _name_case(case, base, title, axes, position)
        try:
            load_case(case)
        except InputError as exc:
            _unknown_axis_key(exc, axes, base_case)
            text = str(exc)
            problem = text[len(exc.field) + 2:] if text.startswith(f"{exc.field}: ") else text
            raise InputError(f"case {n} ({exc.field})", exc.expected, problem=problem) from None
        cases.append((f"{n:04d}", case, dict(zip((ax[0] for ax in axes), combo, strict=True))))
    scales = tuple("log" if isinstance(ax.get("range"), dict) and ax["range"].get("scale")
                   == "log" else "linear" for ax in axes_spec)
    return Study(title, mode, tuple(axes), tuple(cases), base=base_name, units=units,
                 scales=scales)


def run_one(case: dict, folder: str) -> dict:
    """Run one case into ``folder``; return its status (done, summary, or the error).

    Runs in a Dask worker. Errors are caught and recorded, never raised. The case's input is
    recorded first (``input.json``: its :func:`case_fingerprint`, the asperity version and the
    case), and its status (``status.json``, written last) carries the same fingerprint. A
    long-running case (a transient EHL run) checkpoints into ``folder`` and, run again after an
    interruption with the same input, goes on from its last checkpoint with the same final
    numbers; a folder that holds another input's results or checkpoint starts afresh.
    """
    from .cases import load_case
    from .results import write_outcome
    from .runners import run_case

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    record = input_record(case)
    if recorded_input(folder) != record:
        discard_case(folder)  # never resume, nor report, another input's run
    write_json({**record, "case": case}, folder / INPUT_FILE)
    try:
        outcome = run_case(load_case(case), workdir=folder,
                           resume=(folder / "checkpoint.npz").is_file())
        write_outcome(outcome, folder, figures=False)
        status = {"state": "done", "converged": bool(outcome.converged),
                  "summary": outcome.summary, "warnings": list(outcome.warnings)}
        if not outcome.converged:
            status["convergence"] = convergence_message(outcome)
    except Exception as exc:  # recorded for the study, the other cases go on
        status = {"state": "failed", "error": f"{type(exc).__name__}: {exc}"}
    write_json({**status, **record}, folder / "status.json")
    return status


#: The file of a case folder that records the input it runs, written before the run starts.
INPUT_FILE = "input.json"

#: The files a run writes into its case folder (:func:`discard_case` removes only these).
CASE_FILES = ("status.json", "summary.json", "result.nc", "checkpoint.npz", INPUT_FILE)

#: Top-level case keys left out of :func:`case_fingerprint`: text that names the case (the
#: study writes the base file's path into the description) and changes no result.
NAMING_KEYS = ("title", "description")


def case_fingerprint(case: dict) -> str:
    """SHA-256 of a case as it runs: the canonical JSON of the merged case dict (the base case
    with the axis values applied), keys sorted, without its :data:`NAMING_KEYS`.

    Parameters
    ----------
    case : dict
        A case as the study holds it (ready for ``load_case``).
    """
    data = {k: v for k, v in case.items() if k not in NAMING_KEYS}
    text = json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=False,
                      default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def input_record(case: dict) -> dict:
    """What a case folder records of the run's input: ``input_sha256`` (the
    :func:`case_fingerprint`) and ``asperity_version``."""
    from . import __version__

    return {"input_sha256": case_fingerprint(case), "asperity_version": __version__}


def recorded_input(folder: str | Path) -> dict | None:
    """The :func:`input_record` a case folder holds (from ``status.json`` where the case
    finished, else from ``input.json``), or None where it records none (an empty folder, or
    one written by an asperity that did not record inputs)."""
    folder = Path(folder)
    status = case_status(folder)
    if status is None:
        try:
            status = json.loads((folder / INPUT_FILE).read_text(encoding="utf-8"))
        except (FileNotFoundError, json.JSONDecodeError):
            return None
    if not isinstance(status, dict) or "input_sha256" not in status:
        return None
    return {k: status.get(k) for k in ("input_sha256", "asperity_version")}


def discard_case(folder: str | Path) -> None:
    """Remove what a run wrote into a case folder (:data:`CASE_FILES`; nothing else)."""
    for name in CASE_FILES:
        (Path(folder) / name).unlink(missing_ok=True)


def _holds_files(folder: Path) -> bool:
    return any((folder / name).is_file() for name in CASE_FILES)


@dataclass(frozen=True)
class ResumePlan:
    """What running a study into an output folder does with its case folders.

    Attributes
    ----------
    reused : tuple
        Ids of the cases finished (done, converged or not) with the input they have now:
        kept as they are.
    todo : tuple
        Ids of the cases to run: not run yet, stopped, failed, or run with another input.
    changed : tuple
        Ids (among ``todo``) of the cases whose folder holds a run of another input (or of
        another asperity version): its files are removed before the case runs again.
    """

    reused: tuple
    todo: tuple
    changed: tuple

    def line(self) -> str:
        """The resume part of the line said before a study runs (``", 3 to run (5 done before;
        2 run again because their input changed)"``); empty where nothing ran before."""
        if not (self.reused or self.changed):
            return ""
        again = (f"; {len(self.changed)} run again because their input changed"
                 if self.changed else "")
        return f", {len(self.todo)} to run ({len(self.reused)} done before{again})"


def resume_plan(study: Study, out: str | Path) -> ResumePlan:
    """Match a study's cases with the case folders of ``out`` by their input, not their number.

    A finished case is reused only where its folder records the case's
    :func:`input_record` (:func:`case_fingerprint` and asperity version).

    Raises
    ------
    InputError
        ``--out``: where ``out`` holds another study (another title in its ``study.json``), or
        case folders that record no input (written by an earlier asperity), which cannot be
        matched with this study's cases.
    """
    out = Path(out)
    _check_same_study(study, out)
    reused, todo, changed, unknown = [], [], [], []
    for cid, case, _ in study.cases:
        folder = out / "cases" / cid
        record = recorded_input(folder)
        if record is None:
            (unknown if _holds_files(folder) else todo).append(cid)
            continue
        if record != input_record(case):
            changed.append(cid)
            todo.append(cid)
        elif (case_status(folder) or {}).get("state") == "done":
            reused.append(cid)
        else:
            todo.append(cid)
    if unknown:
        raise InputError("--out", "", problem=f"{out / 'cases'} holds {len(unknown)} case "
                         f"folder{'s' * (len(unknown) != 1)} ({_ids(unknown)}) that record no "
                         "input (written by an earlier asperity), so they cannot be matched "
                         f"with this study's cases; give a new --out, or delete {out / 'cases'}"
                         " to run every case again")
    return ResumePlan(tuple(reused), tuple(todo), tuple(changed))


def _rerun_line(plan: ResumePlan, out: Path) -> str:
    """The warning that cases of ``out`` run again because their input changed."""
    n = len(plan.changed)
    return (f"{n} case{'s' * (n != 1)} of {out} ({_ids(list(plan.changed))}) "
            f"{'run' if n != 1 else 'runs'} again: {'their' if n != 1 else 'its'} input (or the "
            "asperity version) changed since the earlier run, whose results are removed")


def _ids(ids: list, limit: int = 5) -> str:
    """Case ids for a message: the first ``limit`` of them, and how many more."""
    shown = ", ".join(ids[:limit])
    return shown + (f" and {len(ids) - limit} more" if len(ids) > limit else "")


def _check_same_study(study: Study, out: Path) -> None:
    """Refuse an output folder whose ``study.json`` names another study."""
    try:
        title = json.loads((out / "study.json").read_text(encoding="utf-8")).get("title")
    except (FileNotFoundError, json.JSONDecodeError, AttributeError):
        return
    if title is not None and title != study.title:
        raise InputError("--out", "", problem=f"{out} holds the study {title!r}, not "
                         f"{study.title!r}; give a new --out, or delete {out} to run "
                         f"{study.title!r} there")


_UNCONVERGED = re.compile(r"\b(?:did|does|do|could) not converge|\bnot converged|"
                          r"\bunconverged\b", re.IGNORECASE)


def convergence_message(outcome) -> str:
    """Why a run did not converge, in its own words: the first of its notes, else of its
    warnings, that says so (the steady EHL runner's "The solver did not converge in 30 sweeps
    ... Raise solver.max_sweeps ..."); a plain statement where the run gave none.

    Parameters
    ----------
    outcome : asperity.results.Outcome
        A run's outcome with ``converged`` False.
    """
    for line in [*outcome.notes, *outcome.warnings]:
        if _UNCONVERGED.search(line):
            return line
    return "the solver did not converge (the run gave no reason; see the case's report)"


def case_status(folder: str | Path) -> dict | None:
    """The ``status.json`` of a study's case folder (its ``state``: running, done, failed),
    or None where there is none yet."""
    folder = Path(folder)
    try:
        return json.loads((folder / "status.json").read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return None


#: Environment variables that size the thread pools of numba, OpenMP and the BLAS libraries.
THREAD_VARIABLES = ("NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS",
                    "MKL_NUM_THREADS")


def local_cluster(workers: int, cores: int | None = None):
    """A quiet Dask ``LocalCluster`` of ``workers`` single-threaded worker processes whose
    compiled kernels share the machine's ``cores`` (default all) instead of each taking them all.

    Each worker starts with its numba, OpenMP and BLAS thread pools at
    ``max(1, cores // workers)`` (:data:`THREAD_VARIABLES`, set before the worker imports
    them). Without that, two workers on two cores ran their parallel sweeps on two threads
    each: four busy threads on two cores.

    Dask's own log lines are silenced (a normal finish printed two "Worker process still alive
    after 4.0 seconds, killing" warnings), and the workers ignore SIGINT: Ctrl-C reaches every
    process of the terminal's group, and each worker printed its tracebacks (about 80 lines)
    before the command line's one line. The caller stops the study; closing the cluster ends
    the workers.

    Raises
    ------
    InputError
        ``--workers``: for fewer than one worker (0 had ended in a ZeroDivisionError).
    """
    import logging
    import os
    import signal
    import threading

    from dask.distributed import LocalCluster

    if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
        raise InputError("--workers", "a whole number of at least 1 (the local cluster's "
                         "worker processes)", workers)
    cores = (os.cpu_count() or 1) if cores is None else cores
    threads = str(max(1, cores // workers))
    main = threading.current_thread() is threading.main_thread()
    # a process started with SIGINT ignored keeps it ignored (Python installs its
    # KeyboardInterrupt handler only where SIGINT has the default action)
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                            dashboard_address=None, silence_logs=logging.CRITICAL,
                            env=dict.fromkeys(THREAD_VARIABLES, threads))
    finally:
        if main:
            signal.signal(signal.SIGINT, previous)


def estimated_seconds(case: dict) -> float | None:
    """The wall time a case is expected to take on 2 cores, where its analysis estimates it
    before it starts (a transient EHL case: nodes x steps x
    :data:`~asperity.runners.ehl_transient.SECONDS_PER_NODE_STEP`, within a factor of 2
    either way); None for the others.

    The mesh, time step and step counts are the transient runner's, from the case's own
    methods (``problem``, ``mesh``, ``timestep``, ``steps``).

    Parameters
    ----------
    case : dict
        A case as the study holds it (ready for ``load_case``).
    """
    from .cases import load_case

    if case.get("analysis") != "ehl-transient":
        return None
    from .runners.ehl_transient import SECONDS_PER_NODE_STEP

    model = load_case(case)
    problem = model.problem()
    nx, ny, domain = model.mesh(problem)
    x, _ = problem.grid(nx, ny, domain)
    warmup, counting = model.steps(problem, x, model.timestep(problem, x))
    return nx * ny * (warmup + counting) * SECONDS_PER_NODE_STEP


def run_study(study: Study, out: str | Path, *, client=None, progress=None) -> xr.Dataset:
    """Run the study's unfinished cases on Dask and combine all results.

    A case folder of ``out`` is reused only where it holds a finished run of the case's input
    as it is now (:func:`resume_plan`); a case whose input changed runs again, with a warning
    that says how many did.

    Parameters
    ----------
    study : Study
    out : path
        Output folder; ``cases/NNNN`` per case, ``study.json``, ``study.nc``, ``study.png``
        and ``report.html``.
    client : dask.distributed.Client, optional
        Where to run; ``None`` runs the cases one after the other in this process.
    progress : callable, optional
        ``progress(done, total, description)``.

    Raises
    ------
    InputError
        ``--out``: for an output folder of another study, or one whose case folders record no
        input (:func:`resume_plan`); nothing runs.
    """
    out = Path(out)
    plan = resume_plan(study, out)
    for cid in plan.changed:
        discard_case(out / "cases" / cid)
    if plan.changed:
        warnings.warn(_rerun_line(plan, out), stacklevel=2)
    _write_study_record(study, out)
    cases = dict((cid, case) for cid, case, _ in study.cases)
    todo = [(cid, cases[cid]) for cid in plan.todo]
    total, done = len(study.cases), len(plan.reused)
    if progress:
        progress(done, total, f"{study.title}: {done} of {total} cases done")
    if client is None:
        for cid, case in todo:
            run_one(case, str(out / "cases" / cid))
            done += 1
            if progress:
                progress(done, total, f"{study.title}: case {cid}")
    else:
        from dask.distributed import as_completed

        futures = {client.submit(run_one, case, str(out / "cases" / cid), pure=False,
                                 key=f"asperity-case-{cid}-{id(study)}"): cid
                   for cid, case in todo}
        for future in as_completed(futures):
            future.result()
            done += 1
            if progress:
                progress(done, total, f"{study.title}: case {futures[future]}")
    ds = combine(study, out)
    write_netcdf(ds, out / "study.nc")
    write_study_report(ds, out)
    return ds


def _write_study_record(study: Study, out: Path) -> None:
    """Write ``OUT/study.json``: the study's title, mode and base, and each case's id and
    input fingerprint (before any case runs, so that a stopped study names itself)."""
    from . import __version__

    out.mkdir(parents=True, exist_ok=True)
    write_json({"title": study.title, "mode": study.mode, "base": study.base,
                "asperity_version": __version__, "cases": [c for c, _, _ in study.cases],
                "inputs": {cid: case_fingerprint(case) for cid, case, _ in study.cases}},
               out / "study.json")


_ANGLES = {"radian", "degree", "arcminute", "arcsecond", "turn", "revolution", "gradian"}


def _coordinate(values: list, unit: str | None = None):
    """Axis values as numbers in the SI unit of their dimension (and that unit, CF-style), or
    as strings.

    Parameters
    ----------
    values : list
        The axis values as the study gives them: numbers, quantities (``"50 cm/s"``) or text.
    unit : str, optional
        The SI unit of the swept key where it is a quantity. A bare number is in that unit
        (as in a case file); without it, in the SI unit of the axis' quantities.

    Returns
    -------
    (ndarray, str)
        The coordinate (floats, else strings) and its CF unit (``"1"`` for text).
    """
    from .units import DIMENSIONS, registry, to_si

    if all(is_bare(v) or isinstance(v, bool) for v in values):
        return np.array([float(v) for v in values]), cf_units(unit) if unit else "1"
    try:
        ureg = registry()
        qs = [ureg.Quantity(v) for v in values if not is_bare(v)]
        if qs[0].dimensionless:  # pint counts angles as pure numbers: radians, or a ratio
            angle = {name for name, _ in qs[0].unit_items()} & _ANGLES
            si = "rad" if angle else "dimensionless"
        else:
            si = next(u for u in DIMENSIONS.values()
                      if u and ureg.Quantity(1, u).dimensionality == qs[0].dimensionality)
        if unit and ureg.Quantity(1, unit).dimensionality == ureg.Quantity(1, si).dimensionality:
            si = unit
        dimension = {"rad": "angle", "dimensionless": "dimensionless"}.get(si) or next(
            d for d, u in DIMENSIONS.items()  # read as the cases read them (turns counted)
            if u and ureg.Quantity(1, u).dimensionality == ureg.Quantity(1, si).dimensionality)
        numbers = np.array([float(v) if is_bare(v) else to_si(v, dimension, "axis")
                            for v in values], dtype=float)
        return numbers, "1" if si == "dimensionless" else cf_units(si)
    except Exception:  # labels that are not quantities stay strings
        return np.array([str(v) for v in values]), "1"


def combine(study: Study, out: str | Path) -> xr.Dataset:
    """Gather every case's scalars into one Dataset with the axes as dimensions."""
    out = Path(out)
    statuses = [case_status(out / "cases" / cid) or {"state": "missing"}
                for cid, _, _ in study.cases]
    keys: list[str] = []
    for s in statuses:
        for k, v in (s.get("summary") or {}).items():
            if isinstance(v, int | float | bool) and k not in keys:
                keys.append(k)
    names = [ax[0] for ax in study.axes]
    coords = {}
    units = study.units or (None,) * len(study.axes)
    scales = study.scales or ("linear",) * len(study.axes)
    for (name, axis_keys, values, labels), key_unit, scale in zip(study.axes, units, scales,
                                                                  strict=True):
        arr, unit = ((np.array(labels), "1") if labels is not None
                     else _coordinate(values, key_unit))
        coords[name] = (name if study.mode == "cross" else "case", arr,
                        {"units": unit, "long_name": ", ".join(axis_keys), "scale": scale})
    shape = (tuple(len(ax[2]) for ax in study.axes) if study.mode == "cross"
             else (len(study.cases),))
    dims = tuple(names) if study.mode == "cross" else ("case",)

    def field(fn, dtype=float):
        return np.array([fn(s) for s in statuses], dtype=dtype).reshape(shape)

    data = {}
    for k in keys:
        label, unit = describe_key(k)
        if k.endswith("fraction") and unit == "%":
            unit = ""  # stored as a fraction; shown in percent only in reports
        attrs = {"long_name": label, "units": cf_units(unit)}
        if all(isinstance((s.get("summary") or {}).get(k, False), bool) for s in statuses):
            attrs |= {"flag_values": "0 1", "flag_meanings": "no yes"}  # CF flags
        data[k] = (dims, field(lambda s, k=k: (s.get("summary") or {}).get(k, math.nan)), attrs)
    data["state"] = (dims, field(lambda s: s["state"], object).astype(str),
                     {"long_name": "done, failed or missing", "units": "1"})
    data["converged"] = (dims, field(lambda s: float(s["converged"]) if "converged" in s
                                     else math.nan),
                         {"long_name": "converged", "units": "1", "flag_values": "0 1",
                          "flag_meanings": "no yes"})
    data["warnings"] = (dims, field(lambda s: "\n".join(s.get("warnings", [])), object)
                        .astype(str),
                        {"long_name": "trust warnings of the case, one per line", "units": "1"})
    data["error"] = (dims, field(lambda s: s.get("error", ""), object).astype(str),
                     {"long_name": "error message of a failed case", "units": "1"})
    data["convergence"] = (dims, field(lambda s: s.get("convergence", ""), object).astype(str),
                           {"long_name": "why a case that ran did not converge (its run's "
                                         "message)", "units": "1"})
    from . import __version__

    attrs = {"title": study.title, "mode": study.mode, "axes": ",".join(names),
             "Conventions": "CF-1.8", "source": "asperity", "asperity_version": __version__,
             "base": study.base}
    return xr.Dataset(data, coords=coords, attrs=attrs)

