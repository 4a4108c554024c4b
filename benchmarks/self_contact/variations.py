#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: the clamp of ``mortarcontact.cases.self_contact`` with the roles given, varied as a
user would (element size, load, slave side, number of load steps, friction, 3D), run by
mortarcontact and by Kratos 10.4 on the same files (compare.py's ``--run`` mode, one subprocess per
run). Writes benchmarks/self_contact/results_variations.md: converged?, Newton iterations per step
of each code, the largest displacement difference over the largest displacement, and the opening
of the slot that the search at the start of a step can bridge (search radius 3.5 x the slave
element size) against the largest closing of the slot in one step without contact.

    python benchmarks/self_contact/variations.py [--filter REGEX]
"""
from __future__ import annotations

import argparse
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.append(os.path.join(HERE, "..", "hertz"))  # after this folder: hertz has a compare.py too
RESULTS = os.path.join(HERE, "results_variations.md")
SEARCH_FACTOR = 3.5  # Kratos' default search_factor, which the generated cases keep

NOTES = """Where the tips crossed within a step, the next search pairs the crossed faces and pushes
the arms apart (the arms are one body: a face of the slave's own body is a partner up to a face's
size behind it unless one element holds both faces). Kratos leaves the arms crossed for many steps
(overlap column: in 16 of the 20 steps of deep_left_slave_20_steps, up to 0.18 deep, 3.6 elements;
deep_left_slave: 0.116 after step 1, still 0.030 after step 8), we only in the step that crossed,
deeper crossings for two more steps (deep_left_slave: 0.116, 0.056, 0.008, then 0): the search
pairs a face of the other arm only up to a face's size behind. Neither code's step-start search
sees a slot that closes by more than its reach within the step.

