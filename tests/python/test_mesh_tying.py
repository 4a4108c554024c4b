"""Issue 13, item 1: mortar mesh tying (ComponentsMeshTying, mesh_tying_process).

- the shared Kratos cases mesh_tying_test/* run unchanged, pass their own json checks and match
  Kratos 10.4 on the same files;
- tied patch tests (2D quads, 3D hexahedra on quad and on triangle faces), non-matching interfaces:
  a uniform stress state is transmitted exactly (every nodal displacement is the exact linear field
  and the multipliers are the exact traction, to 1e-10);
- a cantilever cut in two non-matching meshes deflects as the same cantilever meshed in one piece
  and as Timoshenko beam theory;
- ScalarMeshTying of TEMPERATURE between heat conduction blocks: the tied thermal patch test.
"""
from __future__ import annotations

import json
import os

import numpy as np
import pytest
from test_contact_cases import run_csma_case

import mortarcontact as mc

import case_builder as cb
from csma_cases import CSMA_CASES, KRATOS_SNAPSHOTS, MESH_TYING_CASES, check_blocks

# Kratos 10.4.4 on the same files: the tie is linear, both codes solve it in one iteration; the
# difference is round-off of the direct solvers.
KRATOS_TOLERANCE = 1e-9


def _reference(case: str) -> dict:
    values = {}
    for input_file, _, variables, _ in check_blocks(case):
        with open(os.path.join(CSMA_CASES, input_file)) as f:
            data = json.load(f)
        for key, node in data.items():
            if key.startswith("NODE_"):
                values.setdefault(key, {}).update({v: node[v][-1] for v in variables if v in node})
    return values


def _difference(values: dict, expected: dict) -> float:
    """max |value - expected| over the checked nodes and variables, relative to the largest expected
    magnitude (the slope patch's DISPLACEMENT_X are round-off, 1e-16, against DISPLACEMENT_Y 1e-2)."""
    pairs = [(values[key][name], node[name]) for key, node in expected.items() for name in node]
    return max(abs(v - e) for v, e in pairs) / max(abs(e) for _, e in pairs)


@pytest.mark.parametrize("case", [c for c, _ in MESH_TYING_CASES], ids=lambda c: os.path.basename(c))
def test_shared_mesh_tying_case(csma_cases, monkeypatch, case):
    """Runs unchanged (its own json check passes: absolute 1e-3) in one Newton iteration, and gives
    Kratos 10.4's values on the same files."""
    monkeypatch.chdir(csma_cases)
    analysis, _ = run_csma_case(case, "tying")
    name = os.path.basename(case)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    with open(os.path.join(KRATOS_SNAPSHOTS, f"{name}_tying.json")) as f:
        kratos = json.load(f)
    to_kratos = _difference(analysis.snapshot, kratos["nodes"])
    to_reference = _difference(analysis.snapshot, _reference(case))
    kratos_to_reference = _difference(kratos["nodes"], _reference(case))
    print(f"{name}: {iterations} Newton iterations (Kratos 10.4: {kratos['newton_iterations']}); difference to "
          f"Kratos 10.4 {to_kratos:.1e}, to the reference {to_reference:.1e} (Kratos 10.4 to the reference "
          f"{kratos_to_reference:.1e})")
    assert to_kratos <= KRATOS_TOLERANCE
    assert iterations == kratos["newton_iterations"]
    # The reference files come from older Kratos revisions (Kratos 10.4 differs from them as much as
    # we do); the cases' own check is absolute 1e-3, which they pass by far.
    reference = _reference(case)
    assert max(abs(analysis.snapshot[key][name] - value) for key, node in reference.items()
               for name, value in node.items()) <= 1e-3


# ---------------------------------------------------------------------------------------------
# Tied patch tests

E, NU = 2.0e5, 0.3
LAME = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))


