"""Hertz contact of a cylinder on a block (plane strain, frictionless ALM mortar contact).

A cylinder of radius R = 1 is pressed by a displacement of its top onto an elastic block in four load
steps (E = 1000, nu = 0.3 for both bodies). For a contact half-width a << R, Hertz' theory gives
    a = sqrt(4 P R / (pi E*)),   p(x) = p0 sqrt(1 - x^2 / a^2),   p0 = 2 P / (pi a),
with E* = E / (2 (1 - nu^2)) for two equal bodies and P the force per unit thickness.
This script meshes the case with gmsh (mortarcontact.cases.hertz: a .msh with physical groups,
read with model_import_settings.input_type "gmsh"), adds a ParaView output, runs it with
mortarcontact and draws hertz_cylinder.png: the computed contact pressure against Hertz' ellipse,
and the deformed mesh near the contact coloured by pressure.
Usage: python run_demo.py [2k|8k|30k]   (default 8k, about 7k DoFs)
"""
from __future__ import annotations

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

import mortarcontact as mc
from mortarcontact.cases import hertz

HERE = os.path.dirname(os.path.abspath(__file__))

OUTPUT = {"vtk_output": [{
    "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
    "Parameters": {"model_part_name": "Structure", "output_control_type": "step", "output_interval": 1,
                   "output_path": "vtk_output",
                   "nodal_solution_step_data_variables": ["DISPLACEMENT", "REACTION",
                                                          "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "WEIGHTED_GAP",
                                                          "NORMAL"],
                   "nodal_flags": ["ACTIVE", "SLAVE", "MASTER"],
                   "gauss_point_variables_in_elements": ["VON_MISES_STRESS"]}}]}


def main() -> None:
    size = sys.argv[1] if len(sys.argv) > 1 else "8k"
    folder = hertz.write_case("hertz2d", size, os.path.join(HERE, "case"))
    parameters_file = os.path.join(folder, "ProjectParameters.json")
    with open(parameters_file) as f:
        parameters = json.load(f)
    parameters["output_processes"] = OUTPUT
    parameters["problem_data"]["echo_level"] = 1
    with open(parameters_file, "w") as f:
        json.dump(parameters, f, indent=4)
    reference = hertz.load_reference(folder)

    os.chdir(folder)
    analysis = mc.run("ProjectParameters.json")
    root = analysis.model["Structure"]
    scale = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    force = abs(root.GetSubModelPart("DISPLACEMENT_bottom").GetNodalValues(mc.REACTION)[:, 1].sum())
    theory = hertz.hertz_2d(force, reference["radius"], reference["effective_modulus"])
    slave = root.GetSubModelPart("Contact_slave")
    x = slave.NodeCoordinates(initial=True)[:, 0]
    pressure = np.maximum(-scale * slave.GetNodalValues(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), 0.0)
    order = np.argsort(x)
    a, p0 = theory["half_width"], theory["peak_pressure"]
    print(f"force per unit thickness {force:.4g}; Hertz: a = {a:.4g}, p0 = {p0:.4g}; "
          f"computed peak {pressure.max():.4g} ({pressure.max() / p0 - 1:+.2%})")

    fig, (left, right) = plt.subplots(1, 2, figsize=(14, 5.5))
    xs = np.linspace(-a, a, 400)
    left.plot(xs / a, p0 * np.sqrt(1 - (xs / a) ** 2) / p0, "k-", label="Hertz")
    left.plot(x[order] / a, pressure[order] / p0, "o-", ms=4, label="mortarcontact (slave nodes)")
    left.set_xlim(-2, 2)
    left.set_xlabel("x / a")
    left.set_ylabel("contact pressure / p0")
    left.set_title(f"Cylinder on block: peak {pressure.max() / p0 - 1:+.1%} vs Hertz, "
                   f"{sum(1 for p in pressure if p > 0)} nodes in contact")
    left.grid(alpha=0.3)
    left.legend()

    points = root.NodeCoordinates(initial=False)[:, :2]
    ids = {int(i): k for k, i in enumerate(root.NodeIds())}
    polygons, stress = [], []
    for name, (element_ids, connectivity) in root.EntityConnectivity(False).items():
        values = root.IntegrationPointMeans(mc.VON_MISES_STRESS, list(element_ids), False)
        for nodes, value in zip(connectivity, values):
            polygon = points[[ids[int(n)] for n in nodes[:3 if "Triangle" in name else 4]]]
            center = polygon.mean(axis=0)
            if abs(center[0]) < 0.7 and abs(center[1]) < 0.6:
                polygons.append(polygon)
                stress.append(value)
    collection = PolyCollection(polygons, array=np.array(stress), cmap="viridis", edgecolors="k", linewidths=0.1)
    right.add_collection(collection)
    right.set_xlim(-0.6, 0.6)
    right.set_ylim(-0.5, 0.5)
    right.set_aspect("equal")
    right.set_title("von Mises stress near the contact (deformed mesh)")
    fig.colorbar(collection, ax=right, label="von Mises stress")
    fig.tight_layout()
    out = os.path.join(HERE, "hertz_cylinder.png")
    fig.savefig(out, dpi=120)
    print(f"wrote {out} and ParaView files in {os.path.join(folder, 'vtk_output')}")


if __name__ == "__main__":
    main()
