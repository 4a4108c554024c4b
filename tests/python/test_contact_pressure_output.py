"""Issue 15, item 4: the contact pressure a user finds in the VTU / XDMF output is physical. The
multipliers are unknowns scaled by SCALE_FACTOR k (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE -0.00142
where the pressure is 29.2); NORMAL_CONTACT_STRESS (Kratos' name of the post-processed normal
traction, negative in compression) and CONTACT_PRESSURE (its opposite) are in stress units: k
lambda_n on the ALM formulations, eps g on the penalty one, checked on the gmsh Hertz cylinder
against the closed form (mortarcontact.cases.hertz.evaluate) as read back from the files."""
from __future__ import annotations

import glob
import importlib.util
import json
import os

import meshio
import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import use_components, use_penalty

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")

from mortarcontact.cases import hertz  # noqa: E402

MULTIPLIER = {"scalar": "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "components": "VECTOR_LAGRANGE_MULTIPLIER",
              "penalty": None}


@pytest.fixture(scope="module")
def hertz_case(tmp_path_factory):
    folder = hertz.write_case("hertz2d", "2k", str(tmp_path_factory.mktemp("hertz")))
    return folder, hertz.load_reference(folder)


def run_with_output(folder: str, formulation: str, file_format: str, output: str):
    """Runs the Hertz case in `formulation` writing the slave surface to `output`; returns the
    analysis and the point data of the last output step as read back by meshio (by node id)."""
    params = read_project_parameters(os.path.join(folder, "ProjectParameters.json"))
    {"scalar": lambda p: None, "components": use_components, "penalty": use_penalty}[formulation](params)
    historical = ["NORMAL", "REACTION"] + ([MULTIPLIER[formulation]] if MULTIPLIER[formulation] else [])
    params.AddValue("output_processes", mc.Parameters(json.dumps({"vtk_output": [{
        "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure.Contact_slave", "output_path": output,
                       "file_format": file_format, "write_ids": True,
                       "nodal_solution_step_data_variables": historical,
                       "nodal_data_value_variables": ["NORMAL_CONTACT_STRESS", "CONTACT_PRESSURE"],
                       "nodal_flags": ["ACTIVE"]}}]})))
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
        analysis.Run()
    finally:
        os.chdir(cwd)
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    if file_format == "xdmf":
        with meshio.xdmf.TimeSeriesReader(os.path.join(output, "Structure.Contact_slave.xdmf")) as reader:
            points, _ = reader.read_points_cells()
            _, point_data, _ = reader.read_data(reader.num_steps - 1)
    else:
        last = max(glob.glob(os.path.join(output, "*.vtu")), key=lambda p: int(p.rsplit("_", 1)[1][:-4]))
        mesh = meshio.read(last)
        points, point_data = mesh.points, mesh.point_data
    part = analysis.model["Structure.Contact_slave"]
    ids = point_data["KRATOS_NODE_ID"] if "KRATOS_NODE_ID" in point_data else part.NodeIds()
    assert sorted(np.asarray(ids).ravel().tolist()) == sorted(part.NodeIds().tolist())
    return analysis, {"x": points[:, 0], "y": points[:, 1], **point_data}


@pytest.mark.parametrize("formulation, file_format", [("scalar", "binary"), ("components", "xdmf"),
                                                      ("penalty", "binary")])
def test_contact_pressure_in_the_files_is_the_hertz_pressure(hertz_case, tmp_path, formulation, file_format):
    folder, reference = hertz_case
    analysis, data = run_with_output(folder, formulation, file_format, str(tmp_path / "out"))
    stress, pressure = data["NORMAL_CONTACT_STRESS"], data["CONTACT_PRESSURE"]
    active = data["ACTIVE"] > 0.5
    assert np.count_nonzero(active) >= 5
    assert np.array_equal(pressure, -stress)
    assert np.all(stress[~active] == 0.0) and np.all(pressure[active] > 0.0)

    root = analysis.model["Structure"]
    k = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    peak = pressure.max()
    if MULTIPLIER[formulation]:
        # k lambda_n: the augmented pressure differs by eps g, within the gap tolerance
        multiplier = data[MULTIPLIER[formulation]]
        normal_multiplier = multiplier if multiplier.ndim == 1 else np.sum(multiplier * data["NORMAL"], axis=1)
        assert np.abs(normal_multiplier).max() < 1e-2 * peak  # the scaled unknown is no pressure
        assert stress[active] == pytest.approx(k * normal_multiplier[active], abs=1e-4 * peak)

    bottom = analysis.model["Structure.DISPLACEMENT_bottom"]
    record = {"status": "ok", "process_info": {},
              "reactions": {"DISPLACEMENT_bottom": float(bottom.GetNodalValues(mc.REACTION)[:, 1].sum())},
              "slave": [{"x": float(x), "y": float(y), "lm": None, "augmented": float(s), "active": bool(a)}
                        for x, y, s, a in zip(data["x"], data["y"], stress, active)]}
    result = hertz.evaluate(record, reference)
    print(f"{formulation}: peak {result['peak_pressure']:.4g} (Hertz {result['hertz_peak_pressure']:.4g}), "
          f"errors p {result['peak_pressure_error']:+.2%}, a {result['half_width_fit_error']:+.2%}, "
          f"force from pressure {result['force_from_pressure']:.5g} / reaction {result['force']:.5g}")
    assert abs(result["peak_pressure_error"]) < 0.05
    assert abs(result["half_width_fit_error"]) < 0.05
    assert result["force_from_pressure"] == pytest.approx(result["force"], rel=0.02)
