"""The seed's Table 2 at its own mesh: contact statistics of a (partly) finished
``holmes-table2-paper`` study against the paper's percentages.

Reads ``OUT/cases/NNNN/result.nc`` and ``summary.json`` of ``asperity sweep
holmes-table2-paper --out OUT``. Cases may be missing or still running (a study is run a case
at a time on a small machine); only cases whose status.json says done are read. Prints, per
finished case, the paper's Table 2 value beside ours (the percentage of counting steps with
contact at one or more nodes) and the statistics of ``ehl_mesh_study.py`` (contact area over
the Hertz area, largest Q, share of the contact at the transverse edges ``|y| > 0.8 b`` and
downstream, the node of the largest Q, largest pressure, sweeps per step). ``--figure PATH``
draws the per-node time in contact of the finished cases side by side.

Run: ``python benchmarks/ehl_table2_paper.py OUT [--figure table2.png]``.
"""

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from ehl_mesh_study import (  # noqa: E402
    LOCATION_COLUMNS,
    SOLVER_COLUMNS,
    figure,
    mesh_row,
    print_table,
)

from asperity.sweep import load_study  # noqa: E402


def rows(out: Path):
    """Statistics of the study's finished cases, with their labels and the paper's values."""
    study = load_study("holmes-table2-paper")
    labels = study.axes[0][3]  # "A-A 0.1", ...: the surfaces axis's labels, one per case
    found = []
    for (cid, case, _), label in zip(study.cases, labels, strict=True):
        folder = out / "cases" / cid
        status = folder / "status.json"
        # a running case streams a partial result.nc; only finished cases are read
        if not status.exists() or json.loads(status.read_text())["state"] != "done":
            continue
        row = mesh_row(folder)
        row["label"] = label
        row["paper"] = case["paper_contact_time_percent"]
        found.append(row)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="the study's output folder")
    parser.add_argument("--figure", type=Path, help="write the time-in-contact maps here")
    args = parser.parse_args()
    found = rows(args.out)
    print_table(found, [
        ("case", 18, lambda r: r["label"]), ("seed %", 6, lambda r: f"{r['paper']:.1f}"),
        ("ours %", 6, lambda r: f"{r['contact_percent']:.1f}"), *LOCATION_COLUMNS,
        ("p_max GPa", 9, lambda r: f"{r['max_pressure_gpa']:.2f}"), *SOLVER_COLUMNS,
    ])
    if args.figure and found:
        figure(found, args.figure, title=lambda r: f"{r['label']}: {r['contact_percent']:.1f} "
               f"% of steps\n(seed: {r['paper']:g} %)")


if __name__ == "__main__":
    main()
