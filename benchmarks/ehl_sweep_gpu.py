"""The transient mixed-EHL sweep on a GPU (CuPy) against the compiled CPU sweep, 801 x 201.

Issue 17 asks, where a session has a GPU, for a measured CuPy path of the sweep. This is that
measurement, not a solver option: the x-line relaxation (``asperity.ehl.kernels.line_sweep``:
zebra rows, block elimination of the 2 x 2 (p, h) blocks, active set), the flow factors
(``Lubricant.flow_field``), the oscillation damping and the far-field refresh (two FFTs and
``far_field``) in CUDA C (``ehl_sweep_gpu.cu``, one thread per row of a colour) and CuPy
(``cupy.fft``), with the same operations in the same order. The step around them is the
library's own ``TimeStepper`` (its set-up of a step, its refresh cycles, convergence test
and Anderson mixing) on a GPU state.

Two modes:

- ``--export STATE.npz`` (any machine): a timestep of the seed's C-C gear case at the paper
  mesh, from the last step of a finished ``holmes-table2-paper`` run (``--result``, its
  ``result.nc``): pressure, film and roughness of that step, and the roughness one timestep
  later (the transverse-ground surfaces shifted along x by ``u dt``).
- default: the step set up by ``TimeStepper.start_step`` from that state, then (1) one
  refresh, the flow factors and one sweep on the GPU against the CPU kernels (largest
  differences), (2) the medians of the time per sweep and per refresh, CPU with 2 threads
  and with all cores, GPU host-timed and with events; the projected time per step at the
  full run's 26.4 sweeps and 13.2 refreshes per step, (3) the step relaxed to convergence by
  ``TimeStepper.relax`` on the CPU with 2 threads and on the GPU: wall time, sweeps,
  refreshes and the difference of the results.

Run: ``python benchmarks/ehl_sweep_gpu.py --export .gpu/state.npz --result
RUN/cases/0007/result.nc`` here, then ``python benchmarks/ehl_sweep_gpu.py --state
.gpu/state.npz`` on the GPU machine.
"""

import argparse
import sys
import time
from pathlib import Path

import numba
import numpy as np

from asperity.ehl.anderson import AndersonMixer
from asperity.ehl.kernels import CAVITATED, CONTACT, line_sweep
from asperity.ehl.solver import EHLState
from asperity.ehl.stepper import StepOptions, TimeStepper

sys.path.insert(0, str(Path(__file__).parent))
from ehl_table2 import gear_case  # noqa: E402

#: The measured full paper run (docs/ehl-transient.md, Cost): sweeps and refreshes per step.
PAPER_SWEEPS, PAPER_REFRESHES = 26.4, 13.2
PAPER_STEPS = 4428


def export(result_path, out, xi=0.25):
    """Write a timestep's state and the next step's roughness (module docstring) to ``out``."""
    import xarray as xr

    data = xr.open_dataset(result_path)
    prob = gear_case(xi)
    x, y = data.x.values, data.y.values
    dt = float(data.attrs["timestep_s"])
    z1, z2 = data.surface1.values, data.surface2.values

    def moved(z, u):  # a transverse-ground surface moved on by u dt along x
        return np.stack([np.interp(x - u * dt, x, z[:, k]) for k in range(y.size)], axis=1)

    np.savez(out, x=x, y=y, xi=xi, dt=dt, p=data.pressure.values, h=data.film.values,
             phi=-(z1 + z2) / prob.film_scale,
             phi_next=-(moved(z1, prob.u1) + moved(z2, prob.u2)) / prob.film_scale)
    print(f"a step of {result_path} ({x.size} x {y.size}) written to {out}")


def cpu_stepper(path) -> TimeStepper:
    """The library's stepper with the exported state, its next step set up (the paper
    example's refresh every 2 sweeps): the CPU reference."""
    d = np.load(path)
    prob = gear_case(float(d["xi"]))
    opts = StepOptions.for_problem(prob, refresh=2)
    stepper = TimeStepper(prob, d["x"], d["y"], opts, float(d["dt"]),
                          prob.film_estimate() / prob.film_scale)
    state = stepper.state
    state.P = d["p"] / prob.p_hertz
    state.H = d["h"] / prob.film_scale
    state.roughness = d["phi"]
    state.kind[state.P <= 0.0] = CAVITATED
    state.kind[state.H <= 0.0] = CONTACT
    fluid = (state.kind == 0) & ~state.edge  # the separation from the film's deflection
    state.H0 = float(np.median((state.H - state.film_from_pressure())[fluid]))
    stepper.start_step(d["phi_next"])
    return stepper