Per step we take more iterations than Kratos in the step after a crossing (fine meshes: 6 against
3-4) and in a few first contact steps (load_2_right_slave step 2, 3d_right_slave_4_steps step 1),
fewer in total in every variation. The step after a crossing, traced node by node in
fine_right_slave step 3 (benchmarks/robustness/iterates.py): the search pairs the six crossed tip
nodes of the slave wall and predicts them active; as the tips rotate apart the semi-smooth Newton
releases them one per iteration (6, 4, 3, 2, 1, 1, 1 active) and the step ends with the tip corner
touching the other tip and every other node 0.0017-0.015 clear. Kratos pairs only three of them
(the tip faces get no pair: NODAL_AREA 0), releases two in its first iteration and ends the step
in 3 iterations with the three unpaired tip nodes inside the other arm, the tip 0.0075 deep (30 %
of an element), and still 0.0025 after step 4. Kratos does not converge in step 9 of
load_4_20_steps nor in the last step of either frictional variation.
"""

# name: (dim, element size, load factor, slave side, steps, friction coefficient)
VARIATIONS = {
    "base": (2, 0.05, 1.0, "left", 8, 0.0),
    "right_slave": (2, 0.05, 1.0, "right", 8, 0.0),
    "fine_left_slave": (2, 0.025, 1.0, "left", 8, 0.0),
    "fine_right_slave": (2, 0.025, 1.0, "right", 8, 0.0),
    "finest_left_slave": (2, 0.0125, 1.0, "left", 8, 0.0),
    "load_0.5": (2, 0.05, 0.5, "left", 8, 0.0),
    "load_2": (2, 0.05, 2.0, "left", 8, 0.0),
    "load_2_right_slave": (2, 0.05, 2.0, "right", 8, 0.0),
    "deep_left_slave": (2, 0.05, 3.0, "left", 8, 0.0),
    "deep_left_slave_20_steps": (2, 0.05, 3.0, "left", 20, 0.0),
    "load_4_20_steps": (2, 0.05, 4.0, "left", 20, 0.0),
    "4_steps": (2, 0.05, 1.0, "left", 4, 0.0),
    "20_steps": (2, 0.05, 1.0, "left", 20, 0.0),
    "friction_0.3": (2, 0.05, 1.0, "left", 8, 0.3),
    "friction_0.3_right_slave": (2, 0.05, 1.0, "right", 8, 0.3),
    "3d": (3, 0.1, 1.0, "left", 8, 0.0),
    "3d_right_slave_4_steps": (3, 0.1, 1.0, "right", 4, 0.0),
}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--filter", default="", help="regular expression on the variation names")
    args = parser.parse_args(argv)
    from mortarcontact.cases import self_contact
    from mortarcontact.cases.mesh_files import write_kratos_mdpa

    import harness  # the Kratos 10.4 venv of the benchmarks (MORTARCONTACT_KRATOS_VENV)
    from compare import displacement_difference, overlaps, run_child, steps_summary

    pythons = {"mortarcontact": sys.executable, "kratos": harness.kratos_python()}
    lines = ["| variation | dim | size | load | slave | steps | mu | reach / closing | mortarcontact | Kratos 10.4 "
             "| overlap: mortarcontact / Kratos | max abs(du) / max abs(u) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    size, pressure = dict(self_contact.SIZE), self_contact.PRESSURE
    with tempfile.TemporaryDirectory() as scratch:
        for name, (dim, h, load, slave, steps, mu) in VARIATIONS.items():
            if not re.search(args.filter, name):
                continue
            self_contact.SIZE[dim], self_contact.PRESSURE = h, pressure * load
            folder = self_contact.write_case(dim, os.path.join(scratch, name), "given", steps=steps, friction=mu,
                                             slave=slave)
            self_contact.SIZE.update(size)
            self_contact.PRESSURE = pressure
            write_kratos_mdpa(folder)
            records, cells, cells_overlap = {}, [], []
            for code, python in pythons.items():
                output = os.path.join(scratch, f"{name}-{code}.json")
                record = run_child(python, code, folder, output)
                if isinstance(record, str):
                    cells.append(f"crashed: {record[:80]}")
                    continue
                records[code] = record
                status, iterations = steps_summary(record)
                cells.append(f"{status}: {iterations}")
                if dim == 2:
                    depths = overlaps(record)
                    deepest = max(range(len(depths)), key=depths.__getitem__)
                    overlapped = sum(depth > 0.01 * h for depth in depths)
                    cells_overlap.append(f"{depths[deepest]:.4f} (step {deepest + 1}); {overlapped}" if overlapped
                                         else "0")
            difference = ""
            if len(records) == 2:
                difference = f"{displacement_difference(records['mortarcontact'], records['kratos']):.1e}"
            # The slot (2 GAP) closes by about twice the free tip deflection (0.43 per unit load in
            # 2D) over the steps; the step-start search bridges SEARCH_FACTOR x the slave size.
            closing = f"{2 * 0.43 * load / steps:.3f}" if dim == 2 else "-"
            line = (f"| {name} | {dim} | {h} | {load} x | {slave} | {steps} | {mu} | "
                    f"{SEARCH_FACTOR * h:.3f} / {closing} | {cells[0]} | {cells[1]} | "
                    f"{' / '.join(cells_overlap) or '-'} | {difference} |")
            lines.append(line)
            print(line, flush=True)
    load_average = os.getloadavg()[0]
    with open(RESULTS, "w") as f:
        f.write("# The clamp with the roles given, varied: mortarcontact and Kratos 10.4\n\n"
                "Generated by `benchmarks/self_contact/variations.py` (case: `mortarcontact.cases.self_contact`, "
                "tolerances 1e-6 relative). Cells: converged?, Newton iterations per step. 'reach / closing': the "
                "search radius of the step-start search (search_factor 3.5 x the slave element size) against the "
                "closing of the slot per step of free bending (2 x 0.43 x load / steps, 2D: the measured free tip "
                "deflection); where the closing is the larger, the step that closes the slot can start without a "
                "pair and the tips pass through each other in both codes. 'overlap' (2D): the deepest a node of one "
                "inner wall lies inside the other arm at the end of a step (its step), and in how many steps the "
                "arms end more than 1 % of an element inside each other. "
                f"Load average {load_average:.1f} at the end ({os.cpu_count()} cores).\n\n"
                + "\n".join(lines) + "\n\n" + NOTES)
    return 0


if __name__ == "__main__":
    sys.exit(main())
