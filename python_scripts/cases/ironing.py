# SPDX-License-Identifier: BSD-3-Clause
"""The ironing problem in 2D plane strain: a stiff circular die pressed into an elastic slab and
dragged along it with Coulomb friction (after Puso & Laursen 2004 and Yang, Laursen & Meng 2005).

The variant here: the materials of the 2D ironing inputs in circulation (die E = 6896, slab
E = 689.6, both nu = 0.32), friction mu = 0.3, a die whose contact face is an arc of radius
``RADIUS`` (the circular segment below the chord DIE_HEIGHT above its lowest point), a slab
[0, SLAB_LENGTH] x [-SLAB_HEIGHT, 0] clamped at its bottom. The die's top is pushed down by
DEPTH in ``PRESS_STEPS`` load steps, then moved along x by TRAVEL in ``DRAG_STEPS`` more steps
(end time 1), its vertical displacement held. Small-displacement solids (the die only translates; the
slab's strains stay below about 10 %); the contact is evaluated in the current configuration,
so the die slides over many slab elements. The published reaction curves of the papers were not
available in a form to compare against; the checks are the ones that hold for any ironing run:
global equilibrium (die-top reaction against slab-bottom reaction) and, while the die slides,
Coulomb's law at every slipping node and the ratio of the total tangential to the total normal
contact force, mu.

    python -m mortarcontact.cases.ironing --out /tmp/cases
"""
from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np

from . import hertz
from .mesh_files import write_case_mesh, write_json_files

RADIUS = 3.0
DIE_HEIGHT = 1.0
DIE_START = 2.5  # x of the die's lowest point
SLAB_LENGTH, SLAB_HEIGHT = 12.0, 2.0
YOUNG = {"die": 6896.0, "slab": 689.6}
POISSON = 0.32
FRICTION = 0.3
DEPTH, TRAVEL = 0.3, 3.0
PRESS_STEPS, DRAG_STEPS = 6, 60
H_DIE, H_SLAB = 0.08, 0.12  # element sizes at the contact (the slab coarsens with depth)


def mesh():
    """(die, slab) as (coordinates (n, 3), triangles) from gmsh, through hertz.mesh_bodies."""
    import gmsh

    def die():
        geo = gmsh.model.geo
        half = math.sqrt(RADIUS ** 2 - (RADIUS - DIE_HEIGHT) ** 2)
        centre = geo.addPoint(DIE_START, RADIUS, 0)
        left, bottom = geo.addPoint(DIE_START - half, DIE_HEIGHT, 0), geo.addPoint(DIE_START, 0, 0)
        right = geo.addPoint(DIE_START + half, DIE_HEIGHT, 0)
        arcs = [geo.addCircleArc(left, centre, bottom), geo.addCircleArc(bottom, centre, right)]
        geo.addPlaneSurface([geo.addCurveLoop([*arcs, geo.addLine(right, left)])])
        geo.synchronize()

    def slab():
        gmsh.model.occ.addRectangle(0.0, -SLAB_HEIGHT, 0.0, SLAB_LENGTH, SLAB_HEIGHT)
        gmsh.model.occ.synchronize()

    def size(_dim, _tag, x, y, _z, _lc):
        return H_DIE if y > -1e-9 else min(0.5, H_SLAB - 0.2 * y)

    return hertz.mesh_bodies(2, size, die, slab)