class GPUState:
    """The fields of an :class:`EHLState` on the GPU (C order) and the CUDA kernels of one
    sweep and one refresh (``ehl_sweep_gpu.cu``)."""

    def __init__(self, state: EHLState):
        import cupy as cp

        self.cp = cp
        self.nx, self.ny = nx, ny = state.P.shape
        kn = state.f_near.size - 1
        bl, bu = max(2, kn), max(1, kn)  # the row's band (asperity.ehl.kernels._relax_row)
        src = (Path(__file__).parent / "ehl_sweep_gpu.cu").read_text()
        module = cp.RawModule(code=src, options=("-std=c++17", f"-DBL={bl}", f"-DBU={bu}"))
        self.k_release, self.k_relax, self.k_flow, self.k_far, self.k_damp = (
            module.get_function(n) for n in ("release_nodes", "relax_rows", "flow_field",
                                             "far_field", "damp"))
        prob = state.problem
        self.qi = cp.asarray([nx, ny, kn], dtype=cp.int32)
        self.qd = cp.asarray([state.lam, state.dX, state.dY, state.theta, state.mass, state.c])
        p_unit, h_unit, scale = state.flow_units
        roelands, *laws = prob.lubricant.flow_law_parameters(prob.sliding_speed)
        self.ld = cp.asarray([p_unit, h_unit, scale, scale * p_unit, float(roelands), *laws])
        c = cp.ascontiguousarray
        self.problem = prob
        self.cell_area = state.cell_area
        self.refreshes = 0
        self.lag_derivatives = True
        self.P, self.H = cp.asarray(state.P), cp.asarray(state.H)
        self.kind = c(cp.asarray(state.kind))
        self.efar, self.rhs_t = c(cp.asarray(state.efar)), c(cp.asarray(state.rhs_t))
        self.source = c(cp.asarray(state.laplacian(state.roughness) + prob.curvature))
        self.rigid = c(cp.asarray(state.geometry + state.roughness))  # H - H0 - c W
        self.edge = cp.asarray(state.edge)
        self.f_near = cp.asarray(state.f_near)
        self.H0, self.c = state.H0, state.c
        conv = state.film_kernel
        self.fft_shape = conv.fft_shape
        self.spectrum = cp.asarray(conv.spectrum)
        self.ex, self.ey, self.rho, self.dex, self.dey = (cp.empty((nx, ny)) for _ in range(5))
        self.stored = cp.empty(nx * (4 + 2 * bu + 3) * ny)  # NS of ehl_sweep_gpu.cu per node
        self.x = cp.empty(nx * 2 * ny)
        self.dp_row, self.dh_row = cp.zeros(ny), cp.zeros(ny)
        self.p_before, self.h_before = cp.empty_like(self.P), cp.empty_like(self.H)
        self.last_change = cp.zeros_like(self.P)
        self.has_last = 0
        self.damping = state.damping
        self.relaxation = 1.0
        self.derivatives = False

    @property
    def P(self):
        return self._P

    @P.setter
    def P(self, value):  # the kernels take C-ordered fields (a mixed iterate comes F-ordered)
        self._P = self.cp.ascontiguousarray(value)

    @property
    def H(self):
        return self._H

    @H.setter
    def H(self, value):
        self._H = self.cp.ascontiguousarray(value)

    def start_iteration(self):
        self.has_last = 0

    def load(self):
        return float(self.P.sum()) * self.cell_area

    def flow(self, slopes):
        n = self.nx * self.ny
        self.k_flow(((n + 255) // 256,), (256,),
                    (self.P, self.H, self.ld, np.int32(n), np.int32(slopes), self.ex, self.ey,
                     self.rho, self.dex, self.dey))

    def refresh(self):
        """FFT refresh of the far field and the edge films (EHLState.refresh)."""
        cp = self.cp
        fx, fy = self.fft_shape
        W = cp.fft.irfft2(cp.fft.rfft2(self.P, s=(fx, fy)) * self.spectrum,
                          s=(fx, fy))[: self.nx, : self.ny]
        W = cp.ascontiguousarray(W)
        n = self.nx * self.ny
        self.k_far(((n + 255) // 256,), (256,),
                   (W, self.P, self.source, self.f_near, self.qi, self.qd, self.efar))
        film = self.H0 + self.rigid + self.c * W
        self.H[self.edge] = film[self.edge]
        self.derivatives = False
        self.refreshes += 1

    def sweep(self, method="line"):
        """Flow factors (with slopes once per refresh while ``lag_derivatives``), the zebra
        line sweep, damping; returns (max |dP|, max |dH|) on the host. The under-relaxation
        of the stepper's last fallback is not in the CUDA kernels."""
        if self.relaxation != 1.0:
            raise NotImplementedError("the CUDA sweep has no under-relaxation (relaxation 1 only)")
        cp = self.cp
        self.flow(not (self.derivatives and self.lag_derivatives))
        self.derivatives = True
        cp.copyto(self.p_before, self.P)
        cp.copyto(self.h_before, self.H)
        self.rows()
        n = self.nx * self.ny
        self.k_damp(((n + 255) // 256,), (256,),
                    (self.P, self.H, self.p_before, self.h_before, self.last_change,
                     np.float64(self.damping), np.int32(self.has_last), np.int32(n)))
        self.has_last = 1
        return float(self.dp_row.max()), float(self.dh_row.max())

    def rows(self):
        """The zebra line sweep's two colours of rows (release, then the row solves)."""
        ny = self.ny
        for colour in range(2):
            first = 1 + colour
            count = max(0, (ny - 1 - first + 1) // 2)
            fields = (self.P, self.H, self.ex, self.ey, self.rho, self.efar, self.rhs_t,
                      self.dex, self.dey, self.kind, self.f_near, self.qi, self.qd,
                      np.int32(first), np.int32(count))
            nodes = count * (self.nx - 2)
            self.k_release(((nodes + 127) // 128,), (128,),
                           (*fields[:7], self.kind, self.f_near, self.qi, self.qd,
                            np.int32(first), np.int32(count)))
            self.k_relax(((count + 31) // 32,), (32,),
                         (*fields, self.stored, self.x, self.dp_row, self.dh_row))

    def shift_separation(self, delta):
        self.H0 += delta
        self.H += delta


class GPUStepper(TimeStepper):
    """The library's :class:`TimeStepper` (:meth:`~TimeStepper.relax`: refresh cycles,
    convergence test, Anderson mixing) with the settings of ``cpu`` on a GPU copy of its
    state; only the mixing vector is built with CuPy."""

    def __init__(self, cpu: TimeStepper):
        super().__init__(cpu.problem, cpu.state.x, cpu.state.y, cpu.options, 1.0, cpu.film_scale)
        self.mass = cpu.mass
        self.state = GPUState(cpu.state)
        cp = self.state.cp
        self.mixer = AndersonMixer(cpu.options.acceleration,
                                   dot=lambda u, v: float(cp.dot(u, v)))

    def mix_vector(self):
        state, scale, cp = self.state, self.film_scale, self.state.cp
        return cp.concatenate([state.P.ravel(order="F"), state.H.ravel(order="F") / scale,
                               cp.asarray([state.H0 / scale])])


def compare_one(path):
    """Largest differences of one refresh, flow-factor evaluation and sweep, GPU vs CPU."""
    state = cpu_stepper(path).state
    gpu = GPUState(state)
    cp = gpu.cp
    state.refresh()
    gpu.refresh()
    d_efar = float(np.abs(cp.asnumpy(gpu.efar) - state.efar).max() / np.abs(state.efar).max())
    ex, ey, rho, dex, dey, _ = state.flow_coefficients(slopes=True)
    gpu.flow(True)
    d_flow = max(float(np.abs(cp.asnumpy(g) - c).max() / max(np.abs(c).max(), 1e-300))
                 for g, c in ((gpu.ex, ex), (gpu.ey, ey), (gpu.rho, rho), (gpu.dex, dex),
                              (gpu.dey, dey)))
    P, H, kind = state.P.copy(order="F"), state.H.copy(order="F"), state.kind.copy(order="F")
    dp_c, dh_c = line_sweep(P, H, ex, ey, rho, state.efar, state.rhs_t, state.lam, state.dX,
                            state.dY, state.theta, state.mass, state.c, state.f_near, kind,
                            dex, dey, None)
    gpu.derivatives = True
    gpu.damping = 1.0  # the bare line sweep
    dp_g, dh_g = gpu.sweep()
    d_p = float(np.abs(cp.asnumpy(gpu.P) - P).max())
    d_h = float(np.abs(cp.asnumpy(gpu.H) - H).max() / np.abs(H).max())
    d_kind = int((cp.asnumpy(gpu.kind) != kind).sum())
    print(f"one refresh: efar rel. diff {d_efar:.1e}; flow factors and slopes rel. diff "
          f"{d_flow:.1e}")
    print(f"one line sweep (changes: CPU max|dP| {dp_c:.3e}, max|dH| {dh_c:.3e}; GPU "
          f"{dp_g:.3e}, {dh_g:.3e}): max|P_gpu - P_cpu| {d_p:.1e} p_h, film rel. {d_h:.1e}, "
          f"active-set differences {d_kind} nodes")


def median_time(fn, repeats=15, sync=None):
    """Median wall seconds of ``fn()`` (followed by ``sync()``)."""
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        if sync is not None:
            sync()
        times.append(time.perf_counter() - t)
    return float(np.median(times))


def timings(path):
    """Median seconds per sweep and per refresh: CPU at 2 threads and all, GPU."""
    state = cpu_stepper(path).state
    gpu = GPUState(state)
    rows = {}
    for threads in sorted({2, numba.config.NUMBA_NUM_THREADS}):
        numba.set_num_threads(threads)
        state.refresh()
        state.sweep("line")
        rows[f"CPU, {threads} threads"] = (median_time(lambda: state.sweep("line")),
                                           median_time(state.refresh))
    sync = gpu.cp.cuda.Device().synchronize
    gpu.refresh()
    gpu.sweep()
    rows["GPU"] = (median_time(gpu.sweep, 50, sync), median_time(gpu.refresh, 50, sync))
    start, end = gpu.cp.cuda.Event(), gpu.cp.cuda.Event()

    def event_time(fn, repeats=50):
        out = []
        for _ in range(repeats):
            start.record()
            fn()
            end.record()
            end.synchronize()
            out.append(gpu.cp.cuda.get_elapsed_time(start, end) * 1e-3)
        return float(np.median(out))

    parts = {"flow factors": event_time(lambda: gpu.flow(True)),
             "row solves": event_time(gpu.rows),
             "refresh (FFTs, far field, edges)": event_time(gpu.refresh)}
    nodes = state.P.size
    print(f"\n{'':>16} {'ms/sweep':>9} {'ms/refresh':>11} {'ns/node/sweep':>14} "
          f"{'s/step (26.4 sw, 13.2 refr)':>28} {'paper case, min':>16}")
    base = None
    for name, (ts, tr) in rows.items():
        step = PAPER_SWEEPS * ts + PAPER_REFRESHES * tr
        base = base or step
        print(f"{name:>16} {1e3 * ts:9.2f} {1e3 * tr:11.2f} {1e9 * ts / nodes:14.1f} "
              f"{step:28.3f} {PAPER_STEPS * step / 60:16.1f}  (x{base / step:.1f})")
    print("GPU parts (events, ms): " + ", ".join(f"{k} {1e3 * v:.3f}" for k, v in parts.items()))
    print("Projected step: the full run's mean sweeps and refreshes per step at these unit "
          "costs (Anderson mixing and the load sum not counted).")


def one_step(path, threads=2):
    """The step relaxed to convergence by ``TimeStepper.relax`` on the CPU (``threads``) and
    on the GPU from the same state, twice each: wall time of the second, sweeps, refreshes,
    difference."""
    numba.set_num_threads(threads)
    out = {}
    for name in ("CPU", "GPU", "CPU", "GPU"):  # the second of each timed (warmed up)
        stepper = cpu_stepper(path)
        sync = None
        if name == "GPU":
            stepper = GPUStepper(stepper)
            sync = stepper.state.cp.cuda.Device().synchronize
        t = time.perf_counter()
        report = stepper.relax()
        if sync is not None:
            sync()
        wall = time.perf_counter() - t
        P = stepper.state.P if name == "CPU" else stepper.state.cp.asnumpy(stepper.state.P)
        out[name] = (wall, report, P)
    opts = stepper.options
    print(f"\nthe step relaxed to convergence (TimeStepper.relax, tol {opts.tol:g}, "
          f"refresh {opts.refresh}, Anderson {opts.acceleration}):")
    for name, (wall, report, _) in out.items():
        label = f"CPU, {threads} threads" if name == "CPU" else "GPU"
        print(f"{label:>16}: {wall:.3f} s, {report.sweeps} sweeps, {report.refreshes} "
              f"refreshes, converged {report.converged}, residual {report.residual:.1e}")
    d_p = float(np.abs(out["GPU"][2] - out["CPU"][2]).max())
    print(f"max|P_gpu - P_cpu| at the converged step {d_p:.1e} p_h; time ratio CPU/GPU "
          f"{out['CPU'][0] / out['GPU'][0]:.1f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--export", help="write a step's state here (.npz)")
    parser.add_argument("--result", help="result.nc of a finished 801 x 201 C-C run (export)")
    parser.add_argument("--state", default=".gpu/state.npz")
    args = parser.parse_args()
    if args.export:
        export(args.result, args.export)
        return
    print(f"{numba.config.NUMBA_NUM_THREADS} CPU threads available")
    compare_one(args.state)
    timings(args.state)
    one_step(args.state)


if __name__ == "__main__":
    main()
