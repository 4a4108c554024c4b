#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: runs the robustness sweep (sweep_cases.py) with Kratos 10.4 and mortarcontact and
writes the summary table benchmarks/robustness/results.md.

Each case is generated afresh (deterministic), then run twice by each code, each run in its own
subprocess (benchmarks/hertz/case_runner.py, OMP_NUM_THREADS=1, stopped after ``--timeout``
seconds):

- as written (Kratos' default normal_variation, "K0", and the case's tolerances): what a user
  sees. Convergence and Newton iterations per step are compared on these runs.
- tight (``TIGHT_KRATOS``, ``TIGHT_OURS``): tolerances 1e-12 relative / 1e-20 absolute, 50
  iterations at most, and normal_variation "no_derivatives_computation_with_normal_update" ("K1":
  Kratos recomputes the nodal normals before every iteration, as mortarcontact always does; K0
  freezes them after the first iteration, so that its converged answer depends on its own first
  iterate and on the load step); Kratos with search_factor 10 (``KRATOS_TIGHT_SEARCH_FACTOR``).
  The agreement of the results is measured on these runs: both
  converged to the same discrete problem, differences are differences of the discretisation.

A run that raises, does not converge in a step or times out is recorded and the sweep goes on.
Kratos' records are reused while the case files and the run's overrides are unchanged
(``--rerun-kratos`` runs it anyway). Per case the raw records go to results/<case>/<run>.json and
the comparison to results/<case>.json (both ignored by git); results.md is rebuilt from every
stored comparison, so a ``--filter`` run updates its rows and keeps the others.

Compared, node by node (both codes read the same mesh: the gmsh file, and for Kratos the mdpa
mesh_files.write_kratos_mdpa makes of it): the displacements of all nodes (largest
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
#: ProjectParameters.json overrides of the tight runs (case_runner.py --set): the case's
#: contact_residual_criterion for Kratos, whose residual is that of the previous iterate with the
#: normals of the current one; mortarcontact's residual is that of the current iterate with the
#: normals of the previous one, which vanishes before the normals settle, so the increments
#: (contact_and_criterion) must be small too.
TIGHT_TOLERANCES = {f"{block}_{kind}_tolerance": value for block in ("displacement", "residual")
                    for kind, value in (("relative", 1e-12), ("absolute", 1e-20))}
TIGHT_COMMON = ["solver_settings.max_iteration=50",
                'processes.contact_process_list.0.Parameters.normal_variation="no_derivatives_computation_with_normal_update"']
#: Kratos accepts a step when the relative OR the absolute bound holds, for the displacements and
#: for the multipliers (contact_settings.contact_*, 1e-4 / 1e-9 by default). With the absolute
#: bound at 1e-20 its tight runs of 3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm stopped
#: at |r|^2/|r0|^2 = 8e-12 (step 3), 3.8e-6 away from the solution it converges to, which ours
#: matches to 1e-9 (README.md, agreement). So its absolute bounds are 1e-28, multipliers included:
#: above the round-off floor of the cases whose first residual is already tiny (3e-30 on
#: 2d_quad_flat_r0.5_overhang-none_gap_disp_4steps_penalty), which 1e-30 kept from converging.
KRATOS_TIGHT_ABSOLUTE = 1e-28
#: Kratos takes as candidates the master faces whose centre lies within search_factor x the slave
#: face's half-size of the slave's centre, whatever the master's own size. With the default 3.5 a
#: master face more than about 2.5 times the slave's is missed where a slave face slides past the
#: edge of the master face under it (a slave node that started over a master node), in every step:
#: the overlap is left out of the nodal area and the pressure there is too high by that share
#: (README.md, "A finer slave node over a master node"). Our search reaches every master whose
#: bounding ball meets the search ball. 10 covers the sweep's size ratios (0.25 .. 4).
KRATOS_TIGHT_SEARCH_FACTOR = 10.0
TIGHT_KRATOS = [f"solver_settings.{prefix}{block}_{kind}_tolerance={value:g}"
                for prefix in ("", "contact_settings.contact_") for block in ("displacement", "residual")
                for kind, value in (("relative", 1e-12), ("absolute", KRATOS_TIGHT_ABSOLUTE))] + TIGHT_COMMON + [
    f"processes.contact_process_list.0.Parameters.search_parameters.search_factor={KRATOS_TIGHT_SEARCH_FACTOR:g}"]
TIGHT_OURS = ([f"solver_settings.{prefix}{key}={value:g}" for prefix in ("", "contact_settings.contact_")
               for key, value in TIGHT_TOLERANCES.items()] + TIGHT_COMMON
              + ['solver_settings.convergence_criterion="contact_and_criterion"'])
#: run name -> (code, overrides)
RUNS = {"kratos": ("kratos", []), "mortarcontact": ("mortarcontact", []),
        "kratos_tight": ("kratos", TIGHT_KRATOS), "mortarcontact_tight": ("mortarcontact", TIGHT_OURS)}
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
       "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty",
       "2d_quad_flat_r0.5_overhang-both_gap_disp_4steps_alm"],
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
        elif formulation == "fric":  # the whole traction vector, normal and tangential
            p = [scale * c for c in node.get("vector_lm") or [0.0, 0.0, 0.0]]
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


