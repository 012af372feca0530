"""Figures of a parameter study: each swept result against the first axis, one line per value of
the other axes (small multiples, one panel per result); a logarithmic x axis for an axis
swept on a log range (``scale = "log"``) or spanning more than a factor of 50, its ticks
plain numbers at the swept values (at most ``LOG_TICKS`` of them) where their labels do not
crowd, else at 1, 2 and 5, or 1 and 3, or 1 times the powers of ten, the first of these whose
labels stand apart (a 7-point study 0.01-2 m/s labelled "0.02418" beside "0.05848"), never
matplotlib's default minor labels, which for a range within about a decade (5-80 N) are
``2×10¹ 3×10¹ 4×10¹ 6×10¹`` written over each other. A result that changes by less than
``FLAT_SPAN`` of its size over the study is drawn on a range of ``FLAT_RANGE`` about its
mean, so that round-off does not look like a trend. On a log x axis a positive result
spanning more than a factor ``LOG_Y_SPAN`` is drawn on a log y axis too, so that a power law
(an EHL film against speed, ``h ~ u^0.67``) is a straight line whose slope reads as its
exponent; on a linear y axis it looked like an exponential rise.

Cases are drawn by their mark (:func:`asperity.report.study_case_marks`): one that did not
converge as a red cross apart from the line, which breaks there (its numbers are not a
solution: a gear study's 15 000 K flash temperature and negative film had been joined to the
good points like a result); one warned of a mesh error over 100 % as a hollow square and one
with other warnings as a hollow circle, on the line; each kind named once in the legend."""

from __future__ import annotations

import itertools

import numpy as np
from matplotlib import rcParams
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullFormatter

from ..formatting import (
    coordinate_unit,
    describe_key,
    format_axis_value,
    format_number,
    result_unit,
)
from .style import plt

__all__ = ["FLAT_RANGE", "FLAT_SPAN", "LOG_TICKS", "LOG_Y_SPAN", "MARK_STYLES", "PANEL_WIDTH",
           "REFERENCE_STYLES", "log_tick_values", "plot_study"]

#: A log x axis with at most this many swept values has a tick at each of them.
LOG_TICKS = 8

#: On a log x axis, a panel whose positive values span more than this factor gets a log y
#: axis (a film over a decade of speed: 129 nm to 1.09 um, a factor 8.5).
LOG_Y_SPAN = 3.0

#: A panel's values spanning less than this fraction of their largest magnitude are "flat".
FLAT_SPAN = 1e-3
#: A flat panel's y range: its mean plus and minus this fraction of the mean's magnitude.
FLAT_RANGE = 0.02

#: Line styles of the closed-form references drawn beside a result, in turn.
REFERENCE_STYLES = ("--", "-.", ":")

#: Width of a panel, in inches.
PANEL_WIDTH = 4.0
#: The part of a panel's width its y ticks and label take, in inches.
_Y_LABELS_WIDTH = 0.9
#: Width of a character of a tick label, in ems (a digit of DejaVu Sans is 0.636 em wide).
_CHAR_EM = 0.64
#: Space left between neighbouring tick labels, in ems.
_LABEL_GAP_EM = 0.8
#: The ticks tried on a log x axis after the swept values: multiples of the powers of ten.
_LOG_SUBS = ((1.0, 2.0, 5.0), (1.0, 3.0), (1.0,))

#: How the marked cases (:func:`asperity.report.study_case_marks`) are drawn, and their
#: legend entries: mark -> (marker, filled in the line's colour, edge colour or None for the
#: line's, legend entry).
MARK_STYLES = {
    "not converged": ("x", True, "red", "not converged (not a solution)"),
    "mesh error over 100 %": ("s", False, None, "mesh error over 100 % (warning)"),
    "with warnings": ("o", False, None, "with warnings (see the report)"),
}


def _flat_limits(values: np.ndarray) -> tuple[float, float] | None:
    """y limits of ``mean -+ FLAT_RANGE |mean|`` for values that are flat, else None."""
    finite = values[np.isfinite(values)]
    if finite.size < 2:
        return None
    size = float(np.max(np.abs(finite)))
    if size == 0.0 or np.ptp(finite) > FLAT_SPAN * size:
        return None
    mean = float(np.mean(finite))
    return mean - FLAT_RANGE * abs(mean), mean + FLAT_RANGE * abs(mean)


