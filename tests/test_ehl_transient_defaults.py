"""Default mesh and time steps of a transient case written without [grid] or [time].

docs/ehl-transient.md, "The default mesh of a transient case": the mesh follows the film
(as a steady case's does) and a single feature (10 cells per half-width along x, 5 across on
the bump example); a feature enters when counting starts and is counted until it has crossed
the domain. A mesh or counting period chosen in the case file that misses the feature is
reported with the setting that would not.
"""

from dataclasses import replace

import numpy as np
import pytest
import tomllib

from asperity import diagnostics
from asperity.cases import load_case
from asperity.ehl import Lubricant, PointContact, solve_steady, stepper
from asperity.ehl.stepper import BLOWN_UP_SWEEPS, UNDER_RELAXATION, StepOptions, TimeStepper
from asperity.ehl.transient import MovingSurface, solve_transient
from asperity.errors import InputError
from asperity.examples import example_text
from asperity.materials import Material
from asperity.runners import run_case

STEEL = Material(210e9, 0.3)


def _bump(**changes):
    """The bump example with tables replaced or added (``{"grid": {...}}``); a table given
    with its ``kind`` is replaced whole (a smooth surface takes none of the bump's keys)."""
    data = tomllib.loads(example_text("bump-ball-on-disc"))
    for table, keys in changes.items():
        data[table] = dict(keys) if "kind" in keys else {**data.get(table, {}), **keys}
    return load_case(data)


def _run_setup(case):
    problem = case.problem()
    nx, ny, domain = case.mesh(problem)
    x, y = problem.grid(nx, ny, domain)
    dt = 0.5 * (x[1] - x[0]) / max(problem.u1, problem.u2)
    warmup, counting = case.steps(problem, x, dt)
    return problem, x, y, dt, warmup, counting


def test_without_a_feature_the_mesh_is_the_steady_default_mesh():
    """A transient case without [grid] node counts and without a feature runs on the mesh its
    steady case would: the film's spacing along x (the gear case's H_c = 0.105 asks for a/64:
    5 dX^2/H_c is 4.6 % at a/32 against the 2 % aimed at), b/10 across within
    3 dX <= dY <= 16 dX. The former fixed 129 x 65 (a/32) is what a thin film got and what
    the film-mesh check rejected."""
    case = _bump(surface2={"kind": "smooth"})
    problem = case.problem()
    nx, ny, domain = case.mesh(problem)
    assert (nx, ny) == problem.default_nodes(domain)
    film = problem.film_estimate() / problem.film_scale
    x, y = problem.grid(nx, ny, domain)
    assert diagnostics.ehl_film_mesh(x, problem.a, film) == []
    assert diagnostics.ehl_film_mesh(problem.grid(129, 65, domain)[0], problem.a, film) != []
    gear = PointContact(0.0191, 0.151, 962.0, 28.125, 21.875, STEEL, STEEL,
                        Lubricant(0.005, 11.1e-9, eyring_stress=10e6))
    gx, gy = gear.grid(*gear.default_nodes())
    assert gear.a / (gx[1] - gx[0]) == pytest.approx(64)


def test_feature_spacing_refines_the_default_mesh_keeping_the_cell_shape():
    """dX <= w/8, dY <= w/3 for a bump of half-width w, and dY >= 3 dX (on flatter cells the
    relaxation of the bump case failed); the mesh without the feature is coarser."""
    case = _bump()
    problem = case.problem()
    nx, ny, domain = case.mesh(problem)
    x, y = problem.grid(nx, ny, domain)
    dx, dy = x[1] - x[0], y[1] - y[0]
    w = case.surface2.half_width
    assert w / dx >= 8 and w / dy >= 3 - 0.2     # the cells come in blocks of 8
    assert dy >= 3 * dx
    assert nx * ny > np.prod(problem.default_nodes(domain))


def _bump_centre(case, problem, x, y, dt, warmup, total, step):
    """Where the solver sees the bump at ``step``: the x of surface 2's largest height on the
    row nearest y = 0 (:class:`MovingSurface`, as the run moves it), or None when none of the
    bump is inside the domain."""
    surf = case.surfaces(problem, x, y, warmup, total, dt)[1]
    moving = MovingSurface(surf, problem.u2, x, y, total * dt, "surface2")
    row = moving.heights(step * dt)[:, np.argmin(np.abs(y))]
    return x[np.argmax(row)] if row.max() > 0.01 * case.surface2.amplitude else None


def test_bump_without_grid_or_time_is_resolved_and_counted_through():
    """The bump enters when counting starts, crosses the contact's centre during the count
    and has left the domain at its end, as the solver moves it."""
    case = _bump()
    problem, x, y, dt, warmup, counting = _run_setup(case)
    total = warmup + counting
    w = case.surface2.half_width
    assert warmup == 0
    assert _bump_centre(case, problem, x, y, dt, warmup, total, warmup) is None
    crossing = warmup + int(round((w - x[0]) / (problem.u2 * dt)))   # centre at x = 0
    assert abs(_bump_centre(case, problem, x, y, dt, warmup, total, crossing)) <= x[1] - x[0]
    assert _bump_centre(case, problem, x, y, dt, warmup, total, total) is None
    assert diagnostics.unresolved_feature("surface2", "bump half-width", w, x[1] - x[0],
                                          y[1] - y[0]) == []


def test_short_counting_period_is_reported_with_the_steps_that_cover_it():
    case = _bump(time={"counting_steps": 400})
    problem, x, y, dt, warmup, counting = _run_setup(case)
    u = problem.u2
    start = x[0] - case.surface2.feature_lead()

    def passage(steps):
        return diagnostics.feature_passage("surface2", "bump", start, start + u * steps * dt,
                                           problem.a, u * dt, warmup, steps)

    (line,) = passage(counting)
    needed = int(line.split("time.counting_steps >= ")[1].split()[0])
    assert needed > counting
    assert passage(needed) == []
    assert passage(needed - 2) != []