def _two_blocks_2d(lower=(3, 2), upper=(2, 3)):
    """Lower block [0,1]x[0,1] and upper [0,1]x[1,2], each meshed on its own (own interface nodes)."""
    c1, q1 = cb.structured_quads(*lower, 1.0, 1.0)
    c2, q2 = cb.structured_quads(*upper, 1.0, 1.0)
    c2 = c2 + np.array([0.0, 1.0])
    coords = np.vstack([c1, c2])
    n1 = len(c1)
    q2 = [tuple(n + n1 for n in q) for q in q2]
    ids = np.arange(1, len(coords) + 1)
    top_lower = ids[:n1][np.isclose(c1[:, 1], 1.0)]
    bottom_upper = ids[n1:][np.isclose(c2[:, 1], 1.0)]
    parts = {
        "Lower": {"nodes": ids[:n1], "elements": range(1, len(q1) + 1)},
        "Upper": {"nodes": ids[n1:], "elements": range(len(q1) + 1, len(q1) + len(q2) + 1)},
        "Tying": {"nodes": np.concatenate([top_lower, bottom_upper])},
    }
    return coords, {"SmallDisplacementElement2D4N": q1 + q2}, parts


def _tying_process(slave="Lower", mpc=False):
    """mesh_tying_process, or with mpc mpc_contact_process with contact_type MeshTying, on Tying."""
    if mpc:
        return {"python_module": "mpc_contact_process", "kratos_module": "ContactStructuralMechanicsApplication",
                "Parameters": {"model_part_name": "Structure", "contact_type": "MeshTying",
                               "assume_master_slave": {"0": [slave]}, "contact_model_part": {"0": ["Tying"]}}}
    return {"python_module": "mesh_tying_process", "kratos_module": "ContactStructuralMechanicsApplication",
            "Parameters": {"model_part_name": "Structure", "assume_master_slave": {"0": [slave]},
                           "mesh_tying_model_part": {"0": ["Tying"]}}}


def _tying_solver(mpc=False):
    """The solver settings of _tying_process."""
    if mpc:
        return {"convergence_criterion": "residual_criterion", "mpc_contact_settings": {"contact_type": "MeshTying"}}
    return {"convergence_criterion": "contact_residual_criterion",
            "contact_settings": {"mortar_type": "ComponentsMeshTying"}}


def _run(folder, name, coords, elements, parts, law, processes, conditions=None, contact=True, solver=None,
         mpc=False):
    cb.write_mdpa(os.path.join(folder, f"{name}.mdpa"), coords, elements, conditions, parts)
    params = cb.project_parameters(name, 3 if law.endswith("3DLaw") else 2, **processes, solver={
        **(_tying_solver(mpc) if contact else {"convergence_criterion": "residual_criterion"}), **(solver or {})})
    if contact:
        params["processes"]["contact_process_list"] = [_tying_process(mpc=mpc)]
    path = cb.write_case(folder, name, params, cb.materials("Structure", law, E, NU))
    return cb.run_analysis(folder, path)


def _linear_field(gradient):
    """Expressions of u = G x (initial coordinates) for assign_vector_variable_process."""
    return [" + ".join(f"({gradient[i][j]!r})*{'XYZ'[j]}" for j in range(len(gradient))) for i in range(len(gradient))]


def exact_patch(analysis, gradient, slave_normal, dim):
    """Asserts every node at u = G x (to 1e-10); the patch's stress and its traction sigma n_slave (that
    of the master side on the slave side)."""
    root = analysis.model["Structure"]
    x0 = np.array([[n.X0, n.Y0, n.Z0] for n in root.Nodes])[:, :dim]
    u = root.GetNodalValues(mc.DISPLACEMENT)[:, :dim]
    g = np.array(gradient)
    assert np.abs(u - x0 @ g.T).max() <= 1e-10 * np.abs(x0 @ g.T).max()
    strain = 0.5 * (g + g.T)
    lam, mu = LAME
    stress = lam * np.trace(strain) * np.eye(dim) + 2 * mu * strain  # plane strain in 2D
    return stress, stress @ np.array(slave_normal)


def _check_patch(analysis, gradient, slave_normal, dim):
    """Every node at u = G x; k lambda = sigma n_slave at every slave node and component whose multiplier
    is free (a row tied only through DoFs fixed on both sides has its multiplier fixed to zero: the
    supports take that load)."""
    stress, traction = exact_patch(analysis, gradient, slave_normal, dim)
    root = analysis.model["Structure"]
    k = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    checked = 0
    for node in root.GetSubModelPart("Contact").Nodes:
        if not node.Is(mc.SLAVE):
            continue
        multiplier = k * np.asarray(node.GetSolutionStepValue(mc.VECTOR_LAGRANGE_MULTIPLIER))
        for c in range(dim):
            if node.IsFixed(mc.GetVariable(f"VECTOR_LAGRANGE_MULTIPLIER_{'XYZ'[c]}")):
                continue
            assert abs(multiplier[c] - traction[c]) <= 1e-10 * np.abs(stress).max(), (node.Id, c)
            checked += 1
    return checked


