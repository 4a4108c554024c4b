#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4: contact search and mortar integration time per contact pair, from the smallest to the
largest Hertz case (target: constant within +-20 %, i.e. linear scaling).

The per-phase timings of a whole analysis hold only four searches of a few milliseconds each on
the small cases, too few to tell a scaling trend from noise. Here each case is run for one load
step with mortarcontact (so that the bodies touch and the pairs are those of a loaded contact),
then, on that state:

- the contact search (clear the pairs, KD-tree, candidate checks, coverage walk, pair creation,
  active-set prediction) is repeated ``--repeat`` times,
- the mortar weighted gap of all pairs (segmentation, dual basis, D, M, gap, per pair) likewise,

and the median of each is divided by the number of pairs. One thread (OMP_NUM_THREADS=1), the
cases alternating between repetitions so that a slow patch of the machine hits all of them.

The search does two kinds of work: a tree query and candidate checks for every slave face, and
the checks, coverage walk and pair creation for every pair. On the refined 2D cases the search
radius (a multiple of the face size) no longer reaches the master from the far slave faces: pairs
per slave face fall from 2 to 0.8, and the cost per pair rises although nothing grows faster than
linearly. So the table also gives the least-squares fit t = a * slave faces + b * pairs per family
and how far each case lies from it: a fit within a few per cent with the same a and b from the
smallest to the largest case is linear scaling.

    python benchmarks/hertz/contact_scaling.py --cases hertz2d_2k,hertz2d_30k,hertz2d_250k
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from mortarcontact.cases.hertz import load_reference  # noqa: E402

import harness  # noqa: E402

DEFAULT_CASES = "hertz2d_2k,hertz2d_8k,hertz2d_30k,hertz2d_100k,hertz2d_250k,hertz3d_15k,hertz3d_50k"


def measure(case_dir: str, repeat: int, linear_solver: str | None) -> dict:
    """In this process: one load step, then the repeated search and weighted gap."""
    import time

    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis

    import case_runner

    os.chdir(case_dir)
    parameters = case_runner.mortarcontact_parameters(os.path.join(case_dir, "ProjectParameters.json"), linear_solver)
    analysis = StructuralMechanicsAnalysis(mc.Model(), parameters, progress=False, case_dir=case_dir)
    analysis.Initialize()
    analysis.OpenStep(1)
    if not analysis.solver.SolveSolutionStep():
        raise RuntimeError(f"{case_dir}: the first load step did not converge")
    searches = [s for p in analysis.processes for s in getattr(p, "searches", [])]
    updater = analysis.solver.mortar_updater
    part = analysis.solver.GetComputingModelPart()
    search_seconds, gap_seconds, pairs, slaves = [], [], 0, 0
    for _ in range(repeat):
        started = time.perf_counter()
        stats = [s.UpdateMortarConditions() for s in searches]
        search_seconds.append(time.perf_counter() - started)
        pairs = sum(st["pairs"] for st in stats)
        slaves = sum(st["slave_conditions"] for st in stats)
        started = time.perf_counter()
        updater.ComputeWeightedGap(part)
        gap_seconds.append(time.perf_counter() - started)
    return {"pairs": pairs, "slave_conditions": slaves, "search": statistics.median(search_seconds),
            "weighted_gap": statistics.median(gap_seconds),
            "dofs": load_reference(case_dir)["counts"]["dofs"]}


def linear_fit(rows):
    """Least-squares t = a * slaves + b * pairs over (slaves, pairs, t) rows; returns a, b and the
    relative deviation of each row from the fit."""
    import numpy as np

    A = np.array([[r[0], r[1]] for r in rows], dtype=float)
    t = np.array([r[2] for r in rows])
    (a, b), *_ = np.linalg.lstsq(A, t, rcond=None)
    return a, b, [(A[i] @ (a, b)) / t[i] - 1.0 for i in range(len(rows))]


