#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 14, "factorize better": the sparse direct solvers on the contact systems of the Hertz cases.

For each case, one load step is run with the default settings and its last Newton system (contact
active) is taken; every solver then factorizes it: first with the symbolic analysis (orderings:
METIS above 5000 equations for UMFPACK, each library's default otherwise), then again with the
analysis reused, as within a Newton loop whose pattern does not change (medians of --repeat).
Times are CPU seconds of this process (OMP_NUM_THREADS=1: one core), which a loaded machine
distorts less than wall time; the wall time is in the JSON record. CHOLMOD needs a symmetric
positive definite matrix: on a contact system it is reported with the matrix's asymmetry.

    python benchmarks/hertz/linear_solvers.py                      # hertz3d_15k, hertz2d_30k
    python benchmarks/hertz/linear_solvers.py --cases hertz2d_100k,hertz3d_50k --repeat 2
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")  # before the BLAS that the solvers load

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mortarcontact.cases.hertz import load_reference

import harness

#: (label, linear_solver_settings); the factorization is never kept between the timed solves.
SOLVERS = (
    ("UMFPACK", {"solver_type": "umfpack", "reuse_factorization": False}),
    ("KLU", {"solver_type": "klu", "reuse_factorization": False}),
    ("Eigen SparseLU (METIS)", {"solver_type": "sparse_lu_eigen", "ordering": "metis"}),
    ("CHOLMOD (supernodal)", {"solver_type": "cholmod"}),
    ("MUMPS (PETSc plugin)", {"solver_type": "petsc"}),
)


def first_step_analysis(folder: str):
    """The case's analysis after its first load step (contact active), not finalized yet."""
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    params = read_project_parameters(os.path.join(folder, "ProjectParameters.json"))
    problem = params["problem_data"]
    step = params["solver_settings"]["time_stepping"]["time_step"].GetDouble()
    problem["end_time"].SetDouble(problem["start_time"].GetDouble() + step)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False, case_dir=folder)
    analysis.Initialize()
    analysis.RunSolutionLoop()
    return analysis


def contact_system(folder: str):
    """The last Newton system of the case's first load step, with contact active."""
    analysis = first_step_analysis(folder)
    A = analysis.solver.strategy.GetBuilderAndSolver().GetSystemMatrix().tocsc()  # Finalize frees it
    analysis.Finalize()
    return A


def asymmetry(A) -> float:
    """max |a_ij - a_ji| / max |a_ij|."""
    difference = abs(A - A.T)
    return float(difference.max() / abs(A).max()) if difference.nnz else 0.0


def perturbed(A, k: int):
    B = A.copy()
    B.setdiag(B.diagonal() * (1.0 + 1e-12 * k))
    return B


def timed(solve):
    wall, cpu = time.perf_counter(), time.process_time()
    x = solve()
    return x, time.process_time() - cpu, time.perf_counter() - wall


#: A solver whose first solve takes this many times UMFPACK's is not timed again (KLU on 3D).
SLOW = 5.0


def bench_solver(A, b, settings: dict, repeat: int, skew: float, reference_cpu: float | None) -> dict:
    import mortarcontact as mc

    if settings["solver_type"] == "cholmod" and skew > 1e-12:
        return {"status": f"not applicable: the matrix is not symmetric (asymmetry {skew:.1e})"}
    try:
        solver = mc.CreateLinearSolver(mc.Parameters(json.dumps(settings)))
        x, first_cpu, first_wall = timed(lambda: solver.Solve(A, b))
        if reference_cpu is not None and first_cpu > SLOW * reference_cpu:
            repeat = 0
        # The same pattern with other values (diagonal scaled by 1 + 1e-12 k): a solver that
        # skips an unchanged matrix still factorizes each of them.
        again = [timed(lambda k=k: solver.Solve(perturbed(A, k), b, initialize=False)) for k in range(1, repeat + 1)]
    except (mc.Error, RuntimeError) as error:  # e.g. no PETSc plugin in this build
        return {"status": f"failed: {str(error).splitlines()[0][:160]}"}
    residual = float(np.linalg.norm(b - A @ x) / np.linalg.norm(b))
    return {"status": "ok", "name": solver.Name(), "first_cpu": first_cpu, "first_wall": first_wall,
            "again_cpu": statistics.median(c for _, c, _ in again) if again else None,
            "again_wall": statistics.median(w for _, _, w in again) if again else None, "residual": residual}


def run_case(name: str, cases_dir: str, repeat: int) -> dict:
    folder = harness.ensure_case(name, cases_dir)
    A = contact_system(folder)
    b = A @ np.ones(A.shape[0])
    skew = asymmetry(A)
    result = {"case": name, "dofs": load_reference(folder)["counts"]["dofs"], "equations": A.shape[0],
              "nonzeros": int(A.nnz), "asymmetry": skew, "solvers": {}}
    reference = None
    for label, settings in SOLVERS:
        result["solvers"][label] = bench_solver(A, b, settings, repeat, skew, reference)
        if reference is None and result["solvers"][label]["status"] == "ok":
            reference = result["solvers"][label]["first_cpu"]
        print(name, label, result["solvers"][label], flush=True)
    return result


def table(results: list[dict]) -> str:
    lines = ["| case | equations | non-zeros | solver | analysis + factorization + solve [s] "
             "| factorization + solve, analysis reused [s] | relative residual |",
             "|---|---|---|---|---|---|---|"]
    for r in results:
        for label, s in r["solvers"].items():
            head = f"| {r['case']} | {r['equations']} | {r['nonzeros']} | {label} "
            if s["status"] != "ok":
                lines.append(head + f"| {s['status']} | | |")
                continue
            again = f"{s['again_cpu']:.3f}" if s["again_cpu"] is not None else f"not repeated (> {SLOW:g} x UMFPACK)"
            lines.append(head + f"| {s['first_cpu']:.3f} | {again} | {s['residual']:.1e} |")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", default="hertz3d_15k,hertz2d_30k", help="comma-separated Hertz case names")
    parser.add_argument("--repeat", type=int, default=3, help="factorizations with the analysis reused (median)")
    parser.add_argument("--cases-dir", default=os.path.join(harness.HERE, "cases"))
    parser.add_argument("--output", default=os.path.join(harness.HERE, "results_linear_solvers.md"))
    args = parser.parse_args()
    results = [run_case(name, args.cases_dir, args.repeat) for name in args.cases.split(",")]
    os.makedirs(harness.RESULTS_DIR, exist_ok=True)
    with open(os.path.join(harness.RESULTS_DIR, "linear_solvers.json"), "w") as f:
        json.dump(results, f, indent=1)
    text = ("# Sparse direct solvers on the Hertz contact systems\n\n"
            "Generated by `benchmarks/hertz/linear_solvers.py`: the last Newton system of the first load step "
            "of each case (contact active), factorized by each solver; CPU seconds on one core "
            f"(OMP_NUM_THREADS=1), medians of {args.repeat} factorizations with the analysis reused.\n\n"
            f"Machine: {harness.machine_line(1)}.\n\n" + table(results) + "\n")
    harness.write_report(args.output, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