def _outer_nodes(coords, box):
    low, high = np.array(box[0]), np.array(box[1])
    on = (np.isclose(coords, low) | np.isclose(coords, high)).any(axis=1)
    return np.arange(1, len(coords) + 1)[on]


def test_tied_patch_2d_transmits_a_constant_stress_exactly(tmp_path):
    """Non-matching 2D interface (3 slave segments against 2 master ones): u = G x (tension,
    compression and shear) on the outer boundary of both blocks; every node takes the exact linear
    field and k lambda the exact traction sigma n (normal and shear)."""
    gradient = [[1.0e-3, 4.0e-4], [-2.0e-4, -1.5e-3]]
    coords, elements, parts = _two_blocks_2d()
    parts["Outer"] = {"nodes": _outer_nodes(coords, ([0.0, 0.0], [1.0, 2.0]))}
    fix = cb.fix_process("Outer", [*_linear_field(gradient), 0.0])
    analysis = _run(str(tmp_path), "patch2d", coords, elements, parts, "LinearElasticPlaneStrain2DLaw",
                    {"constraints": [fix]})
    # the two interior slave nodes in both components, the two end ones in none
    assert _check_patch(analysis, gradient, [0.0, 1.0], 2) == 4


def _run_thermal(folder, name, coords, elements, parts, gradient, dim, fixed):
    """The blocks as steady heat conduction (LaplacianElement, CONDUCTIVITY 2) tied by
    ScalarMeshTying on TEMPERATURE, with T = gradient . x fixed at the nodes `fixed`."""
    thermal = {name.replace("SmallDisplacementElement", "LaplacianElement"): cells for name, cells in elements.items()}
    parts["Outer"] = {"nodes": fixed}
    expression = " + ".join(f"({g!r})*{'XYZ'[i]}" for i, g in enumerate(gradient))
    fix = {"python_module": "assign_scalar_variable_process", "kratos_module": "KratosMultiphysics",
           "Parameters": {"model_part_name": "Structure.Outer", "variable_name": "TEMPERATURE",
                          "value": expression, "interval": [0.0, "End"]}}
    cb.write_mdpa(os.path.join(folder, f"{name}.mdpa"), coords, thermal, None, parts)
    params = cb.project_parameters(name, dim, constraints=[fix], solver={
        "convergence_criterion": "contact_residual_criterion", "auxiliary_dofs_list": ["TEMPERATURE"],
        "auxiliary_reaction_list": ["REACTION_FLUX"], "contact_settings": {"mortar_type": "ScalarMeshTying"}})
    tying = _tying_process()
    tying["Parameters"]["variable_name"] = "TEMPERATURE"
    params["processes"]["contact_process_list"] = [tying]
    materials = {"properties": [{"model_part_name": "Structure", "properties_id": 1,
                                 "Material": {"Variables": {"CONDUCTIVITY": CONDUCTIVITY}, "Tables": {}}}]}
    path = cb.write_case(folder, name, params, materials)
    return cb.run_analysis(folder, path)


CONDUCTIVITY = 2.0


