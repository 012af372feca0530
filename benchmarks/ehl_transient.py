"""Cost of a transient EHL step on the seed's gear case (Holmes et al. 2005), on three meshes.

For each mesh, rough steps (built-in C on both surfaces, xi = 0.25, low-passed at 3 dx) once
the slower surface's roughness has passed x = -a, timed one by one:

- 131 x 29 and 261 x 57 (a/40 x b/10, a/80 x b/20) on the reduced domain -2a..1.25a,
  -1.4b..1.4b;
- 571 x 201 at the seed's spacing a/200 x b/50 on -1.6a..1.25a, -2b..2b (the seed's 801 x 201
  cut short upstream, so that the roughness reaches the contact in ~300 steps), with the
  ``holmes-rough-CC-paper`` example's solver settings.

Printed per mesh: median wall and CPU time per step (the CPU time of all threads is less
disturbed by other processes on a shared machine), sweeps and far-field FFT refreshes per
step, work units per step and ns per node per work unit, wall and CPU. A work unit is one
finest-grid sweep (line sweep, flow factors, damping and load shift, as the step runs it); a
refresh counts as the ratio of its CPU time to a sweep's, the least of 9 rounds alternated
between the meshes at each run's last state. Constant ns per node per work unit across the
meshes means the cost grows linearly with the nodes at a given number of work units per step.
The paper case (801 x 201, ~4,400 steps) is estimated from the seed-spacing row's wall cost
per node and work unit and the work per step of the measured full run (docs/ehl-transient.md,
Cost): an estimate, not a run.

``--full`` runs the ``holmes-rough-CC-paper`` example itself end to end through the runner as
``asperity run`` does (figures and files aside): wall time against the 8 min goal of issue 17,
steps, sweeps per step in the warm-up and counting phases, and the results compared in
docs/ehl-transient.md (contact-time fraction, largest pressure and contact count rate, steady
central film). Long: 20-43 min on 2 cores, with the speed of this shared machine.

Like the command line, the benchmark keeps freed memory for reuse
(:func:`asperity.memory.retain_freed_memory`); ``--default-allocator`` times without it.

Run: ``python benchmarks/ehl_transient.py [--meshes 131x29,261x57,571x201] [--full]
[--default-allocator]``.
"""

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numba
import numpy as np

from asperity.cases import load_case
from asperity.ehl import solve_steady, solve_transient
from asperity.ehl.kernels import CAVITATED, CONTACT
from asperity.ehl.solver import EHLState
from asperity.ehl.stepper import StepOptions
from asperity.examples import example_text
from asperity.memory import retain_freed_memory
from asperity.runners import run_case

sys.path.insert(0, str(Path(__file__).parent))
from ehl_table2 import gear_case, mesh_profile, reduced_domain  # noqa: E402

PAPER_STEPS = 4428
GOAL_MINUTES = 8
#: The measured full paper run (docs/ehl-transient.md, Cost): mean sweeps per step.
PAPER_SWEEPS = 16.5


def mesh_setup(nx, ny):
    """(problem, domain, solver keywords) of a benchmark mesh; 571 x 201 is the seed's spacing."""
    prob = gear_case(0.25)
    if (nx, ny) == (571, 201):
        refresh = load_case(example_text("holmes-rough-CC-paper")).solver.refresh  # as it runs
        a, b = prob.a, prob.b
        return prob, ((-1.6 * a, 1.25 * a), (-2.0 * b, 2.0 * b)), {"refresh": refresh}
    return prob, reduced_domain(prob), {}


def last_state(prob, x, y, result, options: StepOptions):
    """An :class:`EHLState` at the run's last pressure, film and roughness, for timing."""
    state = EHLState(prob, x, y, options.implicit_near)
    state.damping = options.damping
    state.P = result.pressure / prob.p_hertz
    state.H = result.film / prob.film_scale
    state.roughness = -(result.surface1 + result.surface2) / prob.film_scale
    state.kind[state.P <= 0.0] = CAVITATED
    state.kind[state.H <= 0.0] = CONTACT
    state.theta = options.theta
    return state


