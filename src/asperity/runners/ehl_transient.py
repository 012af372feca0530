"""Runner of ``analysis = "ehl-transient"``: rough surfaces moving through an EHL contact.

Builds the contact problem and the two moving surfaces of the case, runs
:func:`asperity.ehl.solve_transient` from the smooth steady solution, and packages the seed's
statistics: the contact-count rate map (Figs. 4-8), the fraction of steps with contact
(Table 2), pressure maxima, the film histogram, flow vectors (Fig. 14) and centre-line
snapshots with the two surfaces (Figs. 3, 10).

Long runs checkpoint to ``workdir/checkpoint.npz``; with ``resume=True`` a killed run goes on
from its last checkpoint and ends with the same numbers as an uninterrupted one. At every
checkpoint the statistics so far are also written to ``workdir/result.nc`` (atomically), so
nothing is lost if the run is stopped; the final result replaces that file.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import xarray as xr

from .. import diagnostics
from ..cases.ehl import MAX_NODES, MAX_NX, MAX_NY
from ..ehl import solve_transient
from ..ehl.problem import LineContact
from ..ehl.smooth_start import start_rows
from ..ehl.statistics import COUNT_RATE_UNITS, count_rate
from ..ehl.stepper import BLOWN_UP_FLOOR, StepOptions, TimeStepper
from ..ehl.transient import TransientResult, default_warmup_steps
from ..formatting import format_duration
from ..references import film_formula_comparisons
from ..results import Comparison, Outcome, variable, write_netcdf
from ..surfaces.features import STRAIGHT_FEATURES
from ..surfaces.parameters import acf_decay_lengths
from ..surfaces.topography import Topography
from .ehl_steady import chosen_mesh, ehl_warnings

__all__ = ["CHECKPOINTS", "SECONDS_PER_NODE_STEP", "run"]

#: This runner takes ``workdir`` and ``resume`` (see :func:`asperity.runners.run_case`).
CHECKPOINTS = True
#: Steps relaxed again that get a note of their own in the report; the rest are counted.
MAX_FALLBACK_NOTES = 8
#: Wall seconds per node and time step of a transient run on 2 cores, for the estimate shown
#: before it starts: the seed's gear case 1.9e-6 (801 x 201 nodes, 4,428 steps, 23 min), a
#: ball bearing with a dent 1.6e-6 (513 x 889, 1,124 steps, 13.4 min; docs/ehl-transient.md,
#: Cost, and session 35's user cases).
SECONDS_PER_NODE_STEP = 2e-6


def _dataset(case, problem, res) -> xr.Dataset:
    """result.nc: the result's variables (:meth:`TransientResult.to_dataset`) with the run's
    attributes."""
    dataset = res.to_dataset()
    dataset.attrs = {
        "title": case.title, "analysis": "ehl-transient", "Conventions": "CF-1.8",
        "timestep_s": res.dt, "warmup_steps": res.warmup_steps,
        "counting_steps": res.counting_steps, "steps_done": res.steps_done,
        "hertz_a_m": problem.a, "converged": int(res.converged),
        "fixed_point_pressure": res.fixed_point_pressure,
        "fixed_point_film": res.fixed_point_film,
        "fixed_point_sweeps": res.fixed_point_sweeps,
        "fixed_point_settled": int(res.fixed_point_settled)}
    return dataset


def _outcome(res, step: int, settings: int = 1) -> str:
    """How the step (0-based) that changed ``settings`` solver settings, or added y-line
    sweeps, ended, for the report's note."""
    ended = "converged" if res.step_converged[step] else "still did not converge"
    if res.y_lines[step]:
        changed = "the y-line sweeps"
    else:
        changed = "the changed setting" if settings == 1 else "the changed settings"
    return (f" (the sweeps of all tries are counted: {res.sweeps[step]}; with {changed} it "
            f"{ended})")