def _log_ticks(ax, x: np.ndarray) -> None:
    """Plain-number ticks on a log x axis (:func:`log_tick_values`); no minor tick labels."""
    size = FontProperties(size=rcParams["xtick.labelsize"]).get_size_in_points()
    ticks = log_tick_values(x, 72.0 * (PANEL_WIDTH - _Y_LABELS_WIDTH), size)
    _plain_log_labels(ax.xaxis, FixedLocator(ticks))


def log_tick_values(x, width_pt: float, size_pt: float) -> np.ndarray:
    """Ticks of a log x axis over the swept values ``x`` whose labels do not crowd.

    The swept values where there are at most :data:`LOG_TICKS`, else (or where their labels
    would crowd) 1, 2 and 5 times the powers of ten, else 1 and 3 times, else the powers of
    ten alone, else every second or third of them: the first whose labels stand apart on an
    axis ``width_pt`` points wide with matplotlib's margins, in type ``size_pt`` points high.

    Parameters
    ----------
    x : array_like
        The swept values, all > 0.
    width_pt : float
        Width of the axis in points.
    size_pt : float
        Size of the tick labels in points.

    Returns
    -------
    numpy.ndarray
    """
    values = np.unique(np.asarray(x, dtype=float))
    margin = float(rcParams["axes.xmargin"])
    low, high = np.log10(values[0]), np.log10(values[-1])
    span = (high - low) * (1.0 + 2.0 * margin) or 1.0
    candidates = [values] if values.size <= LOG_TICKS else []
    ends = (low - margin * (high - low), high + margin * (high - low))
    candidates += [_decade_multiples(*ends, subs) for subs in _LOG_SUBS]
    candidates += [c[np.round(np.log10(c)) % step == 0] for step in (2, 3)
                   for c in candidates[-1:]]  # every second or third power of ten
    candidates = [c for c in candidates if c.size >= 2] or [values]
    for ticks in candidates:
        if not _crowded(ticks, span, width_pt, size_pt):
            return ticks
    return candidates[-1]


def _decade_multiples(low: float, high: float, subs) -> np.ndarray:
    """``subs`` times the powers of ten from ``10**low`` to ``10**high``."""
    ticks = [m * 10.0**e for e in range(int(np.floor(low)), int(np.ceil(high)) + 1)
             for m in subs]
    return np.array([t for t in ticks if low <= np.log10(t) <= high])


def _crowded(ticks: np.ndarray, span: float, width_pt: float, size_pt: float) -> bool:
    """Whether neighbouring labels of ``ticks``, on a log axis ``span`` decades over
    ``width_pt`` points, would stand closer than :data:`_LABEL_GAP_EM`."""
    widths = [len(format_number(float(t))) * _CHAR_EM * size_pt for t in ticks]
    for n in range(len(ticks) - 1):
        apart = np.log10(ticks[n + 1] / ticks[n]) / span * width_pt
        if apart < (widths[n] + widths[n + 1]) / 2.0 + _LABEL_GAP_EM * size_pt:
            return True
    return False


def _plain_log_labels(axis, locator) -> None:
    """Major ticks of a log ``axis`` at ``locator``, labelled as plain numbers; no minor
    tick labels."""
    axis.set_major_locator(locator)
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: format_number(v)))
    axis.set_minor_formatter(NullFormatter())


def _log_y(ax, values: np.ndarray) -> None:
    """A log y axis with plain-number ticks at 1, 2 and 5 times the powers of ten (also 3
    within a decade), when ``values`` are all positive and span more than
    :data:`LOG_Y_SPAN`."""
    finite = values[np.isfinite(values)]
    if finite.size < 2 or np.any(finite <= 0) or finite.max() / finite.min() <= LOG_Y_SPAN:
        return
    ax.set_yscale("log")
    # within a decade 1, 2, 5 can leave one label (110-350: 200 only); 3 joins them there
    subs = (1.0, 2.0, 5.0) if finite.max() / finite.min() >= 10.0 else (1.0, 2.0, 3.0, 5.0)
    _plain_log_labels(ax.yaxis, LogLocator(base=10.0, subs=subs))


