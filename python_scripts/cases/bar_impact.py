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
import json
import math
import os
import sys

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


def _mdpa(nx: int) -> str:
    h = LENGTH / nx
    nodes, elements = [], []
    parts = {"left": ([], []), "right": ([], [])}
    node_id = 0
    layers = {}
    for bar, x0 in (("left", -LENGTH - GAP / 2.0), ("right", GAP / 2.0)):
        for i in range(nx + 1):
            layer = []
            for y, z in ((0.0, 0.0), (SIDE, 0.0), (SIDE, SIDE), (0.0, SIDE)):
                node_id += 1
                nodes.append(f"{node_id} {x0 + i * h:.16g} {y:.16g} {z:.16g}")
                layer.append(node_id)
                parts[bar][0].append(node_id)
            layers[bar, i] = layer
        for i in range(nx):
            a, b = layers[bar, i], layers[bar, i + 1]
            elements.append((bar, len(elements) + 1, [a[0], b[0], b[1], a[1], a[3], b[3], b[2], a[2]]))
            parts[bar][1].append(len(elements))
    lines = ["Begin Properties 0", "End Properties", "Begin Nodes", *nodes, "End Nodes",
             "Begin Elements SmallDisplacementElement3D8N"]
    lines += [f"{eid} 0 {' '.join(map(str, conn))}" for _, eid, conn in elements]
    lines.append("End Elements")

    def sub(name, node_ids, element_ids=()):
        return ([f"Begin SubModelPart {name}", "Begin SubModelPartNodes", *map(str, node_ids), "End SubModelPartNodes",
                 "Begin SubModelPartElements", *map(str, element_ids), "End SubModelPartElements",
                 "End SubModelPart"])

    lines += sub("left", *parts["left"]) + sub("right", *parts["right"])
    lines += sub("contact_left", layers["left", nx]) + sub("contact_right", layers["right", 0])
    lines += sub("all_nodes", list(range(1, node_id + 1)))
    return "\n".join(lines) + "\n"


def write_case(out_dir: str, nx: int = NX, time_step: float | None = None, end_time: float | None = None) -> str:
    """Writes bar_impact.mdpa, its materials and ProjectParameters.json into `out_dir`; returns
    the parameters' path. Default time step: 0.9 of the critical one with the penalty springs,
    h / (c sqrt(1 + STIFFNESS_RATIO)) (omega^2 = 4 c^2 / h^2 of the end element plus the spring's
    STIFFNESS_RATIO times that between two end-node masses); default end: 1.5 times the contact
    duration."""
    os.makedirs(out_dir, exist_ok=True)
    c = wave_speed()
    with open(os.path.join(out_dir, "bar_impact.mdpa"), "w") as f:
        f.write(_mdpa(nx))
    law = {"name": "LinearElastic3DLaw"}
    materials = {"properties": [
        {"model_part_name": f"Structure.{bar}", "properties_id": i + 1,
         "Material": {"constitutive_law": law, "Variables": {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": 0.0,
                                                              "DENSITY": DENSITY}}}
        for i, bar in enumerate(("left", "right"))]}
    with open(os.path.join(out_dir, "bar_impact_materials.json"), "w") as f:
        json.dump(materials, f, indent=1)
    parameters = {
        "problem_data": {"problem_name": "bar_impact", "parallel_type": "OpenMP", "start_time": 0.0,
                         "end_time": end_time if end_time is not None else 1.5 * 2.0 * LENGTH / c, "echo_level": 0},
        "solver_settings": {
            "model_part_name": "Structure", "solver_type": "Dynamic", "time_integration_method": "explicit",
            "domain_size": 3, "echo_level": 0, "analysis_type": "non_linear",
            "model_import_settings": {"input_type": "mdpa", "input_filename": "bar_impact"},
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
    path = os.path.join(out_dir, "ProjectParameters.json")
    with open(path, "w") as f:
        json.dump(parameters, f, indent=1)
    return path


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
    import numpy as np

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
