"""Probe the steady EHL defaults on contacts nobody chose by hand (issue 17).

Draws steady lubricated contacts from a seeded random design over the regime users bring,
writes each as the case file a user would write (``analysis = "ehl-steady"``, no ``[grid]``
or ``[solver]`` table), runs it through ``asperity run`` in a subprocess capped at
``--timeout`` seconds, and prints one row per case: Moes M and L, k = b/a, converged or not
(or timed out), sweeps on the finest grid / on all grids, wall time, the central film over
each central-film formula the run's summary gives (Nijenbanning, Hamrock-Dowson, Chittenden,
Moes, the soft-EHL fit), the minimum film over Hamrock-Dowson's or Dowson-Higginson's, and
the warnings printed (abbreviated). A last column flags the rows to look at: not converged,
or a central film outside the band the formula is known to hold in for the case's lubricant
model without a warning (``BANDS``).

The design (``draw_case``): a material pair (steel/steel, steel/glass, steel/Si3N4 ceramic,
PDMS or rubber on glass or steel); a point contact with ``k`` log-uniform in 0.2-12
(entrainment along x; about 40 % with k < 1) or a line contact; Moes M log-uniform in
3-5000; speed, viscosity and radius log-uniform over plausible rig, bearing and gear values,
with L following from them (kept at most 25, and near 0 for the soft pairs and the
water-like fluids); Barus or Roelands, incompressible or Dowson-Higginson, Newtonian or
Eyring (tau0 1-20 MPa), slide/roll 0-1. Draws whose Hertz pressure or load is implausible
for the pair are drawn again.

Run (from the repository root; about 10-25 minutes on two cores)::

    PYTHONPATH=src python benchmarks/ehl_steady_probe.py --seed 40 --cases 30
    PYTHONPATH=src python benchmarks/ehl_steady_probe.py --only 7,12   # rerun two rows

The case files and each run's output stay under ``--out`` (default ``ehl-probe-out``); the
table is also written there as ``table.md``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from asperity.cases import load_case
from asperity.contact.hertz import radius_ratio
from asperity.materials import Material, contact_modulus

#: name -> (E1 Pa, nu1, name1, E2 Pa, nu2, name2, draw weight, highest plausible p_h Pa)
PAIRS = {
    "steel/steel": (210e9, 0.3, "steel", 210e9, 0.3, "steel", 0.35, 3.5e9),
    "steel/glass": (210e9, 0.3, "steel", 75e9, 0.22, "glass", 0.20, 1.2e9),
    "steel/Si3N4": (210e9, 0.3, "steel", 310e9, 0.27, "Si3N4", 0.25, 3.5e9),
    "PDMS/glass": (None, 0.49, "PDMS", 70e9, 0.22, "glass", 0.10, None),
    "rubber/steel": (None, 0.49, "rubber", 210e9, 0.3, "steel", 0.10, None),
}

#: Moes M and the most L drawn
M_RANGE = (3.0, 5000.0)
L_MAX = 25.0
#: point contacts' k = b/a
K_RANGE = (0.2, 12.0)

#: central-film formula key -> (the band of computed/formula the formula is known to hold in
#: for a Newtonian Barus incompressible oil, the band for any other lubricant model); from
#: docs/ehl-robustness.md "The formulas and the accuracy they claim" (Nijenbanning and Moes
#: a few per cent, tested at 6 %; Hamrock-Dowson up to ~20 %, tested at 25 %; Roelands,
#: Dowson-Higginson and Eyring thin the film by 10-20 %, tested at 0.7-1.05)
BANDS = {
    "nijenbanning_central_film_m": ((0.94, 1.06), (0.70, 1.06)),
    "moes_central_film_m": ((0.94, 1.06), (0.70, 1.06)),
}

#: column label of each formula row in the summary
LABELS = {
    "nijenbanning_central_film_m": "Nij",
    "hamrock_dowson_central_film_m": "HD",
    "chittenden_central_film_m": "Ch",
    "moes_central_film_m": "Moes",
    "hamrock_dowson_soft_central_film_m": "HDsoft",
    "hamrock_dowson_minimum_film_m": "HD",
    "chittenden_minimum_film_m": "Ch",
    "dowson_higginson_minimum_film_m": "DH",
    "hamrock_dowson_soft_minimum_film_m": "HDsoft",
    "brewe_hamrock_taylor_minimum_film_m": "BHT",
    "martin_minimum_film_m": "Martin",
}


def log_uniform(rng, low, high):
    """A draw uniform in log between ``low`` and ``high``."""
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def modulus_text(value):
    """A Young's modulus as a user writes it: "210 GPa", "5.826 MPa"."""
    return f"{value / 1e9:.4g} GPa" if value >= 1e9 else f"{value / 1e6:.4g} MPa"