@pytest.mark.parametrize("dim", [2, 3])
def test_tied_thermal_patch_transmits_a_constant_flux_exactly(tmp_path, dim):
    """ScalarMeshTying of TEMPERATURE between steady heat conduction blocks (LaplacianElement) on
    a non-matching interface (2D: 3 slave segments against 2; 3D: 2 x 2 slave faces against
    3 x 3): with T = a . x on the boundary (2D: all of it; 3D: the bottom and top faces, a along
    z, the sides insulated, since T fixed on both sides all around the interface's edge would tie
    more slave rows than it leaves free DoFs: a singular system) every node takes the exact
    linear field, and the multiplier of every free slave node is the exact flux through the
    interface, k lambda =
    CONDUCTIVITY a . n = -q . n (q = -CONDUCTIVITY grad T: the heat the master side puts into the
    slave side per unit area, as k lambda is the traction in the displacement tie)."""
    gradient = [0.7, -1.3] if dim == 2 else [0.0, 0.0, -1.1]
    coords, elements, parts = _two_blocks_2d() if dim == 2 else _two_blocks_3d()
    if dim == 2:
        fixed = _outer_nodes(coords, ([0.0, 0.0], [1.0, 2.0]))
    else:
        fixed = np.flatnonzero(np.isclose(coords[:, 2], 0.0) | np.isclose(coords[:, 2], 2.0)) + 1
    analysis = _run_thermal(str(tmp_path), f"thermal{dim}d", coords, elements, parts, gradient, dim, fixed)
    root = analysis.model["Structure"]
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    x0 = np.array([[n.X0, n.Y0, n.Z0] for n in root.Nodes])[:, :dim]
    temperature = root.GetNodalValues(mc.TEMPERATURE)
    exact = x0 @ np.array(gradient)
    assert np.abs(temperature - exact).max() <= 1e-10 * np.abs(exact).max()
    k = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    flux = CONDUCTIVITY * gradient[-1]  # the slave (lower) side's outward normal is +e_dim
    free = [n for n in root.GetSubModelPart("Contact").Nodes
            if n.Is(mc.SLAVE) and not n.IsFixed(mc.SCALAR_LAGRANGE_MULTIPLIER)]
    assert len(free) == (2 if dim == 2 else 9)
    for node in free:
        assert k * node.GetSolutionStepValue(mc.SCALAR_LAGRANGE_MULTIPLIER) == pytest.approx(flux, rel=1e-10), node.Id


def _tetrahedra(hexahedra):
    """Each hexahedron cut into six tetrahedra around its 0-6 diagonal (its faces into two triangles)."""
    cut = (0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)
    return [tuple(h[i] for i in t) for h in hexahedra for t in cut]


def _two_blocks_3d(lower=(2, 2, 2), upper=(3, 3, 2), lower_tets=False, upper_tets=False):
    c1, h1 = cb.structured_hexes(*lower, 1.0, 1.0, 1.0)
    c2, h2 = cb.structured_hexes(*upper, 1.0, 1.0, 1.0)
    c2 = c2 + np.array([0.0, 0.0, 1.0])
    n1 = len(c1)
    h2 = [tuple(n + n1 for n in h) for h in h2]
    coords = np.vstack([c1, c2])
    ids = np.arange(1, len(coords) + 1)
    blocks = [_tetrahedra(h1) if lower_tets else h1, _tetrahedra(h2) if upper_tets else h2]
    names = ["SmallDisplacementElement3D4N" if len(cells[0]) == 4 else "SmallDisplacementElement3D8N"
             for cells in blocks]
    elements = {}
    for name, cells in zip(names, blocks):
        elements.setdefault(name, []).extend(cells)
    # write_mdpa numbers the elements consecutively, one element block after the other.
    first, count = {}, 1
    for name, cells in elements.items():
        first[name] = count
        count += len(cells)
    lower_numbers = range(first[names[0]], first[names[0]] + len(blocks[0]))
    offset = first[names[1]] + (len(blocks[0]) if names[1] == names[0] else 0)
    upper_numbers = range(offset, offset + len(blocks[1]))
    top_lower = ids[:n1][np.isclose(c1[:, 2], 1.0)]
    bottom_upper = ids[n1:][np.isclose(c2[:, 2], 1.0)]
    parts = {
        "Lower": {"nodes": ids[:n1], "elements": lower_numbers},
        "Upper": {"nodes": ids[n1:], "elements": upper_numbers},
        "Tying": {"nodes": np.concatenate([top_lower, bottom_upper])},
    }
    return coords, elements, parts


VARIANTS_3D = {"quads-on-quads": (False, False), "quads-on-triangles": (False, True),
               "triangles-on-quads": (True, False), "triangles-on-triangles": (True, True)}