def spread(values) -> str:
    low, high = min(values), max(values)
    return f"{100.0 * (high / low - 1.0):.0f} %"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default=DEFAULT_CASES)
    parser.add_argument("--repeat", type=int, default=20, help="searches and gap evaluations per case")
    parser.add_argument("--rounds", type=int, default=3, help="alternating rounds over the cases (medians)")
    parser.add_argument("--cases-dir", default=os.path.join(HERE, "cases"))
    parser.add_argument("--output", default=os.path.join(HERE, "results_contact_scaling.md"))
    parser.add_argument("--linear-solver", help="linear_solver_settings (JSON) for the first load step, e.g. the "
                                                "PETSc field split for hertz3d_150k")
    parser.add_argument("--measure", help=argparse.SUPPRESS)  # internal: one case, in a subprocess
    args = parser.parse_args(argv)
    if args.measure:
        print(json.dumps(measure(args.measure, args.repeat, args.linear_solver)))
        return 0
    names = args.cases.split(",")
    folders = {name: harness.ensure_case(name, args.cases_dir) for name in names}
    runs = {name: [] for name in names}
    env = dict(os.environ, OMP_NUM_THREADS="1")
    for _ in range(args.rounds):
        for name in names:
            command = [sys.executable, __file__, "--measure", folders[name], "--repeat", str(args.repeat)]
            if args.linear_solver:
                command += ["--linear-solver", args.linear_solver]
            out = subprocess.run(command,
                                 capture_output=True, text=True, env=env)
            if out.returncode != 0:
                raise SystemExit(f"{name}: {out.stderr[-2000:]}")
            runs[name].append(json.loads(out.stdout.strip().splitlines()[-1]))
            print(name, runs[name][-1], flush=True)
    rows, per_pair, fit_rows = [], {}, {}
    for name in names:
        pairs, slaves = runs[name][0]["pairs"], runs[name][0]["slave_conditions"]
        search_s = statistics.median(r["search"] for r in runs[name])
        gap = 1e6 * statistics.median(r["weighted_gap"] for r in runs[name]) / pairs
        family = name.split("_")[0]
        per_pair.setdefault(family, {"search": [], "weighted_gap": []})
        per_pair[family]["search"].append(1e6 * search_s / pairs)
        per_pair[family]["weighted_gap"].append(gap)
        fit_rows.setdefault(family, []).append((name, slaves, pairs, 1e6 * search_s))
        rows.append([name, runs[name][0]["dofs"], slaves, pairs, f"{1e6 * search_s / pairs:.2f}", f"{gap:.2f}"])
    fits, deviation = [], {}
    for family, family_rows in fit_rows.items():
        if len(family_rows) < 3:
            continue
        a, b, residuals = linear_fit([r[1:] for r in family_rows])
        for (name, *_), residual in zip(family_rows, residuals):
            deviation[name] = residual
        fits.append(f"| {family} | {a:.2f} | {b:.2f} | {100.0 * max(abs(r) for r in residuals):.1f} % |")
    table = "\n".join(f"| {' | '.join(map(str, r))} | {100.0 * deviation[r[0]]:+.1f} % |" if r[0] in deviation
                      else f"| {' | '.join(map(str, r))} | n/a |" for r in rows)
    summary = [f"| {family} | {spread(v['search'])} | {spread(v['weighted_gap'])} |"
               for family, v in per_pair.items() if len(v["search"]) > 1]
    text = ("# Contact search and mortar integration per pair\n\n"
            "Generated by `benchmarks/hertz/contact_scaling.py`: after the first load step of each case, the "
            f"contact search and the mortar weighted gap of all pairs repeated {args.repeat} times, medians over "
            f"{args.rounds} alternating rounds, one thread. Machine: {harness.machine_line(1)}.\n\n"
            "| case | DoFs | slave faces | pairs | search [us / pair] | mortar weighted gap [us / pair] "
            "| search against the fit |\n|---|---|---|---|---|---|---|\n" + table
            + "\n\nLargest / smallest per-pair cost in each family (target: within 20 %):\n\n"
            "| family | search | mortar weighted gap |\n|---|---|---|\n" + "\n".join(summary)
            + "\n\nSearch time = a x slave faces + b x pairs, least squares per family (the per-pair cost of the "
            "search mixes both; see the script's docstring):\n\n"
            "| family | a [us / slave face] | b [us / pair] | largest deviation from the fit |\n|---|---|---|---|\n"
            + "\n".join(fits) + "\n")
    with open(args.output, "w") as f:
        f.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
