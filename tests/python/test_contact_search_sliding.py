"""Issue 10: the contact search pairs a slave face with the master faces it will slide onto within
the step. A block (nu = 0) is pressed by its top onto a base (nu = 0.3) of the same footprint, both
on symmetry planes: the base's top spreads under the block. The block's mesh is twice as fine as
the base's, so every other slave node lies over a master edge at the start, where the slave faces
only touch the master faces beyond that edge; as the base spreads, those faces come under them.
Every overlap is part of the interface: the nodal areas (the integrals of the slave shape
functions over the overlaps) must be the slave faces' areas. With the faces that only touched left
unpaired they were up to 4.6 % short, and the pressures followed."""
from __future__ import annotations

import json

import numpy as np

import mortarcontact as mc

from case_builder import fix_process, run_analysis, structured_hexes, write_case, write_mdpa

YOUNG = 1.0e6
PRESS = 0.02  # top displacement: 2 % strain in both bodies
BASE_POISSON = 0.3


def _write_case(folder) -> str:
    block_xyz, block_cells = structured_hexes(6, 6, 2, 1.0, 1.0, 0.5)
    base_xyz, base_cells = structured_hexes(3, 3, 2, 1.0, 1.0, 0.5)
    base_xyz = base_xyz - [0.0, 0.0, 0.5]
    nb = len(block_xyz)
    n_block = len(block_cells)
    coords = np.vstack([block_xyz, base_xyz])
    ids = np.arange(1, len(coords) + 1)

    z = coords[:, 2]
    in_block = ids <= nb
    sub_parts = {
        "Parts_block": {"nodes": ids[:nb], "elements": range(1, n_block + 1)},
        "Parts_base": {"nodes": ids[nb:], "elements": range(n_block + 1, n_block + len(base_cells) + 1)},
        "Contact_slave": {"nodes": ids[in_block & (np.abs(z) < 1e-12)]},
        "Contact_master": {"nodes": ids[~in_block & (np.abs(z) < 1e-12)]},
        "Symmetry_x": {"nodes": ids[np.abs(coords[:, 0]) < 1e-12]},
        "Symmetry_y": {"nodes": ids[np.abs(coords[:, 1]) < 1e-12]},
        "Base_bottom": {"nodes": ids[np.abs(z + 0.5) < 1e-12]},
        "Block_top": {"nodes": ids[np.abs(z - 0.5) < 1e-12]},
    }
    cells = list(block_cells) + [tuple(int(i) + nb for i in c) for c in base_cells]
    write_mdpa(f"{folder}/sliding_patch.mdpa", coords, {"SmallDisplacementElement3D8N": cells}, sub_parts=sub_parts)
    materials = {"properties": [
        {"model_part_name": f"Structure.{part}", "properties_id": pid,
         "Material": {"constitutive_law": {"name": "LinearElastic3DLaw"},
                      "Variables": {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": nu, "DENSITY": 1.0}, "Tables": {}}}
        for pid, part, nu in ((1, "Parts_block", 0.0), (2, "Parts_base", BASE_POISSON))]}
    parameters = {
        "problem_data": {"problem_name": "sliding_patch", "parallel_type": "OpenMP", "echo_level": 0,
                         "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {
            "model_part_name": "Structure", "domain_size": 3, "solver_type": "Static", "echo_level": 0,
            "analysis_type": "non_linear",
            "model_import_settings": {"input_type": "mdpa", "input_filename": "sliding_patch"},
            "material_import_settings": {"materials_filename": "sliding_patch_materials.json"},
            "contact_settings": {"mortar_type": "ALMContactFrictionless"},
            "time_stepping": {"time_step": 1.0}, "compute_reactions": True,
            "convergence_criterion": "contact_residual_criterion",
            "residual_relative_tolerance": 1e-12, "residual_absolute_tolerance": 1e-20, "max_iteration": 30},
        "processes": {
            "constraints_process_list": [
                fix_process("Structure.Symmetry_x", [0.0, 0.0, 0.0], (True, False, False)),
                fix_process("Structure.Symmetry_y", [0.0, 0.0, 0.0], (False, True, False)),
                fix_process("Structure.Base_bottom", [0.0, 0.0, 0.0], (False, False, True)),
                fix_process("Structure.Block_top", [0.0, 0.0, -PRESS], (False, False, True))],
            "loads_process_list": [],
            "contact_process_list": [{
                "python_module": "alm_contact_process",
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "Parameters": {"model_part_name": "Structure", "contact_type": "Frictionless",
                               "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
                               "assume_master_slave": {"0": ["Contact_slave"]}}}]},
        "output_processes": {}}
    return write_case(folder, "sliding_patch", parameters, materials)


def test_sliding_interface_is_covered(tmp_path):
    analysis = run_analysis(tmp_path, _write_case(tmp_path))
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    root = analysis.model["Structure"]
    slave = root.GetSubModelPart("Contact_slave")
    # The base spread under the slave nodes that started over its edges at x = 1/3 by about
    # nu * PRESS / 3 = 2e-3, 1.2 % of a slave face.
    spread = [node.GetSolutionStepValue(mc.DISPLACEMENT)[0] for node in root.GetSubModelPart("Contact_master").Nodes
              if abs(node.X0 - 1.0 / 3.0) < 1e-12]
    assert min(spread) > 1.9e-3
    # Each slave node's share of its faces' current areas (bilinear faces: a quarter each).
    position = {node.Id: np.array([node.X0, node.Y0]) + node.GetSolutionStepValue(mc.DISPLACEMENT)[:2]
                for node in slave.Nodes}
    grid = {(round(node.X0 * 6), round(node.Y0 * 6)): node.Id for node in slave.Nodes}
    share = dict.fromkeys(position, 0.0)
    for i in range(6):
        for j in range(6):
            corners = [grid[(i, j)], grid[(i + 1, j)], grid[(i + 1, j + 1)], grid[(i, j + 1)]]
            d1 = position[corners[2]] - position[corners[0]]
            d2 = position[corners[3]] - position[corners[1]]
            for k in corners:
                share[k] += 0.125 * abs(d1[0] * d2[1] - d1[1] * d2[0])
    area = mc.GetVariable("NODAL_AREA")
    # The block's far edges (x = 1, y = 1) overhang the base by the little the base's edge lags.
    inner = [node for node in slave.Nodes if node.X0 < 0.99 and node.Y0 < 0.99]
    error = {f"{node.X0:.3f},{node.Y0:.3f}": node.GetValue(area) / share[node.Id] - 1.0 for node in inner}
    assert max(abs(e) for e in error.values()) < 1e-5, json.dumps(error)