def test_rough_surface_and_feature_warm_up_then_the_feature_enters():
    """Roughness on surface 1 warms up as the seed's does; the bump on surface 2 is placed to
    enter when counting starts, not to pass during the warm-up."""
    case = _bump(surface1={"kind": "builtin", "profile": "C"})
    problem, x, y, dt, warmup, counting = _run_setup(case)
    total = warmup + counting
    assert warmup == int(np.ceil((x[-1] - x[0]) / (problem.u1 * dt) - 1e-9))
    for step in (1, warmup // 2, warmup):
        assert _bump_centre(case, problem, x, y, dt, warmup, total, step) is None
    entered = warmup + int(round(2 * case.surface2.half_width / (problem.u2 * dt)))
    assert _bump_centre(case, problem, x, y, dt, warmup, total, entered) == pytest.approx(
        x[0] + case.surface2.half_width, abs=x[1] - x[0])


def test_a_coarse_mesh_for_the_feature_is_reported():
    w = 20e-6
    (line,) = diagnostics.unresolved_feature("surface2", "bump half-width", w, w / 3, w)
    assert "along x" in line and "along y" in line and "nx" in line and "ny" in line
    assert diagnostics.unresolved_feature("surface2", "ridge half-width", w, w / 5) == []


def test_a_feature_too_small_for_the_node_limit_asks_for_a_mesh():
    with pytest.raises(InputError, match="grid.nx"):
        _bump(surface2={"half_width": "0.5 um"})


def test_feature_case_runs_with_default_mesh_and_steps():
    """A ridge through the dent examples' ball-on-disc contact in rolling, no [grid] or [time]:
    the contact's own domain (inlet at 3.5 a) at a/32 (the film and the ridge ask for no
    more), every step converged, the ridge's whole passage counted, no warning about it."""
    case = load_case({
        "analysis": "ehl-transient", "reduced_modulus": "230.8 GPa",
        "contact": {"type": "point", "rx": "12.5 mm", "ry": "12.5 mm", "load": "15 N"},
        "speeds": {"u": "0.1 m/s", "xi": 0.0},
        "lubricant": {"eta0": "0.25 Pa s", "alpha": "20 1/GPa", "viscosity_model": "barus",
                      "density_model": "incompressible"},
        "surface1": {"kind": "feature", "feature": "ridge", "amplitude": "0.1 um",
                     "half_width": "32 um"}})
    outcome = run_case(case)
    data = outcome.dataset
    a = outcome.summary["hertz_a_m"]
    x = data["x"].values
    assert x[0] == pytest.approx(-3.5 * a, rel=0.02) and x[1] - x[0] <= a / 32
    assert data.attrs["warmup_steps"] == 0 and outcome.converged
    assert not [w for w in outcome.warnings if "ridge" in w]
    # the ridge passed through the Hertz zone: the largest pressure rose above the smooth
    # contact's, and is back to it at the end
    p_max = data["max_pressure"].values
    assert p_max.max() > 1.1 * p_max[0]
    assert p_max[-1] == pytest.approx(p_max[0], rel=0.01)
    # the centre-line figure shows the ridge at the centre: one snapshot has it at x = 0
    crest = x[np.argmax(data["centre_surface1"].values, axis=1)]
    assert np.min(np.abs(crest)) <= x[1] - x[0]


@pytest.fixture(scope="module")
def smooth_fine():
    """The bump example's contact in rolling, smooth, on 129 x 129 nodes (a/32 x b/32): with
    the far field refreshed every 3 sweeps to the end of a step its steady solution diverged
    at step 6 (docs/ehl-transient.md); it still does with a refresh every 6 sweeps until the
    step's residual falls below ``REFRESH_EVERY_SWEEP_BELOW``."""
    problem = _bump(speeds={"xi": 0.0}).problem()
    return problem, problem.default_domain()


@pytest.fixture(scope="module")
def smooth_fine_incompressible():
    """:func:`smooth_fine` with an incompressible oil: no density term to add to the row
    solve, so a step that fails with a refresh at every sweep gets half the load gain."""
    problem = _bump(speeds={"xi": 0.0}, lubricant={"density_model": "incompressible"}).problem()
    return problem, problem.default_domain()


def test_a_step_refreshes_the_far_field_at_every_sweep_once_its_residual_is_small(
        smooth_fine):
    # with a refresh every 3 sweeps to the end of the step, step 6 diverged and was relaxed
    # again with a refresh at every sweep (the fallback); refreshing at every sweep once the
    # residual is below REFRESH_EVERY_SWEEP_BELOW, it converges at the first try
    problem, domain = smooth_fine
    res = solve_transient(problem, nx=129, ny=129, domain=domain, warmup_steps=0,
                          counting_steps=10, max_iter=100)
    assert res.converged and np.all(res.step_converged)
    assert np.all(res.refresh_intervals == 3)           # no fallback
    assert res.sweeps.max() < 20
    # the steps of more than one cycle refreshed at every sweep in their tail: more refreshes
    # than one per 3 sweeps (10 sweeps and 8 refreshes at step 6)
    long = res.sweeps > 3
    assert long.any() and np.all(res.refreshes[long] > np.ceil(res.sweeps[long] / 3))
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)


def test_a_step_that_diverges_is_relaxed_again_with_a_refresh_every_sweep(smooth_fine):
    problem, domain = smooth_fine
    res = solve_transient(problem, nx=129, ny=129, domain=domain, warmup_steps=0,
                          counting_steps=10, max_iter=100, refresh=6)
    assert res.converged and np.all(res.step_converged)
    lowered = np.flatnonzero(res.refresh_intervals == 1)
    assert lowered.size and np.all(res.refresh_intervals[:lowered[0]] == 6)
    assert np.all(res.refresh_intervals[lowered[0]:] == 1)
    assert res.sweeps[lowered[0]] > BLOWN_UP_SWEEPS       # both tries counted
    # smooth surfaces: the solution stays the steady one
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)


def test_a_try_that_blows_up_is_given_up_early_with_the_same_result(monkeypatch, smooth_fine):
    """Step 6 of the smooth contact with a refresh every 6 sweeps (the test above) blows up:
    its residual grows by about 2 times per sweep from 1e-4 to changes of 1-8 p_h and stays
    there. It is given up once it has stayed above 5 times its best and 5 % of p_h for
    ``BLOWN_UP_SWEEPS`` sweeps, not after all of ``max_iter``. The fallback relaxes the step
    again from its start, so the run is the one that spends all 100 sweeps on the failed
    try, to the bit, for fewer sweeps."""
    problem, domain = smooth_fine
    args = dict(nx=129, ny=129, domain=domain, warmup_steps=0, counting_steps=10,
                max_iter=100, refresh=6)
    early = solve_transient(problem, **args)
    monkeypatch.setattr(stepper, "BLOWN_UP_SWEEPS", 10**9)
    late = solve_transient(problem, **args)
    retried = np.flatnonzero(late.tries > 1)
    assert retried.size == 1 and np.array_equal(early.tries, late.tries)
    assert late.sweeps[retried[0]] > 100                # all of max_iter, then the fallback
    assert early.sweeps[retried[0]] < 40                # given up at sweep 25
    np.testing.assert_array_equal(np.delete(early.sweeps, retried),
                                  np.delete(late.sweeps, retried))
    for name in ("pressure", "film", "max_pressure", "min_film", "refresh_intervals"):
        np.testing.assert_array_equal(getattr(early, name), getattr(late, name))