def _listed(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _setting_changes(start, end, update: str) -> tuple[str, str]:
    """The settings ``(refresh, load gain, density term, relaxation)`` that differ between
    ``start`` and ``end``, as the report names them before and after."""
    before, after = [], []
    if end[0] != start[0]:
        before.append(f"the far field refreshed every {start[0]} sweeps")
        after.append("a refresh at every sweep")
    if end[2] != start[2]:
        before.append(f"the density's Newton term in the {update}" if start[2]
                      else f"the density lagged in the {update}")
        after.append("the density lagged" if start[2] else "the density's Newton term")
    if end[1] != start[1]:
        before.append(f"the load gain {start[1]:.3g}")
        after.append(f"the load gain {end[1]:.3g}")
    if end[3] != start[3]:
        before.append("each sweep's change applied in full" if start[3] == 1.0
                      else f"each sweep's change under-relaxed by {start[3]:.3g}")
        after.append(f"each sweep's change under-relaxed by {end[3]:.3g}" if end[3] != 1.0
                     else "each sweep's change applied in full")
    return _listed(before), _listed(after)


def _fallback_notes(case, problem, res) -> list[str]:
    """One note per step relaxed again with safer settings (:meth:`TimeStepper.advance`): the
    settings it failed with, those it and the later steps were relaxed with, and how it
    ended; and one where the stepper went back to the case's own settings,
    :attr:`~asperity.ehl.stepper.TimeStepper.RESTORE_AFTER` steps after the last step relaxed
    again. Past :data:`MAX_FALLBACK_NOTES` steps relaxed again the rest are counted in one
    note (a user's gear case relaxed 41 steps again, a wall of notes over the results)."""
    options = StepOptions.for_problem(problem, method=case.solver.method,
                                      refresh=case.solver.refresh,
                                      load_gain=case.solver.load_gain)
    update = "row solve" if options.method == "line" else "point update"
    relaxed_again = np.flatnonzero(res.tries[:res.steps_done] > 1) + 1
    own = (options.refresh, options.load_gain, False, 1.0)
    notes = []
    previous, since = own, 0
    for step in range(res.steps_done):
        start = previous
        if previous != own and since >= TimeStepper.RESTORE_AFTER:
            start = own
            notes.append((step + 1, f"From step {step + 1} on, {TimeStepper.RESTORE_AFTER} steps "
                                    "after the last step relaxed again, the case's own settings "
                                    "were taken up again."))
        now = (int(res.refresh_intervals[step]), float(res.load_gains[step]),
               bool(res.density_newton[step]), float(res.relaxation[step]))
        if res.tries[step] > 1:
            changed = sum(a != b for a, b in zip(start, now, strict=True))
            text = f"Step {step + 1} did not converge"
            if changed:
                before, after = _setting_changes(start, now, update)
                text += f" with {before}; it and the later steps were relaxed with {after}"
            if res.y_lines[step]:
                text += (", and not with those either" if changed else " with any setting left")
                text += ("; it alone was relaxed once more with a y-line sweep after every "
                         "x-line sweep")
            notes.append((step + 1, f"{text}{_outcome(res, step, changed)}."))
            since = 0
        else:
            since += 1
        previous = now
    if relaxed_again.size <= MAX_FALLBACK_NOTES:
        return [text for _, text in notes]
    last = relaxed_again[MAX_FALLBACK_NOTES - 1]
    rest = relaxed_again[MAX_FALLBACK_NOTES:]
    listed = ", ".join(str(s) for s in rest[:10]) + (", ..." if rest.size > 10 else "")
    return [text for step, text in notes if step <= last] + [
        f"{rest.size} more steps were relaxed again ({listed}): result.nc's tries, "
        "refresh_interval, load_gain, density_newton and relaxation give every step's "
        "settings."]


def _start_notes(start, problem, nx: int, domain) -> list[str]:
    """A note where the rows of the default mesh were doubled because the smooth steady start
    touched on them (:func:`asperity.ehl.smooth_start.start_rows`), and where a finer start
    was refused for not converging."""
    if start is None or len(start.tried) < 2:
        return []

    def rows(n):
        _, y = problem.grid(nx, n, domain)
        return f"{nx} x {n} (dy = b/{problem.b / (y[1] - y[0]):.3g})"

    where = "; ".join(f"{count} nodes on {rows(n)}" for n, count, _ in start.tried if count)
    last, _, converged = start.tried[-1]
    refused = "" if converged else f"; on {rows(last)} it did not converge"
    return [f"The smooth steady start had no film at nodes in its side lobes ({where}), which "
            "the contact statistics would count as contacts at every step, so the rows across "
            f"y of the default mesh were doubled{refused}: the run uses {rows(start.ny)}."]


def _partial_dataset(checkpoint: Path, x, y, dt) -> xr.Dataset | None:
    """Statistics so far, from the checkpoint file (for the streamed result.nc)."""
    try:
        with np.load(checkpoint, allow_pickle=False) as data:
            count = np.array(data["stat_count"])
            steps = int(data["stat_steps"])
            done = int(data["step"])
            max_p = np.array(data["max_pressure"])
    except (OSError, KeyError, ValueError):
        return None
    rate = count_rate(count, steps, dt)
    return xr.Dataset(
        {"contact_count_rate": variable(("x", "y"), rate, COUNT_RATE_UNITS,
                                        "contact count rate Q: counting steps with contact at "
                                        "the node per millisecond of counting time (so far)"),
         "contact_count": variable(("x", "y"), count, "1", "contact count (so far)"),
         "max_pressure": variable("step", max_p, "Pa", "maximum pressure per step")},
        coords={"x": variable("x", x, "m", "x"), "y": variable("y", y, "m", "y"),
                "step": variable("step", np.arange(1, max_p.size + 1), "1", "time step"),
                "time": xr.Variable("step", dt * np.arange(1, max_p.size + 1),
                                    dict(TransientResult.TIME_ATTRS))},
        attrs={"analysis": "ehl-transient", "partial": 1, "status": "partial", "steps_done": done,
               "counting_steps_done": steps})


def run(case, progress=None, workdir=None, resume=False) -> Outcome:
    """Run the transient case; checkpoint into ``workdir`` when given."""
    problem = case.problem()
    line = isinstance(problem, LineContact)
    nx, ny, domain = case.mesh(problem)
    start = None
    if not line and not case.grid.nodes_given:  # the rows on which the smooth start has a film
        if progress is not None:
            progress(0, 1, f"steady start on {nx} x {ny} nodes")
        start = start_rows(problem, nx, ny, domain, contact_film=case.solver.contact_film,
                           method=case.solver.method, tol=case.solver.tolerance,
                           max_nodes=MAX_NODES)
        ny = start.ny
    x, y = problem.grid(nx, ny, domain)
    dt = case.timestep(problem, x)
    warmup, counting = case.steps(problem, x, dt)
    total = warmup + counting
    records = case.surface_records(problem, x, y, warmup, total, dt)
    rough1, rough2 = (None if built is None else built.surface for built in records)
    file_notes, file_warnings = _file_reports(case, records)
    snaps = case.snapshot_steps(problem, x, dt, warmup, total)
    shown = snaps[-1]  # the centre-line figure's step: the last, or a feature at x = 0
    centred = [int(np.rint(-start / step))
               for _, _, start, step in case.feature_tracks(problem, x, dt, warmup)]
    if centred and warmup < centred[0] <= total:
        shown = centred[0]
        snaps = np.union1d(snaps, [shown])
    checkpoint = None if workdir is None else Path(workdir) / "checkpoint.npz"

    def callback(step, residual):
        if progress is not None:
            phase = "warm-up" if step <= warmup else "counting"
            progress(step, total, f"{phase}: step {step}/{total}, residual {residual:.1e}")
        if checkpoint is not None and step % case.solver.checkpoint_every == 0:
            partial = _partial_dataset(checkpoint, x, y, dt)
            if partial is not None:
                write_netcdf(partial, Path(workdir) / "result.nc")

    if progress is not None:  # what the run will cost, before the steady start
        progress(0, total, f"steady start; then {total} steps on {nx} x {ny} nodes, "
                           f"{_expected_duration(nx * ny * total)}")
    with warnings.catch_warnings():  # the steady start's inlet warning: see ehl_warnings
        warnings.filterwarnings("ignore", "domain: the inlet", RuntimeWarning)
        res = solve_transient(
            problem, rough1, rough2, nx=nx, ny=ny, domain=domain, dt=dt,
            counting_steps=counting, warmup_steps=warmup,
            theta=case.solver.theta, method=case.solver.method, tol=case.solver.tolerance,
            max_iter=case.solver.max_sweeps, refresh=case.solver.refresh,
            acceleration=case.solver.acceleration, damping=case.solver.damping,
            load_gain=case.solver.load_gain,
            contact_film=case.solver.contact_film,
            steady=None if start is None else start.steady, snapshot_steps=snaps,
            checkpoint=checkpoint,
            checkpoint_every=case.solver.checkpoint_every, resume=resume, callback=callback)
    # each statistic beside its standard error (TransientResult.standard_errors)
    errors = res.standard_errors()
    nan = float("nan")
    rate_error, hertz_rate = (errors.get(k) for k in ("max_contact_count_rate",
                                                       "hertz_contact_count_rate"))
    base = res.summary()
    summary = {**base,
               "contact_time_percent": 100.0 * res.contact_time_fraction,
               "contact_time_percent_standard_error":
                   100.0 * base["contact_time_fraction_standard_error"],
               "max_contact_count_rate_per_ms": float(np.max(res.contact_count_rate)),
               "max_contact_count_rate_per_ms_standard_error":
                   rate_error.standard_error if rate_error else nan,
               "mean_hertz_contact_count_rate_per_ms": hertz_rate.value if hertz_rate else nan,
               "mean_hertz_contact_count_rate_per_ms_standard_error":
                   hertz_rate.standard_error if hertz_rate else nan,
               "steady_central_film_thickness_m": res.steady_central_film,
               "steps_converged_fraction": float(np.mean(res.step_converged[:res.steps_done]))
               if res.steps_done else 0.0,
               "slide_roll_ratio": problem.slide_roll_ratio,
               "hertz_a_m": problem.a, "converged": bool(res.converged)}
    comparisons = []
    if case.paper_contact_time_percent is not None:
        comparisons.append(Comparison(
            "time with contact at >= 1 node", summary["contact_time_percent"],
            case.paper_contact_time_percent, "Holmes et al. (2005) Table 2", "%",
            note="synthetic stand-in profiles and a reduced mesh: a trend, not a check"
            + (f"; ours ± {summary['contact_time_percent_standard_error']:.2g} % (standard "
               "error of this counting period)"
               if np.isfinite(summary["contact_time_percent_standard_error"]) else "")))
    if np.isfinite(res.steady_film).all():  # the smooth steady start is a steady EHL solution
        comparisons += film_formula_comparisons(
            problem, res.steady_central_film, float(res.steady_film.min()), checked=False,
            label="steady start: ", note="; the smooth steady start of the run, on its mesh: "
            "shown, not checked")
    notes = []
    if not res.steady_converged:
        notes.append(f"The smooth steady start did not converge (its central film "
                     f"{res.steady_central_film * 1e9:.4g} nm is not a converged value); the "
                     f"run went on from it, and its {res.warmup_steps} warm-up steps relax the "
                     "state before counting, so the statistics stand where every step "
                     "converged, but the run counts as not converged.")
    bad = int(np.count_nonzero(~res.step_converged[:res.steps_done]))
    if bad:
        notes.append(f"{bad} of {res.steps_done} steps did not reach the tolerance "
                     f"{case.solver.tolerance:g} within {case.solver.max_sweeps} sweeps; the "
                     "statistics include them.")
    notes += [*_start_notes(start, problem, nx, domain), *file_notes,
              *_fallback_notes(case, problem, res)]
    from ..plotting import ehl_transient as plots

    # a run that stopped early has no snapshot at the steps it did not reach: the centre line
    # of the last one it reached, or none
    reached = np.flatnonzero(np.isfinite(res.centre_film).all(axis=1))
    shown_index = int(np.flatnonzero(res.snapshot_steps == shown)[0])
    if shown_index not in reached and reached.size:
        shown_index = int(reached[-1])
    rate_plot = plots.plot_contact_rate_line if line else plots.plot_contact_rate
    figures = {
        "contact_count_rate": (lambda: rate_plot(res, problem),
                               "Contact count rate Q per ms over the contact (Figs. 4-8)."),
        "film_histogram": (lambda: plots.plot_film_histogram(res),
                           "Film thickness distribution over the counting period."),
    }
    if reached.size:
        centred_shown = res.snapshot_steps[shown_index] == shown != snaps[-1]
        figures["centre_line"] = (
            lambda: plots.plot_centre_line(res, problem, shown_index),
            "Pressure and film on y = 0 with the two surfaces below (Fig. 3)"
            + (", the feature at the centre." if centred_shown else "."))
    tracks = case.feature_tracks(problem, x, dt, warmup)
    if tracks and reached.size > 1:  # where a feature's film change travels, step by step
        positions = {label: start + step * res.snapshot_steps
                     for label, _, start, step in tracks}
        figures["film_snapshots"] = (
            lambda: plots.plot_film_snapshots(res, problem, positions),
            "The film on y = 0 at the recorded steps, the feature's centre marked below each: "
            "the film change moves with the feature in rolling, at the mean speed with "
            "sliding.")
    if not line:
        figures["flow_vectors"] = (lambda: plots.plot_flow_vectors(res, problem),
                                   "Film contours and lubricant flow vectors (Fig. 14).")
    # an unconverged steady start's film would set the inlet and mesh advice: the formula's
    film = res.steady_central_film if res.steady_converged else problem.film_estimate()
    trust = ehl_warnings(case, problem, res.pressure, res.x, res.y, film,
                         film_solved=res.steady_converged, check_hardness=False)
    plastic_notes, plastic_warnings = _plasticity(case, problem, res)
    notes += plastic_notes
    trust += plastic_warnings
    b = None if line else problem.b
    start_mesh = []
    if np.isfinite(res.steady_film).all():  # contacts without roughness, counted all the same
        trust += diagnostics.smooth_start_contact(res.steady_film, res.x, res.y, problem.a,
                                                  b, res.contact_film)
        # the steady start's minimum film, a row of the comparison table (a ball on a disc:
        # 4.1 nm against Hamrock-Dowson's 35.9 on b/20, shown without a word); where the start
        # touches, most often the side lobes, too narrow for the mesh: how to refine
        start_mesh = diagnostics.ehl_minimum_film_mesh(
            res.steady_film, res.x, res.y, problem.a, b, max_nodes=(MAX_NODES, MAX_NX, MAX_NY))
        trust += start_mesh
    least = res.least_film
    if not start_mesh and np.isfinite(least).all() and least.min() > res.contact_film:
        # the reported minimum film without contact, at its step: a feature that crosses the
        # side lobes of a point contact is as thin as the mesh across y lets the lobes be
        trust += diagnostics.ehl_minimum_film_mesh(least, res.x, res.y, problem.a, b,
                                                   max_nodes=(MAX_NODES, MAX_NX, MAX_NY))
    unconverged = ~res.step_converged[:res.steps_done]
    in_a_row = (res.steps_done if unconverged.all() else int(np.argmin(unconverged[::-1])))
    stopped = np.isfinite(res.residuals[res.steps_done - 1]) if res.steps_done else False
    trust += diagnostics.stopped_run(res.steps_done, res.warmup_steps, res.counting_steps,
                                     in_a_row if stopped else 0)
    trust += diagnostics.unconverged_steps(res.step_converged[:res.steps_done],
                                           case.solver.tolerance, case.solver.max_sweeps,
                                           res.residuals[:res.steps_done], BLOWN_UP_FLOOR,
                                           line=line)
    trust += res.fixed_point_warning()
    trust += res.counting_warning()
    trust += _roughness_warnings(case, problem, x, y, warmup, total, dt, (rough1, rough2))
    trust += _feature_warnings(case, problem, x, y, warmup, total, dt)
    trust += _warmup_warnings(case, problem, x, warmup, total, dt)
    return Outcome(_dataset(case, problem, res), summary, figures, comparisons,
                   converged=res.converged, notes=notes,
                   warnings=[*file_warnings, *trust],  # the file's doubts explain the rest
                   chosen=chosen_mesh(case, problem, x, y) | case.lubricant.unused_defaults())


def _plasticity(case, problem, res) -> tuple[list[str], list[str]]:
    """(notes, warnings): every counting step's largest pressure against the bodies' hardness
    (:func:`diagnostics.steps_above_hardness`, warnings) and, with no hardness given, past the
    strain limit (:func:`diagnostics.asperity_plasticity_note`, a note); the asperity contacts
    are elastic. A case given by its reduced modulus has no bodies to judge."""
    done = res.max_pressure[:res.steps_done]
    counted = done[res.warmup_steps:]  # the steps of the reported maximum pressure
    if case.body1 is None or not np.isfinite(counted).any():
        return [], []
    bodies = [("body1", case.body1.material()), ("body2", case.body2.material())]
    return (diagnostics.asperity_plasticity_note(float(np.nanmax(counted)),
                                                 problem.reduced_modulus / 2.0, bodies),
            diagnostics.steps_above_hardness(done, res.warmup_steps, bodies))


def _expected_duration(node_steps: int) -> str:
    """The wall time a run of ``node_steps`` (nodes times steps) takes on 2 cores, in words:
    about ``SECONDS_PER_NODE_STEP`` each, within a factor of 2 either way (docs/ehl-transient.md,
    Cost). A user's long-ellipse dent case ran 1025 x 169 nodes for 2,087 steps with nothing
    to say that it would take a quarter of an hour."""
    seconds = node_steps * SECONDS_PER_NODE_STEP
    if seconds < 60:
        return "about a minute or less on 2 cores"
    return (f"roughly {format_duration(seconds)} on 2 cores ({format_duration(seconds / 2)} to "
            f"{format_duration(2 * seconds)}; a coarser grid to try the case first)")


def _file_reports(case, records) -> tuple[list[str], list[str]]:
    """The notes (units read, form removed) and warnings (the reader's, a doubt on the units)
    of the surfaces read from measured files (:meth:`SurfaceBuild.file_report`)."""
    notes, lines = [], []
    for k, (spec, built) in enumerate(zip((case.surface1, case.surface2), records,
                                          strict=True), start=1):
        if built is not None and spec.kind == "file":
            more, doubts = built.file_report(f"surface{k}.path", Path(spec.path).name)
            if isinstance(built.surface, Topography) and not built.surface.periodic:
                more = (*more, f"surface{k}.path ({Path(spec.path).name}): a map of "
                               f"{built.surface.y.size} rows, placed across y with its middle "
                               "on the contact's centre line (y = 0)")
            notes += more
            lines += doubts
    return notes, lines


def _roughness_warnings(case, problem, x, y, warmup, total, dt, surfaces) -> list[str]:
    """Roughness the mesh cannot resolve (shorter than a few cells along x; a gaussian
    topography's correlation length across y, or a measured map's, from its autocorrelation),
    or that ``lowpass`` removed, per surface."""
    dx = x[1] - x[0]
    specs = (case.surface1, case.surface2)
    raw = surfaces
    if any(spec.lowpass > 0 for spec in specs):
        unfiltered = {f"surface{k}": spec.model_copy(update={"lowpass": 0.0})
                      for k, spec in enumerate(specs, 1)}
        raw = case.model_copy(update=unfiltered).surfaces(problem, x, y, warmup, total, dt)
    lines = []
    for k, (spec, surf, before) in enumerate(zip(specs, surfaces, raw, strict=True), 1):
        if surf is None:
            continue
        if spec.lowpass > 0:
            lines += diagnostics.lowpass_removed(f"surface{k}", before.z, surf.z,
                                                 spec.lowpass * dx)
        else:
            lines += diagnostics.unresolved_roughness(f"surface{k}", surf.z,
                                                      surf.x[1] - surf.x[0], dx)
        if spec.kind == "gaussian":  # generated on the mesh's rows across y
            lines += diagnostics.roughness_resolution(
                f"surface{k}", spec.correlation_length, x, y, along_x=False,
                correlation_length_y=spec.correlation_length_y)
        if spec.kind == "file" and isinstance(surf, Topography) and y.size > 1:
            # a measured map sampled at the mesh's rows: its own decay length across y (the
            # ACF's 0.2 lag along the y axis, ISO 25178-2's rays at 0 and 90 degrees)
            _, (along, across) = acf_decay_lengths(surf, directions=2)
            if np.isfinite(across):
                lines += diagnostics.roughness_resolution(
                    f"surface{k}.path", along, x, y, along_x=False,
                    correlation_length_y=across)
    return lines


def _feature_warnings(case, problem, x, y, warmup, total, dt) -> list[str]:
    """A single feature the mesh does not resolve, or whose passage through the Hertz zone
    the counting period does not cover."""
    dx = x[1] - x[0]
    dy = y[1] - y[0] if y.size > 1 else None
    lines = []
    for k, spec in enumerate((case.surface1, case.surface2), start=1):
        if spec.waviness is not None:  # a sine along its direction, judged as x is
            along = spec.waviness.direction == "x"
            lines += diagnostics.unresolved_feature(
                f"surface{k}", "waviness half-wavelength", spec.waviness.wavelength / 2,
                dx if along else None, None if along else dy,
                min_across=diagnostics.FEATURE_MIN_CELLS_ALONG)
    for label, spec, start, step in case.feature_tracks(problem, x, dt, warmup):
        lines += _feature_size(label, spec, problem, y)
        lines += diagnostics.unresolved_feature(
            label, f"{spec.feature} half-width", spec.half_width, dx,
            None if spec.feature in STRAIGHT_FEATURES else dy)
        lines += diagnostics.feature_passage(label, spec.feature, start + warmup * step,
                                             start + total * step, problem.a, step, warmup,
                                             total - warmup)
    return lines


def _feature_size(label: str, spec, problem, y) -> list[str]:
    """A single feature wider than the contact (its half-width above the smaller Hertz
    semi-axis) or than the domain across y: a user's dent of 2 mm half-width in a contact of
    a = 0.67 mm, b = 0.28 mm ran 2,552 steps without a word. Such a feature reshapes the
    whole contact instead of passing through it, which the feature statistics and mesh advice
    do not expect."""
    a = problem.a
    b = None if isinstance(problem, LineContact) else problem.b
    smaller = a if b is None else min(a, b)
    lines = []
    if spec.half_width > smaller:
        axes = f"a = {a * 1e6:.4g} um" + ("" if b is None else f", b = {b * 1e6:.4g} um")
        lines.append(f"{label}.half_width: the {spec.feature} ({spec.half_width * 1e6:.4g} um) "
                     f"is wider than the contact ({axes}; limit: the smaller semi-axis): it "
                     "changes the contact as a whole rather than passing through it; for a "
                     "feature the size of the contact give its shape as waviness or form, or "
                     "check the half-width's unit")
    if b is not None and spec.feature not in STRAIGHT_FEATURES and \
            2.0 * spec.half_width > y[-1] - y[0]:
        lines.append(f"{label}.half_width: the {spec.feature} ({2e6 * spec.half_width:.4g} um "
                     f"across) is wider than the domain across y ({(y[-1] - y[0]) * 1e6:.4g} "
                     "um): it is cut off at the sides (grid.y_min, grid.y_max)")
    return lines


def _warmup_warnings(case, problem, x, warmup: int, total: int, dt: float) -> list[str]:
    """A rough surface (not a single feature) that has not covered the Hertz zone when counting
    starts, so that counted steps see a contact still partly smooth.

    Its roughness enters at the inlet ``x[0]`` at ``t = 0`` and its front reaches ``x = a``
    after ``(a - x[0]) / (u dt)`` steps; the default warm-up waits until it has crossed the
    whole domain (:func:`~asperity.ehl.transient.default_warmup_steps`, the seed's rule). A
    user's elliptical contact with a rough disc and ``warmup_steps = 5`` counted 5 steps in
    which the roughness had come 18 um into a domain of 427 um and reported 0 % contact
    time without a word (docs/ehl-transient.md, "A measured map, a short warm-up").
    """
    a = problem.a
    rough = [(k, abs(u)) for k, (spec, u) in enumerate(
        ((case.surface1, problem.u1), (case.surface2, problem.u2)), start=1)
        if spec.kind not in ("smooth", "feature") or spec.waviness is not None]
    default = default_warmup_steps(x, [u for _, u in rough], dt)
    lines = []
    for k, u in rough:
        travel = u * dt
        covered = int(np.ceil((a - x[0]) / travel - 1e-9))  # steps until its front is at +a
        if warmup >= covered:
            continue
        advice = (f"leave time.warmup_steps out (the default, {default} steps: until the "
                  f"roughness has crossed the domain) or set it >= {covered} (limit: the "
                  "roughness over the whole Hertz zone, -a to +a, when counting starts)")
        front = x[0] + travel * total
        if front <= -a:
            lines.append(f"surface{k}: its roughness never reaches the Hertz zone: in the run's "
                         f"{total} steps it comes from the inlet (x = {x[0] / a:.3g} a) only to "
                         f"x = {front / a:.3g} a, so every statistic is that of the smooth "
                         f"contact; {advice}")
        else:
            lines.append(f"surface{k}: when counting starts (time.warmup_steps = {warmup}) its "
                         f"roughness has come from the inlet (x = {x[0] / a:.3g} a) only to "
                         f"x = {(x[0] + travel * warmup) / a:.3g} a, so the first "
                         f"{min(covered, total) - warmup} of the {total - warmup} counting steps "
                         f"count a contact that is still partly smooth; {advice}")
    return lines

