# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Hertz contact in 2D: from a gmsh geometry to the contact pressure
#
# A cylinder of radius $R = 1$ (its lower half) is pressed onto an elastic block by a displacement
# of its flat top, in plane strain, with frictionless mortar contact (augmented Lagrangian, dual
# multipliers). Both bodies have $E = 1000$, $\nu = 0.3$ (consistent units: lengths in m, stresses
# in Pa). Hertz' line-contact theory, for a force $P$ per unit thickness and two equal bodies
# ($1/E^* = 2(1-\nu^2)/E$), gives
#
# $$a = \sqrt{\frac{4 P R}{\pi E^*}}, \qquad p(x) = p_0 \sqrt{1 - x^2/a^2}, \qquad p_0 = \frac{2P}{\pi a}.$$
#
# Steps: the geometry and its physical groups in gmsh, a `.msh` file, the project parameters as a
# Python dict (`model_import_settings.input_type: "gmsh"`), `mc.Analysis`, and the pressure at the
# slave nodes against the ellipse. The mesh is coarse so that the notebook runs in seconds.

# %%
import json
import math
import os
import tempfile

import gmsh
import matplotlib.pyplot as plt
import numpy as np

import mortarcontact as mc

R, W, H = 1.0, 2.0, 2.0  # cylinder radius, block half-width and height
YOUNG, POISSON = 1000.0, 0.3
DELTA = 0.006  # displacement of the cylinder's top
H_CONTACT, H_FAR = 0.012, 0.25  # element sizes at the contact point and far from it
folder = tempfile.mkdtemp(prefix="hertz_2d_")

# %% [markdown]
# ## Geometry, physical groups, mesh
# Each physical group becomes a sub model part of the same name: the two bodies (their triangles
# become elements), the contact surfaces and the supports (their line cells give the nodes).

# %%
gmsh.initialize(["-noenv"], readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 0)
geo = gmsh.model.geo
left, bottom, right, centre = (geo.addPoint(-R, R, 0), geo.addPoint(0, 0, 0), geo.addPoint(R, R, 0),
                               geo.addPoint(0, R, 0))
arc_left, arc_right = geo.addCircleArc(left, centre, bottom), geo.addCircleArc(bottom, centre, right)
top = geo.addLine(right, left)
cylinder = geo.addPlaneSurface([geo.addCurveLoop([arc_left, arc_right, top])])
corners = [geo.addPoint(x, y, 0) for x, y in ((-W, -H), (W, -H), (W, 0), (-W, 0))]
lines = [geo.addLine(corners[i], corners[(i + 1) % 4]) for i in range(4)]
block = geo.addPlaneSurface([geo.addCurveLoop(lines)])
geo.synchronize()
for dim, tags, name in ((2, [cylinder], "Parts_cylinder"), (2, [block], "Parts_block"),
                        (1, [arc_left, arc_right], "Contact_slave"), (1, [lines[2]], "Contact_master"),
                        (1, [top], "DISPLACEMENT_top"), (1, [lines[0]], "DISPLACEMENT_bottom")):
    gmsh.model.addPhysicalGroup(dim, tags, name=name)
# fine near the initial contact point, coarser away from it
distance = gmsh.model.mesh.field.add("Distance")
gmsh.model.mesh.field.setNumbers(distance, "PointsList", [bottom])
threshold = gmsh.model.mesh.field.add("Threshold")
for key, value in (("InField", distance), ("SizeMin", H_CONTACT), ("SizeMax", H_FAR), ("DistMin", 0.15),
                   ("DistMax", 1.5)):
    gmsh.model.mesh.field.setNumber(threshold, key, value)
gmsh.model.mesh.field.setAsBackgroundMesh(threshold)
for option in ("Mesh.MeshSizeFromPoints", "Mesh.MeshSizeFromCurvature", "Mesh.MeshSizeExtendFromBoundary"):
    gmsh.option.setNumber(option, 0)
gmsh.model.mesh.generate(2)
mesh_file = os.path.join(folder, "hertz.msh")
gmsh.write(mesh_file)
gmsh.finalize()

# %% [markdown]
# ## Project parameters and materials
# The layout and the keys of Kratos' ProjectParameters.json and materials.json; only the mesh input
# is mortarcontact's own: `input_type: "gmsh"` with the element of each body's group.