def test_a_step_that_fails_with_a_refresh_every_sweep_is_relaxed_again_with_half_the_gain(
        smooth_fine_incompressible):
    # a load gain 32 times the default makes the load loop overshoot: step 4 does not
    # converge in 100 sweeps; with half the gain it does, and so do the later steps
    problem, domain = smooth_fine_incompressible
    res = solve_transient(problem, nx=129, ny=129, domain=domain, warmup_steps=0,
                          counting_steps=10, max_iter=100, refresh=1, load_gain=4.8)
    assert res.converged and np.all(res.step_converged)
    assert not res.density_newton.any()                 # nothing to add without compressibility
    halved = np.flatnonzero(res.load_gains < 4.8)
    assert halved.size and np.all(res.load_gains[halved[0]:] == 2.4)
    assert np.all(res.load_gains[:halved[0]] == 4.8)
    assert res.sweeps[halved[0]] > BLOWN_UP_SWEEPS       # both tries counted
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)


def test_a_compressible_oil_gets_the_density_term_before_the_gain_is_halved(smooth_fine):
    # the same overshooting load loop with the Dowson-Higginson oil: step 4 fails with the
    # density lagged and converges with its Newton term in the row solve, at the gain 4.8
    problem, domain = smooth_fine
    res = solve_transient(problem, nx=129, ny=129, domain=domain, warmup_steps=0,
                          counting_steps=10, max_iter=100, refresh=1, load_gain=4.8)
    assert res.converged and np.all(res.step_converged)
    added = np.flatnonzero(res.density_newton)
    assert added.size and np.all(res.density_newton[added[0]:])
    assert np.all(res.load_gains == 4.8)
    assert res.sweeps[added[0]] > BLOWN_UP_SWEEPS       # both tries counted
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)


@pytest.mark.parametrize("oil, settings, changed", [
    ("smooth_fine", {"refresh": 6}, "refresh_intervals"),
    ("smooth_fine", {"refresh": 1, "load_gain": 4.8}, "density_newton"),
    ("smooth_fine_incompressible", {"refresh": 1, "load_gain": 4.8}, "load_gains")])
def test_resume_after_the_settings_were_changed_is_bit_identical(tmp_path, request, oil,
                                                                 settings, changed):
    problem, domain = request.getfixturevalue(oil)
    args = dict(nx=129, ny=129, domain=domain, warmup_steps=0, counting_steps=10, max_iter=100,
                **settings)
    whole = solve_transient(problem, **args)
    values = getattr(whole, changed)
    first = int(np.flatnonzero(values != values[0])[0]) + 1
    path = tmp_path / "run.npz"

    class Killed(Exception):
        pass

    def kill(step, residual):
        if step == first + 2:
            raise Killed

    with pytest.raises(Killed):
        solve_transient(problem, checkpoint=path, checkpoint_every=first + 1, callback=kill,
                        **args)
    resumed = solve_transient(problem, checkpoint=path, checkpoint_every=first + 1,
                              resume=True, **args)
    for name in ("pressure", "film", "sweeps", changed, "max_pressure"):
        np.testing.assert_array_equal(getattr(resumed, name), getattr(whole, name))


def test_the_stepper_goes_back_to_the_run_settings_after_steps_without_a_retry(
        tmp_path, monkeypatch, smooth_fine):
    """With a refresh every 6 sweeps the smooth contact on 129 x 129 nodes fails at step 6
    and is relaxed again with a refresh at every sweep (the fallback test above). With
    ``RESTORE_AFTER`` cut to 3 the stepper takes up the refresh of 6 again after 3 steps
    without a retry: step 10 fails with it once more, within a quarter of the sweep limit,
    and falls back (two tries), and a later restored step converges with it; the report says
    where the settings came back. Resumed
    from a checkpoint between a fallback and a restore, the run is bit-identical."""
    monkeypatch.setattr(TimeStepper, "RESTORE_AFTER", 3)
    problem, domain = smooth_fine
    args = dict(nx=129, ny=129, domain=domain, warmup_steps=0, counting_steps=20,
                max_iter=100, refresh=6)
    res = solve_transient(problem, **args)
    assert res.converged and np.all(res.step_converged)
    np.testing.assert_array_equal(res.tries[:10], [1, 1, 1, 1, 1, 2, 1, 1, 1, 2])
    np.testing.assert_array_equal(res.refresh_intervals[:10], [6] * 5 + [1] * 5)
    # restored, failed within a quarter of max_iter (25 sweeps), relaxed again (step 6: 104)
    assert 25 < res.sweeps[9] < 50
    kept = np.flatnonzero((res.refresh_intervals == 6) & (np.arange(20) > 9))
    assert kept.size and np.all(res.tries[kept] == 1)   # a restored step that converged
    # each fallback is followed by 3 steps at a refresh of 1 (no restore sooner)
    for step in np.flatnonzero(res.tries > 1):
        assert np.all(res.refresh_intervals[step:step + 4] == 1)

    path = tmp_path / "run.npz"

    class Killed(Exception):
        pass

    def kill(step, residual):
        if step == 9:
            raise Killed

    with pytest.raises(Killed):
        solve_transient(problem, checkpoint=path, checkpoint_every=8, callback=kill, **args)
    resumed = solve_transient(problem, checkpoint=path, checkpoint_every=8, resume=True,
                              **args)
    for name in ("pressure", "sweeps", "tries", "refresh_intervals", "max_pressure", "relaxation"):
        np.testing.assert_array_equal(getattr(resumed, name), getattr(res, name))

    case = _bump(surface2={"kind": "smooth"}, speeds={"xi": 0.0}, grid={"nx": 129, "ny": 129},
                 time={"warmup_steps": 0, "counting_steps": 20},
                 solver={"max_sweeps": 100, "refresh": 6})
    notes = run_case(case, workdir=tmp_path / "case").notes
    assert ("From step 10 on, 3 steps after the last step relaxed again, the case's own "
            "settings were taken up again.") in notes
    assert any(n.startswith("Step 10 did not converge with the far field refreshed every 6 "
                            "sweeps; it and the later steps were relaxed with a refresh at "
                            "every sweep") for n in notes)
    # past MAX_FALLBACK_NOTES steps relaxed again, the rest are counted in one note
    import asperity.runners.ehl_transient as runner

    monkeypatch.setattr(runner, "MAX_FALLBACK_NOTES", 1)
    short = run_case(case, workdir=tmp_path / "short").notes
    again = [n for n in short if "relaxed again" in n or n.startswith("Step ")]
    assert any(n.startswith("Step 6 did not converge") for n in again)
    assert not any(n.startswith(("Step 10 ", "From step 10 ")) for n in again)
    more = int(np.count_nonzero(res.tries > 1)) - 1
    assert more >= 1
    assert any(n.startswith(f"{more} more steps were relaxed again (10") for n in again)


