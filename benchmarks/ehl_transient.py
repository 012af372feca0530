"""Time the transient EHL solver per timestep on the seed's gear case (Holmes et al. 2005).

1. Rough surfaces (built-in C on both, xi = 0.25, low-passed at 3 dx) on the reduced domain
   -2a..1.25a, -1.4b..1.4b at two meshes: median time and sweeps per step over the steps in
   which the roughness of both surfaces is inside the Hertz contact.
2. The seed's 801 x 201 mesh: steady start, the cost of one sweep split into its parts (flow
   factors and their derivative, the compiled line sweep, the FFT refresh), and the estimate
   for the paper's ~4,400 steps at the rough sweeps per step of part 1.

Run: ``python benchmarks/ehl_transient.py [--meshes 131x29,261x57] [--paper]``.
"""

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from asperity.ehl import solve_steady, solve_transient
from asperity.ehl.solver import EHLState

sys.path.insert(0, str(Path(__file__).parent))
from ehl_table2 import gear_case, mesh_profile, reduced_domain  # noqa: E402

PAPER_STEPS = 4400


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


def paper_mesh(rough_sweeps):
    """Steady start on 801 x 201 and the cost of one sweep by part."""
    prob = gear_case(0.25)
    t = time.perf_counter()
    st = solve_steady(prob, nx=801, ny=201, levels=4)
    t_steady = time.perf_counter() - t
    state = EHLState(prob, st.x, st.y, near=4)
    state.P = st.pressure / prob.p_hertz
    state.H = st.film / prob.film_scale
    state.H0 = st.separation / prob.film_scale
    parts = {}
    coefficients = state.flow_coefficients
    for name, fun in (("flow factors", coefficients),
                      ("derivatives", lambda: state.flow_derivatives(*coefficients()[:2])),
                      ("refresh (FFT)", state.refresh),
                      ("sweep (all)", lambda: state.sweep("line"))):
        fun()
        reps = []
        for _ in range(3):
            t = time.perf_counter()
            fun()
            reps.append(time.perf_counter() - t)
        parts[name] = float(np.median(reps))
    per_sweep = parts["sweep (all)"] + parts["refresh (FFT)"] / 4
    hours = PAPER_STEPS * rough_sweeps * per_sweep / 3600
    print(f"801 x 201: steady start {t_steady:.0f} s ({st.total_sweeps} sweeps, converged "
          f"{st.converged}); one sweep " + ", ".join(f"{k} {v:.3f} s" for k, v in parts.items()))
    print(f"  paper case: {PAPER_STEPS} steps x {rough_sweeps:.0f} sweeps x {per_sweep:.3f} s = "
          f"{hours:.1f} h (target 0.75 h)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default="131x29,261x57")
    parser.add_argument("--paper", action="store_true", help="also time the 801 x 201 mesh")
    args = parser.parse_args()
    print(f"{'mesh':>10} {'steps':>6} {'s/step':>8} {'sweeps/step':>12} {'max':>5} "
          f"{'failed':>6}")
    sweeps = np.nan
    for mesh in args.meshes.split(","):
        nx, ny = (int(v) for v in mesh.split("x"))
        per_step, sweeps, most, failed, steps = rough_steps(nx, ny)
        print(f"{nx:>5}x{ny:<4} {steps:6d} {per_step:8.3f} {sweeps:12.0f} {most:5d} {failed:6d}",
              flush=True)
    if args.paper:
        paper_mesh(sweeps)


if __name__ == "__main__":
    main()