def differences(variant, ours: dict, kratos: dict) -> dict:
    """Relative differences of displacements, pressures and bottom reaction ({} unless both runs
    have finite results, converged or not)."""
    if not all("displacements" in r and status(r) != "failed" for r in (ours, kratos)):
        return {}
    return {"displacement": _relative(ours["displacements"], kratos["displacements"]),
            "pressure": _relative(pressures(ours, variant.formulation), pressures(kratos, variant.formulation)),
            "reaction": _relative({"bottom": ours["reaction_totals"]["DISPLACEMENT_bottom"]},
                                  {"bottom": kratos["reaction_totals"]["DISPLACEMENT_bottom"]})}


def compare(variant, records: dict) -> dict:
    """Per run its status and iterations; the differences of the tight runs ("tight") and of the
    runs as written ("as_written")."""
    summary = {"case": variant.name, "measured": time.strftime("%Y-%m-%d %H:%M")}
    for run, record in records.items():
        summary[run] = {"status": status(record), "error": (record.get("error") or "")[-300:],
                        "iterations": [s["iterations"] for s in record.get("steps", [])],
                        "converged": [s["converged"] for s in record.get("steps", [])],
                        "seconds": record.get("analysis_seconds"), "wall_seconds": record.get("wall_seconds"),
                        "nodes": record.get("nodes")}
        if variant.symmetric and summary[run]["status"] != "failed" and "reaction_totals" in record:
            reaction = record["reaction_totals"]["DISPLACEMENT_bottom"]
            lateral = math.hypot(*reaction[:variant.dim - 1])
            summary[run]["asymmetry"] = lateral / (math.hypot(*reaction) or 1.0)
    if "kratos_tight" in records:
        summary["tight"] = differences(variant, records["mortarcontact_tight"], records["kratos_tight"])
    summary["as_written"] = differences(variant, records["mortarcontact"], records["kratos"])
    return summary


def runs_of(variant) -> dict:
    """The runs of a case: the frictional ones are compared as written only (both codes to the
    case's 1e-6 tolerances), the question there being who converges and in how many iterations."""
    return {run: spec for run, spec in RUNS.items() if not (variant.frictional and run.endswith("_tight"))}


def _case_hash(folder: str) -> str:
    digest = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        digest.update(name.encode())
        with open(os.path.join(folder, name), "rb") as f:
            digest.update(f.read())
    return digest.hexdigest()


