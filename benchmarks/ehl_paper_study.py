"""A seed study at its own mesh: contact statistics of the finished cases of a
``holmes-*-paper`` study (Table 2, aspect ratio, transverse waviness), with the paper's
Table 2 percentages beside ours where the study carries them.

Reads ``OUT/cases/NNNN/result.nc`` and ``summary.json`` of ``asperity sweep STUDY --out OUT``.
Cases may be missing or still running (a study is run a case at a time on a small machine);
only cases whose status.json says done are read. Prints, per finished case, the percentage of
counting steps with contact at one or more nodes (the seed's Table 2 measure; the paper's
value beside it for ``holmes-table2-paper``) and the statistics of ``ehl_mesh_study.py``
(contact area over the Hertz area, largest Q, share of the contact at the transverse edges
``|y| > 0.8 b`` and downstream, the node of the largest Q, largest pressure, sweeps per step).
``--reference FOLDER --reference-label TEXT`` adds a finished case of another study as a first
row (the waviness study's amplitude 0 is Table 2's C-C at xi = 0.25). ``--figure PATH`` draws
the per-node time in contact of the rows side by side.

Run: ``python benchmarks/ehl_paper_study.py holmes-table2-paper OUT [--figure table2.png]``.
"""

import argparse
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

from asperity.sweep import case_status, load_study  # noqa: E402

PAPER_KEY = "paper_contact_time_percent"


def finished(folder: Path) -> bool:
    """Whether a case folder holds a finished run (a running case streams a partial
    result.nc, which is not read)."""
    return (case_status(folder) or {}).get("state") == "done"


def rows(name: str, out: Path):
    """Statistics of the study's finished cases, with their labels (the first axis's) and the
    paper's Table 2 value where the case has one."""
    study = load_study(name)
    labels = study.axes[0][3]  # "A-A 0.1", "0.25", "0.05 um", ...: one per case
    found = []
    for (cid, case, _), label in zip(study.cases, labels, strict=True):
        folder = out / "cases" / cid
        if not finished(folder):
            continue
        row = mesh_row(folder)
        row["label"] = label
        row["paper"] = case.get(PAPER_KEY)
        found.append(row)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study", help="the study's name, e.g. holmes-table2-paper")
    parser.add_argument("out", type=Path, help="the study's output folder")
    parser.add_argument("--reference", type=Path, help="a finished case folder to show first")
    parser.add_argument("--reference-label", default="reference", help="its label")
    parser.add_argument("--figure", type=Path, help="write the time-in-contact maps here")
    args = parser.parse_args()
    found = rows(args.study, args.out)
    if args.reference is not None:
        if not finished(args.reference):
            parser.error(f"--reference: {args.reference} holds no finished case")
        reference = mesh_row(args.reference)
        reference.update(label=args.reference_label, paper=None)
        found.insert(0, reference)
    print_table(found, [
        ("case", 18, lambda r: r["label"]),
        ("seed %", 6, lambda r: "-" if r["paper"] is None else f"{r['paper']:.1f}"),
        ("ours %", 6, lambda r: f"{r['contact_percent']:.1f}"), *LOCATION_COLUMNS,
        ("p_max GPa", 9, lambda r: f"{r['max_pressure_gpa']:.2f}"),
        ("h_c um", 6, lambda r: f"{r['central_film_um']:.3f}"), *SOLVER_COLUMNS,
    ])
    if args.figure and found:
        def title(r):
            seed = "" if r["paper"] is None else f"\n(seed: {r['paper']:g} %)"
            return f"{r['label']}: {r['contact_percent']:.1f} % of steps{seed}"

        figure(found, args.figure, title=title)


if __name__ == "__main__":
    main()
