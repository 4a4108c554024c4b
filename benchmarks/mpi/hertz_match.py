"""Issue 17's done-when: ``mpirun -n 2 mortarcontact run`` on the Hertz benchmarks matches the serial
run to 1e-8. Runs each benchmark Hertz case (benchmarks/hertz/harness.py's generated cases) on one
process and under ``mpirun -n 2`` with the model cut across the ranks
(``MORTARCONTACT_PARTITIONED_MODEL=1``), both with the same PETSc solver and one OpenMP thread per
process, through benchmarks/hertz/case_runner.py, with two JSON outputs added: every node's
displacements and every contact node's LAGRANGE_MULTIPLIER_CONTACT_PRESSURE at every step (on 2 ranks
gathered by rank 0 into the serial run's file). Prints a Markdown row per case: the largest difference
at any node and step relative to the largest serial value, the Newton iterations per step of both,
and each rank's CPU seconds (the whole analysis) and peak resident memory. Exits 1 when a case
differs by more than 1e-8 or in its iterations.

    python benchmarks/mpi/hertz_match.py                                  # the four cases, MUMPS
    python benchmarks/mpi/hertz_match.py --cases hertz3d_50k --solver fieldsplit
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from scaling import SOLVERS, run

CASES = ("hertz2d_30k", "hertz2d_250k", "hertz3d_15k", "hertz3d_50k")
TOLERANCE = 1e-8
#: (file, model part, variable)
OUTPUTS = (("displacements", "Structure", "DISPLACEMENT"),
           ("pressures", "Structure.Contact", "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"))


def json_outputs(prefix: str) -> list[str]:
    """case_runner.py's ``--set`` of the JSON outputs, their files named ``<prefix>_<file>.json``."""
    outputs = [{"python_module": "json_output_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"model_part_name": part, "output_variables": [variable],
                               "output_file_name": f"{prefix}_{name}.json", "time_frequency": 0.0}}
               for name, part, variable in OUTPUTS]
    return [f"processes.json_output={json.dumps(outputs)}"]


def read_json(path: str):
    with open(path) as f:
        return json.load(f)


def largest_relative_difference(serial: dict, cut: dict) -> float:
    """max |cut - serial| over every node, component and step / max |serial|; the same entities in the
    same order required."""
    if list(serial) != list(cut):
        raise SystemExit("the 2-rank run's JSON output holds other entities or another order")
    pairs = [(s, cut[key][component]) for key, node in serial.items() if key.startswith("NODE_")
             for component, s in node.items()]
    scale = max(abs(v) for s, _ in pairs for v in s)
    return max(abs(a - b) for s, c in pairs for a, b in zip(s, c, strict=True)) / scale


def compare(case: str, solver: str, work: str) -> tuple[str, bool]:
    from mortarcontact.cases import hertz

    family, label = case.rsplit("_", 1)
    case_dir = hertz.write_case(family, label, work)
    load = [os.getloadavg()[0]]
    records = {}
    for ranks in (1, 2):
        prefix = f"ranks{ranks}"
        records[ranks] = run(case_dir, SOLVERS[solver], ranks, work, partitioned=ranks > 1,
                             extra=[arg for item in json_outputs(prefix) for arg in ("--set", item)])
        load.append(os.getloadavg()[0])
    differences = [largest_relative_difference(*(read_json(os.path.join(case_dir, f"ranks{n}_{name}.json"))
                                                 for n in (1, 2))) for name, _, _ in OUTPUTS]
    iterations = {n: [s["iterations"] for s in records[n][0]["steps"]] for n in (1, 2)}
    cpu = {n: " / ".join(f"{r['analysis_cpu_seconds']:.1f}" for r in records[n]) for n in (1, 2)}
    peak = {n: " / ".join(f"{r['peak_rss_mb']:.0f}" for r in records[n]) for n in (1, 2)}
    same = iterations[1] == iterations[2] and max(differences) <= TOLERANCE
    text = (f"| {case} | {records[1][0].get('dofs', '?')} | {solver} | {differences[0]:.1e} | {differences[1]:.1e} | "
            f"{', '.join(map(str, iterations[1]))} | {', '.join(map(str, iterations[2]))} | {cpu[1]} | {cpu[2]} | "
            f"{peak[1]} | {peak[2]} | {' -> '.join(f'{x:.1f}' for x in load)} |")
    return text, same


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default=",".join(CASES), help="comma-separated Hertz case names")
    parser.add_argument("--solver", choices=sorted(SOLVERS), default="mumps")
    parser.add_argument("--keep", help="a folder to keep each case's files and JSON outputs in (default: removed)")
    args = parser.parse_args()
    print("| case | DoFs | solver | displacements, largest difference | pressures, largest difference | "
          "Newton iterations per step, 1 process | 2 ranks | analysis CPU s, 1 process | per rank | "
          "peak memory (MB), 1 process | per rank | load average |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    matched = True
    for case in args.cases.split(","):
        if args.keep:
            work = os.path.join(args.keep, case)
            os.makedirs(work, exist_ok=True)
            text, same = compare(case, args.solver, work)
        else:
            with tempfile.TemporaryDirectory() as work:
                text, same = compare(case, args.solver, work)
        print(text, flush=True)
        matched &= same
    return 0 if matched else 1


if __name__ == "__main__":
    sys.exit(main())
