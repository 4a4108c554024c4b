"""Writes small Kratos-format cases (mdpa + ProjectParameters.json + materials.json) for tests."""
from __future__ import annotations

import contextlib
import json
import os

import numpy as np


def structured_quads(nx: int, ny: int, lx: float, ly: float, order: int = 1):
    """Nodes and counter-clockwise quadrilaterals (4, 8 or 9 nodes for order 1, 2 ('serendipity') or
    3 ('lagrange' 9-node)) on [0, lx] x [0, ly]. Returns (coords (n, 2), connectivity list of tuples)."""
    step = 1 if order == 1 else 2
    mx, my = nx * step, ny * step
    ids = np.zeros((mx + 1, my + 1), dtype=int)
    coords = []
    for i in range(mx + 1):
        for j in range(my + 1):
            if order == 2 and i % 2 == 1 and j % 2 == 1:
                continue  # serendipity elements have no centre node
            ids[i, j] = len(coords) + 1
            coords.append((lx * i / mx, ly * j / my))
    cells = []
    for ex in range(nx):
        for ey in range(ny):
            i, j = ex * step, ey * step
            corners = (ids[i, j], ids[i + step, j], ids[i + step, j + step], ids[i, j + step])
            if order == 1:
                cells.append(corners)
            else:
                mids = (ids[i + 1, j], ids[i + 2, j + 1], ids[i + 1, j + 2], ids[i, j + 1])
                cells.append(corners + mids + ((ids[i + 1, j + 1],) if order == 3 else ()))
    return np.array(coords), cells


def structured_hexes(nx: int, ny: int, nz: int, lx: float, ly: float, lz: float):
    ids = np.arange(1, (nx + 1) * (ny + 1) * (nz + 1) + 1).reshape(nx + 1, ny + 1, nz + 1)
    coords = [(lx * i / nx, ly * j / ny, lz * k / nz)
              for i in range(nx + 1) for j in range(ny + 1) for k in range(nz + 1)]
    cells = []
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                cells.append((ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k],
                              ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]))
    return np.array(coords), cells


def write_mdpa(path: str, coords, elements: dict, conditions: dict | None = None, sub_parts: dict | None = None):
    """elements / conditions: {registered name: [connectivity, ...]} (ids numbered consecutively);
    sub_parts: {name: {"nodes": [...], "elements": [...], "conditions": [...]}}."""
    conditions = conditions or {}
    sub_parts = sub_parts or {}
    with open(path, "w") as f:
        f.write("Begin ModelPartData\nEnd ModelPartData\n\nBegin Properties 0\nEnd Properties\n\nBegin Nodes\n")
        for k, x in enumerate(coords):
            x = list(x) + [0.0] * (3 - len(x))
            f.write(f"{k + 1} {x[0]:.16e} {x[1]:.16e} {x[2]:.16e}\n")
        f.write("End Nodes\n\n")
        for block, entities in (("Elements", elements), ("Conditions", conditions)):
            counter = 0
            for name, cells in entities.items():
                f.write(f"Begin {block} {name}\n")
                for cell in cells:
                    counter += 1
                    f.write(f"{counter} 0 " + " ".join(str(int(n)) for n in cell) + "\n")
                f.write(f"End {block}\n\n")
        for name, content in sub_parts.items():
            f.write(f"Begin SubModelPart {name}\n")
            for key, block in (("nodes", "Nodes"), ("elements", "Elements"), ("conditions", "Conditions")):
                f.write(f"  Begin SubModelPart{block}\n")
                for i in content.get(key, []):
                    f.write(f"    {int(i)}\n")
                f.write(f"  End SubModelPart{block}\n")
            f.write("End SubModelPart\n\n")


def materials(part: str, law: str, young: float, poisson: float, **extra) -> dict:
    variables = {"YOUNG_MODULUS": young, "POISSON_RATIO": poisson, **extra}
    return {"properties": [{"model_part_name": part, "properties_id": 1,
                            "Material": {"constitutive_law": {"name": law}, "Variables": variables, "Tables": {}}}]}


def fix_process(part: str, value, constrained=(True, True, True), variable="DISPLACEMENT",
                interval=(0.0, "End")) -> dict:
    return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": part, "variable_name": variable, "value": list(value),
                           "constrained": list(constrained), "interval": list(interval)}}


def condition_load_process(part: str, variable: str, value) -> dict:
    return {"python_module": "assign_vector_variable_to_conditions_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": part, "variable_name": variable, "value": list(value),
                           "interval": [0.0, "End"]}}