def write_case(out_dir: str, friction: float = FRICTION, slip_augmentation: float = 0.0) -> str:
    """Writes ``out_dir/ironing_2d/`` (gmsh mesh, materials, ProjectParameters.json) and returns it."""
    name = "ironing_2d"
    folder = os.path.join(out_dir, name)
    os.makedirs(folder, exist_ok=True)
    (xd, cd), (xs, cs) = mesh()
    nd = len(xd)
    coords = np.vstack([xd, xs])
    tol = 1e-9
    on_arc = np.abs(np.hypot(xd[:, 0] - DIE_START, xd[:, 1] - RADIUS) - RADIUS) < 1e-7
    die_slave = np.unique(hertz.interface_faces(cd, np.flatnonzero(on_arc & (xd[:, 1] < DIE_HEIGHT - tol))))
    slab_master = np.unique(hertz.interface_faces(cs, np.flatnonzero(np.abs(xs[:, 1]) < tol)))
    parts = {"Parts_die": {"nodes": np.arange(nd), "elements": np.arange(1, len(cd) + 1)},
             "Parts_slab": {"nodes": nd + np.arange(len(xs)), "elements": len(cd) + np.arange(1, len(cs) + 1)},
             "DISPLACEMENT_top": {"nodes": np.flatnonzero(np.abs(xd[:, 1] - DIE_HEIGHT) < tol)},
             "DISPLACEMENT_bottom": {"nodes": nd + np.flatnonzero(np.abs(xs[:, 1] + SLAB_HEIGHT) < tol)},
             "Contact_slave": {"nodes": die_slave}, "Contact_master": {"nodes": nd + slab_master}}
    model_import = write_case_mesh(os.path.join(folder, f"{name}.msh"), coords,
                                   [("SmallDisplacementElement2D3N", 1, cd),
                                    ("SmallDisplacementElement2D3N", len(cd) + 1, cs + nd)], parts)
    materials = {"properties": [
        {"model_part_name": f"Structure.Parts_{part}", "properties_id": pid,
         "Material": {"name": part, "constitutive_law": {"name": "LinearElasticPlaneStrain2DLaw"},
                      "Variables": {"YOUNG_MODULUS": YOUNG[part], "POISSON_RATIO": POISSON, "DENSITY": 1.0,
                                    "THICKNESS": 1.0, "FRICTION_COEFFICIENT": friction}, "Tables": {}}}
        for pid, part in ((1, "die"), (2, "slab"))]}
    dt = 1.0 / (PRESS_STEPS + DRAG_STEPS)
    t_press = PRESS_STEPS * dt
    press = hertz.assign_displacement("DISPLACEMENT_top", [True, True, False],
                                      [0.0, f"-{DEPTH / t_press!r}*t", 0.0])
    press["Parameters"]["interval"] = [0.0, t_press + 0.5 * dt]
    drag = hertz.assign_displacement("DISPLACEMENT_top", [True, True, False],
                                     [f"{TRAVEL / (1.0 - t_press)!r}*(t-{t_press!r})", -DEPTH, 0.0])
    drag["Parameters"]["interval"] = [t_press + 0.5 * dt, "End"]
    parameters = {
        "problem_data": {"problem_name": name, "parallel_type": "OpenMP", "echo_level": 0,
                         "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {
            "model_part_name": "Structure", "domain_size": 2, "solver_type": "Static", "echo_level": 0,
            "analysis_type": "non_linear", "buffer_size": 3,
            "model_import_settings": model_import,
            "material_import_settings": {"materials_filename": f"{name}_materials.json"},
            "contact_settings": {"mortar_type": "ALMContactFrictional"},
            "time_stepping": {"time_step": dt},
            "compute_reactions": True, "convergence_criterion": "contact_residual_criterion",
            "residual_relative_tolerance": 1e-6, "residual_absolute_tolerance": 1e-10, "max_iteration": 30,
            "linear_solver_settings": {"solver_type": "LinearSolversApplication.sparse_lu"}},
        "processes": {
            "constraints_process_list": [
                hertz.assign_displacement("DISPLACEMENT_bottom", [True, True, True], [0.0, 0.0, 0.0]), press, drag],
            "loads_process_list": [],
            "contact_process_list": [{
                "python_module": "alm_contact_process",
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "process_name": "ALMContactProcess",
                "Parameters": {"model_part_name": "Structure", "contact_type": "Frictional",
                               "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
                               "assume_master_slave": {"0": ["Contact_slave"]},
                               "slip_augmentation_coefficient": slip_augmentation}}]},
        "output_processes": {}}
    # mortarcontact's globalized set update (the contact strategy's key, not Kratos'): without it
    # step 19 does not converge
    parameters["solver_settings"]["contact_settings"]["active_set_line_search"] = True
    write_json_files(folder, {f"{name}_materials.json": materials, "ProjectParameters.json": parameters})
    return folder


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="output folder")
    args = parser.parse_args(argv)
    print(write_case(args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
