#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: runs the robustness sweep (sweep_cases.py) with Kratos 10.4 and mortarcontact and
writes the summary table benchmarks/robustness/results.md.

Each case is generated afresh (deterministic), then run once by each code in its own subprocess
(benchmarks/hertz/case_runner.py, OMP_NUM_THREADS=1, stopped after ``--timeout`` seconds). A run
that raises, does not converge in a step or times out is recorded and the sweep goes on. Kratos'
record is reused while the case files are unchanged (``--rerun-kratos`` runs it anyway). Per case
the raw records go to results/<case>/<code>.json and the comparison to results/<case>.json
(both ignored by git); results.md is rebuilt from every stored comparison, so a ``--filter`` run
updates its rows and keeps the others.

Compared, node by node (both codes read the same mdpa): the displacements of all nodes (largest
vector difference over the largest displacement), the contact pressure at the slave nodes
(ALM: -SCALE_FACTOR * LAGRANGE_MULTIPLIER_CONTACT_PRESSURE; components: SCALE_FACTOR *
|VECTOR_LAGRANGE_MULTIPLIER|; penalty: -AUGMENTED_NORMAL_CONTACT_PRESSURE; over the largest
pressure) and the total reaction vector at the clamped bottom (over its length). On the
mirror-symmetric cases (Variant.symmetric) each code's lateral bottom reaction over the total
measures how far its own solution is from symmetric: a yardstick for the differences.

    python benchmarks/robustness/run_sweep.py                        # the whole sweep
    python benchmarks/robustness/run_sweep.py --filter '^2d_.*curved'
    python benchmarks/robustness/run_sweep.py --subset test --snapshots tests/cases/robustness
    python benchmarks/robustness/run_sweep.py --report               # results.md from stored results
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "hertz"))
sys.path.insert(0, HERE)

import harness  # noqa: E402
import sweep_cases  # noqa: E402

CODES = ("kratos", "mortarcontact")
RESULTS_DIR = os.path.join(HERE, "results")
TOLERANCE = 1e-6
KRATOS_VERSION = harness.KRATOS_VERSION

#: Named subsets. "test": the cases tests/python/test_robustness_sweep.py runs by default (a few
#: seconds in total with mortarcontact): the coarse ones but the penalty case, which Kratos does
#: not solve, and a few small ones from the families; "test-slow": those it runs with -m slow.
SLOW_TESTS = ["3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse",
              "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm",
              "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm",
              "3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm"]
SUBSETS = {
    "test": [v.name for v in sweep_cases.variants()
             if v.coarse and v.formulation != "penalty" and v.name not in SLOW_TESTS]
    + ["3d_hex_flat_r4_overhang-none_gap_disp_4steps_alm", "3d_hex_flat_r1.001_overhang-none_gap_disp_4steps_alm",
       "3d_hex_inclined_r2_overhang-none_gap_disp_4steps_alm",
       "2d_quad_flat_r0.5_overhang-none_gap_disp_4steps_penalty",
       "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty"],
    "test-slow": SLOW_TESTS,
}


# -- one case ---------------------------------------------------------------------------------
def pressures(record: dict, formulation: str) -> dict[str, float]:
    """Contact pressure (compression positive) per slave node id."""
    scale = (record.get("process_info") or {}).get("SCALE_FACTOR") or 0.0
    out = {}
    for node in record["slave"]:
        if formulation == "alm":
            p = -scale * (node["lm"] or 0.0)
        elif formulation == "comp":
            p = scale * math.sqrt(sum(c * c for c in node.get("vector_lm") or [0.0]))
        else:
            p = -(node["augmented"] or 0.0) if node["active"] else 0.0
        out[str(node["id"])] = p
    return out


def status(record: dict) -> str:
    if record.get("status") != "ok":
        return record.get("status", "failed")
    values = [c for u in record["displacements"].values() for c in u]
    if not all(math.isfinite(c) for c in values):
        return "failed"
    return "ok" if record["steps"] and all(s["converged"] for s in record["steps"]) else "not converged"


def _relative(ours: dict, theirs: dict) -> float:
    """max |ours - theirs| over max |theirs|, over the keys of ``theirs`` (values: numbers or vectors)."""
    def norm(x):
        return math.sqrt(sum(c * c for c in x)) if isinstance(x, list) else abs(x)

    def minus(a, b):
        return [p - q for p, q in zip(a, b)] if isinstance(a, list) else a - b

    scale = max((norm(v) for v in theirs.values()), default=0.0)
    worst = max((norm(minus(ours[k], v)) for k, v in theirs.items()), default=0.0)
    return worst / scale if scale > 0.0 else (0.0 if worst == 0.0 else math.inf)