def _axis_values(ds, name):
    """(numbers for the x axis or None for labels, tick labels) of a study coordinate."""
    values = ds[name].values
    unit = ds[name].attrs.get("units", "1")
    if np.issubdtype(values.dtype, np.number):
        return values.astype(float), [format_axis_value(float(v), unit) for v in values]
    return None, [str(v) for v in values]


def _draw_cases(ax, xs: np.ndarray, y: np.ndarray, marks: np.ndarray, label) -> tuple:
    """One line of a panel: the clean cases as dots on it, the marked ones as
    :data:`MARK_STYLES` draws them (a case that did not converge off the line, which breaks
    there). Returns the line and the marks drawn (of points with a value)."""
    bad = marks == "not converged"
    clean = np.flatnonzero((marks == "") & np.isfinite(y))
    (line,) = ax.plot(xs, np.where(bad, np.nan, y), "o-", ms=4, lw=1.2, label=label,
                      markevery=[int(i) for i in clean])
    drawn = set()
    for mark, (marker, filled, edge, _) in MARK_STYLES.items():
        chosen = (marks == mark) & np.isfinite(y)
        if not chosen.any():
            continue
        drawn.add(mark)
        colour = edge or line.get_color()
        ax.plot(xs[chosen], y[chosen], marker, ls="none", ms=7 if filled else 5, mew=1.6,
                color=colour, mfc=colour if filled else "white", zorder=3)
    return line, drawn


def _mark_handles(drawn: set) -> list:
    """Legend entries of the marks drawn in a panel, in the order of :data:`MARK_STYLES`."""
    handles = []
    for mark, (marker, filled, edge, text) in MARK_STYLES.items():
        if mark in drawn:
            colour = edge or "0.3"
            handles.append(Line2D([], [], marker=marker, ls="none", ms=7 if filled else 5,
                                  mew=1.6, color=colour, mfc=colour if filled else "white",
                                  label=text))
    return handles


def _unit_size(values: np.ndarray, marks: np.ndarray) -> float:
    """The magnitude a panel's unit is chosen for: the largest of the cases that converged
    (a failed solve's 11 MN does not make the good cases' kN read as MN), else of all."""
    good = np.abs(values[(marks != "not converged") & np.isfinite(values)])
    return float(good.max()) if good.size else float(np.nanmax(np.abs(values)))


