"""Issue 4 (benchmarks) and issue 3 (Hertz correctness): the gmsh-generated Hertz cases are valid
cases (a gmsh file for us, its mdpa for Kratos) that both readers load alike, with non-empty
interface parts, and their Hertz reference values satisfy the closed-form relations. Fast; Kratos
is not needed."""
from __future__ import annotations

import importlib.util
import json
import math
import os
import subprocess
import sys

import pytest

import mortarcontact as mc

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")


from mortarcontact.cases import hertz  # noqa: E402
from mortarcontact.cases.mesh_files import write_kratos_mdpa  # noqa: E402
from mortarcontact.solvers.meshio_import import read_mesh  # noqa: E402

#: The benchmarks' runner, run as a script (as a user would)
RUNNER = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz", "case_runner.py")


@pytest.fixture(scope="module")
def case_2d(tmp_path_factory):
    folder = hertz.write_case("hertz2d", "2k", str(tmp_path_factory.mktemp("hertz")))
    return folder, hertz.load_reference(folder)


def _read(folder: str, dim: int):
    """The case's model part as the solver builds it: its gmsh file through model_import_settings."""
    with open(os.path.join(folder, "ProjectParameters.json")) as f:
        settings = json.load(f)["solver_settings"]
    imports = settings["model_import_settings"]
    assert imports["input_type"] == "gmsh" and imports["input_filename"].endswith(".msh")
    mesh, node_ids = read_mesh(os.path.join(folder, imports["input_filename"]), "gmsh", "model_import_settings")
    part = mc.Model().CreateModelPart("Structure", dim)
    for name in ("DISPLACEMENT", "REACTION"):
        part.AddNodalSolutionStepVariable(mc.GetVariable(name))
    mc.import_meshio(part, mesh, element_names=imports["element_names"], domain_size=dim, node_ids=node_ids)
    return part


def _describe(part, entities: bool = True) -> dict:
    data = {"nodes": part.NodeIds().tolist(), "elements": [e.Id for e in part.Elements],
            "conditions": [c.Id for c in part.Conditions],
            "sub_model_parts": {sub.Name: _describe(sub, False) for sub in part.SubModelParts}}
    if entities:
        data["coordinates"] = part.NodeCoordinates(True).tobytes()
        data["entities"] = [(e.Id, e.Info(), e.NodeIds(), e.GetProperties().Id) for e in part.Elements]
    return data


def test_kratos_mdpa_is_the_model_part_we_read(case_2d):
    """Kratos reads mdpa: the one it gets (mesh_files.write_kratos_mdpa) holds the model part that
    our gmsh import builds, coordinates to the last bit, and the Kratos runner reads it in place of
    the gmsh file."""
    folder, _ = case_2d
    mdpa = write_kratos_mdpa(folder)
    assert mdpa == os.path.join(folder, f"{os.path.basename(folder)}.mdpa")
    from_mdpa = mc.Model().CreateModelPart("Structure")
    mc.ReadModelPart(from_mdpa, mdpa)
    assert _describe(from_mdpa) == _describe(_read(folder, 2))
    sys.path.insert(0, os.path.dirname(RUNNER))
    from case_runner import kratos_parameters

    with open(os.path.join(folder, "ProjectParameters.json")) as f:
        kratos = json.loads(kratos_parameters(f.read(), folder))
    assert kratos["solver_settings"]["model_import_settings"] == {"input_type": "mdpa",
                                                                  "input_filename": os.path.basename(folder)}


def test_mesh_reads_with_expected_counts(case_2d):
    folder, reference = case_2d
    counts = reference["counts"]
    part = _read(folder, 2)
    assert part.NumberOfNodes() == counts["nodes"]
    assert part.NumberOfElements() == counts["elements"] == counts["curved_elements"] + counts["block_elements"]
    assert part.NumberOfConditions() == 0
    assert counts["dofs"] == 2 * counts["nodes"] + counts["slave_nodes"]
    assert 1500 <= counts["dofs"] <= 2500  # the "2k" size
    assert part.GetSubModelPart("Parts_cylinder").NumberOfElements() == counts["curved_elements"]
    assert part.GetSubModelPart("Parts_block").NumberOfElements() == counts["block_elements"]


