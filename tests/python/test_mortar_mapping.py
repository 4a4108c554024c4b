"""Issue 13, item 4: mortar mapping of nodal scalars and vectors between non-matching surfaces
(SimpleMortarMapperProcess).

- the shared Kratos references integration_tests/test_integration_triangle and _quad (T = z and
  DISPLACEMENT = (x, y, z) on the master, mapped onto the slave; tests/cases/mortar_integration_reference.md
  section 7) to 1e-12, and Kratos 10.4's own values on the same files;
- a linear field is mapped exactly on a flat non-matching interface (triangles on quads, lines in 2D),
  scalar and vector, historical and not;
- without D^-1 the result is the dual-weighted field D u (nodal areas times the field);
- the conservative mapping keeps the total of a nodal force exactly and the work f . u of every
  linear field.
"""
from __future__ import annotations

import itertools
import json
import os

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact import _core

CASES = os.path.join(os.path.dirname(__file__), "..", "cases", "kratos_csma", "integration_tests")

# Kratos 10.4.4, SimpleMortarMapperProcess with its defaults from Parts_Parts_Auto2 (T = z,
# DISPLACEMENT = (x, y, z)) onto Parts_Parts_Auto1, run with benchmarks/kratos_cases/mortar_mapping_kratos.py.
with open(os.path.join(os.path.dirname(__file__), "..", "cases", "kratos_10_4", "mortar_mapping.json")) as _f:
    KRATOS = json.load(_f)


def _read(name: str):
    model = mc.Model()
    root = model.CreateModelPart("Structure")
    for variable in (mc.DISPLACEMENT, mc.TEMPERATURE, mc.NORMAL):
        root.AddNodalSolutionStepVariable(variable)
    mc.ReadModelPart(root, os.path.join(CASES, f"{name}.mdpa"))
    return model, root


@pytest.mark.parametrize("name", ["test_integration_triangle", "test_integration_quad"])
def test_shared_integration_cases(name):
    """The Kratos CSMA mapper cases: every slave value within 1e-12 of the reference file (whose
    values are the linear master field at the slave node's normal projection, e.g. 0.1 / 1.01) and of
    Kratos 10.4 (their check is absolute 1e-3)."""
    _model, root = _read(name)  # the model owns the parts
    master, slave = root.GetSubModelPart("Parts_Parts_Auto2"), root.GetSubModelPart("Parts_Parts_Auto1")
    for node in master.Nodes:
        node.SetSolutionStepValue(mc.TEMPERATURE, node.Z)
        node.SetSolutionStepValue(mc.DISPLACEMENT, [node.X, node.Y, node.Z])
    for variable in ("TEMPERATURE", "DISPLACEMENT"):
        settings = _core.Parameters(json.dumps({"origin_variable": variable, "integration_order": 2}))
        mapper = _core.SimpleMortarMapperProcess(master, slave, settings)
        mapper.Execute()
        assert mapper.NumberOfPairs() == 1 and mapper.NumberOfMappedNodes() == slave.NumberOfNodes()
    with open(os.path.join(CASES, f"{name}.json")) as f:
        reference = json.load(f)
    compared = 0
    for node in slave.Nodes:
        values = {"TEMPERATURE": node.GetSolutionStepValue(mc.TEMPERATURE),
                  **{f"DISPLACEMENT_{a}": node.GetSolutionStepValue(mc.DISPLACEMENT)[i] for i, a in enumerate("XYZ")}}
        for variable, value in values.items():
            expected = reference[f"NODE_{node.Id}"][variable][-1]
            assert value == pytest.approx(expected, abs=1e-12), (node.Id, variable)
            assert value == pytest.approx(KRATOS[name][str(node.Id)][variable], abs=1e-12), (node.Id, variable)
            compared += 1
    assert compared == 4 * slave.NumberOfNodes()


