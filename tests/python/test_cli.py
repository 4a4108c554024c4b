"""Issue 2: the command line runs a case, and bad input gives one clear message (file, line, key,
entity, value, nearest name), a non-zero exit code, no traceback and no half-written output."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest

from case_builder import fix_process, materials, project_parameters, structured_quads, write_case, write_mdpa


def run_cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "mortarcontact", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


def square_case(tmp_path, *, young=1000.0, element="SmallDisplacementElement2D4N", constraints=None, edit=None):
    coords, cells = structured_quads(2, 2, 1.0, 1.0)
    bottom = [k + 1 for k, x in enumerate(coords) if abs(x[1]) < 1e-12]
    top = [k + 1 for k, x in enumerate(coords) if abs(x[1] - 1.0) < 1e-12]
    write_mdpa(tmp_path / "square.mdpa", coords, {element: cells}, {},
               {"Parts_solid": {"nodes": range(1, len(coords) + 1), "elements": range(1, len(cells) + 1)},
                "bottom": {"nodes": bottom}, "top": {"nodes": top}})
    if constraints is None:
        constraints = [fix_process("Structure.bottom", [0.0, 0.0, 0.0]),
                       fix_process("Structure.top", [None, "-0.01*t", None], (False, True, False))]
    params = project_parameters("square", 2, constraints=constraints)
    params["output_processes"] = {"vtk_output": [{
        "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure", "output_path": "vtk_output",
                       "nodal_solution_step_data_variables": ["DISPLACEMENT"]}}]}
    if edit:
        edit(params)
    return write_case(tmp_path, "square", params,
                      materials("Structure.Parts_solid", "LinearElasticPlaneStrain2DLaw", young, 0.3))


def assert_clean_failure(result, code, *fragments):
    assert result.returncode == code, result.stdout + result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, f"{fragment!r} not in {result.stderr!r}"


def test_version():
    result = run_cli("--version")
    assert result.returncode == 0
    assert result.stdout.startswith("mortarcontact ")


def test_runs_a_case_and_writes_vtu(tmp_path):
    path = square_case(tmp_path)
    result = run_cli("run", str(path), cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    files = [f for _, _, names in os.walk(tmp_path / "vtk_output") for f in names]
    assert any(f.endswith(".vtu") for f in files) and any(f.endswith(".pvd") for f in files), files
    # The run ends with a summary, also when piped (no progress bar): steps, time, files written.
    summary = result.stdout.strip().splitlines()[-1]
    pvd = next(f for f in files if f.endswith(".pvd"))
    assert summary.startswith("square: 1 step to t = 1") and "s in the solution loop" in summary, summary
    assert f"wrote vtk_output/{pvd}" in summary or f"wrote vtk_output{os.sep}{pvd}" in summary, summary


def test_misspelt_settings_key(tmp_path):
    def edit(params):
        params["solver_settings"]["max_iteraton"] = 3
    result = run_cli("run", str(square_case(tmp_path, edit=edit)))
    assert_clean_failure(result, 2, "max_iteraton", "max_iteration")


def test_wrong_value_type(tmp_path):
    def edit(params):
        params["solver_settings"]["max_iteration"] = "ten"
    result = run_cli("run", str(square_case(tmp_path, edit=edit)))
    assert_clean_failure(result, 2, "max_iteration", "ten")


def test_unknown_element_name(tmp_path):
    result = run_cli("run", str(square_case(tmp_path, element="SmallDisplacementElement2D4")))
    assert_clean_failure(result, 2, "square.mdpa", "SmallDisplacementElement2D4N")


def test_malformed_mdpa_line(tmp_path):
    path = square_case(tmp_path)
    mdpa = tmp_path / "square.mdpa"
    lines = mdpa.read_text().splitlines()
    line = lines.index("Begin Nodes") + 2  # node 2, 1-based line number
    lines[line - 1] = lines[line - 1].replace("e", "x", 1)
    mdpa.write_text("\n".join(lines) + "\n")
    result = run_cli("run", str(path))
    assert_clean_failure(result, 2, f"square.mdpa:{line}")


def test_element_with_missing_node(tmp_path):
    path = square_case(tmp_path)
    mdpa = tmp_path / "square.mdpa"
    lines = mdpa.read_text().splitlines()
    index = lines.index("Begin Elements SmallDisplacementElement2D4N") + 1
    lines[index] = "1 0 1 2 99 4"
    mdpa.write_text("\n".join(lines) + "\n")
    result = run_cli("run", str(path))
    assert_clean_failure(result, 2, "99")


@pytest.mark.parametrize("young", [-1.0, 0.0, float("nan")])
def test_bad_material_value(tmp_path, young):
    path = square_case(tmp_path, young=young)
    if young != young:  # NaN is not valid JSON; write it as a string the reader must reject
        data = json.loads((tmp_path / "square_materials.json").read_text(), parse_constant=lambda c: c)
        data["properties"][0]["Material"]["Variables"]["YOUNG_MODULUS"] = "nan"
        (tmp_path / "square_materials.json").write_text(json.dumps(data))
    result = run_cli("run", str(path))
    assert result.returncode == 2, result.stderr
    assert "YOUNG_MODULUS" in result.stderr and "Traceback" not in result.stderr


def test_singular_system_names_free_dofs(tmp_path):
    # Only the top is pulled down: nothing holds the body horizontally (rigid-body modes).
    pulled = [fix_process("Structure.top", [None, "-0.01*t", None], (False, True, False))]
    result = run_cli("run", str(square_case(tmp_path, constraints=pulled)))
    assert_clean_failure(result, 4, "DISPLACEMENT_")
    assert not (tmp_path / "vtk_output").exists() or not any(
        f.endswith(".vtu.tmp") for _, _, names in os.walk(tmp_path / "vtk_output") for f in names)


def test_active_node_that_lost_its_overlap_is_explained(tmp_path):
    # Half the block's height pushed down in one step: an iterate carries slave node 111's faces
    # off the master, so its multiplier has no equation. The message says so and names the remedy
    # instead of asking whether the multiplier DoF is constrained.
    case = os.path.join(os.path.dirname(__file__), "..", "cases", "robustness",
                        "2d_quad_flat_r0.25_overhang-none_gap_disp_4steps_alm_coarse")
    shutil.copytree(case, tmp_path / "case")
    parameters = tmp_path / "case" / "ProjectParameters.json"
    params = json.loads(parameters.read_text())
    params["solver_settings"]["time_stepping"]["time_step"] = 1.0
    params["processes"]["constraints_process_list"][1]["Parameters"]["value"] = [0.0, "-0.5*t", 0.0]
    parameters.write_text(json.dumps(params))
    result = run_cli("run", str(parameters), cwd=tmp_path / "case")
    assert_clean_failure(result, 4, "active slave node(s) 111 lost every mortar overlap", "max_number_splits")


def test_unknown_process_suggests_nearest(tmp_path):
    def edit(params):
        params["processes"]["constraints_process_list"][0]["python_module"] = "assign_vector_variable_proces"
    result = run_cli("run", str(square_case(tmp_path, edit=edit)))
    assert_clean_failure(result, 2, "assign_vector_variable_process")


def test_not_implemented_option_of_a_contact_case_is_reported(csma_cases, tmp_path):
    case = os.path.join(csma_cases, "ALM_frictional_contact_test_2D", "hyper_simple_patch_test_parameters.json")
    with open(case) as f:
        params = json.load(f)
    solver = params["solver_settings"]
    for block, key in (("model_import_settings", "input_filename"), ("material_import_settings", "materials_filename")):
        solver[block][key] = os.path.join(csma_cases, solver[block][key])
    params["processes"]["contact_process_list"][0]["Parameters"]["slip_step_reset_frequency"] = -1
    case = tmp_path / "parameters.json"
    case.write_text(json.dumps(params))
    result = subprocess.run([sys.executable, "-m", "mortarcontact", "run", str(case)], capture_output=True, text=True,
                            cwd=tmp_path, timeout=300)
    assert_clean_failure(result, 3, "slip_step_reset_frequency")


def test_frictional_contact_case_runs_from_the_command_line(csma_cases):
    case = os.path.join(csma_cases, "ALM_frictional_contact_test_2D", "hyper_simple_patch_test_parameters.json")
    result = subprocess.run([sys.executable, "-m", "mortarcontact", "run", case], capture_output=True, text=True,
                            cwd=csma_cases, timeout=300)
    assert result.returncode == 0, result.stderr


def test_frictionless_contact_case_runs_from_the_command_line(csma_cases):
    case = os.path.join(csma_cases, "ALM_frictionless_contact_test_2D", "hyper_simple_patch_test_parameters.json")
    result = subprocess.run([sys.executable, "-m", "mortarcontact", "run", case], capture_output=True, text=True,
                            cwd=csma_cases, timeout=300)
    assert result.returncode == 0, result.stderr


def test_non_convergence_names_step_iteration_and_norms(tmp_path):
    def edit(params):
        params["solver_settings"]["max_iteration"] = 1
        params["solver_settings"]["residual_relative_tolerance"] = 1e-14
        params["solver_settings"]["residual_absolute_tolerance"] = 1e-20
    path = square_case(tmp_path, edit=edit)
    result = run_cli("run", str(path), cwd=tmp_path)
    assert_clean_failure(result, 4, "step 1", "did not converge", "iteration")


def test_element_without_material_names_element_and_properties(tmp_path):
    path = square_case(tmp_path)
    materials_file = tmp_path / "square_materials.json"
    data = json.loads(materials_file.read_text())
    data["properties"][0]["model_part_name"] = "Structure.bottom"  # a part without elements
    materials_file.write_text(json.dumps(data))
    result = run_cli("run", str(path), cwd=tmp_path)
    assert_clean_failure(result, 2, "element 1", "properties 0", "constitutive law")
