#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: Kratos 10.4's contact tangent against central finite differences of its own residual,
at the start of one load step of a sweep case (README.md, penalty cases). For every contact pair
with an active slave node: the largest difference |K - K_fd| over the largest |K| entry, and the
largest row sum of K over the columns of one displacement component, which a rigid translation
of the pair must leave at zero (K_fd's row sums are round-off). The nodal normals stay fixed, which
is what Kratos' default normal_variation linearises.

    $MORTARCONTACT_KRATOS_VENV/bin/python kratos_tangent_check.py CASE_DIR STEP [--step-size 1e-8]
"""
from __future__ import annotations

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hertz"))
import case_runner


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("case_dir")
    parser.add_argument("step", type=int)
    parser.add_argument("--step-size", type=float, default=1e-8)
    args = parser.parse_args(argv)
    case_dir = os.path.abspath(args.case_dir)
    os.chdir(case_dir)

    import KratosMultiphysics as KM
    import KratosMultiphysics.ConstitutiveLawsApplication  # registers the laws
    import KratosMultiphysics.ContactStructuralMechanicsApplication  # registers the contact conditions
    import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
    from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
        StructuralMechanicsAnalysis,
    )

    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
    with open("ProjectParameters.json") as f:
        text = case_runner.kratos_parameters(f.read(), case_dir)

    class Reached(Exception):
        pass

    class Stage(StructuralMechanicsAnalysis):
        def InitializeSolutionStep(self):
            super().InitializeSolutionStep()  # the search has made the pairs and the predicted set
            if self._GetSolver().GetComputingModelPart().ProcessInfo[KM.STEP] == args.step:
                raise Reached

    model = KM.Model()
    stage = Stage(model, KM.Parameters(text))
    stage.Initialize()
    try:
        stage.RunSolutionLoop()
    except Reached:
        pass
    else:
        print(f"step {args.step} was not reached", file=sys.stderr)
        return 1
    root = model.GetModelPart("Structure")
    info = root.ProcessInfo
    components = {"DISPLACEMENT_X": KM.DISPLACEMENT_X, "DISPLACEMENT_Y": KM.DISPLACEMENT_Y,
                  "DISPLACEMENT_Z": KM.DISPLACEMENT_Z}

    def local_system(condition):
        lhs, rhs = KM.Matrix(), KM.Vector()
        condition.CalculateLocalSystem(lhs, rhs, info)
        return np.array(lhs), np.array(rhs)

    def move(node, name, value):  # the pair reads the current coordinates, X0 + u
        node.SetSolutionStepValue(components[name], value)
        axis = name[-1]
        setattr(node, axis, getattr(node, axis + "0") + value)

    worst_error, worst_sum, worst_sum_fd, pairs = 0.0, 0.0, 0.0, 0
    for condition in root.GetSubModelPart("ComputingContact").Conditions:
        dofs = [(dof.Id(), dof.GetVariable().Name()) for dof in condition.GetDofList(info)]
        nodes = {node_id: root.GetNode(node_id) for node_id, _ in dofs}
        if not any(node.Is(KM.ACTIVE) and node.Is(KM.SLAVE) for node in nodes.values()):
            continue
        lhs, _ = local_system(condition)
        if not np.any(lhs):
            continue  # no overlap
        fd = np.zeros_like(lhs)
        for column, (node_id, name) in enumerate(dofs):
            node = nodes[node_id]
            u = node.GetSolutionStepValue(components[name])
            move(node, name, u + args.step_size)
            plus = local_system(condition)[1]
            move(node, name, u - args.step_size)
            minus = local_system(condition)[1]
            move(node, name, u)
            fd[:, column] = -(plus - minus) / (2.0 * args.step_size)  # LHS = -d(RHS)/du
        scale = np.abs(lhs).max()
        error = np.abs(lhs - fd).max() / scale

        columns = [[c for c, (_, name) in enumerate(dofs) if name == component] for component in components]
        row_sum, row_sum_fd = (max(np.abs(m[:, cols].sum(axis=1)).max() for cols in columns if cols) / scale
                               for m in (lhs, fd))
        pairs += 1
        print(f"pair {condition.Id:6d} nodes {sorted(nodes)}: |K| {scale:.3e}, |K - K_fd|/|K| {error:.2e}, "
              f"translation row sum /|K|: K {row_sum:.2e}, K_fd {row_sum_fd:.2e}")
        worst_error, worst_sum, worst_sum_fd = max(worst_error, error), max(worst_sum, row_sum), max(
            worst_sum_fd, row_sum_fd)
    print(f"{pairs} pairs with an active slave node: largest |K - K_fd|/|K| {worst_error:.2e}; largest translation "
          f"row sum /|K|: K {worst_sum:.2e}, K_fd {worst_sum_fd:.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
