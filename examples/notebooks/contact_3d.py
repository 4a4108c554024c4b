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
# # 3D contact of two blocks with non-matching meshes, built from numpy arrays
#
# An elastic block $[0,1]^2 \times [1,2]$ (3 x 3 x 2 hexahedra) stands on another,
# $[0,1]^2 \times [0,1]$ (4 x 4 x 2 hexahedra): the meshes of the contact surface do not match.
# The top is pushed down by $\delta$, the bottom rests on rollers, the faces $x = 0$ and $y = 0$
# are symmetry planes. Both blocks have $E = 1000$, $\nu = 0.25$ (consistent units), so the exact
# solution is a uniform uniaxial stress $\sigma = E\,\delta / 2$, which the mortar method
# transmits exactly across non-matching meshes (a patch test). The contact pressure is that force
# over the current (deformed) area of the interface, which the lateral expansion
# $\nu\,\delta/2$ enlarges: $p = E\,(\delta/2) / (1 + \nu\,\delta/2)^2$ at every slave node.
#
# The model is built with the public model API: nodes and elements from numpy arrays in one call
# each, properties from a dict, `mc.Analysis` over the model part
# (`"input_type": "use_input_model_part"`).

# %%
import numpy as np

import mortarcontact as mc

YOUNG, POISSON, DELTA = 1000.0, 0.25, 0.01


def hexahedra(n, z0, first_node):
    """Nodes (ids, coordinates) and 8-node connectivity of an n x n x 2 grid of [0, 1]^2 x [z0, z0 + 1]."""
    x, y, z = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1), np.linspace(z0, z0 + 1, 3),
                          indexing="ij")
    ids = first_node + np.arange(x.size).reshape(x.shape)
    cells = np.stack([ids[:-1, :-1, :-1], ids[1:, :-1, :-1], ids[1:, 1:, :-1], ids[:-1, 1:, :-1],
                      ids[:-1, :-1, 1:], ids[1:, :-1, 1:], ids[1:, 1:, 1:], ids[:-1, 1:, 1:]], axis=-1)
    return ids, np.column_stack([x.ravel(), y.ravel(), z.ravel()]), cells.reshape(-1, 8)


# %% [markdown]
# ## The model
# `mc.Analysis` first (it adds the historical variables the solver needs), then the mesh.

# %%
def fix(part, constrained, value):
    return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": f"Structure.{part}", "variable_name": "DISPLACEMENT",
                           "constrained": constrained, "value": value, "interval": [0.0, "End"]}}


parameters = {
    "problem_data": {"problem_name": "blocks_3d", "echo_level": 0, "start_time": 0.0, "end_time": 1.0},
    "solver_settings": {
        "solver_type": "Static", "model_part_name": "Structure", "domain_size": 3, "analysis_type": "non_linear",
        "model_import_settings": {"input_type": "use_input_model_part"},
        "contact_settings": {"mortar_type": "ALMContactFrictionless"},
        "time_stepping": {"time_step": 1.0},
        "convergence_criterion": "contact_residual_criterion",
        "compute_reactions": True,
    },
    "processes": {
        "constraints_process_list": [fix("bottom", [False, False, True], [None, None, 0.0]),
                                     fix("top", [False, False, True], [None, None, f"-{DELTA}*t"]),
                                     fix("symmetry_x", [True, False, False], [0.0, None, None]),
                                     fix("symmetry_y", [False, True, False], [None, 0.0, None])],
        "contact_process_list": [{
            "python_module": "alm_contact_process",
            "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
            "Parameters": {"model_part_name": "Structure", "contact_type": "Frictionless",
                           "contact_model_part": {"0": ["Contact_slave", "Contact_master"]},
                           "assume_master_slave": {"0": ["Contact_slave"]}}}],
    },
    "output_processes": {},
}
model = mc.Model()
analysis = mc.Analysis(model, parameters)
part = model["Structure"]

lower_ids, lower_xyz, lower_cells = hexahedra(4, 0.0, 1)
upper_ids, upper_xyz, upper_cells = hexahedra(3, 1.0, lower_ids.size + 1)
part.CreateNewNodes(np.concatenate([lower_ids.ravel(), upper_ids.ravel()]), np.vstack([lower_xyz, upper_xyz]))
part.CreateNewProperties(1, {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON}, "LinearElastic3DLaw")
cells = np.vstack([lower_cells, upper_cells])
part.CreateNewElements("SmallDisplacementElement3D8N", np.arange(1, len(cells) + 1), cells, 1)

xyz = part.NodeCoordinates()
ids = part.NodeIds()
groups = {"bottom": xyz[:, 2] == 0.0, "top": xyz[:, 2] == 2.0, "symmetry_x": xyz[:, 0] == 0.0,
          "symmetry_y": xyz[:, 1] == 0.0,
          "Contact_slave": np.isin(ids, upper_ids[:, :, 0]), "Contact_master": np.isin(ids, lower_ids[:, :, -1])}
for name, selected in groups.items():
    part.CreateSubModelPart(name).AddNodes(ids[selected].tolist())
print(part)

# %% [markdown]
# ## Run and check

# %%
analysis.Run()
print(analysis.Summary())
slave = part.GetSubModelPart("Contact_slave")
pressure = slave.GetNodalNonHistoricalValues(mc.CONTACT_PRESSURE)
print("contact pressure at the slave nodes:", np.round(pressure, 12))
u = part.GetNodalValues(mc.DISPLACEMENT)
strain = -DELTA / 2.0
assert np.allclose(pressure, -YOUNG * strain / (1.0 - POISSON * strain) ** 2, rtol=1e-9)
assert np.allclose(u[:, 2], strain * xyz[:, 2], atol=1e-12)
assert np.allclose(u[:, 0], -POISSON * strain * xyz[:, 0], atol=1e-12)

# %% [markdown]
# The arrays `GetNodalValues`, `NodeCoordinates`, `GetNodalNonHistoricalValues` return are copies
# (each node owns its storage): change values with `SetNodalValues`.
