#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 14, 3D: why the field split's Krylov iterations grow with the contact zone, and what a
preconditioner that condenses the contact constraints does instead. A study for the design of the
next 3D preconditioner, on Newton systems of the Hertz spheres; not run by `make bench`.

The default 3D solver (PETSc field split, lower Schur factorization) preconditions the multiplier
block with S = C - B diag(K)^-1 B^T ("selfp"). Its inverse is local, while the multipliers' true
Schur complement C - B K^-1 B^T is the interface compliance of both bodies, an operator whose
condition number grows with the contact zone measured in elements: the FGMRES iterations grow
with it (benchmarks/hertz/results_3d_multigrid.md).

The condensed preconditioner eliminates, at each active slave node j, its multiplier together
with one of its displacement components c(j) (the one along which the normal is largest): the
multiplier appears in the rows of node j alone through the diagonal dual-mortar weight k D_jj n_c
(L below), and the constraint row of node j depends on u_c(j) through G_jj = k D_jj n_c plus
derivative terms of the normals and of D, M (off-diagonal in G, 1e-4 of the diagonal here). With
G approximated by its diagonal, the eliminated block has the sparse inverse

    P = [[0, G_d^-1], [L_d^-1, -L_d^-1 K_cc G_d^-1]]      (pivot displacements, then multipliers)

and the remaining unknowns (displacements only: inactive multipliers are eliminated by their
diagonal) carry S = A_rr - A_rp P A_pr, the stiffness of the two bodies tied in the normal
direction at the active nodes, which algebraic multigrid handles as it handles elasticity. One
application: y = P r_p; z_r = AMG(S)(r_r - A_rp y); z_p = P (r_p - A_pr z_r).

Both preconditioners use the same multigrid here (pyamg's smoothed aggregation with the rigid-body
modes, one V-cycle; BoomerAMG in the solver itself), GMRES to 1e-8, so the counts compare the
treatments of the contact constraints, not the multigrids. In the solver the field split runs
BoomerAMG, which does better on the displacement block: 24 iterations per solve on hertz3d_15k,
28.5 on hertz3d_600k; PETSc's GAMG on the condensed system (rigid-body modes, threshold 0.01) took
17 on hertz3d_15k at three times the CPU of the whole run, its set-up at every Newton iteration
(issue 14, 2026-11-28). Needs pyamg (`pip install pyamg`); it is not a dependency of mortarcontact.

    python benchmarks/hertz/condensed_preconditioner.py                       # hertz3d_15k, hertz3d_50k
    python benchmarks/hertz/condensed_preconditioner.py --cases hertz3d_150k --states 2:2,4:2
