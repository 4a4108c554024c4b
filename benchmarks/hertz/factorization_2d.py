#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 14: what one factorization of a 2D Hertz contact system costs, and why.

Takes one Newton matrix of the case (the converged state of its first load step, contact active,
from ImplicitSolvingStrategy.BuildSystem) and times, alone in this process (CPU seconds,
OMP_NUM_THREADS=1 unless --threads), each sparse direct solver on it:
  - UMFPACK through its C interface (ctypes), split into symbolic analysis, numeric factorization
    and solve, with the fill nnz(L + U) and the flops it reports, for its orderings (AMD/COLAMD,
    METIS, CHOLMOD's choice) and strategies (auto, symmetric, unsymmetric);
  - the same on the displacement block alone (the multiplier rows and columns removed): what the
    saddle-point rows with their zero diagonal cost in pivoting and fill;
  - CHOLMOD (supernodal LL^T) on the symmetric part of the displacement block, KLU, MUMPS and
    PETSc's own LU (through the PETSc plugin), scipy's SuperLU, each as mortarcontact's
    solver: analysis + factorization + solve, then factorization + solve with the analysis kept.
Medians of --repeat. Writes benchmarks/hertz/results_factorization_2d.md.

    python benchmarks/hertz/factorization_2d.py                      # hertz2d_30k
    python benchmarks/hertz/factorization_2d.py --case hertz2d_250k --repeat 1 \
        --output benchmarks/hertz/results_factorization_2d_250k.md
"""
from __future__ import annotations

import argparse
import ctypes
import json
import os
import statistics
import sys
import time

# Before the BLAS that the solvers load.
os.environ["OMP_NUM_THREADS"] = next((a.split("=", 1)[1] for a in sys.argv if a.startswith("--threads=")), "1")
os.environ["OPENBLAS_NUM_THREADS"] = os.environ["OMP_NUM_THREADS"]

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import linear_solvers

import harness

# UMFPACK's C interface (suitesparse/umfpack.h): control and info indices.
CONTROL, INFO = 20, 90
STRATEGY, ORDERING, IRSTEP = 5, 10, 7
LNZ, UNZ, FLOPS, STRATEGY_USED = 43, 44, 42, 18
ORDERINGS = {"AMD / COLAMD (UMFPACK's default)": 1, "METIS": 3, "CHOLMOD (AMD, then METIS if better)": 0}
STRATEGIES = {"auto": 0, "unsymmetric": 1, "symmetric": 3}


def newton_matrix(folder: str):
    """(A, dofs) of the converged first load step: the matrix the next Newton iteration factorizes."""
    analysis = linear_solvers.first_step_analysis(folder)
    root = analysis.solver.GetComputingModelPart().GetRootModelPart()
    analysis.solver.mortar_updater.UpdateNormals(root)
    A, _, dofs = analysis.solver.strategy.BuildSystem(root)
    analysis.Finalize()
    A = sp.csc_matrix(A)
    A.sum_duplicates()
    A.sort_indices()
    return A, dofs


class Umfpack:
    """umfpack_dl_* through ctypes: each phase timed on its own."""

    def __init__(self):
        self.lib = ctypes.CDLL("libumfpack.so.5")
        self.lib.umfpack_dl_defaults.argtypes = [ctypes.c_void_p]

    def run(self, A, b, ordering: int, strategy: int, repeat: int) -> dict:
        lib = self.lib
        control = (ctypes.c_double * CONTROL)()
        info = (ctypes.c_double * INFO)()
        lib.umfpack_dl_defaults(control)
        control[ORDERING], control[STRATEGY], control[IRSTEP] = ordering, strategy, 0
        ap = np.ascontiguousarray(A.indptr, dtype=np.int64)
        ai = np.ascontiguousarray(A.indices, dtype=np.int64)
        ax = np.ascontiguousarray(A.data, dtype=np.float64)
        x = np.zeros(A.shape[0])
        ptr = lambda a: a.ctypes.data_as(ctypes.c_void_p)  # noqa: E731
        times = {"symbolic": [], "numeric": [], "solve": []}
        result = {}
        for _ in range(repeat):
            symbolic, numeric = ctypes.c_void_p(), ctypes.c_void_p()
            t = time.process_time()
            status = lib.umfpack_dl_symbolic(ctypes.c_int64(A.shape[0]), ctypes.c_int64(A.shape[1]), ptr(ap), ptr(ai),
                                             ptr(ax), ctypes.byref(symbolic), control, info)
            times["symbolic"].append(time.process_time() - t)
            if status != 0:
                return {"status": f"symbolic analysis failed (status {status})"}
            result["strategy"] = {1: "unsymmetric", 3: "symmetric"}.get(int(info[STRATEGY_USED]), "?")
            t = time.process_time()
            status = lib.umfpack_dl_numeric(ptr(ap), ptr(ai), ptr(ax), symbolic, ctypes.byref(numeric), control, info)
            times["numeric"].append(time.process_time() - t)
            if status != 0:
                return {"status": f"numeric factorization failed (status {status})"}
            result["fill"], result["flops"] = info[LNZ] + info[UNZ] - A.shape[0], info[FLOPS]
            t = time.process_time()
            lib.umfpack_dl_solve(0, ptr(ap), ptr(ai), ptr(ax), ptr(x), ptr(b), numeric, control, None)
            times["solve"].append(time.process_time() - t)
            lib.umfpack_dl_free_numeric(ctypes.byref(numeric))
            lib.umfpack_dl_free_symbolic(ctypes.byref(symbolic))
        result.update({k: statistics.median(v) for k, v in times.items()})
        result["residual"] = float(np.linalg.norm(b - A @ x) / np.linalg.norm(b))
        result["status"] = "ok"
        return result


def mortarcontact_solver(A, b, settings: dict, repeat: int) -> dict:
    import mortarcontact as mc

    try:
        solver = mc.CreateLinearSolver(mc.Parameters(json.dumps(settings)))
        x, first, _ = linear_solvers.timed(lambda: solver.Solve(A, b))
        again = [linear_solvers.timed(lambda k=k: solver.Solve(linear_solvers.perturbed(A, k), b, initialize=False))[1]
                 for k in range(1, repeat + 1)]
    except (mc.Error, RuntimeError) as error:
        return {"status": f"failed: {str(error).splitlines()[0][:140]}"}
    return {"status": "ok", "first": first, "again": statistics.median(again),
            "residual": float(np.linalg.norm(b - A @ x) / np.linalg.norm(b))}


def superlu(A, b, permc: str, repeat: int) -> dict:
    runs = []
    options = {"SymmetricMode": permc != "COLAMD"}
    for _ in range(repeat):
        lu, seconds, _ = linear_solvers.timed(lambda: spla.splu(A, permc_spec=permc, options=options))
        runs.append(seconds)
    x, solve, _ = linear_solvers.timed(lambda: lu.solve(b))
    return {"status": "ok", "first": statistics.median(runs), "again": None, "solve": solve,
            "fill": lu.L.nnz + lu.U.nnz - A.shape[0], "residual": float(np.linalg.norm(b - A @ x) / np.linalg.norm(b))}


def findings(umf: dict) -> str:
    """What the UMFPACK rows say about where a factorization's time goes."""
    if any(r["status"] != "ok" for r in umf.values()):
        return ""
    amd, metis, unsym, block = umf["A", 1, 0], umf["A", 3, 0], umf["A", 3, 1], umf["K", 3, 0]
    return "\n".join((
        f"- Ordering: METIS against AMD, {metis['flops'] / amd['flops']:.2f} x the flops and "
        f"{metis['fill'] / amd['fill']:.2f} x the fill, {metis['numeric'] / amd['numeric']:.2f} x the numeric time, "
        f"{metis['symbolic'] / amd['symbolic']:.1f} x the symbolic time.",
        f"- Multiplier rows: the whole matrix against its displacement block (METIS), "
        f"{metis['numeric'] / block['numeric']:.2f} x the numeric time, "
        f"{metis['fill'] / block['fill']:.2f} x the fill; "
        f"the unsymmetric strategy (pivoting off the diagonal) would cost {unsym['flops'] / metis['flops']:.1f} x "
        "the flops of the symmetric one UMFPACK chooses.",
        f"- BLAS rate of the numeric factorization (METIS): {metis['flops'] / metis['numeric'] / 1e9:.1f} GFlop/s "
        "on one core.",
    ))


def blas_libraries() -> list[str]:
    with open(f"/proc/{os.getpid()}/maps") as f:
        return sorted({line.split()[-1] for line in f if "blas" in line.lower() and line.split()[-1].startswith("/")})


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", default="hertz2d_30k")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--threads", default="1", help="OMP_NUM_THREADS of the BLAS (pass as --threads=N)")
    parser.add_argument("--cases-dir", default=os.path.join(harness.HERE, "cases"))
    parser.add_argument("--output", default=os.path.join(harness.HERE, "results_factorization_2d.md"))
    args = parser.parse_args()

    A, dofs = newton_matrix(harness.ensure_case(args.case, args.cases_dir))
    n = A.shape[0]
    names = [""] * n
    for equation, _, variable, _ in dofs:
        if equation < n:
            names[equation] = variable
    displacement = np.array([i for i in range(n) if names[i].startswith("DISPLACEMENT")])
    multipliers = n - len(displacement)
    K = A[displacement][:, displacement].tocsc()
    K_symmetric = ((K + K.T) * 0.5).tocsc()
    K_symmetric.sort_indices()
    asymmetry = float(abs(K - K.T).max() / abs(K).max())
    rng = np.random.default_rng(1)
    # Right-hand sides of known solutions: the matrix holds penalty-sized and unit-sized rows, so a
    # random b would give solutions whose residual measures that scaling, not the solver.
    b, b_k = A @ rng.standard_normal(n), K @ rng.standard_normal(K.shape[0])

    umf = {}  # (matrix label, ordering, strategy) -> UMFPACK record, for the findings
    rows = []  # (matrix, solver, ordering / strategy, symbolic, numeric, solve, first, again, fill, flops, residual)
    umfpack = Umfpack()
    for matrix_label, M, rhs in (("A (with multipliers)", A, b), ("K_uu (displacements)", K, b_k)):
        for ordering_label, ordering in ORDERINGS.items():
            for strategy_label, strategy in STRATEGIES.items():
                if ordering != 3 and strategy != 0:
                    continue  # the strategies compared with METIS only
                r = umf[matrix_label[0], ordering, strategy] = umfpack.run(M, rhs, ordering, strategy, args.repeat)
                print(matrix_label, ordering_label, strategy_label, r, flush=True)
                if r["status"] != "ok":
                    rows.append((matrix_label, "UMFPACK", f"{ordering_label}, {strategy_label}", r["status"]))
                    continue
                rows.append((matrix_label, "UMFPACK", f"{ordering_label}, {strategy_label} (used: {r['strategy']})",
                             r["symbolic"], r["numeric"], r["solve"], r["symbolic"] + r["numeric"] + r["solve"],
                             r["numeric"] + r["solve"], r["fill"], r["flops"], r["residual"]))
    solvers = (
        ("A (with multipliers)", A, b, "KLU (AMD, BTF)", {"solver_type": "klu", "reuse_factorization": False}),
        ("A (with multipliers)", A, b, "MUMPS (PETSc plugin)", {"solver_type": "petsc"}),
        ("A (with multipliers)", A, b, "PETSc LU (nested dissection)",
         {"solver_type": "petsc", "petsc_options": {"pc_factor_mat_solver_type": "petsc",
                                                    "pc_factor_mat_ordering_type": "nd"}}),
        ("sym(K_uu)", K_symmetric, b_k, "CHOLMOD (supernodal LL^T)", {"solver_type": "cholmod"}),
        ("sym(K_uu)", K_symmetric, b_k, "MUMPS (PETSc plugin)", {"solver_type": "petsc"}),
    )
    for matrix_label, M, rhs, label, settings in solvers:
        r = mortarcontact_solver(M, rhs, settings, args.repeat)
        print(matrix_label, label, r, flush=True)
        rows.append((matrix_label, label, "its default", r["status"]) if r["status"] != "ok" else
                    (matrix_label, label, "its default", None, None, None, r["first"], r["again"], None, None,
                     r["residual"]))
    for permc in ("COLAMD", "MMD_AT_PLUS_A"):
        r = superlu(A, b, permc, args.repeat)
        print("SuperLU", permc, r, flush=True)
        rows.append(("A (with multipliers)", "SuperLU (scipy)", permc, None, None, r["solve"], r["first"] + r["solve"],
                     None, r["fill"], None, r["residual"]))

    cell = lambda v, f: "" if v is None else format(v, f)  # noqa: E731
    lines = ["| matrix | solver | ordering, strategy | symbolic [s] | numeric [s] | solve [s] "
             "| analysis + factorization + solve [s] | factorization + solve, analysis kept [s] | fill nnz(L+U) "
             "| flops | relative residual |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        if len(row) == 4:
            lines.append(f"| {row[0]} | {row[1]} | {row[2]} | {row[3]} | | | | | | | |")
            continue
        m, s, o, sym, num, sol, first, again, fill, flops, res = row
        lines.append(f"| {m} | {s} | {o} | {cell(sym, '.3f')} | {cell(num, '.3f')} | {cell(sol, '.4f')} "
                     f"| {cell(first, '.3f')} | {cell(again, '.3f')} | {cell(fill, '.3g')} | {cell(flops, '.3g')} "
                     f"| {res:.1e} |")
    text = ("# One factorization of a 2D Hertz contact system\n\n"
            "Generated by `benchmarks/hertz/factorization_2d.py`: the Newton matrix of the converged first load "
            f"step of {args.case} (contact active), {n} equations ({multipliers} contact multipliers), "
            f"{A.nnz} non-zeros; its displacement block K_uu: {K.shape[0]} equations, asymmetry "
            f"max|K - K^T| / max|K| = {asymmetry:.1e} (CHOLMOD gets its symmetric part). CPU seconds of this "
            f"process, OMP_NUM_THREADS={args.threads}, medians of {args.repeat}; fill: nnz(L + U) less the "
            "diagonal counted twice.\n\n"
            f"Machine: {harness.machine_line(int(args.threads))}. BLAS: "
            + ", ".join(f"`{p}`" for p in blas_libraries()) + ".\n\n" + "\n".join(lines) + "\n\n"
            + findings(umf) + "\n")
    harness.write_report(args.output, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
