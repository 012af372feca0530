"""The seed's Table 2 at its own mesh: contact statistics of a (partly) finished
``holmes-table2-paper`` study against the paper's percentages.

Reads ``OUT/cases/NNNN/result.nc`` and ``summary.json`` of ``asperity sweep
holmes-table2-paper --out OUT`` (cases may be missing: a study is run a case at a time on a
small machine) and prints, per finished case, the paper's Table 2 value beside ours (the
percentage of counting steps with contact at one or more nodes) and the statistics of
``ehl_mesh_study.py`` (contact area over the Hertz area, largest Q, share of the contact at
the transverse edges ``|y| > 0.8 b`` and downstream, the node of the largest Q, largest
pressure, sweeps per step). ``--figure PATH`` draws the per-node time in contact of the
finished cases side by side.

Run: ``python benchmarks/ehl_table2_paper.py OUT [--figure table2.png]``.
"""

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from ehl_mesh_study import mesh_row  # noqa: E402

from asperity.sweep import load_study  # noqa: E402


def rows(out: Path):
    """Statistics of the study's finished cases, with their labels and the paper's values."""
    study = load_study("holmes-table2-paper")
    labels = study.axes[0][3]  # "A-A 0.1", ...: the surfaces axis's labels, one per case
    found = []
    for (cid, case, _), label in zip(study.cases, labels, strict=True):
        folder = out / "cases" / cid
        if not (folder / "result.nc").exists():
            continue
        row = mesh_row(folder)
        row["label"] = label
        row["paper"] = case["paper_contact_time_percent"]
        found.append(row)
    return found


def figure(found, path):
    """Per-node time in contact of every finished case, side by side."""
    from asperity.plotting.style import plt

    fig, axes = plt.subplots(1, len(found), figsize=(3.2 * len(found), 3.6), sharey=True,
                             constrained_layout=True)
    vmax = max(float(r["frac"].max()) for r in found)
    t = np.linspace(0, 2 * np.pi, 200)
    for ax, row in zip(np.atleast_1d(axes), found, strict=True):
        im = ax.pcolormesh(row["X"], row["Y"], 100 * row["frac"].T, vmin=0, vmax=100 * vmax,
                           cmap="magma_r", shading="nearest")
        ax.plot(np.cos(t), np.sin(t), color="0.5", lw=0.8)
        ax.set_xlim(-1.3, 1.3)
        ax.set_ylim(-1.3, 1.3)
        ax.set_title(f"{row['label']}: {row['contact_percent']:.1f} % of steps\n"
                     f"(seed: {row['paper']:g} %)", fontsize=9)
        ax.set_xlabel("x / a (entrainment ->)")
    np.atleast_1d(axes)[0].set_ylabel("y / b")
    fig.colorbar(im, ax=axes, label="time in contact, % of counting time")
    fig.savefig(path, dpi=150)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="the study's output folder")
    parser.add_argument("--figure", type=Path, help="write the time-in-contact maps here")
    args = parser.parse_args()
    found = rows(args.out)
    print(f"{'case':>18} {'seed %':>6} {'ours %':>6} {'area/Hertz':>10} {'max Q/ms':>8} "
          f"{'|y|>0.8b':>8} {'x>0':>5} {'edge x>0':>8} {'max Q at (x/a, y/b)':>19} "
          f"{'p_max GPa':>9} {'sweeps':>6} {'conv.':>5}")
    for r in found:
        where = "({:+.3f}, {:+.2f})".format(*r["max_at"])
        print(f"{r['label']:>18} {r['paper']:6.1f} {r['contact_percent']:6.1f} "
              f"{r['area_fraction']:10.4f} {r['max_q']:8.0f} {r['edge_share']:8.2f} "
              f"{r['downstream_share']:5.2f} {r['edge_downstream']:8.2f} {where:>19} "
              f"{r['max_pressure_gpa']:9.2f} {r['sweeps']:6.1f} {r['converged']:5.3f}")
    if args.figure and found:
        figure(found, args.figure)


if __name__ == "__main__":
    main()
