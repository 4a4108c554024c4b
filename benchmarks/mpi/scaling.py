"""Strong scaling of the distributed system and PETSc solve (issue 17): one Hertz case run on 1
and on 2 processes (``mpirun -n 2``), one OpenMP thread per process, with the same PETSc solver;
prints a Markdown table of the wall time per phase, the CPU time, the memory after the set-up (the
model read) and at its peak, and the matrix entries each rank keeps, and checks that both runs took
the same Newton iterations.

    python benchmarks/mpi/scaling.py --case hertz2d_100k --solver mumps
    python benchmarks/mpi/scaling.py --case hertz3d_50k --solver fieldsplit
    python benchmarks/mpi/scaling.py --case hertz2d_100k --partitioned-model   # + 2 ranks, model cut
    python benchmarks/mpi/scaling.py --case hertz2d_100k --partitioned-model --mdpa   # each rank reads its piece

``--mdpa`` has every run read the case's mesh as the mdpa ``mesh_files.write_kratos_mdpa`` makes of
it (the same nodes, elements and parts): a rank of a cut model then reads only its piece of it,
where a gmsh mesh is read whole and cut.

The per-rank records come from benchmarks/hertz/case_runner.py (rank r > 0 writes
``<output>.rank<r>.json``).
"""
from __future__ import annotations

import argparse
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
RUNNER = os.path.join(HERE, "..", "hertz", "case_runner.py")
SOLVERS = {
    "mumps": {"solver_type": "petsc"},
    "fieldsplit": {"solver_type": "petsc", "tolerance": 1e-8, "max_iteration": 500,
                   "petsc_options": {"pc_type": "fieldsplit"}},
}


def run(case_dir: str, solver: dict, ranks: int, work: str, partitioned: bool = False, extra=()) -> list[dict]:
    """The per-rank records of one run; `partitioned`: each rank cuts the model to its piece
    (MORTARCONTACT_PARTITIONED_MODEL=1); `extra`: more arguments of case_runner.py."""
    output = os.path.join(work, f"ranks{ranks}{'cut' if partitioned else ''}.json")
    command = [sys.executable, RUNNER, "--code", "mortarcontact", "--linear-solver", json.dumps(solver), *extra,
               case_dir, output]
    if ranks > 1:
        command = [shutil.which("mpirun"), "-n", str(ranks), *command]
    # A waiting rank yields its core (shared machines) instead of polling.
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_mpi_yield_when_idle="1", MORTARCONTACT_PARTITIONED_MODEL="1" if partitioned else "0")
    subprocess.run(command, check=True, env=env)
    records = [output, *sorted(glob.glob(f"{os.path.splitext(output)[0]}.rank*.json"))]
    loaded = []
    for path in records:
        with open(path) as f:
            loaded.append(json.load(f))
    for record in loaded:
        if record["status"] != "ok":
            raise SystemExit(f"{ranks} ranks: {record['status']}: {record.get('error')}")
    return loaded


def read_as_mdpa(case_dir: str) -> None:
    """Points the case's ProjectParameters.json at the mdpa of its mesh."""
    from mortarcontact.cases.mesh_files import write_kratos_mdpa

    mdpa = write_kratos_mdpa(case_dir)
    path = os.path.join(case_dir, "ProjectParameters.json")
    with open(path) as f:
        parameters = json.load(f)
    parameters["solver_settings"]["model_import_settings"] = {
        "input_type": "mdpa", "input_filename": os.path.splitext(os.path.basename(mdpa))[0]}
    with open(path, "w") as f:
        json.dump(parameters, f, indent=2)


def row(ranks, records: list[dict]) -> str:
    def per_rank(*names, digits=2):
        return " / ".join(f"{sum(r['phases'][n] for n in names):.{digits}f}" for r in records)

    def per_rank_value(key, digits=1, unit=1.0):
        return " / ".join(f"{r[key] / unit:.{digits}f}" for r in records)

    iterations = sum(s["iterations"] for s in records[0]["steps"])
    return (f"| {ranks} | {iterations} | {per_rank('elements', 'conditions', 'build_other')} | {per_rank('solve')} | "
            f"{per_rank('dof_setup')} | {per_rank('search', 'weighted_gap', 'normals')} | "
            f"{per_rank_value('analysis_seconds')} | {per_rank_value('analysis_cpu_seconds')} | "
            f"{per_rank_value('setup_rss_mb', 0)} | {per_rank_value('setup_resident_mb', 0)} | "
            f"{per_rank_value('peak_rss_mb', 0)} | "
            f"{per_rank_value('matrix_entries', 2, 1e6)} |")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", default="hertz2d_100k", help="a Hertz case name, e.g. hertz2d_100k, hertz3d_50k")
    parser.add_argument("--solver", choices=sorted(SOLVERS), default="mumps")
    parser.add_argument("--partitioned-model", action="store_true",
                        help="also on 2 processes, each cutting the model (MORTARCONTACT_PARTITIONED_MODEL)")
    parser.add_argument("--mdpa", action="store_true",
                        help="read the mesh as an mdpa (a rank of a cut model reads its piece only)")
    args = parser.parse_args()
    from mortarcontact.cases import hertz

    family, label = args.case.rsplit("_", 1)
    load_before = f"{os.getloadavg()[0]:.1f}"  # on a shared machine the timings are only as good as this
    with tempfile.TemporaryDirectory() as work:
        case_dir = hertz.write_case(family, label, work)
        if args.mdpa:
            read_as_mdpa(case_dir)
        results = {ranks: run(case_dir, SOLVERS[args.solver], ranks, work) for ranks in (1, 2)}
        if args.partitioned_model:
            results["2, model cut"] = run(case_dir, SOLVERS[args.solver], 2, work, partitioned=True)
    steps = {ranks: [s["iterations"] for s in records[0]["steps"]] for ranks, records in results.items()}
    if any(iterations != steps[1] for iterations in steps.values()):
        raise SystemExit(f"the Newton iterations differ: {steps}")
    dofs = results[1][0].get("dofs", "?")
    print(f"{args.case} ({dofs} DoFs, {'mdpa' if args.mdpa else 'gmsh'} mesh), PETSc {args.solver}, one thread per "
          "process; wall-clock seconds per rank "
          f"(rank 0 / rank 1); load average before and after: {load_before} / {os.getloadavg()[0]:.1f}")
    print()
    print("| processes | Newton iterations | assembly | linear solve | DoF set-up + pattern | contact search + "
          "mortar | analysis | analysis CPU s | peak memory after set-up (MB) | resident after set-up (MB) | "
          "peak memory (MB) | matrix entries kept (M) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for ranks, records in results.items():
        print(row(ranks, records))
    return 0


if __name__ == "__main__":
    sys.exit(main())