def test_interface_and_boundary_parts(case_2d):
    folder, reference = case_2d
    part = _read(folder, 2)
    slave = part.GetSubModelPart("Contact_slave")
    master = part.GetSubModelPart("Contact_master")
    assert slave.NumberOfNodes() == reference["counts"]["slave_nodes"] > 10
    assert master.NumberOfNodes() == reference["counts"]["master_nodes"] > 10
    a = reference["target"]["half_width"]
    cylinder = set(part.GetSubModelPart("Parts_cylinder").NodeIds())
    for node in slave.Nodes:  # on the arc, near the contact, in the slave body
        assert abs(math.hypot(node.X0, node.Y0 - reference["radius"]) - reference["radius"]) < 1e-9
        assert abs(node.X0) <= 4.0 * a + 1e-12 and node.Id in cylinder
    for node in master.Nodes:  # on the block top
        assert node.Y0 == 0.0 and abs(node.X0) <= 5.0 * a + 1e-12 and node.Id not in cylinder
    # the initial contact point (zero gap) is a slave node; the block top is meshed independently
    assert sum(1 for n in slave.Nodes if n.X0 == 0.0 and n.Y0 == 0.0) == 1
    assert sum(1 for n in part.Nodes if n.X0 == 0.0 and n.Y0 == 0.0) <= 2
    top = part.GetSubModelPart("DISPLACEMENT_top")
    bottom = part.GetSubModelPart("DISPLACEMENT_bottom")
    assert top.NumberOfNodes() > 0 and all(n.Y0 == reference["radius"] for n in top.Nodes)
    assert bottom.NumberOfNodes() > 0 and all(n.Y0 == -reference["block_height"] for n in bottom.Nodes)
    # the interface is symmetric about x = 0 (full model, mirrored mesh not required: counts only)
    assert sum(1 for n in slave.Nodes if n.X0 < 0.0) > 5 and sum(1 for n in slave.Nodes if n.X0 > 0.0) > 5


def test_parameters_and_materials(case_2d):
    folder, _ = case_2d
    with open(os.path.join(folder, "ProjectParameters.json")) as f:
        params = json.load(f)
    settings = params["solver_settings"]
    assert settings["contact_settings"]["mortar_type"] == "ALMContactFrictionless"
    assert settings["time_stepping"]["time_step"] * 4 == params["problem_data"]["end_time"]
    contact = params["processes"]["contact_process_list"][0]
    assert contact["python_module"] == "alm_contact_process"
    assert contact["Parameters"]["assume_master_slave"] == {"0": ["Contact_slave"]}
    with open(os.path.join(folder, settings["material_import_settings"]["materials_filename"])) as f:
        laws = {p["Material"]["constitutive_law"]["name"] for p in json.load(f)["properties"]}
    assert laws == {"LinearElasticPlaneStrain2DLaw"}
    from mortarcontact.project_parameters import read_project_parameters

    read_project_parameters(os.path.join(folder, "ProjectParameters.json"))  # our parser accepts it


def test_hertz_values_satisfy_closed_forms(case_2d):
    _, reference = case_2d
    target, r, e_star = reference["target"], reference["radius"], reference["effective_modulus"]
    e, nu = reference["young_modulus"], reference["poisson_ratio"]
    assert e_star == pytest.approx(e / (2.0 * (1.0 - nu * nu)), rel=1e-14)
    p, a, p0 = target["force"], target["half_width"], target["peak_pressure"]
    assert a == pytest.approx(math.sqrt(4.0 * p * r / (math.pi * e_star)), rel=1e-12)
    assert p0 == pytest.approx(2.0 * p / (math.pi * a), rel=1e-12)
    assert a / r == pytest.approx(0.1, rel=1e-12)
    # the elliptical pressure integrates to the force: int p0 sqrt(1 - x^2/a^2) dx = pi a p0 / 2
    assert math.pi * a * p0 / 2.0 == pytest.approx(p, rel=1e-12)
    assert reference["applied_displacement"] > 0.0


def test_hertz_3d_closed_forms():
    e_star = hertz.effective_modulus(1000.0, 0.3)
    h = hertz.hertz_3d(0.7, 1.0, e_star)
    a, p0 = h["half_width"], h["peak_pressure"]
    assert a ** 3 == pytest.approx(3.0 * 0.7 * 1.0 / (4.0 * e_star), rel=1e-12)
    assert 2.0 * math.pi * a * a * p0 / 3.0 == pytest.approx(0.7, rel=1e-12)  # integral of the hemispherical pressure
    assert hertz.force_for_half_width(3, a, 1.0, e_star) == pytest.approx(0.7, rel=1e-12)
    assert h["approach"] == pytest.approx(a * a, rel=1e-12)


def test_interior_faces_on_the_interface_are_rejected():
    import numpy as np

    cells = np.array([[0, 1, 2], [1, 3, 2]])  # two triangles sharing the edge 1-2
    assert hertz.interface_faces(cells, np.array([0, 1])).tolist() == [[0, 1]]
    with pytest.raises(RuntimeError, match="interior"):
        hertz.interface_faces(cells, np.array([1, 2]))