def project_parameters(name: str, domain_size: int, *, constraints=(), loads=(), solver: dict | None = None,
                       end_time: float = 1.0, time_step: float = 1.0, outputs: dict | None = None) -> dict:
    solver_settings = {
        "solver_type": "Static", "model_part_name": "Structure", "domain_size": domain_size, "echo_level": 0,
        "analysis_type": "non_linear",
        "model_import_settings": {"input_type": "mdpa", "input_filename": name},
        "material_import_settings": {"materials_filename": f"{name}_materials.json"},
        "time_stepping": {"time_step": time_step},
        "convergence_criterion": "residual_criterion",
        "residual_relative_tolerance": 1e-10, "residual_absolute_tolerance": 1e-12, "max_iteration": 20,
        "linear_solver_settings": {"solver_type": "skyline_lu_factorization"},
    }
    solver_settings.update(solver or {})
    return {"problem_data": {"problem_name": name, "parallel_type": "OpenMP", "echo_level": 0,
                             "start_time": 0.0, "end_time": end_time},
            "solver_settings": solver_settings,
            "processes": {"constraints_process_list": list(constraints), "loads_process_list": list(loads)},
            "output_processes": outputs or {}}


def write_case(folder, name: str, parameters: dict, materials_data: dict) -> str:
    path = os.path.join(folder, f"{name}_parameters.json")
    with open(path, "w") as f:
        json.dump(parameters, f, indent=2)
    with open(os.path.join(folder, f"{name}_materials.json"), "w") as f:
        json.dump(materials_data, f, indent=2)
    return path


def write_block_on_base(folder, name: str, *, block: tuple, base: tuple, cells: tuple, friction: float,
                        gravity: tuple, solver: dict, contact: dict, end_time: float, time_step: float,
                        ramp: float = 0.0) -> str:
    """A block (nx, ny cells) resting on the top of a base clamped at its bottom (bx, by cells),
    plane strain, linear quadrilaterals, both E = 1e6, nu = 0.3, rho = 1, FRICTION_COEFFICIENT
    `friction`; the block's bottom is the slave, its top-left corner node the sub-part block_corner and
    its left side's node at mid-height (when ny is even) block_side. `gravity` = (modulus, direction) on the block,
    raised linearly from 0 over the time `ramp` when it is positive; `contact` = (python_module,
    extra Parameters) of the contact process; `solver` updates the solver settings."""
    nx, ny, bx, by = cells
    block_xy, block_cells = structured_quads(nx, ny, *block)
    block_xy = block_xy - [block[0] / 2, 0.0]
    base_xy, base_cells = structured_quads(bx, by, *base)
    base_xy = base_xy - [base[0] / 2, base[1]]
    nb = len(block_xy)
    coords = np.vstack([block_xy, base_xy])
    ids = np.arange(1, len(coords) + 1)
    on_block_bottom = np.abs(block_xy[:, 1]) < 1e-12
    on_block_left = np.abs(block_xy[:, 0] + block[0] / 2) < 1e-12
    block_corner = ids[:nb][on_block_left & (np.abs(block_xy[:, 1] - block[1]) < 1e-12)]
    block_side = ids[:nb][on_block_left & (np.abs(block_xy[:, 1] - block[1] / 2) < 1e-12)]
    on_base_top = np.abs(base_xy[:, 1]) < 1e-12
    on_base_bottom = np.abs(base_xy[:, 1] + base[1]) < 1e-12
    n_block_cells = len(block_cells)
    write_mdpa(f"{folder}/{name}.mdpa", coords,
               {"SmallDisplacementElement2D4N": list(block_cells) + [tuple(int(i) + nb for i in c)
                                                                      for c in base_cells]},
               sub_parts={"Parts_block": {"nodes": ids[:nb], "elements": range(1, n_block_cells + 1)},
                          "Parts_base": {"nodes": ids[nb:],
                                         "elements": range(n_block_cells + 1, n_block_cells + len(base_cells) + 1)},
                          "Contact_slave": {"nodes": ids[:nb][on_block_bottom]},
                          "block_corner": {"nodes": block_corner},
                          "block_side": {"nodes": block_side},
                          "Contact_master": {"nodes": ids[nb:][on_base_top]},
                          "DISPLACEMENT_bottom": {"nodes": ids[nb:][on_base_bottom]}})
    return _block_on_base_case(folder, name, 2, friction=friction, gravity=gravity, solver=solver, contact=contact,
                               end_time=end_time, time_step=time_step, ramp=ramp)


