"""Cattaneo partial slip: asperity (FISTA, FFT) against tamaas' PolonskyKeerTan, in one run.

Periodic grids of 128^2 and 256^2, force-controlled tangential load Q = 0.5 mu P, a body with
nu = 0.5 against a rigid flat so that the normal and tangential problems decouple. tamaas
solves the normal and tangential problems together from the Hertz gap; asperity is given the
Hertz pressure. Both stick radii are compared with Cattaneo's a (1 - Q/(mu P))^(1/3).
A 256^2 solve with a twisting moment as well (which tamaas cannot do) is timed last.

Run: ``python benchmarks/tangential.py`` (timings on a shared machine: read the ratios).
"""

from __future__ import annotations

import time

import numpy as np

from asperity.contact import hertz_point, solve_tangential
from asperity.materials import Material

E, NU, R, P, MU = 1.0, 0.5, 1.0, 1e-3, 0.3
BODY = Material(E, NU, "incompressible")
RIGID = Material(float("inf"), 0.3, "rigid")
RATIO = 0.5


def stick_radius(stick, dx):
    return np.sqrt(stick.sum() * dx * dx / np.pi)


def problem(n):
    hz = hertz_point(P, R, R, BODY, RIGID)
    L = 5.0 * hz.a
    x = (np.arange(n) + 0.5) * L / n - 0.5 * L
    X, Y = np.meshgrid(x, x, indexing="ij")
    return hz, L, x, X, Y


def run_asperity(n, moment=0.0):
    hz, L, x, X, Y = problem(n)
    p = hz.pressure(X, Y)
    p *= P / (p.sum() * (x[1] - x[0]) ** 2)
    t0 = time.perf_counter()
    r = solve_tangential(p, x, x, MU, BODY, RIGID, force=(RATIO * MU * P, 0.0), moment=moment,
                         periodic=True)
    return time.perf_counter() - t0, r, hz, x


def run_tamaas(n):
    import tamaas as tm

    hz, L, x, X, Y = problem(n)
    model = tm.ModelFactory.createModel(tm.model_type.surface_2d, [L, L], [n, n])
    model.E, model.nu = E, NU
    surface = -(X**2 + Y**2) / (2 * R)
    solver = tm.PolonskyKeerTan(model, surface, 1e-8, MU)
    solver.max_iter = 5000
    solver.dump_freq = 10**9
    t0 = time.perf_counter()
    err = solver.solve([RATIO * MU * P / L**2, 0.0, P / L**2])
    dt = time.perf_counter() - t0
    t = np.array(model.traction)
    p, qt = t[..., 2], np.hypot(t[..., 0], t[..., 1])
    stick = (p > 0) & (qt < MU * p * (1 - 1e-6))
    return dt, stick, err, hz, x


def main():
    print(f"{'n':>5} {'code':>9} {'time s':>8} {'iters':>6} {'convs':>6} {'stick err':>10}")
    times = {}
    for n in (128, 256):
        dt, r, hz, x = run_asperity(n)
        c = hz.a * (1 - RATIO) ** (1 / 3)
        e = stick_radius(r.stick, x[1] - x[0]) / c - 1
        times[n, "asperity"] = dt
        print(f"{n:5d} {'asperity':>9} {dt:8.2f} {r.iterations:6d} {r.convolutions:6d} "
              f"{e:+10.4f}  residual {r.residual:.1e} converged {r.converged}")
        try:
            dt, stick, err, hz, x = run_tamaas(n)
        except ImportError:
            print(f"{n:5d} {'tamaas':>9}  not installed")
            continue
        e = stick_radius(stick, x[1] - x[0]) / c - 1
        times[n, "tamaas"] = dt
        print(f"{n:5d} {'tamaas':>9} {dt:8.2f} {'-':>6} {'-':>6} {e:+10.4f}  "
              f"final error {err:.1e}")
        ratio = times[n, 'tamaas'] / times[n, 'asperity']
        print(f"      speed-up asperity vs tamaas: {ratio:.1f}x")
    hz = hertz_point(P, R, R, BODY, RIGID)
    moment = 0.3 * 3 * np.pi * MU * P * hz.a / 16
    dt, r, hz, x = run_asperity(256, moment=moment)
    print(f"  256 force + moment: {dt:.2f} s, {r.iterations} iterations, "
          f"converged {r.converged}, rotation {r.rotation:.3e} rad")


if __name__ == "__main__":
    main()