def hard_speeds(rng, e_prime, rx, U):
    """Speed and viscosity (u m/s, eta0 Pa s) with ``eta0 u = U E' Rx``: u log-uniform in
    0.02-30 m/s, eta0 kept in 0.002-2 Pa s; None when no draw of 20 gives both."""
    for _ in range(20):
        u = log_uniform(rng, 0.02, 30.0)
        eta0 = U * e_prime * rx / u
        if 0.002 <= eta0 <= 2.0:
            return u, eta0
    return None


def draw_case(rng, index, kind):
    """One plausible steady contact of ``kind`` ("point", "line", "soft") as ``(case dict,
    design record)``, or None when the draw is implausible.

    Hard pairs: M log-uniform in :data:`M_RANGE` and p_h uniform from 0.2 GPa to the pair's
    limit fix ``W`` and ``U``; alpha (8-30 1/GPa, one draw in ten 0.5-3: a water-based fluid)
    then gives L, kept at most :data:`L_MAX`. Soft pairs: load, speed, viscosity and radius
    drawn directly, kept where M lies in :data:`M_RANGE`."""
    soft = kind == "soft"
    pairs = [n for n in PAIRS if (PAIRS[n][0] is None) == soft]
    weights = np.array([PAIRS[n][6] for n in pairs])
    pair = pairs[rng.choice(len(pairs), p=weights / weights.sum())]
    e1, nu1, n1, e2, nu2, n2, _, p_limit = PAIRS[pair]
    if soft:
        e1 = log_uniform(rng, 1e6, 5e6) if pair.startswith("PDMS") else \
            log_uniform(rng, 4e6, 20e6)
    e_prime = 2.0 * contact_modulus(Material(e1, nu1), Material(e2, nu2))  # E' = 2 E*
    line = kind == "line" or (soft and rng.uniform() < 0.25)
    k = 1.0 if line else log_uniform(rng, *K_RANGE)
    ry_over_rx = 1.0 / radius_ratio(1.0 / k)
    M = log_uniform(rng, *M_RANGE)
    rx = log_uniform(rng, 2e-3, 15e-3) if soft else log_uniform(rng, 2e-3, 40e-3)
    if soft:
        u = log_uniform(rng, 0.005, 2.0)
        eta0 = log_uniform(rng, 0.001, 1.0)
        alpha = 0.0 if rng.uniform() < 0.5 else rng.uniform(10e-9, 20e-9)  # glycerol / silicone
        U = eta0 * u / (e_prime * rx)
        W = M * (2 * U) ** (0.5 if line else 0.75)
    else:
        p_h = rng.uniform(0.2e9, p_limit)
        # Hertz: a line's W' = 2 pi (p_h/E')^2; a point's W = (2 pi^3 / 9) (p_h/E')^3 R^2/Rx^2
        # for the circle of radius R = sqrt(Rx Ry) (the ellipse's exact p_h is checked below)
        W = 2 * math.pi * (p_h / e_prime) ** 2 if line else \
            2 * math.pi**3 / 9 * (p_h / e_prime) ** 3 * ry_over_rx
        U = 0.5 * (W / M) ** (2.0 if line else 4.0 / 3.0)
        speeds = hard_speeds(rng, e_prime, rx, U)
        if speeds is None:
            return None
        u, eta0 = speeds
        alpha = log_uniform(rng, 0.5e-9, 3e-9) if rng.uniform() < 0.1 else \
            log_uniform(rng, 8e-9, 30e-9)
    if alpha * e_prime * (2 * U) ** 0.25 > L_MAX:
        return None
    if line:
        w = W * e_prime * rx
        load = {"radius": f"{rx * 1e3:.4g} mm", "load_per_length": f"{w:.5g} N/m"}
    else:
        f = W * e_prime * rx**2
        load = {"rx": f"{rx * 1e3:.4g} mm", "ry": f"{rx * ry_over_rx * 1e3:.5g} mm",
                "load": f"{f:.5g} N"}
    viscosity = "barus" if alpha == 0.0 or rng.uniform() < 0.5 else "roelands"
    density = "incompressible" if rng.uniform() < 0.5 else "dowson-higginson"
    tau0 = None if rng.uniform() < 0.5 else log_uniform(rng, 1e6, 20e6)
    xi = 0.0 if rng.uniform() < 0.3 else float(rng.uniform(0.0, 1.0))
    case = {
        "analysis": "ehl-steady",
        "title": f"probe {index:02d}: {pair} {'line' if line else f'point k={k:.3g}'}",
        "body1": {"name": n1, "youngs_modulus": modulus_text(e1), "poisson_ratio": nu1},
        "body2": {"name": n2, "youngs_modulus": modulus_text(e2), "poisson_ratio": nu2},
        "contact": {"type": "line" if line else "point", **load},
        "speeds": {"u": f"{u:.4g} m/s", "xi": round(xi, 3)},
        "lubricant": {"eta0": f"{eta0:.4g} Pa s", "alpha": f"{alpha * 1e9:.4g} 1/GPa",
                      "viscosity_model": viscosity, "density_model": density},
    }
    if tau0 is not None:
        case["lubricant"]["tau0"] = f"{tau0 / 1e6:.3g} MPa"
    problem = load_case(case).problem()
    if not M_RANGE[0] <= problem.M <= M_RANGE[1]:
        return None
    if p_limit is not None and not 0.15e9 <= problem.p_hertz <= p_limit:
        return None
    if soft and (problem.a / rx > 0.2 or not 1e-3 <= u <= 5.0):  # far beyond the half-space
        return None
    meta = {"pair": pair, "line": line, "k": None if line else problem.hertz.b / problem.a,
            "M": problem.M, "L": problem.L, "p_h": problem.p_hertz, "u": u, "eta0": eta0,
            "alpha": alpha, "xi": xi, "tau0": tau0, "viscosity": viscosity,
            "density": density}
    return case, meta


