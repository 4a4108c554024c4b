"""Issue 15, item 2: the public Python model API. Nodes, elements and conditions from numpy arrays
in one call, properties from a dict, no get-or-create GetProperties, and ``mc.Analysis`` over a
model built in Python, checked against a closed-form solution and against ``mc.run`` on files."""
from __future__ import annotations

import json
import shutil
import time

import numpy as np
import pytest

import mortarcontact as mc

from small_models import square_grid

PLANE_STRAIN = {"YOUNG_MODULUS": 200.0, "POISSON_RATIO": 0.25, "THICKNESS": 1.0}


def test_bulk_nodes_in_any_id_order_match_one_by_one_creation():
    rng = np.random.default_rng(7)
    ids = rng.permutation(np.arange(1, 201)) * 3  # not consecutive, shuffled
    xyz = rng.random((200, 3))
    bulk = mc.Model().CreateModelPart("S")
    bulk.CreateNewNodes(ids, xyz)
    loop = mc.Model().CreateModelPart("S")
    for i in np.argsort(ids):
        loop.CreateNewNode(int(ids[i]), *xyz[i])
    assert bulk.NodeIds().tolist() == loop.NodeIds().tolist() == sorted(ids.tolist())
    assert np.array_equal(bulk.NodeCoordinates(), loop.NodeCoordinates())
    assert np.array_equal(bulk.NodeCoordinates(initial=True), xyz[np.argsort(ids)])


def test_bulk_nodes_of_a_sub_model_part_reach_its_ancestors_and_accept_2d_coordinates():
    root = mc.Model().CreateModelPart("S")
    sub = root.CreateSubModelPart("Parts").CreateSubModelPart("block")
    sub.CreateNewNodes([4, 5], np.array([[1.0, 2.0], [3.0, 4.0]]))
    for part in (root, root.GetSubModelPart("Parts"), sub):
        assert part.NodeIds().tolist() == [4, 5]
    assert root.NodeCoordinates().tolist() == [[1.0, 2.0, 0.0], [3.0, 4.0, 0.0]]


@pytest.mark.parametrize("ids, coordinates, message", [
    ([1, 2, 1], np.zeros((3, 3)), "S: node 1 is given twice"),
    ([9, 3], np.zeros((2, 3)), "S: node 3 exists already"),
    ([7, 0], np.zeros((2, 3)), "node ids must be positive integers, found 0"),
    ([7, 8], np.zeros((3, 3)), r"coordinates: expected an array \(2, 3\) or \(2, 2\)"),
])
def test_bulk_nodes_check_everything_before_creating_any(ids, coordinates, message):
    part = mc.Model().CreateModelPart("S")
    part.CreateNewNodes([3, 4], np.zeros((2, 3)))
    with pytest.raises(mc.InputError, match=message):
        part.CreateNewNodes(ids, coordinates)
    assert part.NodeIds().tolist() == [3, 4]


def test_bulk_elements_and_conditions_match_one_by_one_creation():
    _, root = square_grid(3, 2)
    quads = np.array([[j * 4 + i + 1, j * 4 + i + 2, j * 4 + i + 6, j * 4 + i + 5] for j in range(2) for i in range(3)])
    properties = root.CreateNewProperties(1, PLANE_STRAIN, "LinearElasticPlaneStrain2DLaw")
    root.CreateNewElements("SmallDisplacementElement2D4N", [6, 5, 4, 3, 2, 1], quads[::-1], properties)
    top = root.GetSubModelPart("top")
    top.CreateNewConditions("LineLoadCondition2D2N", [1, 2, 3], [[9, 10], [10, 11], [11, 12]], properties)
    ids, connectivity = root.EntityConnectivity()["Quadrilateral2D4"]
    assert ids.tolist() == [1, 2, 3, 4, 5, 6] and np.array_equal(connectivity, quads)
    assert [c.Id for c in top.Conditions] == [1, 2, 3] and root.NumberOfConditions() == 3
    assert {e.GetProperties().Id for e in root.Elements} == {1}
    assert top.GetCondition(2).NodeIds() == [10, 11]
    with pytest.raises(mc.InputError, match="element 4 exists already"):
        root.CreateNewElements("SmallDisplacementElement2D4N", [7, 4], quads[:2], 1)
    with pytest.raises(mc.InputError, match="needs 4 nodes, got 3"):
        root.CreateNewElements("SmallDisplacementElement2D4N", [7], quads[:1, :3], 1)
    # An id names properties the part lists: the root's 1, not those of a sub model part that lists none.
    root.CreateNewConditions("LineLoadCondition2D2N", [4], [[1, 2]], 1)
    with pytest.raises(mc.InputError, match=r"model part Structure.top has no properties 1 \(it has none\); create "
                                            r"them with CreateNewProperties\(1\)"):
        top.CreateNewConditions("LineLoadCondition2D2N", [5], [[9, 10]], 1)
    assert root.NumberOfElements() == 6 and root.NumberOfConditions() == 4


