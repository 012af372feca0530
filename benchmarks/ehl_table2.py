"""Table 2 of the mixed-EHL seed (Holmes, Evans & Snidle 2005) at a reduced resolution.

Percentage of the counting timesteps with contact at one or more mesh points for the gear case
of Table 1 (Rx 19.1 mm, Ry 151 mm, 962 N, u_mean 25 m/s) with the built-in stand-ins of the
profiles A, B, C on both surfaces, and C against a smooth surface (also scaled by sqrt 2).

The reduced case: domain -2a..1.25a, -1.4b..1.4b (the seed: -2.5a..1.5a, -2b..2b), default
mesh 131 x 29 (dx = a/40, dy = b/10; the seed a/200, b/50), the seed's timestep
dx/(2 u_max), warm-up until the slower surface has crossed the domain, then ``--counting``
steps. Each profile is low-passed with a Gaussian filter of cutoff ``--cutoff`` mesh spacings
(default 3): shorter wavelengths cannot be represented on the mesh. The profiles are
SYNTHETIC stand-ins (``asperity.surfaces.builtin_profile``), so the numbers are a qualitative
comparison only.

Besides the percentage it prints the largest count Q of a node and the mean number of nodes in
contact per counting step (the percentage saturates when contact is frequent; this does not).

Run: ``python benchmarks/ehl_table2.py [--nx 131 --ny 29 --counting 200 --jobs 2]``.
"""

import argparse
import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from asperity.ehl import Lubricant, PointContact, solve_steady, solve_transient
from asperity.materials import Material
from asperity.surfaces import builtin_profile
from asperity.surfaces.filters import gaussian_filter

#: (surface 1, surface 2, xi, paper %); a surface is (built-in profile, height scale) or None
CASES = [
    (("A", 1.0), ("A", 1.0), 0.1, 38), (("A", 1.0), ("A", 1.0), 0.25, 26),
    (("A", 1.0), ("A", 1.0), 0.5, 34),
    (("B", 1.0), ("B", 1.0), 0.1, 19), (("B", 1.0), ("B", 1.0), 0.25, 20),
    (("B", 1.0), ("B", 1.0), 0.5, 4.3),
    (("C", 1.0), ("C", 1.0), 0.1, 98), (("C", 1.0), ("C", 1.0), 0.25, 95),
    (("C", 1.0), ("C", 1.0), 0.5, 86),
    (("A", 1.0), ("C", 1.0), 0.1, 96), (("A", 1.0), ("C", 1.0), 0.25, 77),
    (("A", 1.0), ("C", 1.0), 0.5, 55),
    (("C", 1.0), None, 0.25, 9.2), (("C", 2**0.5), None, 0.25, 48),
]


def gear_case(xi, ry=0.151):
    """The seed's Table 1 gear contact at slide/roll ratio ``xi`` (u_mean 25 m/s)."""
    steel = Material(227e9 * (1 - 0.3**2), 0.3, "steel")
    lub = Lubricant(viscosity=0.005, pressure_viscosity=11.1e-9, eyring_stress=10e6)
    u = 25.0
    return PointContact(0.0191, ry, 962.0, u * (1 + xi / 2), u * (1 - xi / 2), steel, steel,
                        lub)


def reduced_domain(problem):
    """The reduced domain -2a..1.25a, -1.4b..1.4b, m."""
    a, b = problem.a, problem.b
    return (-2.0 * a, 1.25 * a), (-1.4 * b, 1.4 * b)


def mesh_profile(spec, spacing, cutoff):
    """Built-in profile ``(name, scale)`` low-passed at ``cutoff`` mesh spacings (None: smooth)."""
    if spec is None:
        return None
    name, scale = spec
    prof = builtin_profile(name)
    return prof.with_heights(scale * gaussian_filter(prof.z, prof.x, cutoff * spacing,
                                                     periodic=prof.periodic))


def run_case(case, nx, ny, counting, cutoff):
    s1, s2, xi, paper = case
    prob = gear_case(xi)
    domain = reduced_domain(prob)
    x, _ = prob.grid(nx, ny, domain)
    dx = x[1] - x[0]
    t = time.perf_counter()
    st = solve_steady(prob, nx=nx, ny=ny, domain=domain)
    r = solve_transient(prob, mesh_profile(s1, dx, cutoff), mesh_profile(s2, dx, cutoff),
                        nx=nx, ny=ny, domain=domain, steady=st, counting_steps=counting)
    label = "-".join("smooth" if s is None else (("sqrt2" if s[1] != 1 else "") + s[0])
                     for s in (s1, s2))
    return {"case": label, "xi": xi, "paper": paper,
            "ours": 100 * r.contact_time_fraction, "steps": r.steps,
            "warmup": r.warmup_steps, "failed": int((~r.step_converged).sum()),
            "sweeps": float(np.median(r.sweeps)), "max_q": int(r.contact_count.max()),
            "nodes": float(r.contact_count.sum() / r.counting_steps),
            "seconds": time.perf_counter() - t}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nx", type=int, default=131)
    parser.add_argument("--ny", type=int, default=29)
    parser.add_argument("--counting", type=int, default=200)
    parser.add_argument("--cutoff", type=float, default=3.0,
                        help="Gaussian low-pass cutoff in mesh spacings")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--only", default=None, help="comma-separated case indices")
    args = parser.parse_args()
    cases = CASES if args.only is None else [CASES[int(i)] for i in args.only.split(",")]
    runs = [(c, args.nx, args.ny, args.counting, args.cutoff) for c in cases]
    print(f"mesh {args.nx} x {args.ny}, {args.counting} counting steps, low-pass "
          f"{args.cutoff} dx")
    print(f"{'case':>12} {'xi':>5} {'paper %':>8} {'ours %':>7} {'steps':>6} {'failed':>6} "
          f"{'sweeps':>6} {'max Q':>6} {'nodes/step':>10} {'s':>6}")
    with ProcessPoolExecutor(args.jobs) as pool:
        for row in pool.map(run_case, *zip(*runs, strict=True)):
            print(f"{row['case']:>12} {row['xi']:5.2f} {row['paper']:8.1f} {row['ours']:7.1f} "
                  f"{row['steps']:6d} {row['failed']:6d} {row['sweeps']:6.0f} "
                  f"{row['max_q']:6d} {row['nodes']:10.2f} {row['seconds']:6.0f}", flush=True)


if __name__ == "__main__":
    main()
