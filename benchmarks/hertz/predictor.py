#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 14, item 3: Newton iterations per load step with and without the extrapolating static
predictor (solver_settings.displacement_extrapolation), against Kratos 10.4, and whether the
answers stay the same. Writes benchmarks/hertz/results_predictor.md.

Cases: the Hertz benchmarks (generated as compare.py does; Kratos is run beside us on the same
files) and the multi-step cases of the robustness sweep's test subset (tests/cases/robustness,
with Kratos 10.4's iterations stored in their kratos_10_4.json). Every run is a fresh subprocess
(case_runner.py, OMP_NUM_THREADS=1). "Answer": the largest nodal displacement difference between
the runs with and without the predictor over the largest displacement, and the same for the
slave nodes' contact pressures (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE or, penalty, the augmented
pressure); both converge to the cases' own Newton tolerances, so that is the scale of the
differences.

    python benchmarks/hertz/predictor.py                       # all cases below
    python benchmarks/hertz/predictor.py --hertz hertz2d_2k --robustness ''
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import harness

REPO = os.path.dirname(os.path.dirname(harness.HERE))
ROBUSTNESS = os.path.join(REPO, "tests", "cases", "robustness")
HERTZ = "hertz2d_2k,hertz2d_8k,hertz2d_30k,hertz3d_15k,hertz3dgrid_15k"
#: (column, overrides of mortarcontact's run)
VARIANTS = {"off": ["solver_settings.displacement_extrapolation=false"],
            "on": ["solver_settings.displacement_extrapolation=true"]}


def multi_step_robustness_cases() -> list[str]:
    names = []
    for name in sorted(os.listdir(ROBUSTNESS)):
        with open(os.path.join(ROBUSTNESS, name, "kratos_10_4.json")) as f:
            if len(json.load(f)["iterations"]) > 1:
                names.append(name)
    return names


def _field(record: dict, kind: str) -> dict:
    if kind == "displacement":
        return {k: v for k, v in record["displacements"].items() if v is not None}
    return {str(n["id"]): [n["lm"] if n["lm"] is not None else (n["augmented"] if n["active"] else 0.0)]
            for n in record["slave"]}


def relative_difference(a: dict, b: dict, kind: str) -> float:
    fa, fb = _field(a, kind), _field(b, kind)
    keys = sorted(fb)
    x = np.array([fa[k] for k in keys], dtype=float).reshape(len(keys), -1)
    y = np.array([fb[k] for k in keys], dtype=float).reshape(len(keys), -1)
    scale = np.linalg.norm(y, axis=1).max()
    worst = np.linalg.norm(x - y, axis=1).max()
    return float(worst / scale) if scale > 0.0 else float(worst)


def _its(record: dict) -> list[int] | None:
    return [s["iterations"] for s in record["steps"]] if record.get("status") == "ok" else None


def run(name: str, folder: str, kratos_iterations: list[int] | None, work: str, kratos_python: str | None) -> dict:
    row = {"name": name}
    for variant, overrides in VARIANTS.items():
        out = os.path.join(work, f"{name}_{variant}.json")
        row[variant] = harness.run_once("mortarcontact", folder, out, threads=1, all_nodes=True, overrides=overrides)
    if kratos_iterations is None and kratos_python:
        record = harness.run_once("kratos", folder, os.path.join(work, f"{name}_kratos.json"), threads=1,
                                  python=kratos_python)
        kratos_iterations = _its(record)
    row["kratos"] = kratos_iterations
    off, on = row["off"], row["on"]
    if off.get("status") == "ok" and on.get("status") == "ok":
        row["du"] = relative_difference(on, off, "displacement")
        row["dp"] = relative_difference(on, off, "pressure")
    return row


def _cell(its) -> str:
    return ", ".join(map(str, its)) if its else "n/a"


def table(rows: list[dict]) -> str:
    lines = ["| case | Newton its Kratos 10.4 | ours before | ours with predictor | total K / before / after "
             "| displacement change | pressure change |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        k, off, on = r["kratos"], _its(r["off"]), _its(r["on"])
        totals = " / ".join(str(sum(x)) if x else "n/a" for x in (k, off, on))
        du = f"{r['du']:.1e}" if "du" in r else "n/a"
        dp = f"{r['dp']:.1e}" if "dp" in r else "n/a"
        lines.append(f"| {r['name']} | {_cell(k)} | {_cell(off)} | {_cell(on)} | {totals} | {du} | {dp} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hertz", default=HERTZ, help="comma-separated Hertz case names ('' for none)")
    parser.add_argument("--robustness", default=None,
                        help="comma-separated robustness cases (default: the multi-step ones; '' for none)")
    parser.add_argument("--no-kratos", action="store_true", help="do not run Kratos on the Hertz cases")
    parser.add_argument("--work", default=os.path.join(harness.RESULTS_DIR, "predictor"))
    parser.add_argument("--output", default=os.path.join(harness.HERE, "results_predictor.md"))
    args = parser.parse_args(argv)
    kratos_python = None if args.no_kratos else harness.kratos_python()
    robustness = (multi_step_robustness_cases() if args.robustness is None
                  else [n for n in args.robustness.split(",") if n])
    rows = []
    for name in [n for n in args.hertz.split(",") if n]:
        folder = harness.ensure_case(name, os.path.join(harness.HERE, "cases"))
        rows.append(run(name, folder, None, args.work, kratos_python))
        print(table(rows[-1:]).splitlines()[-1], flush=True)
    for name in robustness:
        folder = os.path.join(args.work, "cases", name)
        shutil.rmtree(folder, ignore_errors=True)
        shutil.copytree(os.path.join(ROBUSTNESS, name), folder)
        with open(os.path.join(folder, "kratos_10_4.json")) as f:
            kratos = json.load(f)["iterations"]
        rows.append(run(name, folder, kratos, args.work, None))
        print(table(rows[-1:]).splitlines()[-1], flush=True)
    with open(args.output, "w") as f:
        f.write(table(rows) + "\n")
    print(f"-> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