def test_properties_from_a_dict_and_no_get_or_create():
    root = mc.Model().CreateModelPart("S")
    assert not root.HasProperties(0)
    with pytest.raises(mc.InputError, match=r"model part S has no properties 0 \(it has none\)"):
        root.GetProperties(0)
    assert not root.HasProperties(0)
    created = root.CreateNewProperties(3, {"YOUNG_MODULUS": 210e9, mc.POISSON_RATIO: 0.3}, "LinearElastic3DLaw")
    same = root.GetProperties(3)
    assert same.Id == created.Id == 3
    assert same.GetValue(mc.YOUNG_MODULUS) == 210e9 and same.GetValue(mc.POISSON_RATIO) == 0.3
    assert same.ConstitutiveLawName() == "LinearElastic3DLaw"
    same.SetValues({"DENSITY": 7850.0})
    assert created.GetValue(mc.DENSITY) == 7850.0
    with pytest.raises(mc.InputError, match="properties 3 exist already"):
        root.CreateNewProperties(3)
    with pytest.raises(mc.InputError, match=r"unknown variable 'YOUNG_MODULUSS'.*did you mean 'YOUNG_MODULUS'"):
        root.CreateNewProperties(4, {"YOUNG_MODULUSS": 1.0})
    with pytest.raises(mc.InputError, match="values: a key must be a variable or its name, got 7"):
        root.CreateNewProperties(4, {7: 1.0})
    with pytest.raises(mc.InputError, match="LinearElasticPlaneStrain2DLaw"):
        root.CreateNewProperties(5, None, "LinearElasticPlaneStrain2Law")
    assert not root.HasProperties(4) and not root.HasProperties(5)  # a failed call creates nothing
    # A sub model part lists the root's properties of the same id: one set per id in the tree.
    sub = root.CreateSubModelPart("block")
    assert sub.CreateNewProperties(3).GetValue(mc.DENSITY) == 7850.0


def test_returned_arrays_are_copies_and_setters_write_back():
    """As documented (docs/api.md, "Views and copies"): no getter returns a view of the nodes'
    storage, so writing into its array changes nothing; the setters are the way back."""
    _, root = square_grid(2, 1)
    values = root.GetNodalValues(mc.DISPLACEMENT)
    coordinates = root.NodeCoordinates()
    values[:] = 1.0
    coordinates[:] = 5.0
    assert not root.GetNodalValues(mc.DISPLACEMENT).any()
    assert root.NodeCoordinates().max() == 2.0
    root.SetNodalValues(mc.DISPLACEMENT, values)
    assert (root.GetNodalValues(mc.DISPLACEMENT) == 1.0).all()


def test_100k_nodes_and_200k_triangles_in_one_call_each():
    """The measurement of the issue: 100k nodes in one call. Bounds far above the measured times
    (0.06 s for the nodes, 0.9 s for the elements, on a shared 2-core machine), which a per-node
    Python round trip or a re-sort per insertion would exceed."""
    n = 100_000
    rng = np.random.default_rng(1)
    part = mc.Model().CreateModelPart("S")
    part.AddNodalSolutionStepVariable(mc.DISPLACEMENT)
    started = time.perf_counter()
    part.CreateNewNodes(rng.permutation(n) + 1, rng.random((n, 3)))
    nodes_seconds = time.perf_counter() - started
    part.CreateNewProperties(0)
    started = time.perf_counter()
    connectivity = rng.integers(1, n + 1, (2 * n, 3))
    part.CreateNewElements("SmallDisplacementElement2D3N", np.arange(1, 2 * n + 1), connectivity, 0)
    elements_seconds = time.perf_counter() - started
    assert part.NumberOfNodes() == n and part.NumberOfElements() == 2 * n
    assert nodes_seconds < 1.0, nodes_seconds
    assert elements_seconds < 10.0, elements_seconds


def _compression_parameters(model_import: dict, materials: str = "") -> dict:
    """A plane-strain block [0, 3] x [0, 2] pressed down by 0.02 on its top, roller bottom, the left
    side held in x: a homogeneous state that bilinear quadrilaterals reproduce exactly."""
    def fix(part, constrained, value):
        return {"python_module": "assign_vector_variable_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"model_part_name": f"Structure.{part}", "variable_name": "DISPLACEMENT",
                               "constrained": constrained, "value": value, "interval": [0.0, "End"]}}
    return {
        "problem_data": {"problem_name": "compression", "echo_level": 0, "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {"solver_type": "Static", "model_part_name": "Structure", "domain_size": 2,
                            "analysis_type": "linear", "model_import_settings": model_import,
                            "material_import_settings": {"materials_filename": materials},
                            "time_stepping": {"time_step": 1.0}},
        "processes": {"constraints_process_list": [
            fix("bottom", [False, True, True], [None, 0.0, 0.0]),
            fix("left", [True, False, True], [0.0, None, 0.0]),
            fix("top", [False, True, True], [None, -0.02, 0.0])]},
        "output_processes": {},
    }