def draw_cases(seed, count):
    """``count`` plausible cases from ``numpy.random.default_rng(seed)``: a shuffled list of
    kinds (2/15 soft pairs, 4/15 line contacts, the rest point contacts), each drawn again
    until plausible."""
    rng = np.random.default_rng(seed)
    soft = max(1, round(count * 2 / 15))
    lines = round(count * 4 / 15)
    kinds = rng.permutation(["soft"] * soft + ["line"] * lines
                            + ["point"] * (count - soft - lines))
    cases = []
    for kind in kinds:
        drawn = None
        while drawn is None:
            drawn = draw_case(rng, len(cases), str(kind))
        cases.append(drawn)
    return cases


def toml_text(case, meta):
    """The case dict as a user's TOML file, with a comment naming the draw."""
    lines = [f"# probe draw: {meta['pair']}, M = {meta['M']:.4g}, L = {meta['L']:.3g}"
             + ("" if meta["line"] else f", k = {meta['k']:.3g}")
             + f", p_h = {meta['p_h'] / 1e9:.3g} GPa"]
    for key in ("analysis", "title"):
        lines.append(f'{key} = "{case[key]}"')
    for table in ("body1", "body2", "contact", "speeds", "lubricant"):
        lines.append(f"\n[{table}]")
        for key, value in case[table].items():
            lines.append(f'{key} = "{value}"' if isinstance(value, str) else
                         f"{key} = {value}")
    return "\n".join(lines) + "\n"


def run_one(path, out, timeout):
    """Run ``asperity run`` on one case file; return the record of what came back."""
    env = dict(os.environ)
    start = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, "-m", "asperity.cli", "run", str(path), "-o",
                               str(out), "-q"], capture_output=True, text=True,
                              timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "wall": time.perf_counter() - start}
    wall = time.perf_counter() - start
    record = {"status": "done", "wall": wall, "rc": proc.returncode,
              "stderr": proc.stderr.strip().splitlines()}
    summary = out / "summary.json"
    if summary.exists():
        record["summary"] = json.loads(summary.read_text())
    return record


