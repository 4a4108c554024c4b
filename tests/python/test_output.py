"""Issue 2: ParaView output (spec 1.5): VTU files read back with meshio carry the nodal results,
the PVD collection lists every step with its TIME, XDMF+HDF5 series, Kratos hexahedron node
order mapped to VTK, and settings errors."""
from __future__ import annotations

import json
import logging
import os
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.output.vtk_output_process import _VTK_ORDER
from mortarcontact.process_factory import create_process

from small_models import advance, parameters, quad_elements, square_grid


def vtk_process(model, python_module="vtk_output_process", **settings):
    item = {"python_module": python_module, "kratos_module": "KratosMultiphysics", "Parameters": settings}
    return create_process(parameters(json.dumps(item)), model)


def run_steps(process, root, steps, dt=0.5, on_step=None):
    process.ExecuteInitialize()
    process.ExecuteBeforeSolutionLoop()
    written = []
    for step in range(1, steps + 1):
        advance(root, dt)
        process.ExecuteInitializeSolutionStep()
        if on_step:
            on_step(step)
        process.ExecuteFinalizeSolutionStep()
        if process.IsOutputStep():
            process.PrintOutput()
            written.append(step)
    process.ExecuteFinalize()
    return written


def pvd_entries(path):
    return [(float(d.get("timestep")), d.get("file")) for d in ET.parse(path).getroot().iter("DataSet")]


def set_results(root, step):
    ids = root.NodeIds().astype(float)
    root.SetNodalValues(mc.DISPLACEMENT, np.column_stack([ids * step, -ids, np.zeros_like(ids)]))
    for node in root.Nodes:
        node.Set(mc.SLAVE, node.Id % 2 == 0)
        node.SetValue(mc.NODAL_H, 0.25 * node.Id)


def test_vtu_point_data_and_pvd_times(tmp_path):
    model, root = square_grid(2, 2)
    process = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "vtk"),
                          nodal_solution_step_data_variables=["DISPLACEMENT"], nodal_data_value_variables=["NODAL_H"],
                          nodal_flags=["SLAVE"], file_format="ascii", output_precision=7)
    assert run_steps(process, root, 3, on_step=lambda step: set_results(root, step)) == [1, 2, 3]
    entries = pvd_entries(tmp_path / "vtk" / "Structure.pvd")
    assert entries == [(0.5, "Structure_1.vtu"), (1.0, "Structure_2.vtu"), (1.5, "Structure_3.vtu")]
    mesh = meshio.read(tmp_path / "vtk" / "Structure_3.vtu")
    ids = root.NodeIds()
    assert np.allclose(mesh.points, root.NodeCoordinates(True))
    assert np.allclose(mesh.point_data["DISPLACEMENT"], np.column_stack([ids * 3.0, -ids, np.zeros(len(ids))]))
    assert np.allclose(mesh.point_data["NODAL_H"].ravel(), 0.25 * ids)
    assert np.array_equal(mesh.point_data["SLAVE"].ravel(), (ids % 2 == 0).astype(float))
    assert not [f for f in os.listdir(tmp_path / "vtk") if f.startswith(".")]  # no temporary left


def test_output_interval_in_steps_and_in_time(tmp_path):
    model, root = square_grid(1, 1)
    by_step = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "a"),
                          output_control_type="step", output_frequency=2)
    assert run_steps(by_step, root, 5) == [2, 4]
    model, root = square_grid(1, 1)
    by_time = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "b"),
                          output_control_type="time", output_interval=0.75)
    assert run_steps(by_time, root, 6, dt=0.5) == [2, 3, 5, 6]  # t = 1.0, 1.5, 2.5, 3.0
    assert [t for t, _ in pvd_entries(tmp_path / "b" / "Structure.pvd")] == [1.0, 1.5, 2.5, 3.0]


def test_sub_model_parts_and_legacy_keys(tmp_path):
    model, root = square_grid(2, 2)
    process = vtk_process(model, model_part_name="Structure.computing_domain", folder_name=str(tmp_path / "out"),
                          output_sub_model_parts=True, output_frequency=1, save_output_files_in_folder=True,
                          nodal_solution_step_data_variables=["DISPLACEMENT"], element_data_value_variables=[],
                          element_flags=[], condition_data_value_variables=[], condition_flags=[],
                          gauss_point_variables_extrapolated_to_nodes=[])
    run_steps(process, root, 1, on_step=lambda step: set_results(root, step))
    files = sorted(os.listdir(tmp_path / "out"))
    assert "Structure.top_1.vtu" in files and "Structure.Parts_1.vtu" in files and "Structure.pvd" in files
    top = meshio.read(tmp_path / "out" / "Structure.top_1.vtu")
    assert top.cells[0].type == "vertex" and len(top.points) == 3
    assert np.allclose(top.point_data["DISPLACEMENT"][:, 0], root.GetSubModelPart("top").NodeIds())