def run_case(variant, cases_dir: str, timeout: float, rerun_kratos: bool) -> dict:
    """Runs both codes on one case, as written and tight; Kratos' stored record is reused when it
    was made from the same case files with the same overrides (Kratos 10.4 does not change, so
    only mortarcontact needs re-measuring)."""
    folder = sweep_cases.write_case(variant, cases_dir)
    files = _case_hash(folder)
    records = {}
    for run, (code, overrides) in runs_of(variant).items():
        output = os.path.join(RESULTS_DIR, variant.name, f"{run}.json")
        if code == "kratos" and not rerun_kratos and os.path.exists(output):
            with open(output) as f:
                stored = json.load(f)
            if (stored.get("case_files") == files and stored.get("overrides", []) == overrides
                    and stored.get("status") != "timeout"):
                records[run] = stored
                continue
        python = harness.kratos_python() if code == "kratos" else sys.executable
        records[run] = harness.run_once(code, folder, output, threads=1, python=python, timeout=timeout,
                                        all_nodes=True, overrides=overrides)
        records[run].update(case_files=files, overrides=overrides)
        with open(output, "w") as f:
            json.dump(records[run], f)
    summary = compare(variant, records)
    with open(os.path.join(RESULTS_DIR, f"{variant.name}.json"), "w") as f:
        json.dump(summary, f, indent=1)
    return summary


def write_snapshot(variant, cases_dir: str, target: str) -> None:
    """Copies the case files into ``target/<case>/`` with Kratos' values (kratos_10_4.json) for
    tests/python/test_robustness_sweep.py: convergence and iterations per step as written, and the
    results of the tight run with its overrides."""
    records = {}
    for run in ("kratos", "kratos_tight"):
        with open(os.path.join(RESULTS_DIR, variant.name, f"{run}.json")) as f:
            records[run] = json.load(f)
    folder = os.path.join(target, variant.name)
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.join(cases_dir, variant.name), folder)
    written, tight = records["kratos"], records["kratos_tight"]
    snapshot = {"kratos": KRATOS_VERSION, "status": status(written), "formulation": variant.formulation,
                "iterations": [s["iterations"] for s in written["steps"]],
                "converged": [s["converged"] for s in written["steps"]],
                "tight": {"overrides": TIGHT_OURS, "status": status(tight),
                          "iterations": [s["iterations"] for s in tight["steps"]],
                          "displacements": tight["displacements"], "pressures": pressures(tight, variant.formulation),
                          "reaction_bottom": tight["reaction_totals"]["DISPLACEMENT_bottom"]}}
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
    tight = s.get("tight") or {}
    within = all(tight.get(key) is not None and tight[key] <= TOLERANCE
                 for key in ("displacement", "pressure", "reaction"))
    fewer = (m["status"] == "ok" and len(m["iterations"]) == len(k["iterations"])
             and all(a <= b for a, b in zip(m["iterations"], k["iterations"])))
    return {"kratos_converges": k["status"] == "ok", "we_converge": m["status"] == "ok",
            "iterations_ok": fewer, "within": within,
            "tight_converge": all(s.get(run, {}).get("status") == "ok"
                                  for run in ("kratos_tight", "mortarcontact_tight")),
            "pass": k["status"] == "ok" and m["status"] == "ok" and fewer and within}


SHORT = {"ok": "ok", "not converged": "nc", "failed": "failed", "timeout": "timeout"}


def _run_cell(run: dict) -> str:
    """Iterations per step, prefixed by the status unless converged."""
    its = _iterations(run["iterations"])
    return its if run["status"] == "ok" else f"{SHORT.get(run['status'], run['status'])} {its}".replace(" -", "")