@pytest.mark.parametrize("variant", list(VARIANTS_3D))
def test_tied_patch_3d_transmits_a_constant_stress_exactly(tmp_path, variant):
    """Non-matching 3D interface at z = 1 (2 x 2 slave hexahedron faces against 3 x 3 master ones, either
    side possibly the triangle faces of tetrahedra: quadrilaterals, triangles and mixed pairs): rollers
    on x = 0, y = 0, z = 0 and the normal displacement of u = G x prescribed on x = 1, y = 1, z = 2
    (triaxial stress); exact linear field everywhere and k lambda = sigma n at every slave node (the
    rollers' edge rows excepted, see _check_patch); the MixedULM condensation gives the monolithic
    solution."""
    gradient = np.diag([1.0e-3, -1.5e-3, 8.0e-4])
    lower_tets, upper_tets = VARIANTS_3D[variant]
    coords, elements, parts = _two_blocks_3d(lower_tets=lower_tets, upper_tets=upper_tets)
    constraints = []
    for axis, (low, high) in enumerate(((0.0, 1.0), (0.0, 1.0), (0.0, 2.0))):
        ids = np.arange(1, len(coords) + 1)
        for side, plane in (("low", low), ("high", high)):
            name = f"{'XYZ'[axis]}_{side}"
            parts[name] = {"nodes": ids[np.isclose(coords[:, axis], plane)]}
            value = [None, None, None]  # only the normal component
            value[axis] = gradient[axis][axis] * plane
            constraints.append(cb.fix_process(name, value))
    analysis = _run(str(tmp_path), "patch3d", coords, elements, parts, "LinearElastic3DLaw",
                    {"constraints": constraints})
    assert _check_patch(analysis, gradient, [0.0, 0.0, 1.0], 3) >= 9 * 3 - 6
    # The multipliers were condensed (MixedULM), with the monolithic solve's answer.
    solver = analysis.solver.contact_linear_solver
    assert solver.last_solve_was_condensed, solver.fallback_reason
    monolithic = _run(str(tmp_path), "patch3d_monolithic", coords, elements, parts, "LinearElastic3DLaw",
                      {"constraints": constraints}, solver={"contact_settings": {
                          "mortar_type": "ComponentsMeshTying", "use_mixed_ulm_solver": False}})
    assert not hasattr(monolithic.solver.contact_linear_solver, "last_solve_was_condensed")
    for variable in (mc.DISPLACEMENT, mc.VECTOR_LAGRANGE_MULTIPLIER):
        condensed = analysis.model["Structure"].GetNodalValues(variable)
        assert np.abs(condensed - monolithic.model["Structure"].GetNodalValues(variable)).max() <= \
            1e-10 * np.abs(condensed).max()


# ---------------------------------------------------------------------------------------------
# Cantilever cut in two non-matching meshes

def _cantilever(folder, name, tied, length=10.0, height=1.0, load=-10.0, mpc=False):
    """Plane-stress cantilever clamped at x = 0 (u = 0 on the whole edge), a uniform shear LINE_LOAD
    at x = length. tied: cut at x = length / 2, the left half with 8 elements through the height and
    the right half with 10 (tied by multipliers, or with mpc by constraints); one mesh: 80 x 10.
    The mean tip deflection."""
    return np.mean([u[1] for u in _cantilever_run(folder, name, tied, length, height, load, mpc)[1]])


def _cantilever_run(folder, name, tied, length=10.0, height=1.0, load=-10.0, mpc=False, dynamic=None,
                    analysis_class=None):
    """_cantilever's analysis and the displacements of its tip nodes; dynamic: (time step, end time) of an
    implicit Bossak run (DENSITY 1), the load applied suddenly."""
    halves = [(40, 8, 0.0), (40, 10, length / 2)] if tied else [(80, 10, 0.0)]
    coords, quads, owners = [], [], []
    for k, (nx, ny, x0) in enumerate(halves):
        c, q = cb.structured_quads(nx, ny, length / len(halves), height)
        offset = len(coords)
        coords += [(x + x0, y) for x, y in c]
        quads += [tuple(n + offset for n in cell) for cell in q]
        owners += [k] * len(q)
    coords = np.array(coords)
    ids = np.arange(1, len(coords) + 1)
    end = ids[np.isclose(coords[:, 0], length)]
    end = end[np.argsort(coords[end - 1, 1])]
    lines = [(int(end[i + 1]), int(end[i])) for i in range(len(end) - 1)]  # outward normal +x
    parts = {"Clamp": {"nodes": ids[np.isclose(coords[:, 0], 0.0)]},
             "Tip": {"nodes": end, "conditions": range(1, len(lines) + 1)}}
    if tied:
        n_left = (40 + 1) * (8 + 1)
        cut = ids[np.isclose(coords[:, 0], length / 2)]
        parts.update({"Left": {"nodes": ids[:n_left], "elements": [i + 1 for i, o in enumerate(owners) if o == 0]},
                      "Right": {"nodes": ids[n_left:], "elements": [i + 1 for i, o in enumerate(owners) if o == 1]},
                      "Tying": {"nodes": cut}})
    processes = {"constraints": [cb.fix_process("Clamp", [0.0, 0.0, 0.0])],
                 "loads": [cb.condition_load_process("Tip", "LINE_LOAD", [0.0, load / height, 0.0])]}
    cb.write_mdpa(os.path.join(folder, f"{name}.mdpa"), coords, {"SmallDisplacementElement2D4N": quads},
                  {"LineLoadCondition2D2N": lines}, parts)
    solver = _tying_solver(mpc) if tied else {"convergence_criterion": "residual_criterion"}
    extra = {}
    if dynamic:
        # |r| stalls near 1e-10 at some steps (round-off of a dynamic residual): the absolute tolerance is above
        solver.update({"solver_type": "Dynamic", "time_integration_method": "implicit", "scheme_type": "bossak",
                       "residual_absolute_tolerance": 1e-9})
        extra = {"time_step": dynamic[0], "end_time": dynamic[1]}
    params = cb.project_parameters(name, 2, solver=solver, **processes, **extra)
    if tied:
        params["processes"]["contact_process_list"] = [_tying_process("Left", mpc)]
    density = {"DENSITY": 1.0} if dynamic else {}
    path = cb.write_case(folder, name, params, cb.materials("Structure", "LinearElasticPlaneStress2DLaw", E, NU,
                                                            THICKNESS=1.0, **density))
    analysis = cb.run_analysis(folder, path, analysis_class)
    root = analysis.model["Structure"]
    return analysis, [np.asarray(root.GetNode(int(i)).GetSolutionStepValue(mc.DISPLACEMENT)) for i in end]