def test_quad_elements_become_quad_cells(tmp_path):
    model, root = square_grid(2, 1)
    quad_elements(root, 2, 1)
    process = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path), write_ids=True,
                          nodal_solution_step_data_variables=["DISPLACEMENT"])
    run_steps(process, root, 1, on_step=lambda step: set_results(root, step))
    mesh = meshio.read(tmp_path / "Structure_1.vtu")
    assert [block.type for block in mesh.cells] == ["quad"]
    assert np.array_equal(mesh.cells[0].data, [[0, 1, 4, 3], [1, 2, 5, 4]])
    assert np.array_equal(mesh.cell_data["KRATOS_ELEMENT_ID"][0].ravel(), [1, 2])


def test_hexahedron_node_order_matches_vtk():
    # Our reference hexahedron (core/geometries/reference_element.cpp): corners, bottom / vertical /
    # top mid-edges, face centres bottom, front (y=-1), right (x=1), back, left, top; centre.
    ours = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1],
                     [-1, 1, 1], [0, -1, -1], [1, 0, -1], [0, 1, -1], [-1, 0, -1], [-1, -1, 0], [1, -1, 0],
                     [1, 1, 0], [-1, 1, 0], [0, -1, 1], [1, 0, 1], [0, 1, 1], [-1, 0, 1], [0, 0, -1], [0, -1, 0],
                     [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, 0, 1], [0, 0, 0]], dtype=float)
    # VTK_TRIQUADRATIC_HEXAHEDRON parametric coordinates in [0, 1]^3, mapped to [-1, 1]^3.
    vtk = 2.0 * np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
                          [.5, 0, 0], [1, .5, 0], [.5, 1, 0], [0, .5, 0], [.5, 0, 1], [1, .5, 1], [.5, 1, 1],
                          [0, .5, 1], [0, 0, .5], [1, 0, .5], [1, 1, .5], [0, 1, .5], [0, .5, .5], [1, .5, .5],
                          [.5, 0, .5], [.5, 1, .5], [.5, .5, 0], [.5, .5, 1], [.5, .5, .5]]) - 1.0
    assert np.array_equal(ours[_VTK_ORDER["hexahedron27"]], vtk)
    assert np.array_equal(ours[_VTK_ORDER["hexahedron20"]], vtk[:20])


def test_xdmf_time_series_appears_at_the_end(tmp_path):
    model, root = square_grid(2, 2)
    folder = tmp_path / "xdmf"
    process = vtk_process(model, model_part_name="Structure", output_path=str(folder), file_format="xdmf",
                          nodal_solution_step_data_variables=["DISPLACEMENT"])
    process.ExecuteInitialize()
    process.ExecuteBeforeSolutionLoop()
    for step in (1, 2):
        advance(root, 0.5)
        process.ExecuteInitializeSolutionStep()
        set_results(root, step)
        assert process.IsOutputStep()
        process.PrintOutput()
    assert not (folder / "Structure.xdmf").exists()
    process.ExecuteFinalize()
    assert sorted(os.listdir(folder)) == ["Structure.h5", "Structure.xdmf"]
    with meshio.xdmf.TimeSeriesReader(str(folder / "Structure.xdmf")) as reader:
        points, _ = reader.read_points_cells()
        times = []
        for k in range(reader.num_steps):
            time, point_data, _ = reader.read_data(k)
            times.append(time)
        assert times == [0.5, 1.0]
        ids = root.NodeIds()
        assert np.allclose(point_data["DISPLACEMENT"], np.column_stack([ids * 2.0, -ids, np.zeros(len(ids))]))
    assert np.allclose(points, root.NodeCoordinates(True))


def test_settings_errors(tmp_path):
    model, _ = square_grid(1, 1)
    with pytest.raises(mc.InputError, match="nodal_results"):
        vtk_process(model, model_part_name="Structure", nodal_results=["DISPLACEMENT"])
    with pytest.raises(mc.InputError, match="file_format"):
        vtk_process(model, model_part_name="Structure", file_format="vtk9")
    with pytest.raises(mc.InputError, match="DISPLACEMNT"):
        vtk_process(model, model_part_name="Structure", nodal_solution_step_data_variables=["DISPLACEMNT"])


