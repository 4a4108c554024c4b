"""Issue 18, item 3: impose_rigid_movement_process (StructuralMechanicsApplication) and the
elimination builder with master-slave constraints. Kratos' hyper_simple_patch_test_with_elimination_
with_constraints (tests/cases/kratos_csma, from Kratos' suite) runs unchanged and passes its own json
check; the constraints hold exactly; every key of the process changes what it should."""
from __future__ import annotations

import json
import os

import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.processes.impose_rigid_movement_process import ImposeRigidMovementProcess
from mortarcontact.project_parameters import migrate_project_parameters

from csma_cases import CSMA_CASES

CASE = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test_with_elimination_with_constraints"
PLAIN = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test"


def run_case(case=CASE, edit=None, components=False):
    """The analysis of a CSMA case (its own json checks raise on failure), edited by ``edit``."""
    with open(os.path.join(CSMA_CASES, f"{case}_parameters.json")) as f:
        params = json.load(f)
    if edit:
        edit(params)
    if components:
        params["solver_settings"]["contact_settings"]["mortar_type"] = "ALMContactFrictionlessComponents"
        for item in params["processes"]["contact_process_list"]:
            item["Parameters"]["contact_type"] = "FrictionlessComponents"
    cwd = os.getcwd()
    os.chdir(CSMA_CASES)
    try:
        parameters = mc.Parameters(json.dumps(params))
        migrate_project_parameters(parameters)
        analysis = StructuralMechanicsAnalysis(mc.Model(), parameters, progress=False)
        analysis.Run()
    finally:
        os.chdir(cwd)
    return analysis


def displacement(analysis, node: int):
    return analysis.model.GetModelPart("Structure").GetNode(node).GetSolutionStepValue(mc.DISPLACEMENT)


def rigid_items(params):
    return [item for item in params["processes"]["constraints_process_list"]
            if item["python_module"] == "impose_rigid_movement_process"]


@pytest.mark.parametrize("components", [False, True], ids=["scalar", "components"])
def test_kratos_case_with_elimination_and_constraints(components):
    """Passes its Kratos reference (its json check, 1e-3 relative by default), in 2 Newton
    iterations; u_x(4) = -u_x(3) and u_x(6) = -u_x(5) hold to round-off (relation -1 on
    DISPLACEMENT_X of Contact_Part_1 = {3, 4} and Contact_Part_2 = {5, 6}, master = first node); the
    answer equals the unconstrained patch test's, whose symmetric solution satisfies them."""
    analysis = run_case(components=components)
    assert [it for _, _, it, _, _ in analysis.step_log] == [2]
    assert displacement(analysis, 4)[0] == pytest.approx(-displacement(analysis, 3)[0], abs=1e-15)
    assert displacement(analysis, 6)[0] == pytest.approx(-displacement(analysis, 5)[0], abs=1e-15)
    plain = run_case(PLAIN, components=components)
    for node in (3, 4, 5, 6):
        assert displacement(analysis, node) == pytest.approx(displacement(plain, node), abs=1e-12)
    root = analysis.model.GetModelPart("Structure")
    assert len(root.MasterSlaveConstraints) == 2
    assert len(root.GetSubModelPart("Contact_Part_1").MasterSlaveConstraints) == 1


def _drop_json_check(params):
    params["processes"].pop("json_check_process")


def test_relation_constant_and_master_node_id():
    """relation 0.5, constant 1e-4 and master node 4: u_x(3) = 0.5 u_x(4) + 1e-4 exactly, which
    the symmetric patch does not satisfy, so the answer moves away from the plain one."""
    def edit(params):
        _drop_json_check(params)
        item = rigid_items(params)[0]["Parameters"]
        item.update(relation=0.5, constant=1e-4, master_node_id=4)
        params["processes"]["constraints_process_list"].remove(rigid_items(params)[1])
    analysis = run_case(edit=edit)
    u3, u4 = displacement(analysis, 3)[0], displacement(analysis, 4)[0]
    assert u3 == pytest.approx(0.5 * u4 + 1e-4, abs=1e-15)
    assert abs(u3 - 0.001284260352665) > 1e-5


def test_slave_variable_name_and_vector_master():
    """A vector master variable ties every component; slave_variable_name another variable than
    the master's (DISPLACEMENT_Y of node 4 follows DISPLACEMENT_X of node 3)."""
    def vector(params):
        _drop_json_check(params)
        rigid_items(params)[0]["Parameters"].update(master_variable_name="DISPLACEMENT", relation=1.0)
        params["processes"]["constraints_process_list"].remove(rigid_items(params)[1])
    analysis = run_case(edit=vector)
    assert displacement(analysis, 4)[:2] == pytest.approx(displacement(analysis, 3)[:2], abs=1e-15)
    assert len(analysis.model.GetModelPart("Structure").MasterSlaveConstraints) == 2  # X and Y (2D)

    def crossed(params):
        _drop_json_check(params)
        rigid_items(params)[0]["Parameters"].update(slave_variable_name="DISPLACEMENT_Y", relation=1.0)
        params["processes"]["constraints_process_list"].remove(rigid_items(params)[1])
    analysis = run_case(edit=crossed)
    assert displacement(analysis, 4)[1] == pytest.approx(displacement(analysis, 3)[0], abs=1e-15)


def test_interval_new_model_part_name_and_main_model_part_name():
    """Outside its interval a constraint is off (the plain answer); new_model_part_name lists the
    constraints in a sub part; main_model_part_name names the root the part is looked up in."""
    def late(params):
        _drop_json_check(params)
        for item in rigid_items(params):
            item["Parameters"].update(interval=[2.0, "End"], relation=0.5)
    analysis = run_case(edit=late)
    plain = run_case(PLAIN)
    assert displacement(analysis, 3) == pytest.approx(displacement(plain, 3), abs=1e-12)

    def named(params):
        for item in rigid_items(params):
            item["Parameters"].update(new_model_part_name="Rigid", main_model_part_name="Structure")
    analysis = run_case(edit=named)
    rigid = analysis.model.GetModelPart("Structure.Contact_Part_1.Rigid")
    assert [node.Id for node in rigid.Nodes] == [3, 4] and len(rigid.MasterSlaveConstraints) == 1


def test_bad_keys_are_named():
    model = mc.Model()
    root = model.CreateModelPart("Structure")
    root.AddNodalSolutionStepVariable(mc.DISPLACEMENT)
    root.CreateSubModelPart("Tied")
    with pytest.raises(mc.InputError, match=r"master_variable_name: .*DISPLACEMNT"):
        ImposeRigidMovementProcess(model, mc.Parameters(
            '{"model_part_name": "Tied", "master_variable_name": "DISPLACEMNT"}'))
    with pytest.raises(mc.InputError, match=r"Structure\.Tie"):
        ImposeRigidMovementProcess(model, mc.Parameters('{"model_part_name": "Tie"}'))
