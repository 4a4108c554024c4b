"""Issue 2: the assignment processes, model-part name resolution, the process factory and the
JSON result oracle behave as the Kratos inputs expect (spec 1.4, 1.6, 4.9)."""
from __future__ import annotations

import json

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.process_factory import PROCESS_REGISTRY, create_process, create_process_lists, parts_kept_whole
from mortarcontact.processes import resolve_model_part
from mortarcontact.processes.from_json_check_result_process import CheckResultError, is_close

from small_models import advance, parameters, square_grid


def make(model, python_module, settings, kratos_module="KratosMultiphysics"):
    item = {"python_module": python_module, "kratos_module": kratos_module, "process_name": "Whatever",
            "help": "", "Parameters": settings}
    return create_process(parameters(json.dumps(item)), model)


def dof_fixed(part, variable):
    return np.array([node.IsFixed(variable) for node in part.Nodes])


# --- assignment on nodes ---------------------------------------------------------------------

def test_scalar_constant_fixes_then_frees_after_the_step():
    model, root = square_grid()
    top = root.GetSubModelPart("top")
    process = make(model, "assign_scalar_variable_process",
                   {"model_part_name": "Structure.top", "variable_name": "DISPLACEMENT_X", "value": 0.5,
                    "interval": [0.0, "End"], "mesh_id": 0})
    process.ExecuteBeforeSolutionLoop()
    assert np.array_equal(top.GetNodalValues(mc.DISPLACEMENT)[:, 0], [0.5, 0.5, 0.5])
    assert dof_fixed(top, mc.DISPLACEMENT_X).all()
    assert not dof_fixed(root.GetSubModelPart("bottom"), mc.DISPLACEMENT_X).any()
    assert np.array_equal(root.GetNodalValues(mc.DISPLACEMENT)[:3, 0], [0.0, 0.0, 0.0])
    advance(root, 1.0)
    process.ExecuteInitializeSolutionStep()
    assert dof_fixed(top, mc.DISPLACEMENT_X).all()
    process.ExecuteFinalizeSolutionStep()
    assert not dof_fixed(top, mc.DISPLACEMENT_X).any()
    assert np.array_equal(top.GetNodalValues(mc.DISPLACEMENT)[:, 0], [0.5, 0.5, 0.5])


def test_scalar_expression_of_time_and_position():
    model, root = square_grid(3, 2)
    process = make(model, "assign_scalar_variable_process",
                   {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_Y", "value": "2*t + x*y",
                    "constrained": False})
    advance(root, 0.25)
    process.ExecuteInitializeSolutionStep()
    x = root.NodeCoordinates()
    assert np.allclose(root.GetNodalValues(mc.DISPLACEMENT)[:, 1], 0.5 + x[:, 0] * x[:, 1], rtol=0, atol=1e-14)
    assert not dof_fixed(root, mc.DISPLACEMENT_Y).any()


def test_interval_bounds_are_inclusive_and_nothing_happens_outside():
    model, root = square_grid()
    process = make(model, "assign_scalar_variable_process",
                   {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_X", "value": "t",
                    "interval": [1.0, 2.0]})
    seen = []
    for _ in range(5):  # t = 0.5, 1.0, 1.5, 2.0, 2.5
        time = advance(root, 0.5)
        process.ExecuteInitializeSolutionStep()
        seen.append((time, root.GetNodalValues(mc.DISPLACEMENT)[0, 0], bool(dof_fixed(root, mc.DISPLACEMENT_X).all())))
        process.ExecuteFinalizeSolutionStep()
    assert seen == [(0.5, 0.0, False), (1.0, 1.0, True), (1.5, 1.5, True), (2.0, 2.0, True), (2.5, 2.0, False)]