def _flat_interface(dim: int):
    """Origin and destination meshes of the unit square (3D: z = 0.1 x + 0.05 y, tilted; 2D: the segment
    y = 0.2 x on [0, 1]): origin 3 x 2 quadrilaterals (2D: 3 lines), destination 4 x 5 triangles
    (2D: 5 lines) with their own nodes, 1e-3 apart along the normal."""
    model = mc.Model()
    root = model.CreateModelPart("Structure")
    for variable in (mc.DISPLACEMENT, mc.TEMPERATURE):
        root.AddNodalSolutionStepVariable(variable)
    origin, destination = root.CreateSubModelPart("Origin"), root.CreateSubModelPart("Destination")
    properties = root.CreateNewProperties(0)
    next_id = [1]

    def node(part, x, y, offset):
        if dim == 2:
            position = np.array([x, 0.2 * x, 0.0]) + offset * np.array([-0.2, 1.0, 0.0]) / np.hypot(1.0, 0.2)
        else:
            position = np.array([x, y, 0.1 * x + 0.05 * y]) + offset * np.array([-0.1, -0.05, 1.0]) / np.sqrt(1.0125)
        created = part.CreateNewNode(next_id[0], *position)
        next_id[0] += 1
        return created.Id

    condition_id = [1]

    def add(part, name, nodes):
        part.CreateNewCondition(name, condition_id[0], nodes, properties)
        condition_id[0] += 1

    if dim == 2:
        o = [node(origin, x, 0.0, 0.0) for x in np.linspace(0.0, 1.0, 4)]
        d = [node(destination, x, 0.0, 1e-3) for x in np.linspace(0.0, 1.0, 6)]
        for a, b in itertools.pairwise(o):
            add(origin, "LineCondition2D2N", [a, b])
        for a, b in itertools.pairwise(d):
            add(destination, "LineCondition2D2N", [b, a])
        return model, origin, destination
    o = [[node(origin, x, y, 0.0) for y in np.linspace(0.0, 1.0, 3)] for x in np.linspace(0.0, 1.0, 4)]
    d = [[node(destination, x, y, 1e-3) for y in np.linspace(0.0, 1.0, 6)] for x in np.linspace(0.0, 1.0, 5)]
    for i in range(3):
        for j in range(2):
            add(origin, "SurfaceCondition3D4N", [o[i][j], o[i + 1][j], o[i + 1][j + 1], o[i][j + 1]])
    for i in range(4):
        for j in range(5):
            add(destination, "SurfaceCondition3D3N", [d[i][j], d[i][j + 1], d[i + 1][j]])
            add(destination, "SurfaceCondition3D3N", [d[i + 1][j], d[i][j + 1], d[i + 1][j + 1]])
    return model, origin, destination


def _linear(x):
    return 0.4 + 1.3 * x[0] - 0.7 * x[1] + 2.1 * x[2]


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("historical", [True, False])
def test_linear_field_is_mapped_exactly(dim, historical):
    """A linear field on a flat non-matching interface: every destination node gets the field at its
    normal projection on the origin (1e-3 away: a linear field along the normal too), to 1e-12; scalar
    and vector; mapping_coefficient scales it."""
    _model, origin, destination = _flat_interface(dim)
    normal = np.array([-0.2, 1.0, 0.0]) / np.hypot(1.0, 0.2) if dim == 2 else \
        np.array([-0.1, -0.05, 1.0]) / np.sqrt(1.0125)
    for node in origin.Nodes:
        x = np.array([node.X, node.Y, node.Z])
        if historical:
            node.SetSolutionStepValue(mc.TEMPERATURE, _linear(x))
            node.SetSolutionStepValue(mc.DISPLACEMENT, [_linear(x), -_linear(x), 2.0 * _linear(x)])
        else:
            node.SetValue(mc.TEMPERATURE, _linear(x))
            node.SetValue(mc.DISPLACEMENT, [_linear(x), -_linear(x), 2.0 * _linear(x)])
    for variable in ("TEMPERATURE", "DISPLACEMENT"):
        settings = {"origin_variable": variable, "origin_variable_historical": historical,
                    "destination_variable_historical": historical, "mapping_coefficient": 3.0}
        mapper = _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters(json.dumps(settings)))
        mapper.Execute()
        assert mapper.NumberOfMappedNodes() == destination.NumberOfNodes()
    for node in destination.Nodes:
        x = np.array([node.X, node.Y, node.Z]) - 1e-3 * normal
        get = node.GetSolutionStepValue if historical else node.GetValue
        assert get(mc.TEMPERATURE) == pytest.approx(3.0 * _linear(x), abs=1e-12)
        assert np.allclose(get(mc.DISPLACEMENT), 3.0 * np.array([1.0, -1.0, 2.0]) * _linear(x), atol=1e-12)


