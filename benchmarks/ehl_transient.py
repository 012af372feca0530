"""Time the transient EHL solver per timestep on the seed's gear case (Holmes et al. 2005).

1. Rough surfaces (built-in C on both, xi = 0.25, low-passed at 3 dx) on the reduced domain
   -2a..1.25a, -1.4b..1.4b at two meshes: median time and sweeps per step over the steps in
   which the roughness of both surfaces is inside the Hertz contact.
2. ``--paper``: rough steps timed at the seed's spacing a/200 x b/50 (on a domain cut short
   upstream so that the roughness reaches the contact in ~300 steps) with the solver settings
   of the ``holmes-rough-CC-paper`` example, scaled to the 801 x 201 mesh, the estimate for
   the paper's ~4,400 steps, and the cost of one sweep by part. The estimate is optimistic:
   the timed steps have roughness on both surfaces only in the upstream part of the contact
   (~19 sweeps); once it covers the contact a step takes ~27 (docs/ehl-transient.md, Cost).
3. ``--full``: the paper case itself, ``holmes-rough-CC-paper`` on 801 x 201 (~4,400 steps)
   through the runner as ``asperity run`` does it (figures and files aside): wall time
   against the 45 min target, steps, sweeps per step in the warm-up and counting phases.
   Long: 36 min on 2 free cores.

Like the command line, the benchmark keeps freed memory for reuse
(:func:`asperity.memory.retain_freed_memory`); ``--default-allocator`` times without it.

Run: ``python benchmarks/ehl_transient.py [--meshes 131x29,261x57] [--paper] [--full]
[--default-allocator]``.
"""

import argparse
import inspect
import sys
import tempfile
import time
from pathlib import Path

import numba
import numpy as np

from asperity.cases import load_case
from asperity.ehl import solve_steady, solve_transient
from asperity.ehl.nodal import film_estimate
from asperity.ehl.solver import EHLState
from asperity.examples import example_text
from asperity.memory import retain_freed_memory
from asperity.runners import run_case

sys.path.insert(0, str(Path(__file__).parent))
from ehl_table2 import gear_case, mesh_profile, reduced_domain  # noqa: E402

PAPER_STEPS = 4400
TARGET_MINUTES = 45


def rough_steps(nx, ny):
    """Seconds and sweeps per step with roughness inside the contact, on the reduced domain."""
    prob = gear_case(0.25)
    domain = reduced_domain(prob)
    x, _ = prob.grid(nx, ny, domain)
    dx = x[1] - x[0]
    C = mesh_profile(("C", 1.0), dx, 3.0)
    st = solve_steady(prob, nx=nx, ny=ny, domain=domain)
    dt = 0.5 * dx / prob.u1
    inside = int(np.ceil((-prob.a - x[0]) / (prob.u2 * dt)))  # slower surface reaches -a
    steps = inside + int(np.ceil(prob.a / (prob.u2 * dt)))  # ... and the centre
    stamps = [time.perf_counter()]
    r = solve_transient(prob, C, C, nx=nx, ny=ny, domain=domain, steady=st, warmup_steps=0,
                        counting_steps=steps,
                        callback=lambda step, res: stamps.append(time.perf_counter()))
    seconds = np.diff(stamps)[inside:]
    return (float(np.median(seconds)), float(np.median(r.sweeps[inside:])),
            int(r.sweeps[inside:].max()), int((~r.step_converged).sum()), steps)