def unit_costs(states, method, rounds=9):
    """CPU seconds (all threads) of one sweep and of one far-field refresh per state: the
    least of ``rounds`` rounds that alternate between the states."""
    best = [[np.inf, np.inf] for _ in states]
    for state in states:
        state.refresh()
        state.sweep(method)
    for _ in range(rounds):
        for state, costs in zip(states, best, strict=True):
            t = time.process_time()
            state.sweep(method)
            costs[0] = min(costs[0], time.process_time() - t)
            t = time.process_time()
            state.refresh()
            costs[1] = min(costs[1], time.process_time() - t)
    return best


def rough_steps(nx, ny, steps=60):
    """Time, sweeps, refreshes and work units per rough step on one mesh."""
    prob, domain, settings = mesh_setup(nx, ny)
    x, y = prob.grid(nx, ny, domain)
    dx = x[1] - x[0]
    C = mesh_profile(("C", 1.0), dx, 3.0)
    st = solve_steady(prob, nx=nx, ny=ny, domain=domain)
    dt = 0.5 * dx / prob.u1
    inside = int(np.ceil((-prob.a - x[0]) / (prob.u2 * dt)))  # slower surface reaches -a
    stamps = [(time.perf_counter(), time.process_time())]
    r = solve_transient(prob, C, C, nx=nx, ny=ny, domain=domain, steady=st, warmup_steps=0,
                        counting_steps=inside + steps, **settings,
                        callback=lambda step, res: stamps.append((time.perf_counter(),
                                                                  time.process_time())))
    options = StepOptions.for_problem(prob, **settings)
    return {"mesh": f"{nx}x{ny}", "nodes": nx * ny, "steps": steps,
            "per_step": float(np.median(np.diff(stamps, axis=0)[inside:, 0])),
            "cpu_per_step": float(np.median(np.diff(stamps, axis=0)[inside:, 1])),
            "sweeps": r.sweeps[inside:], "refreshes": r.refreshes[inside:],
            "failed": int((~r.step_converged[inside:]).sum()),
            "state": last_state(prob, x, y, r, options)}


def work_units(row, t_sweep, t_refresh):
    """Work units per step, cost per node and work unit (from the step times and from the
    alternated sweep timing) into ``row``."""
    row["refresh_cost"] = t_refresh / t_sweep
    row["work"] = float(np.mean(row["sweeps"] + row["refreshes"] * row["refresh_cost"]))
    row["ns_node_work"] = 1e9 * row["per_step"] / (row["work"] * row["nodes"])
    row["cpu_ns_node_work"] = 1e9 * row["cpu_per_step"] / (row["work"] * row["nodes"])


def paper_estimate(row):
    """The paper case estimated from a seed-spacing row: (WU per step, wall s per step, CPU s
    per step, minutes at the row's wall cost, minutes at its CPU cost over 2 cores).

    801 x 201 nodes, the measured full run's sweeps per step with the row's refreshes per
    sweep and refresh cost, at the row's cost per node and work unit. The CPU-based minutes
    assume both cores busy all the time: a lower bound for 2 free cores.
    """
    per_sweep = float(np.mean(row["refreshes"]) / np.mean(row["sweeps"]))
    work = PAPER_SWEEPS * (1.0 + per_sweep * row["refresh_cost"])
    wall = row["ns_node_work"] * 1e-9 * work * 801 * 201
    cpu = row["cpu_ns_node_work"] * 1e-9 * work * 801 * 201
    return work, wall, cpu, PAPER_STEPS * wall / 60, PAPER_STEPS * cpu / 2 / 60


def full_case(name="holmes-rough-CC-paper"):
    """An example end to end through its runner; wall time, steps and sweeps."""
    case = load_case(example_text(name))
    with tempfile.TemporaryDirectory() as workdir:
        t = time.perf_counter()
        outcome = run_case(case, workdir=workdir)
        minutes = (time.perf_counter() - t) / 60
    data, summary = outcome.dataset, outcome.summary
    sweeps = data["sweeps"].values
    warmup = int(data.attrs["warmup_steps"])
    print(f"{name}, {data.x.size} x {data.y.size}, end to end: {minutes:.1f} min for "
          f"{sweeps.size} steps ({60 * minutes / sweeps.size:.3f} s/step), goal "
          f"{GOAL_MINUTES} min (ratio {minutes / GOAL_MINUTES:.2f}); sweeps/step median "
          f"{np.median(sweeps[:warmup]):.0f} warm-up, {np.median(sweeps[warmup:]):.0f} counting,"
          f" mean {sweeps.mean():.1f}, max {sweeps.max()}; all converged: {outcome.converged}; "
          f"contact at {summary['contact_time_percent']:.1f} % of the counting steps, largest "
          f"pressure {float(data['max_pressure'].max()) / 1e9:.2f} GPa, largest contact count "
          f"rate {summary['max_contact_count_rate_per_ms']:.0f} per ms, steady central film "
          f"{summary['steady_central_film_thickness_m'] * 1e6:.4f} um")


