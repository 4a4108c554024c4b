"""Issue 2 (extensibility): an out-of-tree C++ condition is built against the installed headers and
CMake package, loaded at run time, registered by name and used from an mdpa file."""
from __future__ import annotations

import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import mortarcontact as mc

from case_builder import project_parameters

PLUGIN_SOURCE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "spring_condition_plugin")


@pytest.fixture(scope="module")
def plugin_library(tmp_path_factory):
    if shutil.which("cmake") is None:
        pytest.skip("cmake is not available")
    build = tmp_path_factory.mktemp("plugin_build")
    configure = subprocess.run(["cmake", "-S", PLUGIN_SOURCE, "-B", str(build), "-G", "Ninja",
                                f"-Dmortarcontact_DIR={mc.get_cmake_dir()}", "-DCMAKE_BUILD_TYPE=Release"],
                               capture_output=True, text=True, timeout=300)
    assert configure.returncode == 0, configure.stdout + configure.stderr
    compile_ = subprocess.run(["cmake", "--build", str(build)], capture_output=True, text=True, timeout=600)
    assert compile_.returncode == 0, compile_.stdout + compile_.stderr
    return str(build / "libspring_condition_plugin.so")


def test_plugin_condition_runs_from_an_mdpa(plugin_library, tmp_path):
    mc.load_plugin(plugin_library)
    assert "GroundSpringCondition2D1N" in mc.ConditionNames()
    assert mc.HasVariable("SPRING_STIFFNESS")
    (tmp_path / "springs.mdpa").write_text(
        "Begin Properties 1\n  SPRING_STIFFNESS 100.0\nEnd Properties\n\n"
        "Begin Nodes\n  1 0.0 0.0 0.0\n  2 1.0 0.0 0.0\nEnd Nodes\n\n"
        "Begin Conditions GroundSpringCondition2D1N\n  1 1 1\n  2 1 2\nEnd Conditions\n\n"
        "Begin Conditions PointLoadCondition2D1N\n  3 1 2\nEnd Conditions\n\n"
        "Begin SubModelPart load\n  Begin SubModelPartNodes\n    2\n  End SubModelPartNodes\n"
        "  Begin SubModelPartConditions\n    3\n  End SubModelPartConditions\nEnd SubModelPart\n")
    params = project_parameters("springs", 2, loads=[{
        "python_module": "assign_vector_variable_to_conditions_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure.load", "variable_name": "POINT_LOAD", "value": [3.0, -5.0, 0.0]}}])
    params["solver_settings"]["material_import_settings"]["materials_filename"] = ""
    path = tmp_path / "springs_parameters.json"
    path.write_text(json.dumps(params))
    analysis = mc.run(str(path), progress=False)
    u = analysis.model["Structure"].GetNodalValues(mc.DISPLACEMENT)
    np.testing.assert_allclose(u[0], [0.0, 0.0, 0.0], atol=1e-14)
    np.testing.assert_allclose(u[1], [0.03, -0.05, 0.0], rtol=1e-12)