def test_a_step_that_fails_with_the_density_term_is_relaxed_again_with_the_density_lagged(
        monkeypatch, smooth_fine):
    """The last fallback: a step that began with the density's Newton term (kept from an
    earlier step) and fails with every other setting is relaxed again with the density
    lagged, as the a/b = 4 contact needs. Here the relaxation is made to fail whenever the
    term is on."""
    problem, domain = smooth_fine
    x, y = problem.grid(65, 65, domain)
    options = StepOptions.for_problem(problem, refresh=1)
    stepper = TimeStepper(problem, x, y, options, 0.5 * (x[1] - x[0]) / problem.u1,
                          problem.film_estimate() / problem.film_scale)
    steady = solve_steady(problem, nx=65, ny=65, domain=domain)
    state = stepper.state
    state.P = steady.pressure / problem.p_hertz
    state.H = steady.film / problem.film_scale
    state.H0 = steady.separation / problem.film_scale
    state.kind[state.P <= 0.0] = 1
    stepper.resume_settings(1, options.load_gain / 4, True)   # every earlier fallback taken
    assert stepper.halvings == TimeStepper.GAIN_HALVINGS
    relax = TimeStepper.relax

    def failing_with_the_term(self, max_sweeps=None):
        report = relax(self, max_sweeps)
        return report._replace(converged=False) if self.options.density_newton else report

    monkeypatch.setattr(TimeStepper, "relax", failing_with_the_term)
    report = stepper.advance(state.roughness)
    assert report.converged and report.tries == 2 and not report.density_newton
    assert stepper.options.load_gain == options.load_gain / 4
    # a step that began lagged and fails with the term added does not drop it again (then
    # its changes are under-relaxed and, on these cells, dY = 1.6 dX, the y-line sweeps are
    # its last try)
    stepper.options = replace(stepper.options, density_newton=False)
    monkeypatch.setattr(TimeStepper, "relax", lambda self, max_sweeps=None: relax(
        self, max_sweeps)._replace(converged=False))
    report = stepper.advance(state.roughness)
    assert not report.converged and report.density_newton
    assert report.relaxation == UNDER_RELAXATION
    assert report.tries == 4 and report.y_lines is True


def test_a_resumed_run_takes_up_the_under_relaxation_its_last_step_ended_with(smooth_fine):
    """A checkpoint's step that ended under-relaxed (the last fallback) gives the resumed
    stepper that setting; NaN (a checkpoint written before it was recorded) or 1 leaves the
    run's own."""
    problem, domain = smooth_fine
    x, y = problem.grid(33, 33, domain)
    options = StepOptions.for_problem(problem)

    def fresh():
        return TimeStepper(problem, x, y, options, 0.5 * (x[1] - x[0]) / problem.u1,
                           problem.film_estimate() / problem.film_scale)

    resumed = fresh()
    resumed.resume_settings(3, options.load_gain, False, 5, UNDER_RELAXATION)
    assert resumed.options.relaxation == UNDER_RELAXATION and resumed.since_retry == 5
    for value in (np.nan, 1.0):
        plain = fresh()
        plain.resume_settings(3, options.load_gain, False, 5, value)
        assert plain.options == options


@pytest.mark.parametrize("ny, rescued", [(65, True), (17, False)])
def test_a_step_that_fails_with_every_setting_on_square_cells_gets_y_lines(
        monkeypatch, smooth_fine, ny, rescued):
    """The last resort on cells less than 3 times as wide as long (65 x 65 nodes over the
    bump case's domain: dY = 1.6 dX): a step that fails with every setting is relaxed once
    more with a y-line sweep after every x-line sweep, for that step only. Here every
    relaxation without them is made to fail. On cells 6.4 dX wide (65 x 17) there is no such
    resort. (On the a/b = 4 seed-mesh run, step 1225 failed with every setting and converged
    so, docs/ehl-transient.md.)"""
    problem, domain = smooth_fine
    x, y = problem.grid(65, ny, domain)
    stepper = TimeStepper(problem, x, y, StepOptions.for_problem(problem),
                          0.5 * (x[1] - x[0]) / problem.u1,
                          problem.film_estimate() / problem.film_scale)
    steady = solve_steady(problem, nx=65, ny=ny, domain=domain)
    state = stepper.state
    state.P = steady.pressure / problem.p_hertz
    state.H = steady.film / problem.film_scale
    state.H0 = steady.separation / problem.film_scale
    state.kind[state.P <= 0.0] = 1
    relax = TimeStepper.relax
    seen = []

    def failing_without_y_lines(self, max_sweeps=None):
        seen.append(self.state.y_lines)
        report = relax(self, max_sweeps)
        return report if self.state.y_lines else report._replace(converged=False)

    monkeypatch.setattr(TimeStepper, "relax", failing_without_y_lines)
    report = stepper.advance(state.roughness)
    assert report.converged == rescued and report.y_lines == rescued
    assert seen == [False] * 6 + [True] * rescued       # first try, 5 fallbacks, y-lines
    assert report.tries == 6 + rescued
    assert not state.y_lines                            # for that step only