def test_gid_output_writes_vtu_with_a_warning(tmp_path, caplog, monkeypatch):
    monkeypatch.chdir(tmp_path)
    model, root = square_grid(1, 1)
    settings = {"model_part_name": "Structure.computing_domain", "output_name": "test_solution",
                "postprocess_parameters": {"result_file_configuration": {
                    "gidpost_flags": {"GiDPostMode": "GiD_PostBinary"}, "output_control_type": "step",
                    "output_frequency": 1, "nodal_results": ["DISPLACEMENT"], "nodal_nonhistorical_results": [],
                    "nodal_flags_results": ["SLAVE"], "gauss_point_results": []}, "point_data_configuration": []}}
    with caplog.at_level(logging.WARNING, logger="mortarcontact"):
        process = vtk_process(model, "gid_output_process", **settings)
    assert "GiD files are not written" in caplog.text
    run_steps(process, root, 1, on_step=lambda step: set_results(root, step))
    mesh = meshio.read(tmp_path / "test_solution_vtk" / "Structure_1.vtu")
    assert set(mesh.point_data) == {"DISPLACEMENT", "SLAVE"}


@pytest.mark.parametrize("umask", [0o022, 0o027])
def test_written_files_get_the_mode_of_ordinary_files(tmp_path, umask):
    """Issue 15, item 4: VTU, PVD and JSON results are readable as any file the user creates
    (0666 less the umask), not mkstemp's private 0600, and still appear atomically."""
    from mortarcontact.utilities import write_text_atomically

    previous = os.umask(umask)
    try:
        model, root = square_grid(2, 2)
        process = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "vtk"),
                              nodal_solution_step_data_variables=["DISPLACEMENT"])
        run_steps(process, root, 1)
        write_text_atomically(str(tmp_path / "results.json"), "{}")
    finally:
        os.umask(previous)
    written = [tmp_path / "vtk" / "Structure.pvd", tmp_path / "vtk" / "Structure_1.vtu", tmp_path / "results.json"]
    assert {path.name: oct(path.stat().st_mode & 0o777) for path in written} == \
        {path.name: oct(0o666 & ~umask) for path in written}
    assert not [f for f in os.listdir(tmp_path / "vtk") if f.startswith(".")]


def test_requested_variables_that_nothing_computes_are_reported(tmp_path, capsys):
    """Issue 15, item 4: a warning names each requested variable that nothing in the run computes,
    the part and the output process: an integration-point value the elements do not compute
    (NODAL_PAUX, written as zeros), and per part a historical variable that is no unknown and held
    zero all run (said at the end): REACTION, set on node 1 in the last step only, is reported for
    the parts without node 1 (top, Parts), not for Structure and bottom. DISPLACEMENT (an unknown,
    zero here) is not reported."""
    model, root = square_grid(2, 2)
    quad_elements(root, 2, 2)

    def react_in_the_last_step(step):
        if step == 3:
            root.GetNode(1).SetSolutionStepValue(mc.REACTION, [0.0, -1.0, 0.0])

    process = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "vtk"),
                          output_sub_model_parts=True, nodal_solution_step_data_variables=["DISPLACEMENT", "REACTION"],
                          gauss_point_variables_in_elements=["NODAL_PAUX"])
    run_steps(process, root, 3, on_step=react_in_the_last_step)
    warnings = [line for line in capsys.readouterr().err.splitlines() if line.startswith("warning")]
    assert len(warnings) == 3, warnings
    assert "vtk_output_process (Structure): NODAL_PAUX is not computed (SmallDisplacementElement2D4N" in warnings[0]
    for line, part in zip(warnings[1:], ("Structure.Parts", "Structure.top")):
        assert f"vtk_output_process ({part}): REACTION is no unknown of the part and was zero" in line
    mesh = meshio.read(tmp_path / "vtk" / "Structure_3.vtu")
    assert np.array_equal(mesh.cell_data["NODAL_PAUX"][0].ravel(), np.zeros(4))
    assert mesh.point_data["REACTION"][0, 1] == -1.0


def test_non_historical_variable_listed_as_historical_is_an_error_before_the_first_step(tmp_path):
    model, _ = square_grid(1, 1)
    process = vtk_process(model, model_part_name="Structure", output_path=str(tmp_path / "vtk"),
                          nodal_solution_step_data_variables=["NORMAL_CONTACT_STRESS"])
    process.ExecuteInitialize()
    with pytest.raises(mc.InputError, match=r"nodal_solution_step_data_variables: NORMAL_CONTACT_STRESS is not a "
                                            r"historical .* of Structure; .* in nodal_data_value_variables"):
        process.Check()
    assert not (tmp_path / "vtk").exists()
