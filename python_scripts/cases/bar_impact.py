# SPDX-License-Identifier: BSD-3-Clause
"""Two equal elastic bars colliding head-on, explicit penalty contact (issue 13).

Each bar has length LENGTH, a square section of side SIDE, NX hexahedra along x, nu = 0 and every
lateral displacement fixed: a 1D bar with wave speed c = sqrt(E / rho). The bars start touching
(the gap is GAP) and move towards each other, each at speed SPEED. 1D wave theory: while in
contact the interface is at rest and carries the force F = rho c A v (A = SIDE^2, v the speed of
each bar, i.e. rho c A V_rel / 2), the compression waves reflect at the free ends and the bars
separate after t_c = 2 L / c with their velocities exchanged (restitution 1) and the kinetic
energy restored. The penalty is manual: eps such that each interface node's spring is STIFFNESS_RATIO
times the axial stiffness of an element's nodal share, E A / (4 h).

    python -m mortarcontact.cases.bar_impact --out /tmp/cases
"""
from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np

from .mesh_files import write_case_mesh, write_json_files

LENGTH, SIDE, NX = 1.0, 0.1, 40
YOUNG, DENSITY = 2.1e11, 7850.0
SPEED = 1.0
GAP = 0.0
STIFFNESS_RATIO = 20.0


def wave_speed() -> float:
    return math.sqrt(YOUNG / DENSITY)


def penalty(nx: int = NX) -> float:
    """eps with eps A_j^2 = STIFFNESS_RATIO E A / (4 h), A_j = A / 4 the nodal area of a face node."""
    h, area = LENGTH / nx, SIDE * SIDE
    return STIFFNESS_RATIO * YOUNG * area / (4.0 * h) / (area / 4.0) ** 2


def critical_time_step(nx: int = NX) -> float:
    """0.9 of the largest stable time step with the penalty springs (write_case)."""
    return 0.9 * (LENGTH / nx) / (wave_speed() * math.sqrt(1.0 + STIFFNESS_RATIO))


def mesh(nx: int = NX):
    """(coordinates (n, 3), hexahedra of the left bar, hexahedra of the right bar, the left bar's
    end nodes at the interface, the right bar's), 0-based."""
    h = LENGTH / nx
    section = np.array([(0.0, 0.0), (SIDE, 0.0), (SIDE, SIDE), (0.0, SIDE)])
    coords, cells, ends = [], [], []
    for x0, end in ((-LENGTH - GAP / 2.0, nx), (GAP / 2.0, 0)):
        first = len(coords)
        for i in range(nx + 1):
            coords += [(x0 + i * h, y, z) for y, z in section]
        layer = first + 4 * np.arange(nx)[:, None] + np.arange(4)
        cells.append(np.hstack([layer[:, [0]], layer[:, [0]] + 4, layer[:, [1]] + 4, layer[:, [1]],
                                layer[:, [3]], layer[:, [3]] + 4, layer[:, [2]] + 4, layer[:, [2]]]))
        ends.append(first + 4 * end + np.arange(4))
    return np.array(coords), cells[0], cells[1], ends[0], ends[1]


def write_case(out_dir: str, nx: int = NX, time_step: float | None = None, end_time: float | None = None) -> str:
    """Writes bar_impact.msh, its materials and ProjectParameters.json into `out_dir`; returns
    the parameters' path. Default time step: 0.9 of the critical one with the penalty springs,
    h / (c sqrt(1 + STIFFNESS_RATIO)) (omega^2 = 4 c^2 / h^2 of the end element plus the spring's
    STIFFNESS_RATIO times that between two end-node masses); default end: 1.5 times the contact
    duration."""
    os.makedirs(out_dir, exist_ok=True)
    c = wave_speed()
    coords, left, right, left_end, right_end = mesh(nx)
    element = "SmallDisplacementElement3D8N"
    model_import = write_case_mesh(
        os.path.join(out_dir, "bar_impact.msh"), coords, [(element, 1, left), (element, 1 + nx, right)],
        {"left": {"nodes": np.unique(left), "elements": 1 + np.arange(nx)},
         "right": {"nodes": np.unique(right), "elements": 1 + nx + np.arange(nx)},
         "contact_left": {"nodes": left_end}, "contact_right": {"nodes": right_end},
         "all_nodes": {"nodes": np.arange(len(coords))}})
    law = {"name": "LinearElastic3DLaw"}
    materials = {"properties": [
        {"model_part_name": f"Structure.{bar}", "properties_id": i + 1,
         "Material": {"constitutive_law": law, "Variables": {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": 0.0,
                                                              "DENSITY": DENSITY}}}
        for i, bar in enumerate(("left", "right"))]}
    parameters = {
        "problem_data": {"problem_name": "bar_impact", "parallel_type": "OpenMP", "start_time": 0.0,
                         "end_time": end_time if end_time is not None else 1.5 * 2.0 * LENGTH / c, "echo_level": 0},
        "solver_settings": {
            "model_part_name": "Structure", "solver_type": "Dynamic", "time_integration_method": "explicit",
            "domain_size": 3, "echo_level": 0, "analysis_type": "non_linear",
            "model_import_settings": model_import,
            "material_import_settings": {"materials_filename": "bar_impact_materials.json"},
            "contact_settings": {"mortar_type": "PenaltyContactFrictionless"},
            "time_stepping": {"time_step": time_step if time_step is not None else critical_time_step(nx)}},
        "processes": {
            "constraints_process_list": [{
                "python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"model_part_name": "Structure.all_nodes", "variable_name": "DISPLACEMENT",
                               "constrained": [False, True, True], "value": [None, 0.0, 0.0],
                               "interval": [0.0, "End"]}}],
            "contact_process_list": [{
                "python_module": "explicit_penalty_contact_process",
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "Parameters": {"model_part_name": "Structure",
                               "contact_model_part": {"0": ["contact_left", "contact_right"]},
                               "assume_master_slave": {"0": ["contact_left"]},
                               "advance_ALM_parameters": {"manual_ALM": True, "penalty": penalty(nx)}}}]},
    }
    write_json_files(out_dir, {"bar_impact_materials.json": materials, "ProjectParameters.json": parameters})
    return os.path.join(out_dir, "ProjectParameters.json")


def set_initial_velocities(root) -> None:
    """VELOCITY +SPEED on the left bar, -SPEED on the right one (historical, current step): call it
    after the analysis' Initialize."""
    velocity = _variable("VELOCITY")
    for bar, v in (("left", SPEED), ("right", -SPEED)):
        for node in root.GetSubModelPart(bar).Nodes:
            node.SetSolutionStepValue(velocity, [v, 0.0, 0.0])


def bar_state(root) -> list[float]:
    """[mean velocity (momentum / mass), kinetic energy, mass] of the left bar, then the right one,
    from the lumped masses (NODAL_MASS) and the half-step velocities."""
    state = []
    for bar in ("left", "right"):
        nodes = root.GetSubModelPart(bar).Nodes
        m = np.array([n.GetValue(_variable("NODAL_MASS")) for n in nodes])
        v = np.array([n.GetSolutionStepValue(_variable("VELOCITY"))[0] for n in nodes])
        state += [float(m @ v) / m.sum(), 0.5 * float(m @ v ** 2), float(m.sum())]
    return state


def _variable(name: str):
    from .. import _core

    return _core.GetVariable(name)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--nx", type=int, default=NX)
    args = parser.parse_args(argv)
    print(write_case(os.path.join(args.out, "bar_impact"), args.nx))
    return 0


if __name__ == "__main__":
    sys.exit(main())
