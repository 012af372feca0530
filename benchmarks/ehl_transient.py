"""Time the transient EHL solver per timestep on the seed's gear case (Holmes et al. 2005).

Smooth-steady start, then one-sided waviness (lambda = a/2, 0.05 um) entering from the inlet on
three meshes of the seed's domain up to its 801 x 201 nodes. Prints the steady start time, the
median time per step, the sweeps per step and the estimate for the paper's ~4,400 steps.
Run: ``python benchmarks/ehl_transient.py [STEPS]``.
"""

import sys
import time

import numpy as np

from asperity.ehl import Lubricant, PointContact, solve_steady, solve_transient
from asperity.materials import Material
from asperity.surfaces import Profile, cell_centres

MESHES = [((201, 51), 2), ((401, 101), 3), ((801, 201), 4)]


def main(steps=10):
    steel = Material(227e9 * (1 - 0.3**2), 0.3, "steel")
    lub = Lubricant(viscosity=0.005, pressure_viscosity=11.1e-9, eyring_stress=10e6)
    u, xi = 25.0, 0.25
    prob = PointContact(0.0191, 0.151, 962.0, u * (1 + xi / 2), u * (1 - xi / 2), steel, steel,
                        lub)
    lam = 0.5 * prob.a
    xs = cell_centres(400, lam / 40)
    wave = Profile(xs, 0.05e-6 * np.sin(2 * np.pi * xs / lam), periodic=True)
    solve_transient(prob, wave, None, nx=33, ny=17, counting_steps=2)  # compile
    print(f"{'mesh':>10} {'steady s':>9} {'s/step':>8} {'sweeps/step':>12} {'4400 steps h':>13}")
    for (nx, ny), levels in MESHES:
        t = time.perf_counter()
        st = solve_steady(prob, nx=nx, ny=ny, levels=levels)
        t_steady = time.perf_counter() - t
        stamps = [time.perf_counter()]
        r = solve_transient(prob, wave, None, nx=nx, ny=ny, steady=st, warmup_steps=0,
                            counting_steps=steps,
                            callback=lambda step, res, s=stamps: s.append(time.perf_counter()))
        per_step = float(np.median(np.diff(stamps)))
        r_sweeps = float(r.sweeps.mean())
        print(f"{nx:>5}x{ny:<4} {t_steady:9.1f} {per_step:8.3f} {r_sweeps:12.1f} "
              f"{4400 * per_step / 3600:13.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