def test_vector_null_component_is_neither_assigned_nor_fixed():
    model, root = square_grid()
    bottom = root.GetSubModelPart("bottom")
    root.SetNodalValues(mc.DISPLACEMENT, np.full((root.NumberOfNodes(), 3), 7.0))
    process = make(model, "assign_vector_variable_process",
                   {"model_part_name": "Structure.bottom", "variable_name": "DISPLACEMENT",
                    "value": [None, "-0.1*t", 0.0], "constrained": [True, True, False], "interval": [0.0, "End"]})
    advance(root, 2.0)
    process.ExecuteInitializeSolutionStep()
    values = bottom.GetNodalValues(mc.DISPLACEMENT)
    assert np.array_equal(values[:, 0], [7.0] * 3)
    assert np.allclose(values[:, 1], -0.2, rtol=0, atol=1e-15)
    assert np.array_equal(values[:, 2], [0.0] * 3)
    assert not dof_fixed(bottom, mc.DISPLACEMENT_X).any()
    assert dof_fixed(bottom, mc.DISPLACEMENT_Y).all()
    assert not dof_fixed(bottom, mc.DISPLACEMENT_Z).any()
    process.ExecuteFinalizeSolutionStep()
    assert not dof_fixed(bottom, mc.DISPLACEMENT_Y).any()


def test_vector_single_constrained_bool_is_expanded():
    model, root = square_grid()
    for constrained, expected in ((False, False), (True, True)):
        make(model, "assign_vector_variable_process",
             {"model_part_name": "Structure.top", "variable_name": "DISPLACEMENT", "value": [1.0, 2.0, 3.0],
              "constrained": constrained}).ExecuteBeforeSolutionLoop()
        top = root.GetSubModelPart("top")
        for axis in "XYZ":
            assert dof_fixed(top, mc.GetVariable(f"DISPLACEMENT_{axis}")).all() == expected
    assert np.array_equal(root.GetSubModelPart("top").GetNodalValues(mc.DISPLACEMENT), [[1.0, 2.0, 3.0]] * 3)


def test_vector_by_direction_normalises_the_direction():
    model, root = square_grid()
    make(model, "assign_vector_by_direction_process",
         {"model_part_name": "Structure.top", "variable_name": "DISPLACEMENT", "modulus": 2.0,
          "direction": [3.0, 4.0, 0.0]}).ExecuteBeforeSolutionLoop()
    assert np.allclose(root.GetSubModelPart("top").GetNodalValues(mc.DISPLACEMENT), [[1.2, 1.6, 0.0]] * 3, atol=1e-15)
    process = make(model, "assign_vector_by_direction_process",
                   {"model_part_name": "Structure.bottom", "variable_name": "DISPLACEMENT", "modulus": "10*t",
                    "direction": [0.0, -2.0, 0.0], "constrained": False})
    advance(root, 0.3)
    process.ExecuteInitializeSolutionStep()
    assert np.allclose(root.GetSubModelPart("bottom").GetNodalValues(mc.DISPLACEMENT), [[0.0, -3.0, 0.0]] * 3,
                       atol=1e-14)


def test_vector_by_direction_rejects_bad_directions():
    model, _ = square_grid()
    base = {"model_part_name": "Structure", "variable_name": "DISPLACEMENT", "modulus": 1.0}
    with pytest.raises(mc.InputError, match="zero length"):
        make(model, "assign_vector_by_direction_process", {**base, "direction": [0.0, 0.0, 0.0]})
    with pytest.raises(mc.NotImplementedFeatureError, match="automatic_inwards_normal"):
        make(model, "assign_vector_by_direction_process", {**base, "direction": "automatic_inwards_normal"})
    with pytest.raises(mc.InputError, match="modulus"):
        make(model, "assign_vector_by_direction_process", {**base, "modulus": None, "direction": [1, 0, 0]})