def write_block_on_base_3d(folder, name: str, *, block: tuple, base: tuple, cells: tuple, friction: float,
                           gravity: tuple, solver: dict, contact: dict) -> str:
    """The 3D block on its base: a block (lx, ly, lz; nx, ny, nz hexahedra) centred on the top of a
    base (lx, ly, lz; bx, by, bz) clamped at its bottom, E = 1e6, nu = 0.3, rho = 1; the block's bottom
    is the slave, its top face the sub-part block_top. One static step;
    the other arguments as write_block_on_base's."""
    nx, ny, nz, bx, by, bz = cells
    block_xyz, block_cells = structured_hexes(nx, ny, nz, *block)
    block_xyz = block_xyz - [block[0] / 2, block[1] / 2, 0.0]
    base_xyz, base_cells = structured_hexes(bx, by, bz, *base)
    base_xyz = base_xyz - [base[0] / 2, base[1] / 2, base[2]]
    nb = len(block_xyz)
    ids = np.arange(1, nb + len(base_xyz) + 1)
    write_mdpa(f"{folder}/{name}.mdpa", np.vstack([block_xyz, base_xyz]),
               {"SmallDisplacementElement3D8N": list(block_cells) + [tuple(int(i) + nb for i in c)
                                                                      for c in base_cells]},
               sub_parts={"Parts_block": {"nodes": ids[:nb], "elements": range(1, len(block_cells) + 1)},
                          "Parts_base": {"nodes": ids[nb:], "elements": range(len(block_cells) + 1,
                                                                               len(block_cells) + len(base_cells) + 1)},
                          "Contact_slave": {"nodes": ids[:nb][np.abs(block_xyz[:, 2]) < 1e-12]},
                          "block_top": {"nodes": ids[:nb][np.abs(block_xyz[:, 2] - block[2]) < 1e-12]},
                          "Contact_master": {"nodes": ids[nb:][np.abs(base_xyz[:, 2]) < 1e-12]},
                          "DISPLACEMENT_bottom": {"nodes": ids[nb:][np.abs(base_xyz[:, 2] + base[2]) < 1e-12]}})
    return _block_on_base_case(folder, name, 3, friction=friction, gravity=gravity, solver=solver, contact=contact,
                               end_time=1.0, time_step=1.0, ramp=0.0)


def _block_on_base_case(folder, name: str, dim: int, *, friction: float, gravity: tuple, solver: dict, contact: dict,
                        end_time: float, time_step: float, ramp: float) -> str:
    """Materials, gravity on the block, the clamped base bottom and the contact process of the block
    on its base (write_block_on_base, write_block_on_base_3d)."""
    variables = {"YOUNG_MODULUS": 1.0e6, "POISSON_RATIO": 0.3, "DENSITY": 1.0, "THICKNESS": 1.0,
                 "FRICTION_COEFFICIENT": friction}
    law = "LinearElasticPlaneStrain2DLaw" if dim == 2 else "LinearElastic3DLaw"
    materials_data = {"properties": [
        {"model_part_name": f"Structure.{part}", "properties_id": pid,
         "Material": {"constitutive_law": {"name": law}, "Variables": dict(variables), "Tables": {}}}
        for pid, part in ((1, "Parts_block"), (2, "Parts_base"))]}
    modulus, direction = gravity

    def gravity_process(interval, value):
        return {"python_module": "assign_vector_by_direction_process", "kratos_module": "KratosMultiphysics",
                "process_name": "AssignVectorByDirectionProcess",
                "Parameters": {"model_part_name": "Structure.Parts_block", "variable_name": "VOLUME_ACCELERATION",
                               "interval": interval, "constrained": False, "modulus": value,
                               "direction": list(direction)}}

    loads = [gravity_process([ramp, "End"], modulus)]
    if ramp > 0.0:
        loads.insert(0, gravity_process([0.0, ramp], f"{modulus} * t / {ramp}"))
    parameters = project_parameters(
        name, dim, constraints=[fix_process("Structure.DISPLACEMENT_bottom", [0.0, 0.0, 0.0])],
        loads=loads, end_time=end_time, time_step=time_step, solver=solver)
    module, extra = contact
    parameters["processes"]["contact_process_list"] = [{
        "python_module": module, "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
        "Parameters": {"model_part_name": "Structure", "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
                       "assume_master_slave": {"0": ["Contact_slave"]}, **extra}}]
    return write_case(folder, name, parameters, materials_data)


def run_analysis(folder, path: str, analysis_class=None, **kwargs):
    """Runs the case `path` from inside `folder` (its relative file names are read there) with
    `analysis_class` (StructuralMechanicsAnalysis by default, without progress bar); returns it."""
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    with contextlib.chdir(folder):
        analysis = (analysis_class or StructuralMechanicsAnalysis)(mc.Model(), read_project_parameters(path),
                                                                   **{"progress": False, **kwargs})
        analysis.Run()
    return analysis