def report(path: str) -> None:
    names = [v.name for v in sweep_cases.variants() if not v.frictional]
    summaries = []
    for name in names:
        stored = os.path.join(RESULTS_DIR, f"{name}.json")
        if os.path.exists(stored):
            with open(stored) as f:
                summaries.append(json.load(f))
    if not summaries:  # only frictional cases run so far
        return
    verdicts = [verdict(s) for s in summaries]
    count = {key: sum(v[key] for v in verdicts) for key in ("kratos_converges", "we_converge", "iterations_ok",
                                                              "within", "tight_converge", "pass")}
    both = sum(v["kratos_converges"] and v["we_converge"] for v in verdicts)
    solved = [v for v in verdicts if v["kratos_converges"]]
    wall = {code: sum(s[run]["wall_seconds"] or 0.0 for s in summaries for run, (c, _) in RUNS.items() if c == code)
            for code in CODES}
    lines = [
        "# Robustness sweep: mortarcontact against Kratos 10.4",
        "",
        f"Generated by `benchmarks/robustness/run_sweep.py` (`make bench-robustness`); cases from "
        f"`sweep_cases.py` (its docstring describes the variants). Kratos {KRATOS_VERSION}, one subprocess per "
        "run, OMP_NUM_THREADS=1. Measured "
        f"{min(s['measured'] for s in summaries)} to {max(s['measured'] for s in summaries)}; the runs "
        f"(subprocess wall time, both runs of a code) add up to {wall['kratos'] / 60.0:.1f} min for Kratos and "
        f"{wall['mortarcontact'] / 60.0:.1f} min for mortarcontact. What the differences have in common, their "
        "causes and the smallest case of each: [README.md](README.md).",
        "",
        "Each case is run twice by each code. **As written** (Kratos' default normal_variation, called K0, and the "
        "case's contact_residual_criterion with relative 1e-6, absolute 1e-12, 30 iterations at most): "
        "convergence and Newton iterations, what a user sees. **Tight** (relative 1e-12 for displacements and "
        f"multipliers, absolute 1e-20 for ours and {KRATOS_TIGHT_ABSOLUTE:g} for Kratos, whose absolute bound "
        "alone ends a step, 50 iterations at most; Kratos with normal_variation "
        "`no_derivatives_computation_with_normal_update`, called "
        "K1, which recomputes the nodal normals before every iteration as mortarcontact always does, and "
        f"search_factor {KRATOS_TIGHT_SEARCH_FACTOR:g}, with which its search finds every master face a slave "
        "face can reach): the agreement of the results. K0 freezes the normals after its first iteration, so "
        "its answer depends on its own first iterate and on the load step (benchmarks/hertz/results_parity.md); "
        "it is no reference below 1e-6. Kratos keeps the case's residual criterion, which measures the residual "
        "of the previous iterate with the current normals; ours measures the current iterate with the normals of "
        "the previous one, which vanishes before the normals settle, so our tight runs use contact_and_criterion "
        "(the same tolerances on the increments too, multipliers included).",
        "",
        f"- cases: {len(summaries)}",
        f"- Kratos (K0) converges: {count['kratos_converges']}",
        f"- we converge: {count['we_converge']} (on {both} of the {count['kratos_converges']} where Kratos does)",
        f"- Newton iterations <= Kratos' (K0) in every step: {count['iterations_ok']}"
        f" ({sum(v['iterations_ok'] for v in solved)} of the {len(solved)})",
        f"- within {TOLERANCE:g} of tight K1 (displacements, pressures and reaction, our code at the same "
        f"tolerances): {count['within']} ({sum(v['within'] for v in solved)} of the {len(solved)}); both tight "
        f"runs converge on {count['tight_converge']}",
        f"- all of these (the goal): {count['pass']}",
        "",
        "Columns: converged as written (K = Kratos K0, M = mortarcontact: ok, nc = not converged in some step, "
        "failed, timeout); Newton iterations per step as written (`2x3` = three steps of 2); `vs K0`: the largest "
        "of the three relative differences between the runs as written; iterations of the tight runs (K1, M), "
        "prefixed by the status unless converged; du, dp, dR: largest relative difference between the tight "
        "runs of the displacements (all nodes), of the slave contact pressures and of the total reaction at "
        "the clamped bottom; sym K1 / M: on the mirror-symmetric cases, each tight run's lateral bottom "
        "reaction over the total (zero for an exactly symmetric solution); analysis time as written (s, "
        "imports excluded); goal: converged, no more iterations than K0 in every step and within "
        f"{TOLERANCE:g} of tight K1.",
        "",
        "| case | nodes | K | M | iterations K | iterations M | vs K0 | tight K1 | tight M | du | dp | dR "
        "| sym K1 / M | t K | t M | goal |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for s, v in zip(summaries, verdicts):
        k, m = s["kratos"], s["mortarcontact"]
        kt, mt = s["kratos_tight"], s["mortarcontact_tight"]
        tight, written = s.get("tight") or {}, s.get("as_written") or {}
        seconds = [f"{c['seconds']:.2f}" if c.get("seconds") is not None else "-" for c in (k, m)]
        symmetry = " / ".join(_difference(c.get("asymmetry")) for c in (kt, mt)) if "asymmetry" in kt else "-"
        as_written = _difference(max(written.values())) if written else "-"
        lines.append(f"| {s['case']} | {k.get('nodes') or m.get('nodes') or '-'} "
                     f"| {SHORT.get(k['status'], k['status'])} "
                     f"| {SHORT.get(m['status'], m['status'])} | {_iterations(k['iterations'])} "
                     f"| {_iterations(m['iterations'])} | {as_written} | {_run_cell(kt)} | {_run_cell(mt)} "
                     f"| {_difference(tight.get('displacement'))} | {_difference(tight.get('pressure'))} "
                     f"| {_difference(tight.get('reaction'))} | {symmetry} | {seconds[0]} "
                     f"| {seconds[1]} | {'yes' if v['pass'] else 'no'} |")
    _write_report(path, lines, summaries, RUNS)


def _write_report(path: str, lines: list[str], summaries: list[dict], runs) -> None:
    """Writes ``lines`` and, after them, the last line of each failed run's error."""
    errors = [(s["case"], run, s[run]["error"]) for s in summaries for run in runs
              if run in s and s[run]["status"] == "failed" and s[run]["error"]]
    if errors:
        lines += ["", "## Errors", ""]
        lines += [f"- {case} ({run}): `{error.strip().splitlines()[-1][:200]}`" for case, run, error in errors]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def report_frictional(path: str) -> None:
    """The frictional cases (issue 12): convergence, Newton iterations per step and the difference
    of the results as written, with the cases where Kratos fails and we converge listed first."""
    summaries = []
    for v in sweep_cases.variants():
        stored = os.path.join(RESULTS_DIR, f"{v.name}.json")
        if v.frictional and os.path.exists(stored):
            with open(stored) as f:
                summaries.append(json.load(f))
    if not summaries:
        return
    verdicts = [verdict(s) for s in summaries]
    k_ok = sum(v["kratos_converges"] for v in verdicts)
    m_ok = sum(v["we_converge"] for v in verdicts)
    only_us = [s["case"] for s, v in zip(summaries, verdicts) if v["we_converge"] and not v["kratos_converges"]]
    only_k = [s["case"] for s, v in zip(summaries, verdicts) if v["kratos_converges"] and not v["we_converge"]]
    both = [(s, v) for s, v in zip(summaries, verdicts) if v["kratos_converges"] and v["we_converge"]]
    total = {code: sum(sum(s[code]["iterations"]) for s, _ in both) for code in CODES}
    fewer = sum(v["iterations_ok"] for _, v in both)
    wall = {code: sum(s[code]["wall_seconds"] or 0.0 for s in summaries) for code in CODES}
    lines = [
        "# Frictional robustness sweep: mortarcontact against Kratos 10.4 (issue 12)",
        "",
        f"Generated by `benchmarks/robustness/run_sweep.py --filter _fric_` from the frictional variants of "
        f"`sweep_cases.py` (`frictional_variants`): ALMContactFrictional, static indentation in 4 steps (t <= 0.5) "
        f"followed by 4 steps in which the top is held at its depth and moved along x by {sweep_cases.SHIFT:g} "
        f"(about the approach: gross sliding for small mu, partial slip for large mu). Each case is run once by "
        f"each code as written (contact_residual_criterion, relative 1e-6, absolute 1e-12, 30 iterations at "
        f"most, Kratos' default normal_variation), Kratos {KRATOS_VERSION}, one subprocess per run, "
        f"OMP_NUM_THREADS=1. Measured {min(s['measured'] for s in summaries)} to "
        f"{max(s['measured'] for s in summaries)}; the runs add up to {wall['kratos'] / 60.0:.1f} min for Kratos "
        f"and {wall['mortarcontact'] / 60.0:.1f} min for mortarcontact (wall time on a shared, loaded machine).",
        "",
        f"- cases: {len(summaries)}",
        f"- Kratos converges in every step: {k_ok}; we do: {m_ok}",
        f"- Kratos fails and we converge: {len(only_us)}" + (f" ({', '.join(only_us)})" if only_us else ""),
        f"- we fail and Kratos converges: {len(only_k)}" + (f" ({', '.join(only_k)})" if only_k else ""),
        f"- where both converge ({len(both)}): Newton iterations in total {total['mortarcontact']} (ours) against "
        f"{total['kratos']} (Kratos); no more iterations than Kratos in every step on {fewer}",
        "",
        "Columns: converged (K = Kratos, M = mortarcontact: ok, nc = not converged in some step, failed, "
        "timeout); Newton iterations per step (`2x3` = three steps of 2; a step that did not converge counts its "
        "30); du, dt, dR: largest relative difference between the two codes' results of the displacements (all "
        "nodes), of the slave traction vectors (SCALE_FACTOR times VECTOR_LAGRANGE_MULTIPLIER: normal and "
        "tangential) and of the total reaction at the clamped bottom, where both codes converge in every step; "
        "analysis time (s, imports excluded).",
        "",
        "| case | nodes | K | M | iterations K | iterations M | du | dt | dR | t K | t M |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    order = sorted(zip(summaries, verdicts), key=lambda sv: (not (sv[1]["we_converge"] and not
                                                                   sv[1]["kratos_converges"]), sv[0]["case"]))
    for s, _ in order:
        k, m = s["kratos"], s["mortarcontact"]
        written = (s.get("as_written") or {}) if k["status"] == m["status"] == "ok" else {}
        seconds = [f"{c['seconds']:.2f}" if c.get("seconds") is not None else "-" for c in (k, m)]
        lines.append(f"| {s['case']} | {k.get('nodes') or m.get('nodes') or '-'} "
                     f"| {SHORT.get(k['status'], k['status'])} | {SHORT.get(m['status'], m['status'])} "
                     f"| {_iterations(k['iterations'])} | {_iterations(m['iterations'])} "
                     f"| {_difference(written.get('displacement'))} | {_difference(written.get('pressure'))} "
                     f"| {_difference(written.get('reaction'))} | {seconds[0]} | {seconds[1]} |")
    _write_report(path, lines, summaries, CODES)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--filter", help="regular expression on the case names")
    parser.add_argument("--subset", choices=sorted(SUBSETS), help="a named subset (see SUBSETS)")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per run (default 300)")
    parser.add_argument("--cases-dir", default=sweep_cases.DEFAULT_OUT)
    parser.add_argument("--output", default=os.path.join(HERE, "results.md"))
    parser.add_argument("--friction-output", default=os.path.join(HERE, "results_friction.md"))
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
            line = " | ".join(f"{run}: {_run_cell(s[run])}" for run in runs_of(variant))
            tight = s.get("tight") or {}
            print(f"[{i}/{len(chosen)}] {variant.name}: {line} | tight du {_difference(tight.get('displacement'))} "
                  f"dp {_difference(tight.get('pressure'))}", flush=True)
            if args.snapshots:
                write_snapshot(variant, args.cases_dir, args.snapshots)
    report(args.output)
    report_frictional(args.friction_output)
    print(f"-> {args.output}, {args.friction_output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