def test_report_names_the_step_relaxed_with_y_lines(tmp_path, monkeypatch):
    """A step rescued by the y-line sweeps gets one note that says so, and result.nc marks
    it (step 3 of 5 made to fail without them; the case already refreshes at every sweep, its
    oil is incompressible and its gain is quartered, so the under-relaxation is the only
    setting left, and the note names it; result.nc records it for the steps after)."""
    case = _bump(surface2={"kind": "smooth"}, speeds={"xi": 0.0}, grid={"nx": 65, "ny": 65},
                 time={"warmup_steps": 0, "counting_steps": 5},
                 lubricant={"density_model": "incompressible"}, solver={"refresh": 1})
    advance, relax = TimeStepper.advance, TimeStepper.relax
    calls = {"step": 0}

    def counted(self, phi):
        calls["step"] += 1
        self.halvings = self.GAIN_HALVINGS
        return advance(self, phi)

    def failing(self, max_sweeps=None):
        report = relax(self, max_sweeps)
        if calls["step"] == 3 and not self.state.y_lines:
            return report._replace(converged=False)
        return report

    monkeypatch.setattr(TimeStepper, "advance", counted)
    monkeypatch.setattr(TimeStepper, "relax", failing)
    outcome = run_case(case, workdir=tmp_path)
    assert outcome.converged
    np.testing.assert_array_equal(outcome.dataset["y_lines"].values, [0, 0, 1, 0, 0])
    np.testing.assert_array_equal(outcome.dataset["relaxation"].values,
                                  [1, 1] + [UNDER_RELAXATION] * 3)
    note = [n for n in outcome.notes if n.startswith("Step 3 ")]
    assert len(note) == 1
    assert note[0].startswith("Step 3 did not converge with each sweep's change applied in "
                              "full; it and the later steps were relaxed with each sweep's "
                              "change under-relaxed by 0.5, and not with those either; it "
                              "alone was relaxed once more with a y-line sweep after every "
                              "x-line sweep (the sweeps of all tries are counted: ")
    assert note[0].endswith("; with the y-line sweeps it converged).")


@pytest.mark.parametrize("density_model, solver, note", [
    ("incompressible", {"refresh": 1, "load_gain": 4.8},
     "did not converge with the load gain 4.8; it and the later steps were relaxed with the "
     "load gain 2.4"),
    ("dowson-higginson", {"refresh": 1, "load_gain": 4.8},
     "did not converge with the density lagged in the row solve; it and the later steps were "
     "relaxed with the density's Newton term"),
    ("dowson-higginson", {"load_gain": 9.6},
     "did not converge with the far field refreshed every 3 sweeps, the density lagged in the "
     "row solve and the load gain 9.6; it and the later steps were relaxed with a refresh at "
     "every sweep, the density's Newton term and the load gain 4.8")])
def test_report_names_the_step_relaxed_again_with_a_changed_setting(tmp_path, density_model,
                                                                    solver, note):
    """A case's ``[solver] load_gain`` too large for the smooth contact on 129 x 129 nodes: the
    report names the first step relaxed again with the density term (compressible oil) or
    half the gain (incompressible), in one note for a step whose retries changed several
    settings (each retry failed but the last), and result.nc carries the setting of every
    step."""
    case = _bump(surface2={"kind": "smooth"}, speeds={"xi": 0.0},
                 lubricant={"density_model": density_model},
                 grid={"nx": 129, "ny": 129},
                 time={"warmup_steps": 0, "counting_steps": 10},
                 solver={"max_sweeps": 100, **solver})
    outcome = run_case(case, workdir=tmp_path)
    data = outcome.dataset
    changed = (data["load_gain"].values < solver["load_gain"]) \
        | (data["density_newton"].values == 1)
    first = int(np.flatnonzero(changed)[0])
    assert outcome.converged and np.all(changed[first:])
    at_step = [n for n in outcome.notes if n.startswith(f"Step {first + 1} ")]
    assert len(at_step) == 1
    assert at_step[0].startswith(f"Step {first + 1} {note} (") and "it converged" in at_step[0]


@pytest.mark.slow
def test_a_ridge_through_a_heavily_loaded_bearing_contact_converges_with_defaults(tmp_path):
    """The inner-race contact of a 6206 ball bearing (p_h 2.21 GPa, Moes M = 1947, L = 18.5)
    with a 0.1 um ridge on the race, default mesh (457 x 153) and steps: with the density
    lagged no step converged from step 290 (the ridge at the inlet edge of the Hertz zone) at
    any refresh or gain; relaxed again with the density's Newton term every step converges
    (1015 steps, 7.2 sweeps per step, 93 s; docs/ehl-transient.md)."""
    case = load_case({
        "analysis": "ehl-transient", "title": "Ridge across the inner race, 6206 bearing",
        "body1": {"youngs_modulus": "208 GPa", "poisson_ratio": 0.3},
        "body2": {"youngs_modulus": "208 GPa", "poisson_ratio": 0.3},
        "contact": {"type": "point", "rx": "3.9 mm", "ry": "40 mm", "load": "450 N"},
        "speeds": {"u": "4 m/s", "xi": 0.05},
        "lubricant": {"eta0": "30 cP", "alpha": "20 1/GPa"},
        "surface2": {"kind": "feature", "feature": "ridge", "amplitude": "0.1 um",
                     "half_width": "15 um"},
        "grid": {"x_min": "-0.3 mm", "x_max": 1.5}})
    outcome = run_case(case, workdir=tmp_path)
    data = outcome.dataset
    assert outcome.converged and data["step_converged"].values.all()
    added = np.flatnonzero(data["density_newton"].values)
    # the term came in as the ridge reached the inlet edge of the Hertz zone
    assert added.size and 250 < added[0] < 330
    assert data["sweeps"].values.mean() < 15
    # the ridge raises the largest pressure above the smooth contact's 2.21 GPa Hertz value
    assert 2.3e9 < data["max_pressure"].values.max() < 3.5e9


