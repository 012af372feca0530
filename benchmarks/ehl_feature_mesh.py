"""Mesh study of a single feature (dent, bump, ridge) through an EHL contact.

Runs a transient case file on several meshes of the same domain, each over the feature's
whole passage (the case's default time steps), keeps the centre line at every step and
prints, per mesh, the cells per feature half-width along x and across y and three measures of
what the feature does to the film, against the finest mesh:

- the deepest film on the centre line within the Hertz zone |x| < a over the passage;
- the film over the feature's centre as it passes x = 0 (interpolated in time and x);
- the largest pressure over the passage.

Usage::

    asperity example bump-ball-on-disc > bump.toml
    python benchmarks/ehl_feature_mesh.py bump.toml --meshes 129x41 257x41 257x81 513x81

docs/ehl-transient.md ("The default mesh of a transient case") holds the measured table.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from asperity.cases import load_case
from asperity.ehl import solve_transient


def run(case, nx: int, ny: int) -> dict:
    """The case on ``nx`` x ``ny`` nodes of its domain; the feature measures and the cost."""
    grid = {**case.grid.model_dump(exclude_unset=True), "nx": nx, "ny": ny}
    case = case.model_copy(update={"grid": type(case.grid)(**grid)})
    problem = case.problem()
    _, _, domain = case.mesh(problem)
    x, y = problem.grid(nx, ny, domain)
    dt = 0.5 * (x[1] - x[0]) / max(problem.u1, problem.u2)
    warmup, counting = case.steps(problem, x, dt)
    surfaces = case.surfaces(problem, x, y, warmup, warmup + counting, dt)
    _, spec, lead, travel = case.feature_tracks(problem, x, dt, warmup)[0]
    steps = np.arange(warmup + 1, warmup + counting + 1)
    clock = time.perf_counter()
    res = solve_transient(problem, *surfaces, nx=nx, ny=ny, domain=domain, dt=dt,
                          warmup_steps=warmup, counting_steps=counting, snapshot_steps=steps)
    wall = time.perf_counter() - clock
    a = problem.a
    inside = np.abs(res.x) < a
    centre = lead + res.snapshot_steps * travel   # the feature's centre
    film_at_0 = np.array([np.interp(0.0, res.x, h) for h in res.centre_film])
    return {"dx": x[1] - x[0], "dy": y[1] - y[0] if y.size > 1 else np.nan,
            "half_width": spec.half_width,
            "deepest": float(res.centre_film[:, inside].min()),
            "over_centre": float(np.interp(0.0, centre, film_at_0)),
            "p_max": float(res.max_pressure[warmup:].max()),
            "steady_hc": res.steady_central_film, "steps": res.steps,
            "sweeps": float(res.sweeps.mean()), "converged": bool(res.converged), "wall": wall}


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", help="transient case file with one feature")
    parser.add_argument("--meshes", nargs="+", default=["129x41", "257x41", "257x81", "513x81"],
                        help="NXxNY meshes of the case's domain, the finest last")
    args = parser.parse_args(argv)
    case = load_case(args.case)
    rows = []
    for mesh in args.meshes:
        nx, ny = (int(n) for n in mesh.split("x"))
        rows.append((mesh, run(case, nx, ny)))
        r = rows[-1][1]
        print(f"{mesh}: {r['steps']} steps, {r['sweeps']:.1f} sweeps per step, "
              f"converged {r['converged']}, {r['wall']:.0f} s", flush=True)
    ref = rows[-1][1]
    print("\n| mesh | cells per half-width along x / across y | deepest film on y = 0, nm "
          "(vs finest) | film over the feature at x = 0, nm (vs finest) | largest p, GPa "
          "(vs finest) | steady h_c, nm | sweeps/step | wall, s |")
    print("|---|---|---|---|---|---|---|---|")
    for mesh, r in rows:
        def rel(key, r=r):
            return f"{100 * (r[key] / ref[key] - 1):+.1f} %"
        print(f"| {mesh} | {r['half_width'] / r['dx']:.1f} / {r['half_width'] / r['dy']:.1f} | "
              f"{r['deepest'] * 1e9:.1f} ({rel('deepest')}) | {r['over_centre'] * 1e9:.1f} "
              f"({rel('over_centre')}) | {r['p_max'] / 1e9:.3f} ({rel('p_max')}) | "
              f"{r['steady_hc'] * 1e9:.1f} | {r['sweeps']:.1f} | {r['wall']:.0f} |")


if __name__ == "__main__":
    main()