def test_assignment_settings_errors():
    model, _ = square_grid()
    with pytest.raises(mc.InputError, match="valu"):
        make(model, "assign_scalar_variable_process",
             {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_X", "valeu": 1.0})
    with pytest.raises(mc.InputError, match="not a scalar"):
        make(model, "assign_scalar_variable_process",
             {"model_part_name": "Structure", "variable_name": "DISPLACEMENT", "value": 1.0})
    with pytest.raises(mc.InputError, match="interval"):
        make(model, "assign_scalar_variable_process",
             {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_X", "value": 1.0, "interval": [2.0, 1.0]})


# --- assignment on conditions ------------------------------------------------------------------

def line_conditions(root, name="LineLoadCondition2D2N"):
    if name not in mc.ConditionNames():
        pytest.skip(f"condition {name} is not registered yet")
    top = root.GetSubModelPart("top")
    ids = [int(i) for i in top.NodeIds()]
    props = root.CreateNewProperties(1)
    for k in range(len(ids) - 1):
        root.CreateNewCondition(name, k + 1, [ids[k], ids[k + 1]], props)
    top.AddConditions(list(range(1, len(ids))))
    return top


def test_vector_to_conditions_sets_values_that_persist():
    model, root = square_grid()
    top = line_conditions(root)
    process = make(model, "assign_vector_variable_to_conditions_process",
                   {"model_part_name": "Structure.top", "variable_name": "LINE_LOAD",
                    "value": [0.0, "-1.0e3*t", None], "interval": [0.0, 1.0]})
    for _ in range(3):  # t = 0.5, 1.0, 1.5 (outside: the t = 1.0 value stays)
        advance(root, 0.5)
        process.ExecuteInitializeSolutionStep()
        process.ExecuteFinalizeSolutionStep()
    for condition in top.Conditions:
        assert np.allclose(condition.GetValue(mc.LINE_LOAD), [0.0, -1000.0, 0.0], rtol=0, atol=1e-12)


def test_vector_by_direction_to_condition_and_scalar_to_conditions():
    model, root = square_grid()
    top = line_conditions(root)
    make(model, "assign_vector_by_direction_to_condition_process",
         {"model_part_name": "Structure.top", "variable_name": "LINE_LOAD", "modulus": 1.0e11,
          "direction": [0.0, -1.0, 0.0], "mesh_id": 0}).ExecuteBeforeSolutionLoop()
    make(model, "assign_scalar_variable_to_conditions_process",
         {"model_part_name": "Structure.top", "variable_name": "POSITIVE_FACE_PRESSURE", "value": "x"}
         ).ExecuteBeforeSolutionLoop()
    for condition in top.Conditions:
        assert np.array_equal(condition.GetValue(mc.LINE_LOAD), [0.0, -1.0e11, 0.0])
        centre_x = np.mean([n.X for n in condition.GetNodes()])
        assert condition.GetValue(mc.POSITIVE_FACE_PRESSURE) == pytest.approx(centre_x, abs=1e-14)


# --- model-part names ----------------------------------------------------------------------------

def test_model_part_name_resolution():
    model, _ = square_grid()
    assert resolve_model_part(model, "Structure").FullName() == "Structure"
    assert resolve_model_part(model, "Structure.Parts.inner").FullName() == "Structure.Parts.inner"
    assert resolve_model_part(model, "inner").FullName() == "Structure.Parts.inner"
    assert resolve_model_part(model, "Structure.computing_domain").FullName() == "Structure"
    with pytest.raises(mc.InputError, match=r"'innr'.*Structure\.Parts\.inner|'innr'.*'inner'"):
        resolve_model_part(model, "innr")


def test_ambiguous_bare_name_lists_the_matches():
    model, root = square_grid()
    root.CreateSubModelPart("Other").CreateSubModelPart("inner")
    with pytest.raises(mc.InputError) as error:
        resolve_model_part(model, "inner")
    assert "ambiguous" in str(error.value)
    assert "Structure.Other.inner" in str(error.value) and "Structure.Parts.inner" in str(error.value)


# --- factory -------------------------------------------------------------------------------------

def test_factory_accepts_every_module_spelling_and_the_registry_form():
    model, _ = square_grid()
    settings = {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_X", "value": 1.0}
    for module in ("KratosMultiphysics", None):
        item = {"python_module": "assign_scalar_variable_process", "Parameters": settings}
        if module:
            item["kratos_module"] = module
        assert type(create_process(parameters(json.dumps(item)), model)).__name__ == "AssignScalarVariableProcess"
    for name in ("Processes.KratosMultiphysics.AssignScalarVariableProcess", "assign_scalar_variable_process"):
        process = create_process(parameters(json.dumps({"name": name, "parameters": settings})), model)
        assert type(process).__name__ == "AssignScalarVariableProcess"


def test_unknown_process_lists_the_nearest_names():
    model, _ = square_grid()
    with pytest.raises(mc.InputError) as error:
        make(model, "assign_vector_variable_proces", {})
    message = str(error.value)
    assert "assign_vector_variable_proces" in message and "'assign_vector_variable_process'" in message


def test_unknown_item_key_is_an_error():
    model, _ = square_grid()
    item = {"python_module": "assign_scalar_variable_process", "kratos_module": "KratosMultiphysics",
            "Parametres": {}}
    with pytest.raises(mc.InputError, match="Parametres"):
        create_process(parameters(json.dumps(item)), model)


@pytest.mark.parametrize("module", ["KratosMultiphysics.ContactStructuralMechanicsApplication",
                                    "ContactStructuralMechanicsApplication"])
def test_contact_processes_are_registered_under_both_module_spellings(module):
    """The contact processes are found whichever spelling of the application the input uses."""
    model, _ = square_grid()
    for name in ("alm_contact_process", "penalty_contact_process", "explicit_penalty_contact_process",
                 "mpc_contact_process", "mesh_tying_process"):
        assert ("ContactStructuralMechanicsApplication", name) in PROCESS_REGISTRY
    assert make(model, "mpc_contact_process", {}, module).python_module == "mpc_contact_process"
    assert make(model, "mesh_tying_process", {}, module).python_module == "mesh_tying_process"


def test_process_lists_run_in_lexicographic_order():
    model, root = square_grid()

    def item(value):
        return {"python_module": "assign_scalar_variable_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"model_part_name": "Structure", "variable_name": "DISPLACEMENT_X", "value": value}}

    block = parameters(json.dumps({"loads_process_list": [item(3.0)],
                                   "constraints_process_list": [item(1.0), item(2.0)], "_disabled": [item(9.0)]}))
    processes = create_process_lists(block, model)
    assert len(processes) == 3
    for process in processes:
        process.ExecuteBeforeSolutionLoop()
    assert root.GetNodalValues(mc.DISPLACEMENT)[0, 0] == 3.0


def test_the_parts_kept_whole_are_named_before_the_mesh_is_read():
    """Issue 17: before a rank reads its piece, the processes name the model parts they need whole
    (the contact interfaces' parts, in any of the slot layouts; not the slave parts); an interface
    over the skin of the whole model needs every element (None: the model is read whole)."""
    def block(*contact_settings):
        items = [{"python_module": "assign_scalar_variable_process", "kratos_module": "KratosMultiphysics",
                  "Parameters": {"model_part_name": "Structure.top", "variable_name": "DISPLACEMENT_X"}}]
        items += [{"python_module": "alm_contact_process",
                   "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                   "Parameters": settings} for settings in contact_settings]
        return parameters(json.dumps({"contact_process_list": items}))

    slots = {"contact_model_part": {"0": ["Contact_slave", "Contact_master"], "3": ["Other"]},
             "assume_master_slave": {"0": ["Contact_slave"]}}
    assert parts_kept_whole(block(slots)) == ["Contact_slave", "Contact_master", "Other"]
    assert parts_kept_whole(block({"contact_model_part": "Contact_Part"}, {"contact_model_part": ["A", "B"]})) == \
        ["Contact_Part", "A", "B"]
    assert parts_kept_whole(block()) == []
    assert parts_kept_whole(block({"contact_model_part": {"0": []}})) is None


# --- JSON oracle ---------------------------------------------------------------------------------

def reference_file(tmp_path, root, times, displacement_y):
    """A reference with DISPLACEMENT_X = 0 and DISPLACEMENT_Y(t) given per node id as a function."""
    data = {"TIME": times}
    for node_id in root.NodeIds():
        data[f"NODE_{node_id}"] = {"DISPLACEMENT_X": [0.0] * len(times),
                                   "DISPLACEMENT_Y": [displacement_y(int(node_id), t) for t in times]}
    path = tmp_path / "reference.json"
    path.write_text(json.dumps(data))
    return str(path)


def check_process(model, path, **extra):
    settings = {"check_variables": ["DISPLACEMENT_X", "DISPLACEMENT_Y"], "input_file_name": path,
                "model_part_name": "Structure", "time_frequency": 0.0, **extra}
    process = make(model, "from_json_check_result_process", settings)
    process.ExecuteInitialize()
    return process


def test_json_check_interpolates_in_time_and_names_the_failing_node(tmp_path):
    model, root = square_grid()
    path = reference_file(tmp_path, root, [0.5, 1.5], lambda i, t: -0.01 * i * t)
    process = check_process(model, path)
    advance(root, 1.0)
    expected = -0.01 * root.NodeIds() * 1.0  # halfway between the stored times
    values = np.zeros((root.NumberOfNodes(), 3))
    values[:, 1] = expected + 0.9e-3  # within the absolute tolerance 1e-3
    root.SetNodalValues(mc.DISPLACEMENT, values)
    process.ExecuteFinalizeSolutionStep()
    assert process.checks_done == 1
    values[2, 1] = expected[2] + 2e-3
    root.SetNodalValues(mc.DISPLACEMENT, values)
    advance(root, 0.0001)
    root.SetNodalValues(mc.DISPLACEMENT, values)
    with pytest.raises(CheckResultError) as error:
        process.ExecuteFinalizeSolutionStep()
    message = str(error.value)
    assert "node 3, DISPLACEMENT_Y" in message and "1 value(s)" in message
    assert isinstance(error.value, AssertionError)


def test_json_check_holds_the_reference_outside_the_stored_times(tmp_path):
    model, root = square_grid()
    path = reference_file(tmp_path, root, [0.5, 1.5], lambda i, t: t)
    process = check_process(model, path, tolerance=1e-12, relative_tolerance=0.0)
    advance(root, 3.0)
    root.SetNodalValues(mc.DISPLACEMENT, np.tile([0.0, 1.5, 0.0], (root.NumberOfNodes(), 1)))
    process.ExecuteFinalizeSolutionStep()
    assert process.checks_done == 1


def test_json_check_time_frequency(tmp_path):
    model, root = square_grid()
    path = reference_file(tmp_path, root, [0.0, 10.0], lambda i, t: 0.0)
    every_step = check_process(model, path, time_frequency=0.0)
    every_second = check_process(model, path, time_frequency=1.0)
    checked = []
    for _ in range(6):  # dt 0.5: the counter exceeds 1.0 strictly at the 3rd and 6th step
        advance(root, 0.5)
        before = every_second.checks_done
        every_step.ExecuteFinalizeSolutionStep()
        every_second.ExecuteFinalizeSolutionStep()
        checked.append(every_second.checks_done > before)
    assert every_step.checks_done == 6
    assert checked == [False, False, True, False, False, True]


def test_tolerance_semantics_follow_isclose():
    assert is_close(100.0, 100.05, tolerance=1e-3, relative_tolerance=1e-3)  # relative passes
    assert not is_close(100.0, 100.2, tolerance=1e-3, relative_tolerance=1e-3)
    assert is_close(0.0, 5e-4, tolerance=1e-3, relative_tolerance=1e-6)  # absolute passes
    assert not is_close(0.0, 2e-3, tolerance=1e-3, relative_tolerance=1e-6)


def test_json_check_non_historical_values(tmp_path):
    model, root = square_grid()
    data = {"TIME": [1.0]}
    for node in root.Nodes:
        node.SetValue(mc.NODAL_H, 0.1 * node.Id)
        data[f"NODE_{node.Id}"] = {"NODAL_H": [0.1 * node.Id]}
    path = tmp_path / "nodal_h.json"
    path.write_text(json.dumps(data))
    process = check_process(model, str(path), check_variables=["NODAL_H"], historical_value=False,
                            relative_tolerance=1e-3)
    advance(root, 1.0)
    process.ExecuteFinalizeSolutionStep()
    root.GetNode(4).SetValue(mc.NODAL_H, 0.5)
    advance(root, 1.0)
    with pytest.raises(CheckResultError, match="node 4, NODAL_H"):
        process.ExecuteFinalizeSolutionStep()


def test_json_output_round_trip_through_the_check(tmp_path):
    model, root = square_grid()
    output = tmp_path / "out" / "results.json"
    writer = make(model, "json_output_process",
                  {"output_variables": ["DISPLACEMENT", "REACTION_Y"], "output_file_name": str(output),
                   "model_part_name": "Structure", "sub_model_part_name": "top", "time_frequency": 0.0})
    writer.ExecuteInitialize()
    writer.ExecuteBeforeSolutionLoop()
    top = root.GetSubModelPart("top")
    for step in range(1, 4):
        advance(root, 0.5)
        top.SetNodalValues(mc.DISPLACEMENT, np.outer(top.NodeIds(), [step, -step, 0.5 * step]))
        top.SetNodalValues(mc.REACTION, np.tile([0.0, 10.0 * step, 0.0], (3, 1)))
        writer.ExecuteFinalizeSolutionStep()
    assert not output.exists()  # written once, at the end
    assert writer.OutputFiles() == []
    writer.ExecuteFinalize()
    assert writer.OutputFiles() == [str(output)]  # for the end-of-run summary
    data = json.loads(output.read_text())
    assert data["TIME"] == [0.5, 1.0, 1.5]
    assert set(data) == {"TIME", "NODE_7", "NODE_8", "NODE_9"}
    assert data["NODE_8"] == {"DISPLACEMENT_X": [8.0, 16.0, 24.0], "DISPLACEMENT_Y": [-8.0, -16.0, -24.0],
                              "DISPLACEMENT_Z": [4.0, 8.0, 12.0], "REACTION_Y": [10.0, 20.0, 30.0]}

    checker = check_process(model, str(output), check_variables=["DISPLACEMENT", "REACTION_Y"],
                            model_part_name="Structure.top", tolerance=1e-12, relative_tolerance=0.0)
    checker.ExecuteFinalizeSolutionStep()  # t = 1.5, the last written values
    top.SetNodalValues(mc.DISPLACEMENT, np.outer(top.NodeIds(), [2.5, -2.5, 1.25]))
    top.SetNodalValues(mc.REACTION, np.tile([0.0, 25.0, 0.0], (3, 1)))
    root.GetProcessInfo().SetValue(mc.TIME, 1.25)  # halfway between the 2nd and 3rd samples
    checker.ExecuteFinalizeSolutionStep()
    top.SetNodalValues(mc.DISPLACEMENT, np.outer(top.NodeIds(), [2.5, -2.5, 1.3]))
    with pytest.raises(CheckResultError, match="DISPLACEMENT_Z"):
        checker.ExecuteFinalizeSolutionStep()


@pytest.mark.parametrize("python_module, file_key", [("json_output_process", "output_file_name"),
                                                     ("from_json_check_result_process", "input_file_name")])
def test_json_non_historical_variable_read_as_historical_is_an_error_before_the_first_step(tmp_path, python_module,
                                                                                           file_key):
    """Issue 15, item 4: CONTACT_PRESSURE with historical_value true is named, with the fix, at Check."""
    model, _ = square_grid(1, 1)
    reference = tmp_path / "reference.json"
    reference.write_text(json.dumps({"TIME": [1.0]}))
    variables_key = "output_variables" if python_module == "json_output_process" else "check_variables"
    item = {"python_module": python_module, "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": "Structure", file_key: str(reference),
                           variables_key: ["DISPLACEMENT_X", "CONTACT_PRESSURE"]}}
    process = create_process(mc.Parameters(json.dumps(item)), model)
    process.ExecuteInitialize()
    with pytest.raises(mc.InputError, match=rf"{variables_key}: CONTACT_PRESSURE is not a historical .* of "
                                            r"Structure; .* set historical_value to false"):
        process.Check()