def compare(variant, records: dict) -> dict:
    summary = {"case": variant.name, "measured": time.strftime("%Y-%m-%d %H:%M")}
    for code, record in records.items():
        summary[code] = {"status": status(record), "error": (record.get("error") or "")[-300:],
                         "iterations": [s["iterations"] for s in record.get("steps", [])],
                         "converged": [s["converged"] for s in record.get("steps", [])],
                         "seconds": record.get("analysis_seconds"), "wall_seconds": record.get("wall_seconds"),
                         "nodes": record.get("nodes")}
    kratos, ours = records.get("kratos", {}), records.get("mortarcontact", {})
    if all("displacements" in r for r in (kratos, ours)) and "failed" not in (summary["kratos"]["status"],
                                                                                summary["mortarcontact"]["status"]):
        summary["displacement"] = _relative(ours["displacements"], kratos["displacements"])
        summary["pressure"] = _relative(pressures(ours, variant.formulation), pressures(kratos, variant.formulation))
        summary["reaction"] = _relative({"bottom": ours["reaction_totals"]["DISPLACEMENT_bottom"]},
                                        {"bottom": kratos["reaction_totals"]["DISPLACEMENT_bottom"]})
    if variant.symmetric:
        for code, record in records.items():
            if summary[code]["status"] != "failed" and "reaction_totals" in record:
                reaction = record["reaction_totals"]["DISPLACEMENT_bottom"]
                lateral = math.hypot(*reaction[:variant.dim - 1])
                summary[code]["asymmetry"] = lateral / (math.hypot(*reaction) or 1.0)
    return summary


def _case_hash(folder: str) -> str:
    digest = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        digest.update(name.encode())
        with open(os.path.join(folder, name), "rb") as f:
            digest.update(f.read())
    return digest.hexdigest()


def run_case(variant, cases_dir: str, timeout: float, rerun_kratos: bool) -> dict:
    """Runs both codes on one case; Kratos' stored record is reused when it was made from the same
    case files (Kratos 10.4 does not change, so only mortarcontact needs re-measuring)."""
    folder = sweep_cases.write_case(variant, cases_dir)
    files = _case_hash(folder)
    records = {}
    for code in CODES:
        output = os.path.join(RESULTS_DIR, variant.name, f"{code}.json")
        if code == "kratos" and not rerun_kratos and os.path.exists(output):
            with open(output) as f:
                stored = json.load(f)
            if stored.get("case_files") == files and stored.get("status") != "timeout":
                records[code] = stored
                continue
        python = harness.kratos_python() if code == "kratos" else sys.executable
        records[code] = harness.run_once(code, folder, output, threads=1, python=python, timeout=timeout,
                                         all_nodes=True)
        records[code]["case_files"] = files
        with open(output, "w") as f:
            json.dump(records[code], f)
    summary = compare(variant, records)
    with open(os.path.join(RESULTS_DIR, f"{variant.name}.json"), "w") as f:
        json.dump(summary, f, indent=1)
    return summary


def write_snapshot(variant, cases_dir: str, target: str) -> None:
    """Copies the case files into ``target/<case>/`` with Kratos' values (kratos_10_4.json) for
    tests/python/test_robustness_sweep.py."""
    with open(os.path.join(RESULTS_DIR, variant.name, "kratos.json")) as f:
        record = json.load(f)
    folder = os.path.join(target, variant.name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.join(cases_dir, variant.name), folder)
    snapshot = {"kratos": KRATOS_VERSION, "status": status(record), "formulation": variant.formulation,
                "iterations": [s["iterations"] for s in record["steps"]],
                "converged": [s["converged"] for s in record["steps"]],
                "displacements": record["displacements"], "pressures": pressures(record, variant.formulation),
                "reaction_bottom": record["reaction_totals"]["DISPLACEMENT_bottom"]}
    with open(os.path.join(folder, "kratos_10_4.json"), "w") as f:
        json.dump(snapshot, f, indent=1)
        f.write("\n")


# -- the table --------------------------------------------------------------------------------
def _iterations(its: list[int]) -> str:
    """3,2,2,2,2 -> 3,2x4"""
    runs = []
    for it in its:
        if runs and runs[-1][0] == it:
            runs[-1][1] += 1
        else:
            runs.append([it, 1])
    return ",".join(str(it) if n == 1 else f"{it}x{n}" for it, n in runs) or "-"


def _difference(x) -> str:
    return "-" if x is None else f"{x:.1e}"


def verdict(s: dict) -> dict:
    k, m = s["kratos"], s["mortarcontact"]
    within = all(s.get(key) is not None and s[key] <= TOLERANCE for key in ("displacement", "pressure", "reaction"))
    fewer = (m["status"] == "ok" and len(m["iterations"]) == len(k["iterations"])
             and all(a <= b for a, b in zip(m["iterations"], k["iterations"])))
    return {"kratos_converges": k["status"] == "ok", "we_converge": m["status"] == "ok",
            "iterations_ok": fewer, "within": within,
            "pass": k["status"] == "ok" and m["status"] == "ok" and fewer and within}