def test_tied_cantilever_matches_beam_theory(tmp_path):
    """Tip deflection of a cantilever (L/h = 10) cut at mid-length into non-matching meshes (8 against
    10 elements through the height): within 1e-3 of the same cantilever meshed in one piece (measured
    5.2e-4) and within 1.5 % of Timoshenko's PL^3/(3EI) + PL/(kGA) (measured 0.93 %; the one-piece mesh
    is 0.87 % stiff: bilinear elements are a little stiff in bending)."""
    length, height, load = 10.0, 1.0, -10.0
    tied = _cantilever(str(tmp_path), "tied", True, length, height, load)
    whole = _cantilever(str(tmp_path), "whole", False, length, height, load)
    inertia = height ** 3 / 12.0
    shear = E / (2 * (1 + NU))
    theory = load * length ** 3 / (3 * E * inertia) + load * length / (5.0 / 6.0 * shear * height)
    print(f"tip deflection: tied {tied:.6e}, one mesh {whole:.6e}, Timoshenko {theory:.6e} "
          f"(tied/theory {tied / theory:.4f}, tied/one mesh {tied / whole:.5f})")
    assert tied == pytest.approx(whole, rel=1e-3)
    assert tied == pytest.approx(theory, rel=1.5e-2)


# ---------------------------------------------------------------------------------------------
# mesh_tying_process keys (tests/python/settings_audit.tsv)

def tied_case(folder: str) -> str:
    """The 2D tied patch as a case in ``folder`` (the base of test_settings_audit's runner)."""
    gradient = [[1.0e-3, 4.0e-4], [-2.0e-4, -1.5e-3]]
    coords, elements, parts = _two_blocks_2d()
    parts["Outer"] = {"nodes": _outer_nodes(coords, ([0.0, 0.0], [1.0, 2.0]))}
    cb.write_mdpa(os.path.join(folder, "tied.mdpa"), coords, elements, None, parts)
    params = cb.project_parameters("tied", 2, constraints=[cb.fix_process("Outer", [*_linear_field(gradient), 0.0])],
                                   solver={"convergence_criterion": "contact_residual_criterion",
                                           "contact_settings": {"mortar_type": "ComponentsMeshTying"}})
    params["processes"]["contact_process_list"] = [_tying_process()]
    return cb.write_case(folder, "tied", params, cb.materials("Structure", "LinearElasticPlaneStrain2DLaw", E, NU))


def _tying(**changes):
    def edit(params):
        params["processes"]["contact_process_list"][0]["Parameters"].update(changes)
    return edit