# %%
materials = {"properties": [{
    "model_part_name": f"Structure.{body}", "properties_id": 1,
    "Material": {"constitutive_law": {"name": "LinearElasticPlaneStrain2DLaw"},
                 "Variables": {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON, "THICKNESS": 1.0}}}
    for body in ("Parts_cylinder", "Parts_block")]}
with open(os.path.join(folder, "materials.json"), "w") as f:
    json.dump(materials, f)


def fix(part, constrained, value):
    return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": f"Structure.{part}", "variable_name": "DISPLACEMENT",
                           "constrained": constrained, "value": value, "interval": [0.0, "End"]}}


parameters = {
    "problem_data": {"problem_name": "hertz_2d", "echo_level": 0, "start_time": 0.0, "end_time": 1.0},
    "solver_settings": {
        "solver_type": "Static", "model_part_name": "Structure", "domain_size": 2,
        "analysis_type": "non_linear",
        "model_import_settings": {"input_type": "gmsh", "input_filename": mesh_file,
                                  "element_names": {"Parts_cylinder": "SmallDisplacementElement",
                                                    "Parts_block": "SmallDisplacementElement"}},
        "material_import_settings": {"materials_filename": os.path.join(folder, "materials.json")},
        "contact_settings": {"mortar_type": "ALMContactFrictionless"},
        "time_stepping": {"time_step": 0.5},
        "convergence_criterion": "contact_residual_criterion",
        "compute_reactions": True,
    },
    "processes": {
        "constraints_process_list": [fix("DISPLACEMENT_bottom", [True, True, True], [0.0, 0.0, 0.0]),
                                     fix("DISPLACEMENT_top", [True, True, True], [0.0, f"-{DELTA}*t", 0.0])],
        "contact_process_list": [{
            "python_module": "alm_contact_process",
            "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
            "Parameters": {"model_part_name": "Structure", "contact_type": "Frictionless",
                           "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
                           "assume_master_slave": {"0": ["Contact_slave"]}}}],
    },
    "output_processes": {},
}

# %% [markdown]
# ## The analysis
# The same dict written to a ProjectParameters.json runs unchanged with `mortarcontact run`.

# %%
model = mc.Model()
analysis = mc.Analysis(model, parameters)
analysis.Run()
part = model["Structure"]
print(part)
print(analysis.Summary())

# %% [markdown]
# ## Pressure against Hertz
# `CONTACT_PRESSURE` (positive in compression, in stress units) is computed at the slave nodes
# after each step; the force is the reaction of the clamped bottom.

# %%
slave = part.GetSubModelPart("Contact_slave")
x = slave.NodeCoordinates(initial=True)[:, 0]
pressure = slave.GetNodalNonHistoricalValues(mc.CONTACT_PRESSURE)
force = abs(part.GetSubModelPart("DISPLACEMENT_bottom").GetNodalValues(mc.REACTION)[:, 1].sum())
e_star = YOUNG / (2.0 * (1.0 - POISSON ** 2))
a = math.sqrt(4.0 * force * R / (math.pi * e_star))
p0 = 2.0 * force / (math.pi * a)
print(f"P = {force:.4g} per unit thickness: Hertz a = {a:.4g}, p0 = {p0:.4g}; computed peak {pressure.max():.4g} "
      f"({pressure.max() / p0 - 1:+.1%}), contact width {np.ptp(x[pressure > 0]):.4g} (Hertz 2a = {2 * a:.4g})")

order = np.argsort(x)
xs = np.linspace(-a, a, 201)
plt.plot(xs, p0 * np.sqrt(1.0 - (xs / a) ** 2), label="Hertz")
plt.plot(x[order], pressure[order], "o-", ms=3, label="mortarcontact")
plt.xlim(-2.0 * a, 2.0 * a)
plt.xlabel("x")
plt.ylabel("contact pressure")
plt.legend()
plt.savefig(os.path.join(folder, "pressure.png"), dpi=80)

# %% [markdown]
# The checks the test suite runs on this notebook: peak within 5 % of Hertz, and the pressure
# integrates to the reaction (equilibrium of the interface) within 1 %.

# %%
assert abs(pressure.max() / p0 - 1.0) < 0.05
integral = np.sum(0.5 * (pressure[order][1:] + pressure[order][:-1]) * np.diff(x[order]))
assert abs(integral / force - 1.0) < 0.01, (integral, force)