def test_a_thick_film_line_contact_gets_the_density_term_in_its_point_update(monkeypatch):
    """A lightly loaded roller (relative radius 4.5 mm, 116 N/mm, 6 m/s, 40 cP, alpha 20/GPa,
    Dowson-Higginson: Moes M = 5.3, L = 21; a case file written as a user would, in psi and
    lbf/in) from its smooth steady solution: with the density lagged in the point update the
    pressure oscillated by 2-3 p_h from step 5 on and no later step converged; relaxed again
    with the linearised density (``LineContactState``) every step converges and the solution
    stays the steady one. The default row solve of the line converges at every step without
    the term, and nearer the steps relaxed to a far tighter tolerance. It refreshes the far
    field at every sweep (``stepper.LINE_REFRESH``): with a refresh every 3 sweeps a step of
    this smooth run blew up at its first try (changes growing 2.5-3 times per sweep within a
    refresh cycle from 5e-4 p_h), at step 11 after round-off changes of the convolution and
    the Anderson mixer, and was relaxed again with the refresh at every sweep.

    Since session 38 the steady start's converged relaxation is polished by Newton
    (:mod:`asperity.ehl.line_newton`); from that start every step converged without the
    term (measured), so the fallback is shown here from the relaxation's start, Newton off."""
    from asperity.ehl import solver

    monkeypatch.setattr(solver, "solve_line_newton", lambda state, target, **options: False)
    case = load_case({
        "analysis": "ehl-transient", "title": "NU 2208 roller, smooth",
        "body1": {"youngs_modulus": "30e6 psi", "poisson_ratio": 0.3},
        "body2": {"youngs_modulus": "30e6 psi", "poisson_ratio": 0.3},
        "contact": {"type": "line", "radius": "0.177 in", "load_per_length": "665 lbf/in"},
        "speeds": {"u": "6 m/s", "xi": 0.1},
        "lubricant": {"eta0": "40 cP", "alpha": "2e-8 1/Pa"},
        "grid": {"x_min": -2.5, "x_max": 1.5},
        "time": {"warmup_steps": 0, "counting_steps": 12}})
    problem = case.problem()
    assert problem.M == pytest.approx(5.26, rel=0.01)
    assert problem.L == pytest.approx(21.2, rel=0.01)
    nx, _, domain = case.mesh(problem)
    res = solve_transient(problem, nx=nx, domain=domain, warmup_steps=0, counting_steps=12,
                          method="point")
    assert res.converged and np.all(res.step_converged)
    added = np.flatnonzero(res.density_newton)
    assert added.size and np.all(res.density_newton[added[0]:])
    assert np.all(res.load_gains == res.load_gains[0])   # not halved: the term was enough
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)
    # The default row solve of the line takes the x-couplings implicitly and needs no term.
    # Both end within 3e-3 of the steps relaxed to tol = 1e-7 (966.05 MPa; the default point
    # update stops after one sweep per step at 968.6 MPa, the row solve at 966.4 MPa).
    row = solve_transient(problem, nx=nx, domain=domain, warmup_steps=0, counting_steps=12)
    assert row.converged and np.all(row.step_converged) and not row.density_newton.any()
    assert np.all(row.tries == 1) and np.all(row.refresh_intervals == stepper.LINE_REFRESH)
    tight = solve_transient(problem, nx=nx, domain=domain, warmup_steps=0, counting_steps=12,
                            method="point", tol=1e-7, max_iter=5000)
    assert tight.converged
    assert res.max_pressure[-1] == pytest.approx(tight.max_pressure[-1], rel=3e-3)
    assert row.max_pressure[-1] == pytest.approx(tight.max_pressure[-1], rel=1e-3)


def test_report_says_when_the_steady_start_did_not_converge(tmp_path, monkeypatch):
    """A steady start cut short (5 sweeps instead of 20000, as the seed-mesh a/b = 1 and 4
    runs ended theirs unconverged): the run goes on, every step converges, the run counts as
    not converged, and the report says why (it said "0 of N steps did not reach the
    tolerance"); the inlet and mesh advice use the formula's film, not the unconverged one."""
    import asperity.ehl.smooth_start as smooth_start  # the run's steady start (session 40)

    real = smooth_start.solve_steady
    monkeypatch.setattr(smooth_start, "solve_steady",
                        lambda *args, **kw: real(*args, **{**kw, "max_iter": 5}))
    case = _bump(surface2={"kind": "smooth"}, speeds={"xi": 0.0}, grid={"nx": 65, "ny": 33},
                 time={"warmup_steps": 20, "counting_steps": 5})
    outcome = run_case(case, workdir=tmp_path)
    data = outcome.dataset
    assert data["step_converged"].values.all() and not outcome.converged
    assert any(n.startswith("The smooth steady start did not converge") for n in outcome.notes)
    assert not any("steps did not reach the tolerance" in n for n in outcome.notes)


@pytest.mark.slow  # 300 steps on 201 x 51: 90 s
def test_the_tail_of_a_step_relaxes_without_the_oscillation_damping(tmp_path):
    """The narrow contact of the seed's aspect-ratio study (a/b = 4, C against C, xi = 0.25) on
    square cells (201 x 51 over -2.5a..1.5a, -2b..2b), 300 steps as the roughness comes in.
    With the damping kept to the end of every step the tail stalled at a residual of 2-4e-4
    for tens of sweeps: 85.4 sweeps per step (164 in the last 150). Undamped once a refresh
    cycle ends below ``UNDAMPED_BELOW`` (1e-2): 33.3 (60.3); docs/ehl-transient.md, "Cost".
    The damping changes the path, not the fixed point."""
    from asperity.sweep import load_study

    data = dict((cid, c) for cid, c, _ in
                load_study("holmes-aspect-ratio-paper").cases)["0002"]
    data = {**data, "grid": {"nx": 201, "ny": 51, "x_min": -2.5, "x_max": 1.5, "y_min": -2.0,
                             "y_max": 2.0},
            "time": {"counting_steps": 300, "warmup_steps": 0}}
    outcome = run_case(load_case(data), workdir=tmp_path)
    sweeps = outcome.dataset["sweeps"].values
    assert outcome.converged
    print(f"a/b = 4 on 201 x 51: {sweeps.mean():.1f} sweeps per step, last 150 "
          f"{sweeps[150:].mean():.1f}, largest {sweeps.max()}")
    assert sweeps.mean() < 45 and sweeps[150:].mean() < 80


# A user's spur reducer (z 19/77, m 5 mm, face 60 mm, 800 N m at 1480 rpm, 0.08 Pa s, alpha
# 22/GPa, no Eyring stress, ground flanks Ra 0.4/0.6 um) as `asperity gear --emit-transient`
# wrote it at its minimum-lambda point.
REDUCER_POINT_A = """
analysis = "ehl-transient"
title = "Spur reducer 19/77: transient mixed EHL at min-lambda"
[body1]
youngs_modulus = 210000000000.0
poisson_ratio = 0.3
[body2]
youngs_modulus = 210000000000.0
poisson_ratio = 0.3
[contact]
type = "line"
radius = 0.002712287213972584
load_per_length = 99572.18923751223
[speeds]
u1 = 0.4352558966754244
u2 = 3.0317785924156078
[lubricant]
eta0 = 0.08
alpha = 2.2000000000000002e-08
viscosity_model = "roelands"
kappa = 6.32e-05
chi = 5.1e-09
density_model = "dowson-higginson"
rho0 = 850.0
gamma = 2.27e-09
lambda = 1.68e-09
[surface1]
kind = "ground"
ra = 4e-07
[surface2]
kind = "ground"
ra = 6e-07
seed = 1
[grid]
nx = 129
x_min = -2.5
x_max = 1.5
[solver]
max_sweeps = 2000
"""