def report(path: str) -> None:
    names = [v.name for v in sweep_cases.variants()]
    summaries = []
    for name in names:
        stored = os.path.join(RESULTS_DIR, f"{name}.json")
        if os.path.exists(stored):
            with open(stored) as f:
                summaries.append(json.load(f))
    verdicts = [verdict(s) for s in summaries]
    count = {key: sum(v[key] for v in verdicts) for key in ("kratos_converges", "we_converge", "iterations_ok",
                                                              "within", "pass")}
    both = sum(v["kratos_converges"] and v["we_converge"] for v in verdicts)
    wall = sum(s[code]["wall_seconds"] or 0.0 for s in summaries for code in CODES)
    lines = [
        "# Robustness sweep: mortarcontact against Kratos 10.4",
        "",
        f"Generated by `benchmarks/robustness/run_sweep.py` (`make bench-robustness`); cases from "
        f"`sweep_cases.py` (its docstring describes the variants). Kratos {KRATOS_VERSION}, one subprocess per "
        "run, OMP_NUM_THREADS=1. Measured "
        f"{min(s['measured'] for s in summaries)} to {max(s['measured'] for s in summaries)}; the runs "
        f"(subprocess wall time, both codes) add up to {wall / 60.0:.1f} min. What the failures have in common "
        "and the smallest case of each: [README.md](README.md).",
        "",
        f"- cases: {len(summaries)}",
        f"- Kratos converges: {count['kratos_converges']}",
        f"- we converge: {count['we_converge']} (on {both} of the {count['kratos_converges']} where Kratos does)",
        f"- Newton iterations <= Kratos' in every step: {count['iterations_ok']}",
        f"- within {TOLERANCE:g} of Kratos (displacements, pressures and reaction): {count['within']}",
        f"- all of these (the goal): {count['pass']}",
        "",
        "Columns: converged (K = Kratos, M = mortarcontact: ok, nc = not converged in some step, failed, "
        "timeout); Newton iterations per step (`2x3` = three steps of 2); largest relative difference "
        "to Kratos of the displacements (all nodes), of the slave contact pressures and of the total "
        "reaction at the clamped bottom; analysis time (s, imports excluded). Convergence criterion "
        "contact_residual_criterion with relative tolerances 1e-6 (absolute 1e-12), 30 iterations at most. "
        "sym K / M: on the mirror-symmetric cases, each code's lateral bottom reaction over the total "
        "(zero for an exactly symmetric solution).",
        "",
        "| case | nodes | K | M | iterations K | iterations M | du | dp | dR | sym K / M | t K | t M | goal |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    short = {"ok": "ok", "not converged": "nc", "failed": "failed", "timeout": "timeout"}
    for s, v in zip(summaries, verdicts):
        k, m = s["kratos"], s["mortarcontact"]
        seconds = [f"{c['seconds']:.2f}" if c.get("seconds") is not None else "-" for c in (k, m)]
        symmetry = " / ".join(_difference(c.get("asymmetry")) for c in (k, m)) if "asymmetry" in k else "-"
        lines.append(f"| {s['case']} | {k.get('nodes') or m.get('nodes') or '-'} "
                     f"| {short.get(k['status'], k['status'])} "
                     f"| {short.get(m['status'], m['status'])} | {_iterations(k['iterations'])} "
                     f"| {_iterations(m['iterations'])} | {_difference(s.get('displacement'))} "
                     f"| {_difference(s.get('pressure'))} | {_difference(s.get('reaction'))} | {symmetry} "
                     f"| {seconds[0]} "
                     f"| {seconds[1]} | {'yes' if v['pass'] else 'no'} |")
    errors = [(s["case"], code, s[code]["error"]) for s in summaries for code in CODES
              if s[code]["status"] == "failed" and s[code]["error"]]
    if errors:
        lines += ["", "## Errors", ""]
        lines += [f"- {case} ({code}): `{error.strip().splitlines()[-1][:200]}`" for case, code, error in errors]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--filter", help="regular expression on the case names")
    parser.add_argument("--subset", choices=sorted(SUBSETS), help="a named subset (see SUBSETS)")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per run (default 300)")
    parser.add_argument("--cases-dir", default=sweep_cases.DEFAULT_OUT)
    parser.add_argument("--output", default=os.path.join(HERE, "results.md"))
    parser.add_argument("--snapshots", help="also copy the cases with Kratos' values into this folder (tests)")
    parser.add_argument("--report", action="store_true", help="only rebuild the table from stored results")
    parser.add_argument("--rerun-kratos", action="store_true",
                        help="run Kratos again even where its record of the same case files is stored")
    args = parser.parse_args(argv)
    os.makedirs(RESULTS_DIR, exist_ok=True)
    chosen = sweep_cases.select(args.filter, SUBSETS[args.subset] if args.subset else None)
    if not args.report:
        for i, variant in enumerate(chosen, 1):
            s = run_case(variant, args.cases_dir, args.timeout, args.rerun_kratos)
            line = " | ".join(f"{c}: {s[c]['status']} {_iterations(s[c]['iterations'])}" for c in CODES)
            print(f"[{i}/{len(chosen)}] {variant.name}: {line} | du {_difference(s.get('displacement'))}", flush=True)
            if args.snapshots:
                write_snapshot(variant, args.cases_dir, args.snapshots)
    report(args.output)
    print(f"-> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
