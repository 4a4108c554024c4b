"""Issue 12: Tresca friction (contact process frictional_law "Tresca", TRESCA_FRICTION_THRESHOLD in
the materials). A block (1 x 0.5) pressed onto a wider, 10^4 times stiffer base (2 x 1, fixed at
its bottom, a non-matching mesh) and dragged sideways far enough to slide: the tangential force
the interface carries is the threshold times the contact length (plane strain, thickness 1),
whatever the normal push, where Coulomb's grows with it. Both at each slave node (the pairs'
forces) and in the support reaction of the base (the flat interface of the stiff base keeps the
normal forces vertical)."""
from __future__ import annotations

import json
import os

import numpy as np
import pytest

import mortarcontact as mc

from case_builder import (
    fix_process,
    materials,
    project_parameters,
    run_analysis,
    structured_quads,
    write_case,
    write_mdpa,
)

E, NU = 2.0e5, 0.3
BASE_E = 1e4 * E
TAU = 40.0    # Tresca threshold (stress)
DRAG = 0.05   # tangential displacement of the block's top, in two steps
#: Newton close to round-off: the tangential force is a small part of the residual (the default
#: squared relative tolerance 1e-4 stops 2 % off the threshold).
TIGHT = {f"{block}_residual_{kind}_tolerance": value
         for block in ("contact", "frictional_stick_contact", "frictional_slip_contact")
         for kind, value in (("relative", 1e-16), ("absolute", 1e-12))}


def write_blocks(folder: str, push: float, mortar_type: str, law: str, base_young: float) -> str:
    base, base_cells = structured_quads(4, 2, 2.0, 1.0)
    block, block_cells = structured_quads(3, 2, 1.0, 0.5)
    block[:, 0] += 0.5
    block[:, 1] += 1.0
    coords = np.vstack([base, block])
    offset = len(base)
    cells = list(base_cells) + [tuple(i + offset for i in c) for c in block_cells]
    ids = np.arange(1, len(coords) + 1)
    base_ids, block_ids = ids[:offset], ids[offset:]
    on = lambda part, y: [int(i) for i in part if abs(coords[i - 1, 1] - y) < 1e-12]  # noqa: E731
    sub_parts = {
        "base": {"nodes": base_ids.tolist(), "elements": list(range(1, len(base_cells) + 1))},
        "block": {"nodes": block_ids.tolist(), "elements": list(range(len(base_cells) + 1, len(cells) + 1))},
        "bottom": {"nodes": on(base_ids, 0.0)},
        "top": {"nodes": on(block_ids, 1.5)},
        "contact_slave": {"nodes": on(block_ids, 1.0)},
        "contact": {"nodes": on(base_ids, 1.0) + on(block_ids, 1.0)},
    }
    write_mdpa(os.path.join(folder, "blocks.mdpa"), coords, {"SmallDisplacementElement2D4N": cells},
               sub_parts=sub_parts)
    penalty = mortar_type.startswith("Penalty")
    contact = {"python_module": "penalty_contact_process" if penalty else "alm_contact_process",
               "kratos_module": "ContactStructuralMechanicsApplication",
               "Parameters": {"model_part_name": "Structure", "contact_model_part": {"0": ["contact"]},
                              "assume_master_slave": {"0": ["contact_slave"]}, "contact_type": "Frictional",
                              "frictional_law": law}}
    parameters = project_parameters(
        "blocks", 2, end_time=2.0,
        constraints=[fix_process("Structure.bottom", (0.0, 0.0, 0.0)),
                     fix_process("Structure.top", (f"{DRAG / 2}*(t-1)", -push, 0.0))],
        solver={"convergence_criterion": "contact_residual_criterion", "buffer_size": 3, "max_iteration": 30,
                "residual_relative_tolerance": 1e-16, "residual_absolute_tolerance": 1e-12,
                "contact_settings": {"mortar_type": mortar_type, **TIGHT}})
    parameters["processes"]["contact_process_list"] = [contact]
    materials_data = materials("Structure.base", "LinearElasticPlaneStrain2DLaw", base_young, NU,
                               TRESCA_FRICTION_THRESHOLD=TAU, FRICTION_COEFFICIENT=0.3)
    block_material = json.loads(json.dumps(materials_data["properties"][0]))
    block_material.update(model_part_name="Structure.block", properties_id=2)
    block_material["Material"]["Variables"]["YOUNG_MODULUS"] = E
    materials_data["properties"].append(block_material)
    return write_case(folder, "blocks", parameters, materials_data)


def drag_force(folder: str, push: float, mortar_type: str, law: str = "Tresca",
               base_young: float = BASE_E) -> tuple[float, float, float]:
    """At the end of the drag: the tangential force the contact pairs apply to the slave (the sum
    over its nodes of the part of their nodal force normal to NORMAL, from the pairs' right-hand
    sides), the support reaction of the base along x, and the current length of the slave face."""
    path = write_blocks(folder, push, mortar_type, law, base_young)
    analysis = run_analysis(folder, path)
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    root = analysis.model["Structure"]
    slave = root.GetSubModelPart("contact_slave")
    assert all(node.Is(mc.ACTIVE) and node.Is(mc.SLIP) for node in slave.Nodes)
    forces = {}
    for pair in root.GetSubModelPart("ComputingContact").Conditions:
        _, rhs = pair.CalculateLocalSystem(root.ProcessInfo)
        for i, node in enumerate(pair.GetNodes()):  # the slave rows follow the 2 x 2 master rows
            forces[node.Id] = forces.get(node.Id, np.zeros(2)) + np.asarray(rhs[4 + 2 * i:6 + 2 * i])
    tangential = 0.0
    for node in slave.Nodes:
        normal = np.asarray(node.GetSolutionStepValue(mc.NORMAL))[:2]
        force = forces[node.Id]
        tangential += np.linalg.norm(force - normal * normal.dot(force))
    x = np.array([[node.X0 + node.GetSolutionStepValue(mc.DISPLACEMENT)[0],
                   node.Y0 + node.GetSolutionStepValue(mc.DISPLACEMENT)[1]] for node in slave.Nodes])
    x = x[np.argsort(x[:, 0])]
    reaction = root.GetSubModelPart("bottom").GetNodalValues(mc.REACTION)[:, 0].sum()
    return tangential, reaction, float(np.linalg.norm(np.diff(x, axis=0), axis=1).sum())


@pytest.mark.parametrize("mortar_type", ["ALMContactFrictional", "PenaltyContactFrictional"])
def test_sliding_block_carries_the_threshold_times_the_contact_length(tmp_path, mortar_type):
    for push in (0.005, 0.01):
        force, reaction, length = drag_force(str(tmp_path), push, mortar_type)
        print(f"{mortar_type}, push {push}: Tresca force {force:.12g}, base reaction {reaction:.12g}, "
              f"threshold x length {TAU * length:.12g}")
        assert force == pytest.approx(TAU * length, rel=1e-10)
        # The base is pulled along the drag (+x): its support pulls back.
        assert -reaction == pytest.approx(TAU * length, rel=5e-4)


def test_coulomb_law_ignores_the_threshold_and_grows_with_the_push(tmp_path):
    """The same materials (FRICTION_COEFFICIENT 0.3 and a threshold; a base as stiff as the block)
    with the Coulomb law: the threshold has no effect and the force is mu times the normal force,
    about twice as large for twice the push."""
    forces = [drag_force(str(tmp_path), push, "ALMContactFrictional", "Coulomb", E)[0] for push in (0.005, 0.01)]
    print(f"Coulomb forces {forces}")
    assert forces[1] > 1.8 * forces[0] > 2 * TAU