def mesh_list(text):
    """The ``--meshes`` option: ``"NXxNY,..."`` as ``[(nx, ny), ...]``; empty entries are
    skipped, so ``--meshes "" --full`` runs the full case alone."""
    meshes = []
    for entry in filter(None, (m.strip() for m in text.split(","))):
        try:
            nx, ny = (int(v) for v in entry.split("x"))
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"expected meshes as NXxNY separated by commas (e.g. 571x201), got {entry!r}"
            ) from None
        meshes.append((nx, ny))
    return meshes


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", type=mesh_list, default="131x29,261x57,571x201",
                        help="meshes NXxNY, comma-separated (empty: none)")
    parser.add_argument("--steps", type=int, default=60, help="rough steps timed per mesh")
    parser.add_argument("--full", action="store_true",
                        help="also run the full paper case end to end (20-43 min)")
    parser.add_argument("--default-allocator", action="store_true",
                        help="leave glibc's malloc thresholds alone (the CLI raises them)")
    args = parser.parse_args()
    retained = not args.default_allocator and retain_freed_memory()
    print(f"freed memory retained for reuse (asperity.memory, as the CLI does): {retained}; "
          f"{numba.get_num_threads()} threads")
    rows = []
    for nx, ny in args.meshes:
        rows.append(rough_steps(nx, ny, args.steps))
        print(f"{nx}x{ny}: {args.steps} rough steps timed", flush=True)
    if rows:
        mesh_table(rows)
    if args.full:
        full_case()


def mesh_table(rows):
    """Print the work units, the cost per node and work unit and the paper case's estimate
    of the timed meshes (:func:`rough_steps`)."""
    for row, (t_sweep, t_refresh) in zip(rows, unit_costs([r["state"] for r in rows], "line"),
                                         strict=True):
        work_units(row, t_sweep, t_refresh)
    print(f"{'mesh':>9} {'nodes':>7} {'s/step':>7} {'CPU s/step':>10} {'sweeps':>7} {'max':>4} "
          f"{'refr.':>6} {'refr./sweep':>11} {'WU/step':>8} {'ns/node/WU':>11} "
          f"{'CPU ns/node/WU':>14} {'failed':>6}")
    for row in rows:
        print(f"{row['mesh']:>9} {row['nodes']:7d} {row['per_step']:7.3f} "
              f"{row['cpu_per_step']:10.3f} {np.mean(row['sweeps']):7.1f} "
              f"{row['sweeps'].max():4d} {np.mean(row['refreshes']):6.1f} "
              f"{row['refresh_cost']:11.2f} {row['work']:8.1f} {row['ns_node_work']:11.0f} "
              f"{row['cpu_ns_node_work']:14.0f} {row['failed']:6d}")
    print("s/step, CPU s/step: medians over the timed steps (wall; CPU time of all threads, less "
          "disturbed by other processes); WU/step: sweeps + refreshes x refr./sweep (the CPU "
          "time of a refresh over a sweep's, least of 9 alternated); ns/node/WU: per step over "
          "WU and nodes")
    for row in rows:
        if row["mesh"] == "571x201":
            work, wall, cpu, minutes, cpu_minutes = paper_estimate(row)
            print(f"estimate, not a run: paper case 801 x 201, {PAPER_STEPS} steps x {work:.1f} "
                  f"WU ({PAPER_SWEEPS} sweeps per step, the measured full run): at this run's "
                  f"wall cost {wall:.3f} s/step, {minutes:.0f} min; at its CPU cost "
                  f"{cpu:.3f} CPU s/step over 2 cores, {cpu_minutes:.0f} min (a lower bound for "
                  f"2 free cores); goal {GOAL_MINUTES} min")


if __name__ == "__main__":
    main()
