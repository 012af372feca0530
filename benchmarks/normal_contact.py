"""Dry frictionless normal contact: asperity against ContactMechanics and tamaas, same inputs.

Cases (all on an ``n`` x ``n`` grid, one E*, one load, the same undeformed-gap array for all):

1. ``hertz-periodic``: a sphere on a periodic grid (continuum kernel 2/(E*|q|) in every code);
2. ``hertz-free``: the same sphere, isolated (non-periodic, Love cells / DC-FFT; tamaas has no
   free-boundary normal solver and is skipped);
3. ``rough-periodic``: a periodic self-affine surface (Hurst 0.8) loaded to ~10 % contact area.

For each case and code: the median wall time of ``--repeat`` solves, the iterations, the FFT
convolutions (asperity), the contact-area fraction, and the ratios to asperity. Run::

    python benchmarks/normal_contact.py --size 1024 --repeat 3
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from asperity.contact import hertz_point, solve_normal
from asperity.elastic import normal_operator
from asperity.materials import Material

E_STAR = 1.0e11  # contact modulus of the two bodies below, Pa
REFERENCE_TOL = 1e-11
TAMAAS_TOL = 1e-9  # tamaas' own error measure; 1e-12 takes minutes even at 512^2
BODY = Material(youngs_modulus=2 * E_STAR * (1 - 0.3**2), poisson_ratio=0.3, name="body")


def cell_centres(n, length):
    return (np.arange(n) + 0.5) * length / n - 0.5 * length


def hertz_case(n, periodic):
    """A sphere (R = 10 mm) under 100 N on a square 4 a wide (periodic) or 3 a wide (free)."""
    radius, load = 0.01, 100.0
    a = hertz_point(load, radius, radius, BODY, BODY).a
    length = (4.0 if periodic else 3.0) * a
    x = cell_centres(n, length)
    gap0 = (x[:, None] ** 2 + x[None, :] ** 2) / (2 * radius)
    return gap0, x, load


def self_affine(n, length, hurst, rms_slope, seed):
    """Periodic self-affine surface: Gaussian random phases, PSD ~ q^-(2 + 2 H) above 2 pi/L."""
    rng = np.random.default_rng(seed)
    qx = 2 * np.pi * np.fft.fftfreq(n, d=length / n)
    qy = 2 * np.pi * np.fft.rfftfreq(n, d=length / n)
    q = np.hypot(qx[:, None], qy[None, :])
    amplitude = np.zeros_like(q)
    amplitude[q > 0] = q[q > 0] ** (-1.0 - hurst)
    noise = rng.normal(size=q.shape) + 1j * rng.normal(size=q.shape)
    heights = np.fft.irfft2(amplitude * noise, s=(n, n))
    slope = np.sqrt(np.mean(np.gradient(heights, length / n, axis=0) ** 2
                            + np.gradient(heights, length / n, axis=1) ** 2))
    return heights * (rms_slope / slope)


def rough_case(n):
    """Self-affine H = 0.8 (rms slope 0.1, 1 mm square); load for ~10 % contact area.

    A/A0 ~ kappa p_mean / (E* h'_rms) with kappa ~ 2 (Persson; Hyun & Robbins).
    """
    length = 1e-3
    heights = self_affine(n, length, 0.8, 0.1, seed=2024)
    gap0 = heights.max() - heights
    x = cell_centres(n, length)
    mean_pressure = 0.1 * E_STAR * 0.1 / 2.0
    return gap0, x, mean_pressure * length**2


def setup_asperity(gap0, x, load, periodic, tol=1e-8):
    """(solve, summary) for asperity; the cached influence spectrum is built here, untimed."""
    normal_operator(x, x, BODY, BODY, periodic)

    def solve():
        return solve_normal(gap0, x, x, BODY, BODY, load=load, periodic=periodic, tol=tol)

    def summary(res):
        if not res.converged:
            raise RuntimeError("asperity did not converge")
        return {"iterations": res.iterations, "ffts": res.ffts, "pressure": res.pressure}

    return solve, summary


def setup_contactmechanics(gap0, x, load, periodic):
    from ContactMechanics import FreeFFTElasticHalfSpace, PeriodicFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients

    n = len(x)
    length = n * (x[1] - x[0])
    halfspace = PeriodicFFTElasticHalfSpace if periodic else FreeFFTElasticHalfSpace
    # `young` without `poisson` is the contact modulus E* in both classes
    substrate = halfspace((n, n), E_STAR, physical_sizes=(length, length))
    heights = -gap0  # ContactMechanics: the rigid surface's heights; gap = u - heights - offset

    def solve():
        return constrained_conjugate_gradients(substrate, heights, external_force=load)

    def summary(res):
        if not res.success:
            raise RuntimeError(f"ContactMechanics: {res.message}")
        pressure = res.jac[:n, :n] / (length / n) ** 2  # jac: pixel forces, compressive > 0
        return {"iterations": res.nit, "ffts": 2 * res.nfev, "pressure": pressure}

    return solve, summary


def setup_tamaas(gap0, x, load, periodic):
    if not periodic:
        return None
    import tamaas as tm

    n = len(x)
    length = n * (x[1] - x[0])
    tm.set_log_level(tm.LogLevel.error)

    def solve():
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [length, length], [n, n])
        model.E, model.nu = E_STAR, 0.0  # tamaas' E* is E / (1 - nu^2)
        solver = tm.PolonskyKeerRey(model, -gap0, TAMAAS_TOL)
        solver.max_iter = 10000
        solver.solve(load / length**2)  # tamaas' load is the mean pressure
        return model

    def summary(model):
        return {"iterations": None, "ffts": None,
                "pressure": np.asarray(model.traction).reshape(n, n)}

    return solve, summary


PEERS = {"ContactMechanics": setup_contactmechanics, "tamaas": setup_tamaas}


def time_interleaved(codes, repeat):
    """Median wall time per code, the codes taking turns so that load drift hits all alike."""
    times = {name: [] for name in codes}
    outputs = {}
    for _ in range(repeat):
        for name, (solve, _) in codes.items():
            t0 = time.perf_counter()
            outputs[name] = solve()
            times[name].append(time.perf_counter() - t0)
    return {name: {"time": float(np.median(times[name])), **summary(outputs[name])}
            for name, (_, summary) in codes.items()}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024, help="grid points per side")
    parser.add_argument("--repeat", type=int, default=3, help="timed solves per code (median)")
    parser.add_argument("--cases", default="hertz-periodic,hertz-free,rough-periodic")
    parser.add_argument("--peers", default=",".join(PEERS), help="comma-separated peers to run")
    args = parser.parse_args(argv)
    n = args.size
    cases = {
        "hertz-periodic": lambda: (*hertz_case(n, True), True),
        "hertz-free": lambda: (*hertz_case(n, False), False),
        "rough-periodic": lambda: (*rough_case(n), True),
    }
    # compile and warm the caches outside the timings
    g, xs, w = hertz_case(32, True)
    solve_normal(g, xs, xs, BODY, BODY, load=w, periodic=True)
    print(f"grid {n} x {n}, median of {args.repeat}; p err: relative L2 pressure error against "
          f"asperity at tol={REFERENCE_TOL:g}")
    header = f"{'case':16s} {'code':20s} {'time s':>8s} {'iter':>6s} {'ffts':>6s} {'area %':>8s}"
    print(header + f" {'p err':>8s} {'asperity/peer':>14s} {'d area %':>9s}")
    for name in args.cases.split(","):
        gap0, x, load, periodic = cases[name]()
        reference = solve_normal(gap0, x, x, BODY, BODY, load=load, periodic=periodic,
                                 tol=REFERENCE_TOL, max_iter=20000).pressure
        codes = {"asperity": setup_asperity(gap0, x, load, periodic),
                 "asperity tol=1e-6": setup_asperity(gap0, x, load, periodic, 1e-6)}
        for peer in filter(None, args.peers.split(",")):
            try:
                setup = PEERS[peer](gap0, x, load, periodic)
            except ImportError:
                setup = None
            if setup is not None:
                codes[peer] = setup
        results = time_interleaved(codes, args.repeat)
        ours = results["asperity"]
        for code, r in results.items():
            it = "-" if r["iterations"] is None else str(r["iterations"])
            cv = "-" if r["ffts"] is None else str(r["ffts"])
            error = np.linalg.norm(r["pressure"] - reference) / np.linalg.norm(reference)
            line = (f"{name:16s} {code:20s} {r['time']:8.2f} {it:>6s} {cv:>6s} "
                    f"{100 * area(r['pressure']):8.3f} {error:8.1e}")
            if not code.startswith("asperity"):
                line += (f" {ours['time'] / r['time']:14.3f}"
                         f" {100 * (area(ours['pressure']) - area(r['pressure'])):9.4f}")
            print(line, flush=True)


def area(pressure):
    """Contact-area fraction."""
    return np.count_nonzero(pressure > 0) / pressure.size

if __name__ == "__main__":
    main()