def test_mesh_tying_process_keys(tmp_path):
    """What each key of mesh_tying_process does (spec 4.8)."""
    from test_settings_audit import _pairs, _run_logged

    def run(name, edit=None, solver=None):
        def both(params):
            if edit:
                edit(params)
            params["solver_settings"]["contact_settings"].update(solver or {})
        return _run_logged(tmp_path / name, base=tied_case, edit=both)

    # model_part_name, mesh_tying_model_part, assume_master_slave: one pair per overlapping
    # (slave, master) segment: 3 slave segments of the lower block against 2 master ones -> 4 pairs
    base, log = run("default", _tying(model_part_name="Structure", mesh_tying_model_part={"0": ["Tying"]},
                                      assume_master_slave={"0": ["Lower"]}))
    assert "has no effect" not in log
    pairs = _pairs(base)
    assert {name for name, _ in pairs} == {"MeshTyingMortarCondition2D2N"} and len(pairs) == 4
    root = base.model["Structure"]
    slaves = {n.Id for n in root.GetSubModelPart("Contact").Nodes if n.Is(mc.SLAVE)}
    assert slaves == {n.Id for n in root.GetSubModelPart("Lower").Nodes if n.Y0 == 1.0}
    # mesh_tying_property_ids
    assert {p for _, p in pairs} == {100}
    assert {p for _, p in _pairs(run("ids", _tying(mesh_tying_property_ids={"0": 1}))[0])} == {1}
    # zero_tolerance_factor, integration_order: the ProcessInfo and the pair properties
    analysis, _ = run("orders", _tying(zero_tolerance_factor=3.0, integration_order=4))
    assert analysis.model["Structure"].ProcessInfo.GetValue(mc.ZERO_TOLERANCE_FACTOR) == 3.0
    pair = next(iter(analysis.model["Structure"].GetSubModelPart("ComputingContact").Conditions))
    assert pair.GetProperties().GetValue(mc.INTEGRATION_ORDER_CONTACT) == 4
    # scale_factor_parameters: the multipliers are the traction over SCALE_FACTOR; automatic:
    # stiffness_factor * E / h of the softer side (h = 0.5 on the upper block's interface)
    def multipliers(analysis):
        part = analysis.model["Structure"].GetSubModelPart("Contact")
        return np.array([n.GetSolutionStepValue(mc.VECTOR_LAGRANGE_MULTIPLIER) for n in part.Nodes if n.Is(mc.SLAVE)])
    automatic = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    doubled, _ = run("stiffness", _tying(scale_factor_parameters={"stiffness_factor": 2.0}))
    assert doubled.model["Structure"].ProcessInfo.GetValue(mc.SCALE_FACTOR) == pytest.approx(2 * automatic)
    manual, _ = run("manual", _tying(scale_factor_parameters={"manual_scale_factor": True, "scale_factor": 5.0}))
    assert manual.model["Structure"].ProcessInfo.GetValue(mc.SCALE_FACTOR) == 5.0
    assert np.allclose(5.0 * multipliers(manual), automatic * multipliers(base), rtol=1e-10, atol=1e-12)
    assert np.abs(multipliers(base)).max() > 0.0
    # interval: outside it nothing is tied
    outside, _ = run("interval", _tying(interval=[2.0, "End"]))
    assert not _pairs(outside)
    # consider_tessellation: both values cut the clipped polygons as a fan (a warning for false)
    _, log = run("fan", _tying(consider_tessellation=False))
    assert "consider_tessellation' = false" in log and "has no effect" in log
    # variable_name: the tied variable chooses the formulation; it must be an unknown of the run
    error, _ = run("scalar", _tying(variable_name="TEMPERATURE"))
    assert isinstance(error, mc.InputError) and 'mortar_type "ScalarMeshTying"' in str(error)
    error, _ = run("no_dof", _tying(variable_name="TEMPERATURE"), solver={"mortar_type": "ScalarMeshTying"})
    assert isinstance(error, mc.InputError) and "'TEMPERATURE' is not an unknown" in str(error)
    error, _ = run("typo", _tying(variable_name="DISPLACMENT"))
    assert isinstance(error, mc.InputError) and "DISPLACEMENT" in str(error)
    # consider_static_condensation: the MixedULM solver condenses the multipliers either way
    condensed, log = run("condensation", _tying(consider_static_condensation=True))
    assert "consider_static_condensation' = true" in log and "has no effect" in log
    assert condensed.solver.contact_linear_solver.last_solve_was_condensed