def _compression_mesh(part) -> None:
    nx, ny = 3, 2
    x, y = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0))
    part.CreateNewNodes(np.arange(1, x.size + 1), np.column_stack([x.ravel(), y.ravel()]))
    grid = np.arange(1, x.size + 1).reshape(ny + 1, nx + 1)
    quads = np.column_stack([grid[:-1, :-1].ravel(), grid[:-1, 1:].ravel(), grid[1:, 1:].ravel(),
                             grid[1:, :-1].ravel()])
    part.CreateNewProperties(1, PLANE_STRAIN, "LinearElasticPlaneStrain2DLaw")
    part.CreateNewElements("SmallDisplacementElement2D4N", np.arange(1, len(quads) + 1), quads, 1)
    for name, nodes in (("bottom", grid[0]), ("top", grid[-1]), ("left", grid[:, 0])):
        part.CreateSubModelPart(name).AddNodes(nodes.tolist())


def test_analysis_over_a_model_built_in_python_gives_the_exact_homogeneous_solution():
    model = mc.Model()
    analysis = mc.Analysis(model, _compression_parameters({"input_type": "use_input_model_part"}))
    part = model["Structure"]
    _compression_mesh(part)
    analysis.Run()
    x = part.NodeCoordinates(initial=True)
    u = part.GetNodalValues(mc.DISPLACEMENT)
    nu = PLANE_STRAIN["POISSON_RATIO"]
    strain_y = -0.02 / 2.0
    # plane strain, sigma_xx = 0: eps_xx = -nu / (1 - nu) eps_yy
    assert np.allclose(u[:, 1], strain_y * x[:, 1], atol=1e-12)
    assert np.allclose(u[:, 0], -nu / (1.0 - nu) * strain_y * x[:, 0], atol=1e-12)
    assert "compression: 1 step" in analysis.Summary()


def test_analysis_from_a_file_a_dict_and_parameters_agree_with_run(tmp_path):
    """The same case written as mdpa + materials + ProjectParameters.json: mc.run(path),
    mc.Analysis(model, path), mc.Analysis(model, dict) and mc.Analysis(model, mc.Parameters) agree."""
    built = mc.Model().CreateModelPart("Structure")
    _compression_mesh(built)
    mc.WriteModelPart(built, str(tmp_path / "block.mdpa"))
    materials = {"properties": [{"model_part_name": "Structure", "properties_id": 1, "Material": {
        "constitutive_law": {"name": "LinearElasticPlaneStrain2DLaw"}, "Variables": PLANE_STRAIN}}]}
    (tmp_path / "materials.json").write_text(json.dumps(materials))
    parameters = _compression_parameters({"input_type": "mdpa", "input_filename": "block"}, "materials.json")
    (tmp_path / "ProjectParameters.json").write_text(json.dumps(parameters))
    reference = mc.run(str(tmp_path / "ProjectParameters.json"), progress=False).model["Structure"]
    expected = reference.GetNodalValues(mc.DISPLACEMENT)
    assert np.abs(expected).max() == pytest.approx(0.02)
    other = tmp_path / "elsewhere"
    shutil.copytree(tmp_path, other, ignore=shutil.ignore_patterns("elsewhere"))
    for given in (str(other / "ProjectParameters.json"), other / "ProjectParameters.json"):
        model = mc.Model()
        mc.Analysis(model, given).Run()
        assert np.array_equal(model["Structure"].GetNodalValues(mc.DISPLACEMENT), expected)
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(tmp_path)
        for given in (parameters, mc.Parameters(json.dumps(parameters))):
            model = mc.Model()
            mc.Analysis(model, given).Run()
            assert np.array_equal(model["Structure"].GetNodalValues(mc.DISPLACEMENT), expected)
    with pytest.raises(mc.InputError, match=r"parameters must be a dict, a ProjectParameters\.json path or an "
                                            r"mc\.Parameters, got list"):
        mc.Analysis(mc.Model(), [parameters])


def test_analysis_names_a_mistyped_key_of_a_dict():
    parameters = _compression_parameters({"input_type": "use_input_model_part"})
    parameters["solver_settings"]["max_iterations"] = 3
    with pytest.raises(mc.InputError, match=r"max_iterations.*did you mean 'max_iteration'"):
        mc.Analysis(mc.Model(), parameters)
