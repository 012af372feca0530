"""Mesh convergence of the contact statistics of a finished ``holmes-mesh-CC`` study.

Reads ``OUT/cases/NNNN/result.nc`` and ``summary.json`` of ``asperity sweep holmes-mesh-CC
--out OUT`` (the seed's C-C case at xi = 0.25 on 301 x 76, 401 x 101, 601 x 151 and 801 x 201
over the same counting time) and prints, per mesh:

- the percentage of counting steps with contact at one or more nodes (the seed's Table 2
  measure) and the mean contact area per step over the Hertz area ``pi a b``;
- the largest contact count rate Q (per ms, the seed's Figs. 4-8) and the largest fraction of
  the counting time a node spends in contact. Q counts timesteps, and the timestep is
  ``dx / (2 u1)``, so at the same fraction of time in contact Q grows as the mesh is refined:
  the time fraction (``Q dt``) is the measure that can converge; ``Q`` is also given scaled to
  the seed's timestep;
- where the contact is: the share of the contact (node-steps weighted by cell area) at the
  transverse edges ``|y| > 0.8 b`` and downstream of the centre (``x > 0``), the share of the
  edge contact that lies downstream, and the node of the largest Q;
- the Q map against the finest mesh's: the time fraction in contact averaged over common bins
  (``a/10 x b/5`` over ``|x| <= 1.2 a``, ``|y| <= 1.2 b``), relative L2 difference and
  correlation coefficient;
- largest pressure, steady central film, mean sweeps per step, wall time from ``summary.json``.

``--figure PATH`` writes the four time-fraction maps side by side.

Run: ``python benchmarks/ehl_mesh_study.py OUT [--figure mesh.png]``.
"""

import argparse
import json
from pathlib import Path

import numpy as np
import xarray as xr

BINS_X = np.linspace(-1.2, 1.2, 25)  # in a
BINS_Y = np.linspace(-1.2, 1.2, 13)  # in b


def load(folder: Path):
    """(dataset, summary) of one finished case folder."""
    data = xr.open_dataset(folder / "result.nc")
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    return data, summary


def binned_fraction(frac, X, Y):
    """Mean over the bins of the per-node time fraction in contact (nodes weighted equally:
    the grids are uniform), shape (len(BINS_X) - 1, len(BINS_Y) - 1)."""
    Xg, Yg = np.meshgrid(X, Y, indexing="ij")
    total, _, _ = np.histogram2d(Xg.ravel(), Yg.ravel(), [BINS_X, BINS_Y], weights=frac.ravel())
    count, _, _ = np.histogram2d(Xg.ravel(), Yg.ravel(), [BINS_X, BINS_Y])
    return total / np.maximum(count, 1)


def mesh_row(folder: Path) -> dict:
    """The statistics of one mesh (see the module docstring)."""
    data, summary = load(folder)
    a = summary["hertz_a_m"]
    x, y = data.x.values, data.y.values
    dx, dy = x[1] - x[0], y[1] - y[0]
    steps = int(data.attrs["counting_steps"])
    count = data.contact_count.values
    frac = count / steps
    # b from the Hertz ellipse of the paper case: y runs over -2b..2b
    b = -y[0] / 2.0
    X, Y = x / a, y / b
    Yg = np.broadcast_to(Y, count.shape)
    Xg = np.broadcast_to(X[:, None], count.shape)
    total = count.sum()
    return {
        "mesh": f"{x.size}x{y.size}",
        "steps": steps,
        "contact_percent": summary["contact_time_percent"],
        "area_fraction": float(total * dx * dy / steps / (np.pi * a * b)),
        "max_q": summary["max_contact_count_rate_per_ms"],
        # Q = (time fraction) / dt, dt proportional to dx: scaled to the seed's dx = a/200
        "max_q_seed_dt": summary["max_contact_count_rate_per_ms"] * dx / (a / 200.0),
        "max_fraction": float(frac.max()),
        "edge_share": float(count[np.abs(Yg) > 0.8].sum() / total) if total else np.nan,
        "downstream_share": float(count[Xg > 0].sum() / total) if total else np.nan,
        "edge_downstream": (float(count[(np.abs(Yg) > 0.8) & (Xg > 0)].sum()
                                  / count[np.abs(Yg) > 0.8].sum()) if total else np.nan),
        "max_at": tuple(float(v) for v in
                        (X[np.unravel_index(count.argmax(), count.shape)[0]],
                         Y[np.unravel_index(count.argmax(), count.shape)[1]])),
        "bins": binned_fraction(frac, X, Y),
        "frac": frac, "X": X, "Y": Y,
        "max_pressure_gpa": summary["max_pressure_pa"] / 1e9,
        "central_film_um": summary["steady_central_film_thickness_m"] * 1e6,
        "sweeps": summary["mean_sweeps_per_step"],
        "converged": summary["steps_converged_fraction"],
    }