def _areas(part):
    """int N_j over the part's faces: a third (triangle), a quarter (flat parallelogram quad) or half
    (line) of each face's area at each of its nodes."""
    areas = {}
    for condition in part.Conditions:
        nodes = condition.GetNodes()
        size = condition.GetGeometry().DomainSize()
        for n in nodes:
            areas[n.Id] = areas.get(n.Id, 0.0) + size / len(nodes)
    return areas


def test_without_the_inverse_of_d_the_dual_weighted_field():
    """inverse_of_d false: D u_d (= M u_o), i.e. the mapped field times the nodal area int N_j."""
    _model, origin, destination = _flat_interface(3)
    for node in origin.Nodes:
        node.SetSolutionStepValue(mc.TEMPERATURE, _linear([node.X, node.Y, node.Z]))
    exact = _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters("{}"))
    exact.Execute()
    field = {n.Id: n.GetSolutionStepValue(mc.TEMPERATURE) for n in destination.Nodes}
    weighted = _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters('{"inverse_of_d": false}'))
    weighted.Execute()
    areas = _areas(destination)
    for node in destination.Nodes:
        assert node.GetSolutionStepValue(mc.TEMPERATURE) == pytest.approx(areas[node.Id] * field[node.Id], abs=1e-12)


@pytest.mark.parametrize("dim", [2, 3])
def test_conservative_mapping_keeps_the_total_and_the_work(dim):
    """Nodal forces f_o mapped conservatively: sum f_d = sum f_o (the destination covers the origin)
    and f_d . u_d = f_o . u_o for a linear field u (the consistent map from destination to origin takes
    it exactly), to 1e-12; without D^-1, f_o is taken as a traction: sum f_d = sum_j f_o,j int N_j."""
    _model, origin, destination = _flat_interface(dim)
    rng = np.random.default_rng(3)
    forces = {n.Id: rng.normal(size=3) for n in origin.Nodes}
    for node in origin.Nodes:
        node.SetSolutionStepValue(mc.DISPLACEMENT, forces[node.Id])
    mapper = _core.SimpleMortarMapperProcess(
        origin, destination, _core.Parameters('{"origin_variable": "DISPLACEMENT", "conservative": true}'))
    mapper.Execute()
    mapped = {n.Id: np.asarray(n.GetSolutionStepValue(mc.DISPLACEMENT)) for n in destination.Nodes}
    total = sum(forces.values())
    assert np.allclose(sum(mapped.values()), total, atol=1e-12)
    work_origin = sum(forces[n.Id][0] * _linear([n.X, n.Y, n.Z]) for n in origin.Nodes)
    work_destination = sum(mapped[n.Id][0] * _linear([n.X, n.Y, n.Z]) for n in destination.Nodes)
    # The destination is 1e-3 off along the normal: the linear field differs by that offset times its
    # normal derivative, the same at every node, so the work differs by it times the total force.
    normal = np.array([-0.2, 1.0, 0.0]) / np.hypot(1.0, 0.2) if dim == 2 else \
        np.array([-0.1, -0.05, 1.0]) / np.sqrt(1.0125)
    shift = 1e-3 * np.dot([1.3, -0.7, 2.1], normal)
    assert work_destination == pytest.approx(work_origin + shift * total[0], abs=1e-12)

    for node in origin.Nodes:
        node.SetSolutionStepValue(mc.DISPLACEMENT, forces[node.Id])
    _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters(
        '{"origin_variable": "DISPLACEMENT", "conservative": true, "inverse_of_d": false}')).Execute()
    areas = _areas(origin)
    weighted_total = sum(forces[i] * areas[i] for i in forces)
    assert np.allclose(sum(np.asarray(n.GetSolutionStepValue(mc.DISPLACEMENT)) for n in destination.Nodes),
                       weighted_total, atol=1e-12)