def plot_study(ds, variables, columns: int = 3, references=None, marks=None):
    """One panel per variable against the study's first axis: one line per combination of
    the other axes (``mode = "cross"``, at most 10), or one line with each point labelled with
    the other axes' values (``mode = "zip"``); the closed-form references of a variable
    beside it, dashed, in its colour and unit, named in the legend (``Hamrock-Dowson
    (1977)`` beside the central film, the solver's line labelled ``solver``).

    Parameters
    ----------
    ds : xarray.Dataset
        ``study.nc`` as combined by :func:`asperity.sweep.combine`.
    variables : list of str
        Summary keys to plot (numeric variables of ``ds``).
    columns : int
        Panels per row.
    references : dict, optional
        Variable -> list of (reference key, name in the legend) drawn beside it (the study
        report passes :func:`asperity.report.study_references`); none by default.
    marks : xarray.DataArray, optional
        The mark of each case (:func:`asperity.report.study_case_marks`, the default): a
        case that did not converge is a red cross apart from the line, one with warnings a
        hollow marker (:data:`MARK_STYLES`).

    Returns
    -------
    matplotlib.figure.Figure
    """
    references = references or {}
    if marks is None:
        from ..report import study_case_marks

        marks = study_case_marks(ds)
    mode = ds.attrs.get("mode", "cross")
    axes_names = [str(n) for n in ds.attrs.get("axes", "").split(",") if n] or [
        d for d in ds.dims]
    first = axes_names[0]
    x, labels = _axis_values(ds, first)
    x_shown = ""
    if x is not None:  # swept angles in degrees, as they are written
        x_scale, x_shown = coordinate_unit(x, ds[first].attrs.get("units", "1"))
        x = x * x_scale
    rows = int(np.ceil(len(variables) / columns))
    fig, axes = plt.subplots(rows, min(columns, len(variables)), squeeze=False,
                             figsize=(4.0 * min(columns, len(variables)), 3.2 * rows),
                             layout="constrained")
    others = axes_names[1:] if mode == "cross" else []
    combos = list(itertools.product(*(range(ds.sizes[o]) for o in others)))[:10]
    paired = ([", ".join(_axis_values(ds, o)[1][i] for o in axes_names[1:])
               for i in range(ds.sizes["case"])] if mode == "zip" and axes_names[1:] else [])
    for ax, key in zip(axes.flat, variables, strict=False):
        label = describe_key(key)[0]
        scale, shown = result_unit(key, _unit_size(ds[key].values.astype(float),
                                                   marks.values))
        drawn, refs = [], references.get(key, [])
        styles = dict(zip((r for r, _ in refs), itertools.cycle(REFERENCE_STYLES)))
        handles, kinds = [], set()
        for combo in combos:
            sel = dict(zip(others, combo, strict=True))
            y = ds[key].isel(sel).values.astype(float) * scale
            text = ", ".join(f"{ds[o].attrs.get('long_name', o)} = "
                             f"{_axis_values(ds, o)[1][i]}" for o, i in sel.items())
            xs = x if x is not None else np.arange(len(labels))
            line, found = _draw_cases(ax, xs, y, marks.isel(sel).values,
                                      text or ("solver" if refs else None))
            kinds |= found
            handles.append(line)
            drawn.append(y)
            for n, (ref, name) in enumerate(refs):  # each formula beside the solver: in a
                # colour of its own on a single line, else in that line's colour
                y_ref = ds[ref].isel(sel).values.astype(float) * scale
                colour = f"C{n + 1}" if len(combos) == 1 else line.get_color()
                (ref_line,) = ax.plot(xs, y_ref, styles[ref], lw=1.4, color=colour,
                                      label=name)
                if len(combos) == 1:
                    handles.append(ref_line)
                drawn.append(y_ref)
        if refs and len(combos) > 1:  # one legend entry per formula, in grey
            handles += [Line2D([], [], ls=styles[ref], lw=1.4, color="0.4", label=name)
                        for ref, name in refs]
        flat = _flat_limits(np.concatenate(drawn)) if drawn else None
        if flat is not None:
            ax.set_ylim(*flat)
        ax.ticklabel_format(axis="y", useOffset=False)
        for i, tag in enumerate(paired):  # zip mode: each point's values of the other axes
            ax.annotate(tag, (xs[i], y[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7, color="0.3")
        if x is None:
            ax.set_xticks(np.arange(len(labels)), labels, rotation=30, ha="right")
        elif np.all(x > 0) and (ds[first].attrs.get("scale") == "log"  # a log range
                                or (len(x) > 2 and x.max() / x.min() > 50)):
            ax.set_xscale("log")
            _log_ticks(ax, x)
            if drawn:
                _log_y(ax, np.concatenate(drawn))
        else:  # the whole axis on every panel, also where some cases have no value
            pad = 0.05 * (np.ptp(x) or 1.0)
            ax.set_xlim(x.min() - pad, x.max() + pad)
        xlabel = ds[first].attrs.get("long_name", first)
        ax.set_xlabel(f"{xlabel} ({x_shown})" if x is not None and x_shown else xlabel)
        ax.set_ylabel(f"{label} ({shown})" if shown else label)
        ax.grid(True, lw=0.3, alpha=0.6)
        if not (others or refs):  # a single line needs no entry of its own
            handles = []
        handles += _mark_handles(kinds)
        if handles:
            ax.legend(handles=handles, fontsize=7)
    for ax in list(axes.flat)[len(variables):]:
        ax.set_visible(False)
    fig.suptitle(ds.attrs.get("title", "Parameter study"), fontsize=11)
    return fig