def compare_maps(rows):
    """Relative L2 difference and correlation of each binned map with the last (finest)."""
    ref = rows[-1]["bins"]
    for row in rows:
        diff = row["bins"] - ref
        row["map_l2"] = float(np.linalg.norm(diff) / np.linalg.norm(ref))
        row["map_corr"] = float(np.corrcoef(row["bins"].ravel(), ref.ravel())[0, 1])


def figure(rows, path, title=None):
    """The per-node time fraction in contact of every row (mesh or case), side by side in
    rows of at most 5 panels; ``title(row)`` gives each panel's title (default: the mesh and
    its contact percentage)."""
    from asperity.plotting.style import plt

    if title is None:
        def title(row):
            return f"{row['mesh']}: {row['contact_percent']:.1f} % of steps"

    ncols = min(len(rows), 5)
    nrows = -(-len(rows) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.2 * ncols, 3.6 * nrows), sharex=True,
                             sharey=True, constrained_layout=True, squeeze=False)
    for ax in axes.flat[len(rows):]:
        ax.set_visible(False)
    vmax = max(float(r["frac"].max()) for r in rows)
    t = np.linspace(0, 2 * np.pi, 200)
    for ax, row in zip(axes.flat[:len(rows)], rows, strict=True):
        im = ax.pcolormesh(row["X"], row["Y"], 100 * row["frac"].T, vmin=0, vmax=100 * vmax,
                           cmap="magma_r", shading="nearest")
        ax.plot(np.cos(t), np.sin(t), color="0.5", lw=0.8)
        ax.set_xlim(-1.3, 1.3)
        ax.set_ylim(-1.3, 1.3)
        ax.set_title(title(row), fontsize=9)
        ax.set_xlabel("x / a (entrainment ->)")
        ax.xaxis.set_tick_params(labelbottom=True)
    for ax in axes[:, 0]:
        ax.set_ylabel("y / b")
    fig.colorbar(im, ax=axes, label="time in contact, % of counting time")
    fig.savefig(path, dpi=150)


#: (header, width, text of a row) of the contact statistics shared with ehl_paper_study.py
LOCATION_COLUMNS = [
    ("area/Hertz", 10, lambda r: f"{r['area_fraction']:.4f}"),
    ("max Q/ms", 8, lambda r: f"{r['max_q']:.0f}"),
    ("|y|>0.8b", 8, lambda r: f"{r['edge_share']:.2f}"),
    ("x>0", 5, lambda r: f"{r['downstream_share']:.2f}"),
    ("edge x>0", 8, lambda r: f"{r['edge_downstream']:.2f}"),
    ("max Q at (x/a, y/b)", 19, lambda r: "({:+.3f}, {:+.2f})".format(*r["max_at"])),
]
SOLVER_COLUMNS = [("sweeps", 6, lambda r: f"{r['sweeps']:.1f}"),
                  ("conv.", 5, lambda r: f"{r['converged']:.3f}")]


def print_table(rows, columns):
    """Print ``rows`` as right-aligned columns ``(header, width, text of a row)``."""
    print(" ".join(f"{head:>{width}}" for head, width, _ in columns))
    for row in rows:
        print(" ".join(f"{text(row):>{width}}" for _, width, text in columns))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="the study's output folder")
    parser.add_argument("--figure", type=Path, help="write the time-fraction maps here")
    args = parser.parse_args()
    folders = sorted(p for p in (args.out / "cases").iterdir() if (p / "summary.json").exists())
    rows = sorted((mesh_row(f) for f in folders), key=lambda r: r["frac"].size)
    compare_maps(rows)
    print_table(rows, [
        ("mesh", 8, lambda r: r["mesh"]), ("steps", 5, lambda r: f"{r['steps']:d}"),
        ("contact %", 9, lambda r: f"{r['contact_percent']:.1f}"),
        *LOCATION_COLUMNS[:2],
        ("Q at seed dt", 12, lambda r: f"{r['max_q_seed_dt']:.0f}"),
        ("max time %", 10, lambda r: f"{100 * r['max_fraction']:.1f}"),
        *LOCATION_COLUMNS[2:],
        ("map L2", 6, lambda r: f"{r['map_l2']:.2f}"),
        ("map r", 5, lambda r: f"{r['map_corr']:.2f}"),
        ("p_max GPa", 9, lambda r: f"{r['max_pressure_gpa']:.2f}"),
        ("h_c um", 6, lambda r: f"{r['central_film_um']:.3f}"), *SOLVER_COLUMNS,
    ])
    if args.figure:
        figure(rows, args.figure)


if __name__ == "__main__":
    main()
