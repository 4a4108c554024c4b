"""Issue 15, item 1: mesh input through meshio (``model_import_settings.input_type`` ``"gmsh"`` and
``"meshio"``): groups become sub model parts, element and condition names come from the settings,
the same mesh read from msh 4.1 and from mdpa gives the same model part and the same contact
solution, and every user mistake gives one clear InputError."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import meshio
import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.solvers.meshio_import import import_mesh, read_mesh

from small_models import parameters

CELL_DIMENSION = {"vertex": 0, "line": 1, "triangle": 2, "quad": 2, "tetra": 3, "hexahedron": 3,
                  "hexahedron20": 3, "pyramid": 3}


def write_msh(path, points, groups, file_format="gmsh") -> None:
    """A gmsh msh 4.1 file of ``groups`` [(name, meshio cell type, 0-based connectivity)]."""
    meshio.write(path, gmsh_mesh(points, groups), file_format=file_format)


def gmsh_mesh(points, groups):
    """The meshio.Mesh of a gmsh file of ``groups``: one physical group and one geometric entity per
    group (tag i + 1). meshio lists the entities of the nodes' "gmsh:dim_tags", so each entity first
    gets a node of its own, then the other nodes go to the highest-dimensional entity that holds them."""
    dim_tags = np.full((len(points), 2), -1)
    nodes = [np.unique(cells) for _, _, cells in groups]
    for i in sorted(range(len(groups)), key=lambda i: len(nodes[i])):
        free = [n for n in nodes[i] if dim_tags[n, 0] < 0]
        assert free, f"{groups[i][0]} has no node of its own"
        dim_tags[free[0]] = (CELL_DIMENSION[groups[i][1]], i + 1)
    for i in sorted(range(len(groups)), key=lambda i: -CELL_DIMENSION[groups[i][1]]):
        free = [n for n in nodes[i] if dim_tags[n, 0] < 0]
        dim_tags[free] = (CELL_DIMENSION[groups[i][1]], i + 1)
    assert np.all(dim_tags >= 0), "every node must be in a group"
    tags = [np.full(len(cells), i + 1) for i, (_, _, cells) in enumerate(groups)]
    return meshio.Mesh(points, [(cell_type, np.asarray(cells)) for _, cell_type, cells in groups],
                       point_data={"gmsh:dim_tags": dim_tags},
                       cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags},
                       field_data={name: np.array([i + 1, CELL_DIMENSION[cell_type]])
                                   for i, (name, cell_type, _) in enumerate(groups)})


def describe(part, entities=True) -> dict:
    """Everything the import decides: node ids and coordinates, entities (name, geometry, nodes,
    properties) and the sub model part tree with the ids it holds."""
    data = {"nodes": part.NodeIds().tolist(),
            "elements": [e.Id for e in part.Elements], "conditions": [c.Id for c in part.Conditions],
            "sub_model_parts": {sub.Name: describe(sub, False) for sub in part.SubModelParts}}
    if entities:
        data["coordinates"] = part.NodeCoordinates(True).tolist()
        data["entities"] = [(kind, e.Id, e.Info(), e.GetGeometry().Name(), e.NodeIds(), e.GetProperties().Id)
                            for kind, group in (("element", part.Elements), ("condition", part.Conditions))
                            for e in group]
    return data


# Two blocks on [0, 2] x [0, 2]: quads below y = 1 (Parts.base), triangles above (Parts.block).
POINTS = np.array([[x, y, 0.0] for y in (0.0, 1.0, 2.0) for x in (0.0, 1.0, 2.0)])
QUADS = np.array([[0, 1, 4, 3], [1, 2, 5, 4]])
TRIANGLES = np.array([[3, 4, 7], [3, 7, 6], [4, 5, 8], [4, 8, 7]])
GROUPS = [("Parts.base", "quad", QUADS), ("Parts.block", "triangle", TRIANGLES),
          ("DISPLACEMENT_bottom", "line", np.array([[0, 1], [1, 2]])),
          ("Load_top", "line", np.array([[6, 7], [7, 8]])),
          ("Corner", "vertex", np.array([[5]]))]
SETTINGS = {"element_names": {"Parts.base": "SmallDisplacementElement2D4N",
                              "Parts.block": "TotalLagrangianElement"},
            "condition_names": {"Load_top": "LineLoadCondition"},
            "properties_ids": {"Parts.block": 2, "Load_top": 3}}


def read_into_model(path, settings=None, input_type="gmsh", domain_size=2):
    model = mc.Model()
    part = model.CreateModelPart("Structure")
    mesh, node_ids = read_mesh(str(path), input_type, "solver_settings.model_import_settings")
    import_mesh(part, mesh, node_ids, imports(settings if settings is not None else SETTINGS), domain_size, str(path))
    return part


def imports(settings: dict):
    full = {"element_names": {}, "condition_names": {}, "properties_ids": {}, **settings}
    return parameters(json.dumps({"solver_settings": {"model_import_settings": full}}))[
        "solver_settings"]["model_import_settings"]


def hand_built(model):
    """The same mesh built through the model-part API, as the mdpa reader would."""
    part = model.CreateModelPart("Structure")
    for k, x in enumerate(POINTS):
        part.CreateNewNode(k + 1, *x)
    properties = {pid: part.CreateNewProperties(pid) for pid in (0, 2, 3)}
    for k, cell in enumerate(QUADS):
        part.CreateNewElement("SmallDisplacementElement2D4N", k + 1, (cell + 1).tolist(), properties[0])
    for k, cell in enumerate(TRIANGLES):
        part.CreateNewElement("TotalLagrangianElement2D3N", k + 3, (cell + 1).tolist(), properties[2])
    for k, cell in enumerate(GROUPS[3][2]):
        part.CreateNewCondition("LineLoadCondition2D2N", k + 1, (cell + 1).tolist(), properties[3])
    contents = {"Parts.base": ([1, 2, 3, 4, 5, 6], [1, 2], []), "Parts.block": ([4, 5, 6, 7, 8, 9], [3, 4, 5, 6], []),
                "DISPLACEMENT_bottom": ([1, 2, 3], [], []), "Load_top": ([7, 8, 9], [], [1, 2]),
                "Corner": ([6], [], [])}
    for name, (nodes, elements, conditions) in contents.items():
        sub = part.CreateSubModelPart(name)
        sub.AddNodes(nodes)
        sub.AddElements(elements)
        sub.AddConditions(conditions)
    return part


@pytest.mark.parametrize("file_format", ["gmsh", "gmsh22"])  # msh 4.1 (cell_sets), msh 2.2 (physical tags)
def test_msh_and_mdpa_give_the_same_model_part(tmp_path, file_format):
    write_msh(tmp_path / "blocks.msh", POINTS, GROUPS, file_format)
    from_msh = read_into_model(tmp_path / "blocks.msh")
    built = hand_built(mc.Model())
    mc.WriteModelPart(built, str(tmp_path / "blocks.mdpa"))
    from_mdpa = mc.Model().CreateModelPart("Structure")
    mc.ReadModelPart(from_mdpa, str(tmp_path / "blocks.mdpa"))
    assert describe(from_msh) == describe(from_mdpa) == describe(built)
    assert from_msh.GetSubModelPart("Parts").SubModelPartNames() == ["base", "block"]
    assert from_msh.GetSubModelPart("Parts").NumberOfElements() == 6


def test_import_meshio_from_memory_equals_the_file_route(tmp_path):
    """mc.import_meshio (the public ModelPart-from-meshio call) on a meshio.Mesh in memory builds
    the model part that input_type "gmsh" builds from the same mesh written to a file."""
    write_msh(tmp_path / "blocks.msh", POINTS, GROUPS)
    from_file = read_into_model(tmp_path / "blocks.msh")
    mesh = gmsh_mesh(POINTS, GROUPS)
    part = mc.Model().CreateModelPart("Structure")
    mc.import_meshio(part, mesh, **SETTINGS)
    assert describe(part) == describe(from_file) == describe(hand_built(mc.Model()))
    assert part.ProcessInfo.GetValue(mc.DOMAIN_SIZE) == 2
    with pytest.raises(mc.InputError, match="is not empty"):
        mc.import_meshio(part, mesh, **SETTINGS)
    with pytest.raises(mc.InputError, match=r"no group 'Parts\.blok'.*did you mean 'Parts\.block'"):
        mc.import_meshio(mc.Model().CreateModelPart("S"), mesh,
                         element_names={"Parts.blok": "SmallDisplacementElement"})


def test_meshio_input_type_reads_other_formats(tmp_path):
    """The same groups as cell_sets / point_sets of a VTU-free format meshio writes: Abaqus inp."""
    mesh = meshio.Mesh(POINTS, [("quad", QUADS), ("triangle", TRIANGLES)],
                       cell_sets={"base": [np.arange(2), np.array([], dtype=int)],
                                  "block": [np.array([], dtype=int), np.arange(4)]},
                       point_sets={"bottom": np.array([0, 1, 2])})
    mesh.write(tmp_path / "blocks.inp")
    part = read_into_model(tmp_path / "blocks.inp", {"element_names": {"base": "SmallDisplacementElement",
                                                                        "block": "SmallDisplacementElement"}},
                           input_type="meshio")
    assert sorted(part.SubModelPartNames()) == ["base", "block", "bottom"]
    assert part.GetSubModelPart("block").NumberOfElements() == 4
    assert part.GetSubModelPart("bottom").NodeIds().tolist() == [1, 2, 3]
    assert [e.GetGeometry().Name() for e in part.Elements] == ["Quadrilateral2D4"] * 2 + ["Triangle2D3"] * 4


def test_quadratic_hexahedron_nodes_follow_our_order(tmp_path):
    """meshio lists hexahedron20 nodes in VTK order; a wrong permutation would distort the cube."""
    corners = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    vtk_edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
    points = np.vstack([corners, [(corners[a] + corners[b]) / 2 for a, b in vtk_edges]])
    write_msh(tmp_path / "cube.msh", points, [("cube", "hexahedron20", np.arange(20).reshape(1, 20))])
    part = read_into_model(tmp_path / "cube.msh", {"element_names": {"cube": "SmallDisplacementElement"}},
                           domain_size=3)
    geometry = part.GetElement(1).GetGeometry()
    assert geometry.Name() == "Hexahedra3D20"
    assert geometry.DomainSize(mc.Configuration.Initial) == pytest.approx(1.0, abs=1e-12)
    for local in ([0.3, -0.5, 0.7], [-1.0, 0.0, 1.0]):
        assert np.allclose(geometry.GlobalCoordinates(local, mc.Configuration.Initial), (np.array(local) + 1) / 2)


# --- errors ------------------------------------------------------------------------------------
@pytest.fixture
def blocks_msh(tmp_path):
    write_msh(tmp_path / "blocks.msh", POINTS, GROUPS)
    return tmp_path / "blocks.msh"


@pytest.mark.parametrize("settings, fragments", [
    ({**SETTINGS, "element_names": {**SETTINGS["element_names"], "Parts.blok": "SmallDisplacementElement"}},
     ["model_import_settings.element_names: no group 'Parts.blok' in", "did you mean 'Parts.block'"]),
    ({**SETTINGS, "element_names": {"Parts.base": "SmallDisplacementElement2D4N"}},
     ["element_names: group 'Parts.block' has triangle cells of the model's dimension", "but no element",
      "\"Parts.block\": \"SmallDisplacementElement2D3N\""]),
    ({**SETTINGS, "element_names": {**SETTINGS["element_names"], "Parts.block": "SmallDisplacementElement2D4N"}},
     ["element_names.Parts.block: element 'SmallDisplacementElement2D4N' has the geometry",
      "Quadrilateral2D4", "triangle cells in", "are Triangle2D3"]),
    ({**SETTINGS, "element_names": {**SETTINGS["element_names"], "Parts.block": "SmallDisplacementElemnt"}},
     ["element_names.Parts.block: unknown element 'SmallDisplacementElemnt'", "SmallDisplacementElement2D3N"]),
    ({**SETTINGS, "condition_names": {"Load_top": "SurfaceLoadCondition3D3N"}},
     ["condition_names.Load_top: condition 'SurfaceLoadCondition3D3N' has the geometry", "Triangle3D3",
      "line cells in", "are Line2D2"]),
    ({**SETTINGS, "properties_ids": {"Load_top": -1}},
     ["properties_ids.Load_top: expected a non-negative integer, found -1"]),
    ({**SETTINGS, "element_names": {**SETTINGS["element_names"], "Corner": "SmallDisplacementElement"}},
     []),  # points of the domain's dimension do not exist: the element name of a vertex group is unused
])
def test_group_settings_errors(blocks_msh, settings, fragments):
    if not fragments:
        read_into_model(blocks_msh, settings)
        return
    with pytest.raises(mc.InputError) as error:
        read_into_model(blocks_msh, settings)
    for fragment in fragments:
        assert fragment in str(error.value), str(error.value)


def test_unsupported_cell_type_names_type_group_and_file(tmp_path):
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]], float)
    write_msh(tmp_path / "pyramid.msh", points, [("Parts_tip", "pyramid", np.arange(5).reshape(1, 5))])
    with pytest.raises(mc.NotImplementedFeatureError) as error:
        read_into_model(tmp_path / "pyramid.msh", {"element_names": {"Parts_tip": "SmallDisplacementElement"}},
                        domain_size=3)
    message = str(error.value)
    assert "pyramid.msh: group 'Parts_tip' has pyramid cells" in message and "hexahedron" in message
    with pytest.raises(mc.NotImplementedFeatureError, match="group 'Parts_tip' has pyramid cells, which "
                                                            "mortarcontact cannot read"):
        read_into_model(tmp_path / "pyramid.msh", {}, domain_size=3)


def test_cells_above_the_domain_dimension(blocks_msh):
    with pytest.raises(mc.InputError, match=r"group 'Parts.base' has quad cells, of dimension 2, in a model of "
                                            "solver_settings.domain_size 1"):
        read_into_model(blocks_msh, {}, domain_size=1)


def test_unreadable_file_and_missing_meshio(tmp_path, monkeypatch):
    (tmp_path / "broken.msh").write_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2\n")
    with pytest.raises(mc.InputError, match=r"broken.msh: meshio cannot read it as 'gmsh' input"):
        read_mesh(str(tmp_path / "broken.msh"), "gmsh", "solver_settings.model_import_settings")
    monkeypatch.setitem(sys.modules, "meshio", None)
    with pytest.raises(mc.InputError, match="\"meshio\" needs the Python package meshio, a dependency of "
                                            "mortarcontact that is not installed"):
        read_mesh(str(tmp_path / "broken.msh"), "meshio", "solver_settings.model_import_settings")


# --- cases -------------------------------------------------------------------------------------
GEOMETRY_CELLS = {"Triangle2D3": "triangle", "Quadrilateral2D4": "quad", "Line2D2": "line", "Tetrahedra3D4": "tetra",
                  "Hexahedra3D8": "hexahedron", "Triangle3D3": "triangle", "Quadrilateral3D4": "quad"}


def msh_of_mdpa(mdpa: str, msh: str) -> dict:
    """Writes the mesh of an mdpa (consecutive node ids, flat sub model parts) as msh 4.1; a part
    with elements is a group of its cells, a part of nodes only a group of vertex cells. Returns
    the model_import_settings that read it back as the same model."""
    root = mc.Model().CreateModelPart("Structure")
    mc.ReadModelPart(root, mdpa)
    assert root.NodeIds().tolist() == list(range(1, root.NumberOfNodes() + 1))
    groups, settings = [], {"input_type": "gmsh", "input_filename": os.path.basename(msh), "element_names": {},
                            "properties_ids": {}}
    # element groups in the order of their element ids, so that the msh numbers them as the mdpa
    for sub in sorted(root.SubModelParts, key=lambda sub: min((e.Id for e in sub.Elements), default=0)):
        assert not sub.SubModelPartNames() and sub.NumberOfConditions() == 0
        if sub.NumberOfElements() == 0:
            groups.append((sub.Name, "vertex", sub.NodeIds().reshape(-1, 1) - 1))
            continue
        (geometry, (ids, connectivity)), = sub.EntityConnectivity().items()
        first = sub.GetElement(int(ids[0]))
        groups.append((sub.Name, GEOMETRY_CELLS[geometry], connectivity - 1))
        settings["element_names"][sub.Name] = first.Info()
        settings["properties_ids"][sub.Name] = first.GetProperties().Id
    write_msh(msh, root.NodeCoordinates(True), groups)
    return settings


@pytest.fixture(scope="module")
def hertz_case(tmp_path_factory):
    """The smallest Hertz case as generated (gmsh 2.2 file), as the mdpa Kratos gets of it, and as
    msh 4.1 written from that mdpa: three parameter files side by side."""
    from mortarcontact.cases import hertz
    from mortarcontact.cases.mesh_files import write_kratos_mdpa

    folder = hertz.write_case("hertz2d", "2k", str(tmp_path_factory.mktemp("hertz_msh")))
    name = os.path.basename(folder)
    mdpa = write_kratos_mdpa(folder)
    with open(os.path.join(folder, "ProjectParameters.json")) as f:
        params = json.load(f)
    for variant, imports in (("mdpa", {"input_type": "mdpa", "input_filename": name}),
                             ("msh41", msh_of_mdpa(mdpa, os.path.join(folder, f"{name}_41.msh")))):
        params["solver_settings"]["model_import_settings"] = imports
        with open(os.path.join(folder, f"ProjectParameters_{variant}.json"), "w") as f:
            json.dump(params, f, indent=2)
    return folder


def test_contact_case_from_msh_matches_mdpa(hertz_case):
    """The Hertz contact case gives the same displacements and contact pressure from its gmsh 2.2
    file, from msh 4.1 and from mdpa."""
    results = []
    for parameters_file in ("ProjectParameters_mdpa.json", "ProjectParameters.json", "ProjectParameters_msh41.json"):
        analysis = mc.run(os.path.join(hertz_case, parameters_file), progress=False)
        root = analysis.model["Structure"]
        results.append((describe(root), root.GetNodalValues(mc.DISPLACEMENT),
                        root.GetNodalValues(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)))
    (mdpa_model, mdpa_u, mdpa_p) = results[0]
    assert np.abs(mdpa_u).max() > 1e-3 and np.abs(mdpa_p).max() > 0.0  # the case does load the contact
    for msh_model, msh_u, msh_p in results[1:]:
        assert msh_model == mdpa_model  # nodes, elements, the contact conditions and parts the processes made
        np.testing.assert_allclose(msh_u, mdpa_u, rtol=0.0, atol=1e-12)
        np.testing.assert_allclose(msh_p, mdpa_p, rtol=0.0, atol=1e-12 * np.abs(mdpa_p).max())


# --- command line ------------------------------------------------------------------------------
def blocks_case(folder, edit=None) -> str:
    """The two blocks, bottom fixed, top pulled down by 0.01, from blocks.msh; VTU output."""
    from case_builder import fix_process, materials, project_parameters, write_case

    write_msh(os.path.join(folder, "blocks.msh"), POINTS, GROUPS)
    params = project_parameters("blocks", 2, constraints=[
        fix_process("Structure.DISPLACEMENT_bottom", [0.0, 0.0, 0.0]),
        fix_process("Structure.Load_top", [None, -0.01, None], (False, True, False))])
    params["solver_settings"]["model_import_settings"] = {
        "input_type": "gmsh", "input_filename": "blocks.msh",
        "element_names": {"Parts.base": "SmallDisplacementElement", "Parts.block": "SmallDisplacementElement"}}
    params["output_processes"] = {"vtk_output": [{
        "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure", "output_path": "vtk_output",
                       "nodal_solution_step_data_variables": ["DISPLACEMENT"]}}]}
    if edit:
        edit(params["solver_settings"]["model_import_settings"])
    return write_case(folder, "blocks", params,
                      materials("Structure.Parts", "LinearElasticPlaneStrain2DLaw", 1000.0, 0.3))


def run_cli(parameters_file, cwd):
    return subprocess.run([sys.executable, "-m", "mortarcontact", "run", parameters_file], capture_output=True,
                          text=True, cwd=cwd, timeout=300)


def test_cli_runs_a_msh_case(tmp_path):
    result = run_cli(blocks_case(str(tmp_path)), tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    mesh = meshio.read(tmp_path / "vtk_output" / "Structure_1.vtu")
    top = np.isclose(mesh.points[:, 1], 2.0)
    assert np.allclose(mesh.point_data["DISPLACEMENT"][top, 1], -0.01)
    assert np.allclose(mesh.point_data["DISPLACEMENT"][np.isclose(mesh.points[:, 1], 0.0)], 0.0)


@pytest.mark.parametrize("edit, code, fragments", [
    (lambda s: s.update(input_filename="nowhere.msh"), 2,
     ["model_import_settings.input_filename: file not found", "nowhere.msh"]),
    (lambda s: s.update(input_type="gmesh"), 3, ["input_type: \"gmesh\" is not supported", "did you mean 'gmsh'"]),
    (lambda s: s.update(input_type="mdpa"), 2,
     ["model_import_settings.element_names: only for input_type \"gmsh\""]),
    (lambda s: (s.update(input_type="mdpa"), s.pop("element_names")), 2,
     ["\"blocks.msh\" is not an mdpa", "read it with input_type \"gmsh\""]),
    (lambda s: s["element_names"].update({"Parts.blok": "SmallDisplacementElement"}), 2,
     ["element_names: no group 'Parts.blok' in", "blocks.msh", "did you mean 'Parts.block'"]),
    (lambda s: s.update(input_filename="blocks_parameters.json", input_type="meshio"), 2,
     ["blocks_parameters.json: meshio cannot read it as 'meshio' input"]),
])
def test_cli_input_errors(tmp_path, edit, code, fragments):
    result = run_cli(blocks_case(str(tmp_path), edit), tmp_path)
    assert result.returncode == code, result.stdout + result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, f"{fragment!r} not in {result.stderr!r}"


def test_group_names_that_cannot_name_a_model_part(tmp_path):
    write_msh(tmp_path / "spaced.msh", POINTS, [("Parts block", "quad", QUADS), ("top", "triangle", TRIANGLES)])
    with pytest.raises(mc.InputError, match=r"spaced.msh: group name 'Parts block' cannot name a sub model part"):
        read_into_model(tmp_path / "spaced.msh", {"element_names": {"Parts block": "SmallDisplacementElement",
                                                                    "top": "SmallDisplacementElement"}})