def paper_spacing(steps=60):
    """Rough steps at the seed's spacing (a/200, b/50) on a domain cut short upstream.

    The seed's 801 x 201 mesh needs ~700 steps before the roughness reaches the contact, so
    the timed run uses -1.6a..1.25a (571 x 201 nodes at the same spacing and y extent; the
    smooth pressure at -1.6a is 0.7 % of p_h, while an inlet at -1.1a, where it is 10 %,
    starved the contact and made steps fail) and times ``steps`` steps once the slower
    surface's roughness has passed x = -a. The cost per node is then scaled to 801 x 201 (the
    sweep is linear in nx, the FFT refresh n log n).
    Also prints the cost of one sweep by part on 801 x 201.
    """
    refresh = load_case(example_text("holmes-rough-CC-paper")).solver.refresh  # as it runs
    prob = gear_case(0.25)
    a, b = prob.a, prob.b
    domain = (-1.6 * a, 1.25 * a), (-2.0 * b, 2.0 * b)
    nx, ny = 571, 201
    x, _ = prob.grid(nx, ny, domain)
    dx = x[1] - x[0]
    C = mesh_profile(("C", 1.0), dx, 3.0)
    t = time.perf_counter()
    st = solve_steady(prob, nx=nx, ny=ny, domain=domain)
    t_steady = time.perf_counter() - t
    dt = 0.5 * dx / prob.u1
    inside = int(np.ceil((-a - x[0]) / (prob.u2 * dt)))
    stamps = [time.perf_counter()]
    r = solve_transient(prob, C, C, nx=nx, ny=ny, domain=domain, steady=st, warmup_steps=0,
                        counting_steps=inside + steps, refresh=refresh,
                        callback=lambda step, res: stamps.append(time.perf_counter()))
    seconds = np.diff(stamps)[inside:]
    per_step = float(np.median(seconds)) * 801 / nx
    sweeps = r.sweeps[inside:]
    hours = PAPER_STEPS * per_step / 3600
    print(f"seed spacing a/200 x b/50 ({nx} x {ny}, steady start {t_steady:.0f} s, "
          f"refresh every {refresh} sweeps as holmes-rough-CC-paper): "
          f"{steps} rough steps, sweeps/step median {np.median(sweeps):.0f} (max {sweeps.max()}), "
          f"failed {int((~r.step_converged[inside:]).sum())}, "
          f"{np.median(seconds):.3f} s/step -> {per_step:.3f} s/step on 801 x 201")

    x, y = prob.grid(801, 201, None)
    near = inspect.signature(solve_transient).parameters["near"].default
    state = EHLState(prob, x, y, near=near)  # the transient solver's default
    state.hertz_start(film_estimate(prob) / prob.film_scale)
    parts = {}
    coefficients = state.flow_coefficients
    for name, fun in (("flow factors", coefficients),
                      ("with slopes", lambda: coefficients(slopes=True)),
                      ("refresh (FFT)", state.refresh),
                      ("sweep (all)", lambda: state.sweep("line"))):
        fun()
        reps = []
        for _ in range(5):
            t = time.perf_counter()
            fun()
            reps.append(time.perf_counter() - t)
        parts[name] = float(np.median(reps))
    print("801 x 201, one sweep: " + ", ".join(f"{k} {v:.3f} s" for k, v in parts.items())
          + f" ({numba.get_num_threads()} threads)")
    print(f"  paper case: {PAPER_STEPS} steps x {per_step:.3f} s = {hours:.1f} h "
          f"(target {TARGET_MINUTES / 60:.2f} h)")


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
          f"{sweeps.size} steps ({60 * minutes / sweeps.size:.3f} s/step), target "
          f"{TARGET_MINUTES} min (ratio {minutes / TARGET_MINUTES:.2f}); sweeps/step median "
          f"{np.median(sweeps[:warmup]):.0f} warm-up, {np.median(sweeps[warmup:]):.0f} counting,"
          f" mean {sweeps.mean():.1f}, max {sweeps.max()}; all converged: {outcome.converged}; "
          f"contact at {summary['contact_time_percent']:.1f} % of the counting steps")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default="131x29,261x57")
    parser.add_argument("--paper", action="store_true",
                        help="also time rough steps at the seed's mesh spacing")
    parser.add_argument("--full", action="store_true",
                        help="also run the full paper case end to end (~36 min)")
    parser.add_argument("--default-allocator", action="store_true",
                        help="leave glibc's malloc thresholds alone (the CLI raises them)")
    args = parser.parse_args()
    retained = not args.default_allocator and retain_freed_memory()
    print(f"freed memory retained for reuse (asperity.memory, as the CLI does): {retained}")
    print(f"{'mesh':>10} {'steps':>6} {'s/step':>8} {'sweeps/step':>12} {'max':>5} "
          f"{'failed':>6}")
    for mesh in args.meshes.split(","):
        nx, ny = (int(v) for v in mesh.split("x"))
        per_step, sweeps, most, failed, steps = rough_steps(nx, ny)
        print(f"{nx:>5}x{ny:<4} {steps:6d} {per_step:8.3f} {sweeps:12.0f} {most:5d} {failed:6d}",
              flush=True)
    if args.paper:
        paper_spacing()
    if args.full:
        full_case()


if __name__ == "__main__":
    main()
