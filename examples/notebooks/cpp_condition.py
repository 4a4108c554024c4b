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
# # Extending mortarcontact with a C++ condition
#
# `examples/spring_condition_plugin` is a complete out-of-tree plugin: a new variable
# (`SPRING_STIFFNESS`) and a condition tying each of its nodes to the ground, $f = -k\,u$. It is
# built against the installed headers and CMake package, loaded at run time, and from then on its
# names work everywhere a registered name does: mdpa files, `element_names` / `condition_names`
# of gmsh input, `CreateNewConditions`.
#
# The model: a plane-strain strip $[0, 4] \times [0, 1]$ resting on a Winkler foundation of
# modulus $k_w$ (springs at the bottom nodes, each with the stiffness of its tributary length),
# loaded on its top by a uniform pressure $q$. With $\nu = 0$ the exact solution is
# $u_y = -q/k_w - q\,y/E$, which bilinear quadrilaterals reproduce exactly.

# %%
import os
import shutil
import subprocess
import tempfile

import numpy as np

import mortarcontact as mc

SOURCE = os.path.abspath(os.path.join("..", "spring_condition_plugin"))
with open(os.path.join(SOURCE, "ground_spring_condition.cpp")) as source:
    print(source.read()[:1200], "...")

# %% [markdown]
# ## Build and load the plugin
# CMake finds the installed package through `mc.get_cmake_dir()`.

# %%
build = tempfile.mkdtemp(prefix="spring_plugin_")
generator = ["-G", "Ninja"] if shutil.which("ninja") else []
subprocess.run(["cmake", "-S", SOURCE, "-B", build, *generator, f"-Dmortarcontact_DIR={mc.get_cmake_dir()}",
                "-DCMAKE_BUILD_TYPE=Release"], check=True, capture_output=True)
subprocess.run(["cmake", "--build", build], check=True, capture_output=True)
mc.load_plugin(os.path.join(build, "libspring_condition_plugin.so"))
print([name for name in mc.ConditionNames() if "Spring" in name], mc.HasVariable("SPRING_STIFFNESS"))

# %% [markdown]
# ## The model, from numpy arrays

# %%
YOUNG, Q, K_W = 1000.0, 2.0, 50.0
NX, NY, LENGTH = 8, 2, 4.0


def fix(part, constrained, value):
    return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": f"Structure.{part}", "variable_name": "DISPLACEMENT",
                           "constrained": constrained, "value": value, "interval": [0.0, "End"]}}


parameters = {
    "problem_data": {"problem_name": "winkler_strip", "echo_level": 0, "start_time": 0.0, "end_time": 1.0},
    "solver_settings": {"solver_type": "Static", "model_part_name": "Structure", "domain_size": 2,
                        "analysis_type": "linear", "model_import_settings": {"input_type": "use_input_model_part"},
                        "time_stepping": {"time_step": 1.0}},
    "processes": {"loads_process_list": [{
        "python_module": "assign_vector_variable_to_conditions_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure.top", "variable_name": "LINE_LOAD", "value": [0.0, -Q, 0.0]}}]},
    "output_processes": {},
}
model = mc.Model()
analysis = mc.Analysis(model, parameters)
part = model["Structure"]

x, y = np.meshgrid(np.linspace(0.0, LENGTH, NX + 1), np.linspace(0.0, 1.0, NY + 1))
grid = np.arange(1, x.size + 1).reshape(x.shape)
part.CreateNewNodes(grid.ravel(), np.column_stack([x.ravel(), y.ravel()]))
part.CreateNewProperties(1, {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": 0.0, "THICKNESS": 1.0},
                         "LinearElasticPlaneStrain2DLaw")
quads = np.column_stack([grid[:-1, :-1].ravel(), grid[:-1, 1:].ravel(), grid[1:, 1:].ravel(), grid[1:, :-1].ravel()])
part.CreateNewElements("SmallDisplacementElement2D4N", np.arange(1, len(quads) + 1), quads, 1)

# springs: the plugin's condition, its variable set by name like any other
h = LENGTH / NX
bottom = grid[0]
part.CreateNewProperties(2, {"SPRING_STIFFNESS": K_W * h})
part.CreateNewProperties(3, {"SPRING_STIFFNESS": K_W * h / 2.0})  # the two end nodes
part.CreateNewConditions("GroundSpringCondition2D1N", np.arange(1, NX), bottom[1:-1, None], 2)
part.CreateNewConditions("GroundSpringCondition2D1N", [NX, NX + 1], bottom[[0, -1], None], 3)
top = part.CreateSubModelPart("top")
top_nodes = grid[-1]
top.CreateNewConditions("LineLoadCondition2D2N", NX + 2 + np.arange(NX),
                        np.column_stack([top_nodes[1:], top_nodes[:-1]]), part.GetProperties(1))
print(part)

# %%
analysis.Run()
u = part.GetNodalValues(mc.DISPLACEMENT)
exact = -Q / K_W - Q * part.NodeCoordinates(initial=True)[:, 1] / YOUNG
print("largest error of u_y:", np.abs(u[:, 1] - exact).max(), "settlement", u[grid[0] - 1, 1].mean())
assert np.allclose(u[:, 1], exact, rtol=1e-10, atol=1e-14)
assert np.allclose(u[:, 0], 0.0, atol=1e-14)
