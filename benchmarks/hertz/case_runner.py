#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4: runs one Hertz case with Kratos or mortarcontact and writes raw results as JSON.

Executed in a subprocess by run_kratos.py and compare.py, with the Python of the code under test
(Kratos: the benchmark's own virtual environment; mortarcontact: the project's Python), so only
the standard library is imported here besides that code. Both codes expose the same Kratos-like
Python API (Model, analysis stage, nodes with Id / X0 / GetSolutionStepValue), so one script
serves both.

    python case_runner.py --code kratos CASE_DIR OUT.json
    python case_runner.py --code mortarcontact --linear-solver '{"solver_type": "petsc", ...}' CASE_DIR OUT.json

``--linear-solver`` replaces mortarcontact's linear_solver_settings (the case files keep the
Kratos spelling that both codes read, e.g. for the 3D cases too large for a direct solver).
``--set KEY.PATH=JSON`` (repeatable) overrides one entry of ProjectParameters.json for either code
(list indices as numbers), e.g. ``--set solver_settings.max_iteration=50``.

Recorded: wall time of the analysis (Initialize + solution loop + Finalize, imports excluded)
and of its set-up, time and Newton iterations per step, mortarcontact's time per phase (search,
mortar weighted gap and normals, contact-condition and element assembly, DoF set-up and sparsity,
linear solve, rest) and the CPU seconds of the parts of the linear solve (mc.LinearSolveClocks)
(Kratos: ProcessInfo NL_ITERATION_NUMBER after each step; mortarcontact: the stage's step log),
convergence per step, peak resident memory of the process (getrusage), and at the end: per slave
node the initial coordinates, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE (historical), AUGMENTED_NORMAL_CONTACT_PRESSURE and
NORMAL_CONTACT_STRESS (MPC contact; non-historical), WEIGHTED_GAP and the ACTIVE flag; the sums of
REACTION over the clamped bottom and the pushed top. A failure is recorded as status "not
available" (not implemented) or "failed" with the message, and the script exits 0 so that the
harness can report it.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import time
import traceback


def _peak_rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def _resident_mb() -> float:
    """The resident memory now (Linux), which drops when a rank frees the part of the model it cut
    away (the peak does not)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20


def _blas_libraries() -> list[str]:
    """The BLAS shared libraries mapped into this process (which one UMFPACK used)."""
    try:
        with open("/proc/self/maps") as f:
            paths = {line.split()[-1] for line in f if line.rsplit("/", 1)[-1].startswith(("libblas", "libopenblas"))}
    except OSError:  # not Linux
        return []
    return sorted(os.path.realpath(p) for p in paths)


def _extract(model, get_variable, dim: int, flag_active, all_nodes: bool = False) -> dict:
    """``all_nodes``: also every node's DISPLACEMENT, each slave node's VECTOR_LAGRANGE_MULTIPLIER
    and the REACTION vectors summed over the bottom and the top (the robustness sweep)."""
    root = model.GetModelPart("Structure")
    axis = dim - 1

    def value(node, name, historical=True):
        try:
            var = get_variable(name)
            return float(node.GetSolutionStepValue(var) if historical else node.GetValue(var))
        except Exception:  # variable absent in this code or on this node
            return None

    def vector(node, name):
        try:
            return [float(c) for c in node.GetSolutionStepValue(get_variable(name))]
        except Exception:  # variable absent in this code or on this node
            return None

    slave = []
    for node in root.GetSubModelPart("Contact_slave").Nodes:
        slave.append({"id": node.Id, "x": node.X0, "y": node.Y0, "z": node.Z0,
                      "lm": value(node, "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"),
                      "augmented": value(node, "AUGMENTED_NORMAL_CONTACT_PRESSURE", historical=False),
                      "normal_contact_stress": value(node, "NORMAL_CONTACT_STRESS", historical=False),
                      "weighted_gap": value(node, "WEIGHTED_GAP"),
                      "active": bool(node.Is(flag_active)) if flag_active is not None else None})
        if all_nodes:
            slave[-1]["vector_lm"] = vector(node, "VECTOR_LAGRANGE_MULTIPLIER")
    reactions = {}
    component = "REACTION_" + "XYZ"[axis]
    for part in ("DISPLACEMENT_bottom", "DISPLACEMENT_top"):
        total = 0.0
        for node in root.GetSubModelPart(part).Nodes:
            total += value(node, component) or 0.0
        reactions[part] = total
    displacement = "DISPLACEMENT_" + "XYZ"[axis]
    top = [value(node, displacement) for node in root.GetSubModelPart("DISPLACEMENT_top").Nodes]
    info = {}
    for name in ("SCALE_FACTOR", "INITIAL_PENALTY"):
        info[name] = None
        for read in (lambda v: root.ProcessInfo[v], lambda v: root.ProcessInfo.GetValue(v)):
            try:
                info[name] = float(read(get_variable(name)))
                break
            except Exception:  # this spelling of the API, or the value, is not available
                continue
    result = {"slave": slave, "reactions": reactions, "top_displacement": top[0] if top else None,
              "nodes": root.NumberOfNodes(), "process_info": info}
    if all_nodes:
        result["displacements"] = {str(node.Id): vector(node, "DISPLACEMENT") for node in root.Nodes}
        result["reaction_totals"] = {
            part: [sum(c) for c in zip(*(vector(node, "REACTION") for node in root.GetSubModelPart(part).Nodes))]
            for part in ("DISPLACEMENT_bottom", "DISPLACEMENT_top")}
    return result


def run_kratos(parameters_text: str, dim: int, record: dict, all_nodes: bool = False):
    import KratosMultiphysics as KM
    import KratosMultiphysics.ConstitutiveLawsApplication  # registers the hyperelastic laws (not always pulled in)
    import KratosMultiphysics.ContactStructuralMechanicsApplication  # registers the contact solver
    import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
    from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
        StructuralMechanicsAnalysis,
    )

    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)

    class Instrumented(StructuralMechanicsAnalysis):
        def InitializeSolutionStep(self):
            self._step_start = time.perf_counter()
            super().InitializeSolutionStep()

        def Initialize(self):
            super().Initialize()
            solver = self._GetSolver()
            solve = solver.SolveSolutionStep

            def solve_and_record():
                self._converged = bool(solve())
                return self._converged

            solver.SolveSolutionStep = solve_and_record

        def FinalizeSolutionStep(self):
            super().FinalizeSolutionStep()
            info = self._GetSolver().GetComputingModelPart().ProcessInfo
            record["steps"].append({"time": info[KM.TIME], "iterations": info[KM.NL_ITERATION_NUMBER],
                                    "converged": getattr(self, "_converged", None),
                                    "seconds": time.perf_counter() - self._step_start})

    model = KM.Model()
    analysis = Instrumented(model, KM.Parameters(parameters_text))
    started, cpu_started = time.perf_counter(), time.process_time()
    analysis.Initialize()
    record["setup_seconds"] = time.perf_counter() - started
    analysis.RunSolutionLoop()
    analysis.Finalize()
    record["analysis_seconds"] = time.perf_counter() - started
    record["analysis_cpu_seconds"] = time.process_time() - cpu_started
    record.update(_extract(model, KM.KratosGlobals.GetVariable, dim, KM.ACTIVE, all_nodes))


def overridden(parameters_text: str, overrides: list[str]) -> str:
    """``parameters_text`` (JSON) with each ``KEY.PATH=JSON`` of ``overrides`` applied."""
    if not overrides:
        return parameters_text
    parameters = json.loads(parameters_text)
    for item in overrides:
        key, _, value = item.partition("=")
        *parents, last = [int(part) if part.isdigit() else part for part in key.split(".")]
        target = parameters
        for part in parents:  # a missing object on the path is created (e.g. search_parameters)
            target = target.setdefault(part, {}) if isinstance(part, str) else target[part]
        target[last] = json.loads(value)
    return json.dumps(parameters)


def kratos_parameters(parameters_text: str, case_dir: str) -> str:
    """Kratos reads mdpa only: a case whose mesh is a gmsh / meshio file is given to Kratos as the
    mdpa next to that file, which mortarcontact.cases.mesh_files.write_kratos_mdpa writes from it
    (the harness does, before a Kratos run)."""
    parameters = json.loads(parameters_text)
    imports = parameters["solver_settings"]["model_import_settings"]
    if imports.get("input_type") not in ("gmsh", "meshio"):
        return parameters_text
    stem = os.path.splitext(imports["input_filename"])[0]
    if not os.path.exists(os.path.join(case_dir, stem + ".mdpa")):
        raise FileNotFoundError(f"{stem}.mdpa: Kratos' copy of {imports['input_filename']} is missing; write it with "
                                "mortarcontact.cases.mesh_files.write_kratos_mdpa")
    parameters["solver_settings"]["model_import_settings"] = {"input_type": "mdpa", "input_filename": stem}
    return json.dumps(parameters)


def mortarcontact_parameters(parameters_path: str, linear_solver: str | None = None, overrides: list[str] = ()):
    """The case's project parameters for mortarcontact, with ``linear_solver`` (JSON) in place of
    its linear_solver_settings when given and ``overrides`` (see ``overridden``) applied."""
    import mortarcontact as mc
    from mortarcontact.project_parameters import migrate_project_parameters

    with open(parameters_path) as f:
        parameters = mc.Parameters(overridden(f.read(), list(overrides)))
    migrate_project_parameters(parameters)
    if linear_solver:
        solver_settings = parameters["solver_settings"]
        solver_settings.RemoveValue("linear_solver_settings")
        solver_settings.AddValue("linear_solver_settings", mc.Parameters(linear_solver))
    return parameters


def run_mortarcontact(parameters_path: str, dim: int, record: dict, linear_solver: str | None = None,
                      all_nodes: bool = False, overrides: list[str] = ()):
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis

    parameters = mortarcontact_parameters(parameters_path, linear_solver, overrides)
    if linear_solver:
        record["linear_solver"] = json.loads(linear_solver)
    model = mc.Model()
    started, cpu_started = time.perf_counter(), time.process_time()
    analysis = StructuralMechanicsAnalysis(model, parameters, progress=False, stop_on_non_convergence=False,
                                           case_dir=os.path.dirname(parameters_path))
    analysis.Initialize()
    # Each step's Newton iterations: residual norm, linear tolerance and iterations (issue 14)
    finalize_step = analysis.FinalizeSolutionStep

    def finalize_and_record():
        record["newton"].append([{"residual": r.residual_norm, "linear_tolerance": r.linear_tolerance,
                                  "linear_iterations": r.linear_iterations}
                                 for r in analysis.solver.strategy.GetIterationHistory()])
        finalize_step()

    record["newton"] = []
    analysis.FinalizeSolutionStep = finalize_and_record
    record["setup_seconds"] = time.perf_counter() - started
    record["setup_rss_mb"] = _peak_rss_mb()  # imports, plugins, the model read, processes set up
    record["setup_resident_mb"] = _resident_mb()
    analysis.RunSolutionLoop()
    builder = analysis.solver.strategy.GetBuilderAndSolver()
    record["dofs"] = builder.NumberOfDofs()  # Finalize frees them
    record["matrix_entries"] = builder.SystemMatrixNonZeros()  # under mpirun: this rank's rows
    analysis.Finalize()
    record["analysis_seconds"] = time.perf_counter() - started
    record["analysis_cpu_seconds"] = time.process_time() - cpu_started
    for _step, t, iterations, converged, seconds in analysis.step_log:
        record["steps"].append({"time": t, "iterations": iterations, "converged": converged, "seconds": seconds})
    record["phases"] = _mortarcontact_phases(analysis, record["analysis_seconds"])
    record["linear_solver_counters"] = analysis.solver.strategy.GetBuilderAndSolver().GetLinearSolverCounters()
    record["linear_solve_clocks"] = mc.LinearSolveClocks()  # CPU seconds per part of the solve phase
    searches = [s for p in analysis.processes for s in getattr(p, "searches", [])]
    record["contact_pairs"] = sum(s.ComputingPart().NumberOfConditions() for s in searches)
    record["searches"] = sum(s.NumberOfSearches() for s in searches)
    record.update(_extract(model, mc.GetVariable, dim, getattr(mc, "ACTIVE", None), all_nodes))


def _mortarcontact_phases(analysis, total: float) -> dict:
    """Cumulative seconds per phase from the builder, the contact searches and the mortar updater
    (all timed in C++ with one clock read per phase); "rest" is the analysis time not covered."""
    solver = analysis.solver
    t = solver.strategy.GetBuilderAndSolver().GetTimings()
    search = sum(s.TotalSeconds() for p in analysis.processes for s in getattr(p, "searches", []))
    updater = getattr(solver, "mortar_updater", None)
    mortar = updater.GetTimings() if updater is not None else {"weighted_gap": 0.0, "normals": 0.0}
    phases = {"search": search, "weighted_gap": mortar["weighted_gap"], "normals": mortar["normals"],
              "conditions": t.conditions, "elements": t.elements, "build_other": t.build - t.elements - t.conditions,
              "dof_setup": t.dof_setup + t.sparsity, "solve": t.solve}
    phases["rest"] = total - sum(phases.values())
    return phases


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Runs one Hertz case and writes raw results (JSON).")
    parser.add_argument("--code", choices=("kratos", "mortarcontact"), required=True)
    parser.add_argument("--linear-solver", help="mortarcontact's linear_solver_settings (JSON) instead of the case's")
    parser.add_argument("--all-nodes", action="store_true",
                        help="also record every node's displacement and the reaction vectors")
    parser.add_argument("--set", action="append", default=[], metavar="KEY.PATH=JSON",
                        help="override one entry of ProjectParameters.json (repeatable)")
    parser.add_argument("case_dir")
    parser.add_argument("output")
    args = parser.parse_args(argv)
    if args.linear_solver and args.code != "mortarcontact":
        parser.error("--linear-solver applies to mortarcontact only")
    output = os.path.abspath(args.output)
    case_dir = os.path.abspath(args.case_dir)
    os.chdir(case_dir)  # relative paths inside the case resolve from its folder, as in Kratos
    parameters_path = os.path.join(case_dir, "ProjectParameters.json")
    with open(parameters_path) as f:
        parameters_text = overridden(f.read(), args.set)
    dim = json.loads(parameters_text)["solver_settings"]["domain_size"]
    record = {"code": args.code, "case": os.path.basename(case_dir), "status": "ok", "steps": [],
              "overrides": args.set}
    process_started = time.perf_counter()
    try:
        if args.code == "kratos":
            run_kratos(kratos_parameters(parameters_text, case_dir), dim, record, args.all_nodes)
        else:
            run_mortarcontact(parameters_path, dim, record, args.linear_solver, args.all_nodes, args.set)
    except Exception as error:  # reported, not raised: the harness tabulates it
        name = type(error).__name__
        not_available = "NotImplemented" in name or "not implemented" in str(error).lower()
        record["status"] = "not available" if not_available else "failed"
        record["error"] = f"{name}: {error}"
        record["traceback"] = traceback.format_exc()
    record["process_seconds"] = time.perf_counter() - process_started
    record["peak_rss_mb"] = _peak_rss_mb()
    record["blas"] = _blas_libraries()
    if args.code == "mortarcontact":
        import mortarcontact as mc

        # Under mpirun each rank records its own phases and memory: rank r > 0 beside rank 0's file.
        if (rank := mc._core.LaunchedRank()) > 0:
            output = f"{os.path.splitext(output)[0]}.rank{rank}.json"
    with open(output, "w") as f:
        json.dump(record, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