@pytest.mark.parametrize("rise, under", [(stepper.REDAMP_RISE, UNDER_RELAXATION),
                                         (np.inf, 1.0), (np.inf, UNDER_RELAXATION)],
                         ids=["redamped", "never", "never-under-relaxed"])
def test_an_undamped_step_that_grows_takes_the_damping_back(monkeypatch, rise, under):
    """Steps 506-510 of the reducer's 1984: an asperity of the faster flank in contact at the
    node before the outlet boundary (x = 1.47 a), its pressure alternating from sweep to sweep
    against the lagged edge film. Damped, the alternation decays by about 0.9 per sweep; once
    undamped (``UNDAMPED_BELOW``) it grew by 1.7 per sweep, and these five steps failed with
    every fallback (Anderson mixing off or with memory 6, damping 0.5 or off, a refresh at
    every sweep: 5-6 failed; docs/ehl-transient.md). With the damping taken back when the
    residual rises above ``REDAMP_RISE`` times its best, all of the first 510 steps converge;
    never taking it back (the code before) fails them again when the last fallback (every
    change under-relaxed, ``UNDER_RELAXATION``) is taken away (four of the five: 506-509,
    and 506, 507, 509, 510 since the point update's film Newton term changed the steady
    start), and with it they converge, under-relaxed, without the damping taken back."""
    monkeypatch.setattr(stepper, "REDAMP_RISE", rise)
    monkeypatch.setattr(stepper, "UNDER_RELAXATION", under)
    res = _reducer_point_a(510)
    failed = np.flatnonzero(~res.step_converged) + 1
    if np.isfinite(rise):
        assert failed.size == 0
    elif under == 1.0:
        assert len(set(failed) & set(range(506, 511))) >= 4
    else:
        assert failed.size == 0
        assert np.all(res.relaxation[505:509] == UNDER_RELAXATION)


def _reducer_point_a(steps):
    """The first ``steps`` steps of the spur reducer's case (``REDUCER_POINT_A``)."""
    case = load_case(tomllib.loads(REDUCER_POINT_A))
    problem = case.problem()
    nx, ny, domain = case.mesh(problem)
    x, y = problem.grid(nx, ny, domain)
    dt = 0.5 * (x[1] - x[0]) / max(problem.u1, problem.u2)
    warmup, counting = case.steps(problem, x, dt)
    assert warmup + counting == 1984
    rough = case.surfaces(problem, x, y, warmup, warmup + counting, dt)
    return solve_transient(problem, *rough, nx=nx, ny=ny, domain=domain, dt=dt,
                           warmup_steps=min(warmup, steps - 1),
                           counting_steps=steps - min(warmup, steps - 1), max_iter=2000)


@pytest.mark.slow
def test_every_step_of_the_spur_reducer_converges_with_the_under_relaxation():
    """All 1984 steps of the reducer (Newtonian, Roelands, asperity pressures of 10-30 GPa):
    9 of them failed with every other fallback, each try ending in an exact limit cycle of
    the active set (changes of 1.5-12 p_h per sweep to the sweep limit); under-relaxed
    (``UNDER_RELAXATION``) they converge (docs/ehl-transient.md, "Session 33"). About 1-2 min."""
    res = _reducer_point_a(1984)
    assert res.step_converged.all()
    assert np.any(res.relaxation == UNDER_RELAXATION)


def _narrow_contact(nx, ny, steps, tolerance):
    """The a/b = 4 contact of the seed's aspect-ratio study (C against C, xi = 0.25) on square
    cells, ``steps`` steps from the smooth start as the roughness comes in."""
    from asperity.sweep import load_study

    data = dict((cid, c) for cid, c, _ in
                load_study("holmes-aspect-ratio-paper").cases)["0002"]
    return load_case({**data, "grid": {"nx": nx, "ny": ny},
                      "time": {"counting_steps": steps, "warmup_steps": 0},
                      "solver": {**data.get("solver", {}), "tolerance": tolerance}})


def test_the_check_of_the_last_step_leaves_the_state_as_it_was(tmp_path, monkeypatch,
                                                               smooth_fine):
    """The fixed-point check relaxes the converged last step on and puts p, h, H0, the active
    set and the settings back: the result holds the step as it converged, and the check's
    distances are those of the relaxed-on state."""
    seen = {}
    check = TimeStepper.check_fixed_point

    def watched(self, sweeps=None):
        state = self.state
        before = (state.P.copy(), state.H.copy(), state.H0, state.kind.copy(), self.options)
        out = check(self, sweeps)
        seen.update(before=before, after=(state.P, state.H, state.H0, state.kind,
                                          self.options), check=out)
        return out

    monkeypatch.setattr(TimeStepper, "check_fixed_point", watched)
    problem, domain = smooth_fine
    args = dict(nx=65, ny=65, domain=domain, warmup_steps=0, counting_steps=3,
                checkpoint=tmp_path / "run.npz")
    res = solve_transient(problem, **args)
    before, after = seen["before"], seen["after"]
    for k in range(4):
        np.testing.assert_array_equal(after[k], before[k])
    assert after[4] == before[4]
    np.testing.assert_array_equal(res.pressure, before[0] * problem.p_hertz)
    out = seen["check"]
    assert out.sweeps == res.fixed_point_sweeps > 0 and out.settled
    assert res.fixed_point_pressure == out.pressure < 1e-3
    assert res.fixed_point_film == out.film < 1e-3 and not res.warnings
    # resumed from the checkpoint of its last step, the run has no explicit part for that
    # step to relax again: no check (relaxed as a steady problem it moved by 2.4 p_h on the
    # a/b = 4 seed-mesh run)
    seen.clear()
    again = solve_transient(problem, resume=True, **args)
    assert not seen and again.fixed_point_sweeps == 0 and np.isnan(again.fixed_point_pressure)
    np.testing.assert_array_equal(again.pressure, res.pressure)