def test_bad_settings_are_named():
    _model, origin, destination = _flat_interface(3)
    with pytest.raises(mc.InputError, match="origin_variabel"):
        _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters('{"origin_variabel": "TEMPERATURE"}'))
    with pytest.raises(mc.NotImplementedFeatureError, match="discontinuous_interface"):
        _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters('{"discontinuous_interface": true}'))
    mapper = _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters('{"origin_variable": "PRESURE"}'))
    with pytest.raises(mc.InputError, match="PRESSURE"):
        mapper.Execute()
    mapper = _core.SimpleMortarMapperProcess(origin, destination, _core.Parameters('{"origin_variable": "NODAL_H"}'))
    with pytest.raises(mc.InputError, match="not a solution-step variable"):
        mapper.Execute()


def _surfaces(slave_nodes, slave_faces, master_nodes, master_faces):
    model = mc.Model()
    root = model.CreateModelPart("Structure")
    root.AddNodalSolutionStepVariable(mc.TEMPERATURE)
    slave, master = root.CreateSubModelPart("Slave"), root.CreateSubModelPart("Master")
    properties = root.CreateNewProperties(0)
    for part, nodes, faces, first in ((slave, slave_nodes, slave_faces, 1), (master, master_nodes, master_faces, 100)):
        for node_id, x in nodes.items():
            part.CreateNewNode(node_id, *x)
        for k, face in enumerate(faces):
            part.CreateNewCondition("SurfaceCondition3D3N" if len(face) == 3 else "SurfaceCondition3D4N", first + k,
                                    face, properties)
    return model, slave, master


@pytest.mark.parametrize("case", ["MAP-C1", "MAP-C2", "MAP-C3"])
def test_kratos_core_mapper_cases(case):
    """Kratos' C++ mapper tests (tests/cases/mortar_integration_reference.md section 6): T = x^2 + y^2
    (MAP-C3: z^2 + y^2) on a master surface 0.01 (0.001) away, nearly parallel, tilted or folded, listed in
    either orientation; the slave nodes get the field at their own position within the Kratos tolerance
    (1e-4; MAP-C3 1e-3)."""
    if case == "MAP-C1":
        slave = {1: (0, 0, 0), 2: (1, 0, 0), 3: (0, 1, 0.01)}
        master = {4: (0, 0, 0.01), 5: (1, 0, 0.01), 6: (0, 1, 0.02)}
        _model, s, m = _surfaces(slave, [[3, 2, 1]], master, [[4, 5, 6]])
    elif case == "MAP-C2":
        slave = {1: (0, 0, 0), 2: (1, 0, 0), 3: (1, 1, 0.01), 4: (0, 1, 0.01)}
        master = {5: (0, 0, 0.01), 6: (1, 0, 0.01), 7: (1, 1, 0.02), 8: (0, 1, 0.02)}
        _model, s, m = _surfaces(slave, [[1, 2, 3, 4]], master, [[8, 7, 6, 5]])
    else:
        slave = {1: (0, 0, 0), 2: (1, 1, 1), 3: (1, 0, 1), 4: (1, 1, 0)}
        master = {5: (1.001, 0, 1), 6: (1.001, 1, 0), 7: (0.001, 0, 0), 8: (1.001, 1, 1)}
        _model, s, m = _surfaces(slave, [[4, 3, 1], [4, 2, 3]], master, [[7, 5, 6], [5, 8, 6]])
    field = (lambda x, y, z: z * z + y * y) if case == "MAP-C3" else (lambda x, y, z: x * x + y * y)
    for node in m.Nodes:
        node.SetSolutionStepValue(mc.TEMPERATURE, field(node.X, node.Y, node.Z))
    mapper = _core.SimpleMortarMapperProcess(m, s, _core.Parameters("{}"))
    mapper.Execute()
    assert mapper.NumberOfMappedNodes() == s.NumberOfNodes()
    tolerance = 1e-3 if case == "MAP-C3" else 1e-4
    for node in s.Nodes:
        assert node.GetSolutionStepValue(mc.TEMPERATURE) == pytest.approx(field(node.X, node.Y, node.Z),
                                                                        abs=tolerance), node.Id