"""
from __future__ import annotations

import argparse
import os
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import harness

MULTIPLIER = "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"
COMPONENTS = ("DISPLACEMENT_X", "DISPLACEMENT_Y", "DISPLACEMENT_Z")


def newton_system(folder: str, step: int, iterations: int) -> dict:
    """The Newton system after `iterations` iterations of load step `step`, on the free DoFs."""
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    params = read_project_parameters(os.path.join(folder, "ProjectParameters.json"))
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False, case_dir=folder,
                                           stop_on_non_convergence=False)
    analysis.Initialize()
    analysis.OpenStep(step)
    analysis.solver.strategy.SetMaxIterationNumber(iterations)
    analysis.solver.SolveSolutionStep()
    root = analysis.solver.GetComputingModelPart().GetRootModelPart()
    analysis.solver.mortar_updater.UpdateNormals(root)
    A, b, dofs = analysis.solver.strategy.BuildSystem(root)
    free = [d for d in dofs if not d[3]]
    rows = np.array([d[0] for d in free])
    normal = mc.GetVariable("NORMAL")
    slave = {n.Id: (n.Is(mc.ACTIVE), np.array(n.GetSolutionStepValue(normal)))
             for n in root.GetSubModelPart("Contact_slave").Nodes}
    return {"A": A.tocsr()[rows][:, rows].tocsr(), "b": np.asarray(b)[rows],
            "dofs": [(d[1], d[2]) for d in free], "slave": slave,
            "coords": {n.Id: np.array([n.X0, n.Y0, n.Z0]) for n in root.Nodes}}


def rigid_body_modes(system: dict, rows: np.ndarray) -> np.ndarray:
    modes = np.zeros((len(rows), 6))
    for k, i in enumerate(rows):
        node, variable = system["dofs"][i]
        c = COMPONENTS.index(variable)
        modes[k, c] = 1.0
        modes[k, 3:] = [np.cross(e, system["coords"][node])[c] for e in np.eye(3)]
    return modes


def gmres_iterations(A, b, M) -> tuple[int, float]:
    count = [0]
    x, info = spla.gmres(A, b, M=M, rtol=1e-8, restart=300, maxiter=1000,
                         callback=lambda _: count.__setitem__(0, count[0] + 1), callback_type="pr_norm")
    return (count[0] if info == 0 else -1), float(np.linalg.norm(b - A @ x) / np.linalg.norm(b))


def field_split(system: dict):
    """Lower block factorization: multigrid on the displacements, Jacobi on the selfp Schur."""
    import pyamg

    A = system["A"]
    lm = np.array([v == MULTIPLIER for _, v in system["dofs"]])
    u, m = np.where(~lm)[0], np.where(lm)[0]
    Auu, Amu, Aum = A[u][:, u].tocsr(), A[m][:, u].tocsr(), A[m][:, m].tocsr()
    selfp = (Aum - Amu @ sp.diags(1.0 / Auu.diagonal()) @ A[u][:, m]).diagonal()
    amg = pyamg.smoothed_aggregation_solver(Auu, B=rigid_body_modes(system, u), max_coarse=500)

    def apply(r):
        z = np.empty_like(r)
        z[u] = amg.solve(r[u], tol=1e-30, maxiter=1)
        z[m] = (r[m] - Amu @ z[u]) / selfp
        return z

    return spla.LinearOperator(A.shape, apply)


def condensed(system: dict, exact: bool = False):
    """The contact constraints eliminated with their pivot displacements (module docstring)."""
    import pyamg

    A, where = system["A"], {dof: i for i, dof in enumerate(system["dofs"])}
    pivots, multipliers, inactive = [], [], []
    for node, (active, normal) in system["slave"].items():
        if (node, MULTIPLIER) not in where:
            continue
        if not active:
            inactive.append(where[(node, MULTIPLIER)])
            continue
        pivots.append(max((abs(normal[c]), where[(node, v)]) for c, v in enumerate(COMPONENTS)
                          if (node, v) in where)[1])
        multipliers.append(where[(node, MULTIPLIER)])
    na = len(pivots)
    p = np.array(pivots + multipliers + inactive, dtype=int)
    keep = np.ones(A.shape[0], bool)
    keep[p] = False
    r = np.where(keep)[0]
    App = A[p][:, p].tocsr()
    L, G = App[:na, na:2 * na].diagonal(), App[na:2 * na, :na].diagonal()
    Linv, Ginv = sp.diags(1.0 / L), sp.diags(1.0 / G)
    P = sp.bmat([[None, Ginv, None], [Linv, -Linv @ App[:na, :na] @ Ginv, None],
                 [None, None, sp.diags(1.0 / App[2 * na:, 2 * na:].diagonal())]]).tocsr()
    Arp, Apr = A[r][:, p].tocsr(), A[p][:, r].tocsr()
    S = (A[r][:, r] - Arp @ P @ Apr).tocsc()
    G_off = App[na:2 * na, :na] - sp.diags(G)
    stats = {"condensed unknowns": S.shape[0], "G_off": abs(G_off).max() / abs(G).min() if G_off.nnz else 0.0,
             "asymmetry": sp.linalg.norm(S - S.T) / sp.linalg.norm(S)}
    if exact:
        solve = spla.factorized(S)
    else:
        amg = pyamg.smoothed_aggregation_solver(S.tocsr(), B=rigid_body_modes(system, r), max_coarse=500)
        solve = lambda v: amg.solve(v, tol=1e-30, maxiter=1)  # noqa: E731

    def apply(res):
        z = np.empty_like(res)
        z[r] = solve(res[r] - Arp @ (P @ res[p]))
        z[p] = P @ (res[p] - Apr @ z[r])
        return z

    return spla.LinearOperator(A.shape, apply), stats


def measure(name: str, cases_dir: str, states: list[tuple[int, int]]) -> list[dict]:
    folder = harness.ensure_case(name, cases_dir)
    rows = []
    for step, iterations in states:
        system = newton_system(folder, step, iterations)
        A, b = system["A"], system["b"]
        row = {"case": name, "state": f"step {step}, iteration {iterations + 1}", "equations": A.shape[0],
               "active": sum(1 for active, _ in system["slave"].values() if active)}
        for label, exact in (("field split", None), ("condensed", False), ("condensed, exact S", True)):
            if exact and A.shape[0] > 60000:  # a sparse LU of S: too slow beyond
                continue
            start = time.process_time()
            M, stats = (field_split(system), {}) if exact is None else condensed(system, exact)
            row.update(stats)
            row[label] = gmres_iterations(A, b, M)
            row[label + " cpu"] = time.process_time() - start
        print(row, flush=True)
        rows.append(row)
    return rows


def table(rows: list[dict]) -> str:
    lines = ["| case | Newton system | equations | active nodes | field split: GMRES its | condensed: GMRES its "
             "| condensed, S solved exactly | max off-diagonal / min diagonal of G | asymmetry of S |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        exact = str(r["condensed, exact S"][0]) if "condensed, exact S" in r else "-"
        lines.append(f"| {r['case']} | {r['state']} | {r['equations']} | {r['active']} | {r['field split'][0]} "
                     f"| {r['condensed'][0]} | {exact} | {r['G_off']:.1e} | {r['asymmetry']:.1e} |")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", default="hertz3d_15k,hertz3d_50k")
    parser.add_argument("--states", default="2:2,4:2", help="step:iterations pairs (the system of the next iteration)")
    parser.add_argument("--cases-dir", default=os.path.join(harness.HERE, "cases"))
    parser.add_argument("--output", default=os.path.join(harness.HERE, "results_condensed_preconditioner.md"))
    args = parser.parse_args()
    try:
        import pyamg  # noqa: F401
    except ImportError:
        print("condensed_preconditioner.py needs pyamg: pip install pyamg", file=sys.stderr)
        return 2
    states = [tuple(int(v) for v in s.split(":")) for s in args.states.split(",")]
    rows = [row for name in args.cases.split(",") for row in measure(name, args.cases_dir, states)]
    with open(args.output, "w") as f:
        f.write("# The contact constraints in the 3D preconditioner: field split against condensation\n\n"
                f"Generated by `benchmarks/hertz/condensed_preconditioner.py` (its docstring says what is compared). "
                f"GMRES (restart 300) to a relative residual of 1e-8 on the Newton system of the given "
                f"iteration; one smoothed-aggregation V-cycle (pyamg, rigid-body modes) per application in "
                f"both preconditioners.\n\n{table(rows)}\n")
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