def ratios(summary, kind):
    """``label -> computed / formula`` of the central (``kind = "central"``) or minimum
    film."""
    film = summary.get(f"{kind}_film_thickness_m")
    found = {}
    for key, label in LABELS.items():
        if f"_{kind}_film_m" in key and summary.get(key):
            found[label] = film / summary[key]
    return found


def flag(meta, record):
    """Why the row wants a look ('' when it does not)."""
    if record["status"] == "timeout":
        return "timeout"
    summary = record.get("summary")
    if summary is None:
        return f"no summary (exit {record['rc']})"
    if not summary.get("converged"):
        return "not converged"
    newtonian_barus = (meta["viscosity"] == "barus" and meta["density"] == "incompressible"
                       and (meta["tau0"] is None or meta["xi"] == 0.0))
    for key, bands in BANDS.items():
        if summary.get(key):
            low, high = bands[0] if newtonian_barus else bands[1]
            ratio = summary["central_film_thickness_m"] / summary[key]
            if not low <= ratio <= high and not summary.get("warnings"):
                return f"{LABELS[key]} {ratio:.3f} outside {low}-{high}, no warning"
    return ""


def short_warning(text):
    """The first words of a warning line."""
    return " ".join(text.split()[:5])


def row(index, meta, record):
    """One markdown table row."""
    lub = ("B" if meta["viscosity"] == "barus" else "R") + \
        ("" if meta["density"] == "incompressible" else "+DH") + \
        ("" if meta["tau0"] is None else f"+E{meta['tau0'] / 1e6:.2g}")
    k = "line" if meta["line"] else f"{meta['k']:.2f}"
    head = (f"| {index:02d} | {meta['pair']} | {lub} | {meta['xi']:.2f} | {meta['M']:.3g} | "
            f"{meta['L']:.3g} | {k} |")
    summary = record.get("summary")
    if record["status"] == "timeout" or summary is None:
        return head + f" {flag(meta, record)} | | {record['wall']:.0f} | | | | |"
    conv = "yes" if summary["converged"] else f"no ({summary['residual']:.1e})"
    central = ", ".join(f"{k} {v:.3f}" for k, v in ratios(summary, "central").items())
    minimum = ", ".join(f"{k} {v:.3f}" for k, v in ratios(summary, "minimum").items())
    warns = "; ".join(short_warning(w) for w in summary.get("warnings", []))
    return (head + f" {conv} | {summary['sweeps']}/{summary['total_sweeps']} | "
            f"{record['wall']:.0f} | {summary['central_film_thickness_m'] * 1e9:.4g} | "
            f"{central} | {minimum} | {warns} | {flag(meta, record)} |")


HEADER = ("| # | pair | oil | xi | M | L | k | converged | sweeps | s | hc nm | hc vs | "
          "hmin vs | warnings | look |\n|" + "---|" * 15)


def main(argv=None):
    """Draw, run and tabulate the probe."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=40)
    parser.add_argument("--cases", type=int, default=30)
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per run")
    parser.add_argument("--out", type=Path, default=Path("ehl-probe-out"))
    parser.add_argument("--only", default="", help="comma-separated case numbers to run")
    parser.add_argument("--write-only", action="store_true", help="write the case files only")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    cases = draw_cases(args.seed, args.cases)
    only = {int(s) for s in args.only.split(",") if s.strip()}
    rows = []
    start = time.perf_counter()
    print(HEADER, flush=True)
    for index, (case, meta) in enumerate(cases):
        path = args.out / f"case{index:02d}.toml"
        path.write_text(toml_text(case, meta))
        if args.write_only or (only and index not in only):
            continue
        record = run_one(path, args.out / f"run{index:02d}", args.timeout)
        (args.out / f"run{index:02d}.json").write_text(json.dumps(
            {"meta": meta, "record": record}, indent=1, default=str))
        rows.append(row(index, meta, record))
        print(rows[-1], flush=True)
    total = time.perf_counter() - start
    footer = (f"\nseed {args.seed}, {len(rows)} cases, timeout {args.timeout:g} s, "
              f"wall {total / 60:.1f} min")
    print(footer)
    (args.out / "table.md").write_text(HEADER + "\n" + "\n".join(rows) + "\n" + footer + "\n")


if __name__ == "__main__":
    main()
