"""Time the steady EHL solver on the seed's smooth gear case (Holmes et al. 2005, Table 1).

Three meshes on the seed's domain -2.5a < x < 1.5a, -2b < y < 2b, up to its 801 x 201 nodes
(dx = a/200, dy = b/50), x-line relaxation with grid sequencing. Prints wall time, sweeps on
the finest grid and in all, FFT refreshes, and the films against the paper (0.48 / 0.42 um,
1.03 GPa) and Nijenbanning (Newtonian). Run: ``python benchmarks/ehl_steady.py``.
"""

import time

from asperity.ehl import Lubricant, PointContact, nijenbanning_point, solve_steady
from asperity.materials import Material

MESHES = [((201, 51), 2), ((401, 101), 3), ((801, 201), 4)]


def main():
    steel = Material(227e9 * (1 - 0.3**2), 0.3, "steel")
    lub = Lubricant(viscosity=0.005, pressure_viscosity=11.1e-9, eyring_stress=10e6)
    u, xi = 25.0, 0.25
    prob = PointContact(0.0191, 0.151, 962.0, u * (1 - xi / 2), u * (1 + xi / 2), steel, steel,
                        lub)
    nij = nijenbanning_point(prob.load, prob.rx, prob.ry, u, 0.005, 11.1e-9,
                             prob.reduced_modulus).central
    solve_steady(prob, nx=33, ny=17)  # compile the kernels outside the timings
    print(f"paper: hc 0.48 um, hmin 0.42 um (side 0.43), p_max 1.03 GPa; "
          f"Nijenbanning hc {nij * 1e6:.3f} um")
    print(f"{'mesh':>10} {'time s':>8} {'sweeps':>7} {'total':>6} {'ffts':>5} {'hc um':>7} "
          f"{'hmin_cl':>8} {'hmin':>7} {'pmax GPa':>9} {'conv':>5}")
    for (nx, ny), levels in MESHES:
        t = time.perf_counter()
        r = solve_steady(prob, nx=nx, ny=ny, levels=levels)
        wall = time.perf_counter() - t
        print(f"{nx:>5}x{ny:<4} {wall:8.1f} {r.sweeps:7d} {r.total_sweeps:6d} "
              f"{r.fft_refreshes:5d} {r.central_film * 1e6:7.4f} "
              f"{r.minimum_film_centreline * 1e6:8.4f} {r.minimum_film * 1e6:7.4f} "
              f"{r.max_pressure / 1e9:9.4f} {str(r.converged):>5}")


if __name__ == "__main__":
    main()