def test_a_last_step_far_from_its_fixed_point_is_reported(tmp_path):
    """The narrow a/b = 4 contact on square cells (129 x 33), 150 steps. Its steps stop on the
    change per sweep while the relaxation still drifts: with the tolerance 1e-3 the last step
    relaxed on moves p by 2.9 % of p_h and h by 2.8 % of the central film, and the report
    says so and what to change; with the default 1e-4 it moves by 0.16 % and 0.35 %
    (measured), without a warning. The distance falls with the tolerance (here 10-fold for
    a 10-fold tolerance), which is the warning's advice."""
    distances = {}
    for tolerance in (1e-3, 1e-4):
        outcome = run_case(_narrow_contact(129, 33, 150, tolerance),
                           workdir=tmp_path / f"{tolerance:g}")
        attrs = outcome.dataset.attrs
        distances[tolerance] = max(attrs["fixed_point_pressure"], attrs["fixed_point_film"])
        lines = [w for w in outcome.warnings if w.startswith("solver.tolerance:")]
        print(f"tolerance {tolerance:g}: p {attrs['fixed_point_pressure']:.2%} of p_h, h "
              f"{attrs['fixed_point_film']:.2%} of the film after "
              f"{attrs['fixed_point_sweeps']} sweeps")
        assert outcome.summary["fixed_point_distance_pressure_fraction"] == \
            attrs["fixed_point_pressure"]
        if tolerance == 1e-3:
            assert distances[tolerance] > 0.015 and len(lines) == 1
            assert "lower the tolerance (solver.tolerance) by more than" in lines[0]
        else:
            assert distances[tolerance] < 0.006 and not lines
    assert distances[1e-3] > 4 * distances[1e-4]


def test_the_check_measures_the_distance_to_the_step_solved_tightly_from_its_start(
        tmp_path, monkeypatch):
    """An independent measure of what the check reports: the last step of the narrow a/b = 4
    contact (129 x 33, tolerance 1e-3) solved again from the state before it to a tolerance
    of 1e-8, by the step's own relaxation from its start rather than from the converged
    state. Its largest distance from the state that converged at 1e-3 agrees with the
    check's to 10 %: both reach the same solution of the step's equations."""
    import copy

    from asperity.runners.ehl_transient import run as run_transient

    kept = {}
    advance = TimeStepper.advance

    def watched(self, phi):
        kept["before"] = copy.deepcopy(self), phi.copy()  # overwritten until the last step
        return advance(self, phi)

    monkeypatch.setattr(TimeStepper, "advance", watched)
    case = _narrow_contact(129, 33, 150, 1e-3)
    outcome = run_transient(case, workdir=tmp_path)
    attrs = outcome.dataset.attrs
    assert attrs["fixed_point_settled"]
    tight, phi = kept["before"]
    tight.options = replace(tight.options, tol=1e-8, max_sweeps=4000)
    tight.initial = tight.options
    report = advance(tight, phi)
    assert report.converged
    problem = case.problem()
    converged_p = outcome.dataset["pressure"].values / problem.p_hertz
    distance = float(np.abs(tight.state.P - converged_p).max())
    print(f"check {attrs['fixed_point_pressure']:.4f} p_h, solved from the start "
          f"{distance:.4f} p_h ({report.sweeps} sweeps)")
    assert distance == pytest.approx(attrs["fixed_point_pressure"], rel=0.1)


def test_a_step_that_stays_far_with_every_setting_leaves_its_start_to_the_next(
        monkeypatch, smooth_fine_incompressible):
    """The overshooting load loop of the test above with no gain halving left: step 6 fails
    with every setting, its residual far above ``BLOWN_UP_FLOOR``. The step hands its start
    (here the smooth solution of step 5) to the next step, not its blown-up last iterate: a
    user's line contact on 513 nodes carried a 50 GPa iterate into the next step, whose
    pressure reached 1.4e12 Pa and then NaN, and the run stopped (docs/ehl-transient.md).
    The under-relaxation of the last fallback, which rescues this step, is taken away."""
    monkeypatch.setattr(TimeStepper, "GAIN_HALVINGS", 0)
    monkeypatch.setattr(stepper, "UNDER_RELAXATION", 1.0)
    problem, domain = smooth_fine_incompressible
    res = solve_transient(problem, nx=129, ny=129, domain=domain, warmup_steps=0,
                          counting_steps=10, max_iter=100, refresh=1, load_gain=4.8)
    failed = np.flatnonzero(~res.step_converged)
    assert failed.size and failed[0] == 5 and res.steps_done == 10
    assert np.all(res.residuals[failed] >= stepper.BLOWN_UP_FLOOR)
    for step in failed:  # the smooth contact's start is the step before, to the bit
        assert res.max_pressure[step] == res.max_pressure[step - 1]
        assert res.min_film[step] == res.min_film[step - 1]
    assert np.all(np.isfinite(res.pressure)) and np.all(np.isfinite(res.max_pressure))
    assert res.max_pressure[-1] == pytest.approx(res.max_pressure[0], rel=1e-3)


def test_the_row_solve_of_a_line_contact_refreshes_at_every_sweep():
    """The default refresh interval: every sweep for the row solve of a line contact
    (``LINE_REFRESH``), every 3 sweeps for a point contact and for the point update of a line
    contact; a value given is kept."""
    reducer = load_case(tomllib.loads(REDUCER_POINT_A)).problem()
    point = PointContact(0.0191, 0.151, 962.0, 28.125, 21.875, STEEL, STEEL,
                         Lubricant(0.005, 11.1e-9, eyring_stress=10e6))
    assert StepOptions.for_problem(reducer).refresh == stepper.LINE_REFRESH == 1
    assert StepOptions.for_problem(reducer, method="point").refresh == 3
    assert StepOptions.for_problem(point).refresh == 3
    assert StepOptions.for_problem(reducer, refresh=4).refresh == 4


def test_a_feature_lead_beyond_200_half_widths_is_refused():
    """lead = "1 m" for a 30 um dent scheduled 1,229,809 counting steps without a word."""
    import re

    from asperity.cases import load_case
    from asperity.errors import InputError
    from asperity.examples import example_text

    text = example_text("dent-rolling")
    assert "half_width" in text
    with pytest.raises(InputError) as info:
        load_case(re.sub(r"(half_width = [^\n]*\n)", r'\1lead = "1 m"\n', text, count=1))
    assert "lead: expected a lead of at most 200 half-widths" in str(info.value)


@pytest.mark.parametrize("surface, key", [
    ({"kind": "smooth", "amplitude": "0.1 um"}, "surface2.amplitude"),
    ({"kind": "feature", "feature": "bump", "amplitude": "0.05 um", "half_width": "30 um",
      "rms": "0.1 um"}, "surface2.rms"),
    ({"kind": "builtin", "profile": "A", "half_width": "30 um"}, "surface2.half_width"),
])
def test_a_key_the_surface_kind_does_not_use_is_refused(surface, key):
    """rms on a feature surface gave results identical to its absence while the report's
    table listed "surface1.rms 100 nm"; amplitude on a smooth surface was taken likewise."""
    from asperity.errors import InputError

    with pytest.raises(InputError) as info:
        _bump(surface2=surface)
    assert str(info.value).startswith(f"{key}: expected no ")