def test_free_components_are_null_in_the_constraints(case_2d):
    """A number in a free component would be assigned (unfixed) at every step, snapping the nodes
    back to zero displacement in that direction (it made hertz3d_50k diverge)."""
    folder, _ = case_2d
    with open(os.path.join(folder, "ProjectParameters.json")) as f:
        constraints = json.load(f)["processes"]["constraints_process_list"]
    assert constraints
    for process in constraints:
        parameters = process["Parameters"]
        for value, fixed in zip(parameters["value"], parameters["constrained"]):
            assert (value is None) == (not fixed), parameters["model_part_name"]


PETSC_SOLVERS = {
    "mumps": ({"solver_type": "petsc"}, 1e-9),
    # Schur complement of the multipliers with BoomerAMG on the displacements (the solver for
    # large 3D cases): an iterative solve, hence the looser agreement.
    "fieldsplit": ({"solver_type": "petsc", "tolerance": 1e-10, "max_iteration": 500,
                    "petsc_options": {"pc_type": "fieldsplit"}}, 1e-7),
    # Issue 14: the first two FGMRES solves of a load step stop at 1e-6, the later ones at the
    # solver's 1e-10 (the Newton strategy's ForcingTerm).
    "fieldsplit_inexact_newton": ({"solver_type": "petsc", "tolerance": 1e-10, "max_iteration": 500,
                                   "inexact_newton": True, "petsc_options": {"pc_type": "fieldsplit"}}, 1e-5),
}


@pytest.mark.parametrize("variant", sorted(PETSC_SOLVERS))
def test_petsc_linear_solver_gives_the_umfpack_contact_solution(petsc, case_2d, tmp_path, variant):
    """Issue 4: linear_solver_settings {"solver_type": "petsc"} (MUMPS LU through PETSc, or the
    field split with algebraic multigrid) runs the Hertz contact case to the UMFPACK solution in
    the same Newton iterations."""
    folder, _ = case_2d
    settings, tolerance = PETSC_SOLVERS[variant]
    records = {}
    for name, solver in (("umfpack", {"solver_type": "umfpack"}), ("petsc", settings)):
        output = tmp_path / f"{name}.json"
        subprocess.run([sys.executable, RUNNER, "--code", "mortarcontact", "--linear-solver", json.dumps(solver),
                        folder, str(output)], check=True)
        records[name] = json.loads(output.read_text())
        assert records[name]["status"] == "ok", records[name].get("error")
    umfpack, petsc = records["umfpack"], records["petsc"]
    assert [s["iterations"] for s in petsc["steps"]] == [s["iterations"] for s in umfpack["steps"]]
    assert all(s["converged"] for s in petsc["steps"])
    lm = {k: [node["lm"] for node in r["slave"]] for k, r in records.items()}
    scale = max(abs(v) for v in lm["umfpack"])
    assert scale > 0.0
    assert max(abs(a - b) for a, b in zip(lm["petsc"], lm["umfpack"])) < tolerance * scale
    assert petsc["reactions"]["DISPLACEMENT_bottom"] == pytest.approx(umfpack["reactions"]["DISPLACEMENT_bottom"],
                                                                      rel=tolerance * 10)
    asked = [it["linear_tolerance"] for step in petsc["newton"] for it in step]
    assert all(it["linear_tolerance"] == 0.0 for step in umfpack["newton"] for it in step)
    if variant == "mumps":
        assert all(t == 0.0 for t in asked)  # a direct solve
    elif not settings.get("inexact_newton"):
        assert all(t == settings["tolerance"] for t in asked)
    else:
        expected = [1e-6 if k < 2 else settings["tolerance"] for step in petsc["newton"] for k in range(len(step))]
        assert asked == expected and settings["tolerance"] in asked


def test_missing_petsc_plugin_is_a_clear_error():
    """Without its plugin library, "petsc" is a not-implemented error that says how to get it."""
    code = ("import mortarcontact as mc\n"
            "try:\n"
            "    mc._core.CreateLinearSolver(mc.Parameters('{\"solver_type\": \"petsc\"}'))\n"
            "except mc._core.NotImplementedFeatureError as error:\n"
            "    print(error)\n")
    env = dict(os.environ, MORTARCONTACT_PETSC_PLUGIN="/nonexistent/libmortarcontact_petsc.so")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout
    assert "'petsc' is not available" in out and "petsc-dev" in out and "/nonexistent" in out
