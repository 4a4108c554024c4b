"""Issue 2: every parameters, mdpa and materials file of the Kratos CSMA reference cases loads; contact
settings are validated, and the formulations not implemented yet raise a clear error."""
from __future__ import annotations

import glob
import os

import pytest

import mortarcontact as mc
from mortarcontact.project_parameters import read_project_parameters
from mortarcontact.solvers import create_solver
from mortarcontact.solvers.solver_settings import validate_solver_settings

from csma_cases import CSMA_CASES as CASE_DIR

PARAMETER_FILES = sorted(glob.glob(os.path.join(CASE_DIR, "*", "*_parameters.json")))
MDPA_FILES = sorted(glob.glob(os.path.join(CASE_DIR, "*", "*.mdpa")))


@pytest.mark.parametrize("path", PARAMETER_FILES, ids=lambda p: os.path.relpath(p, CASE_DIR))
def test_parameters_files_validate(path, monkeypatch):
    monkeypatch.chdir(CASE_DIR)
    params = read_project_parameters(path)
    solver_settings = params["solver_settings"]
    contact = solver_settings["contact_settings"]["mortar_type"].GetString() \
        if solver_settings.Has("contact_settings") else ""
    implemented = contact in ("", "ALMContactFrictionless", "PenaltyContactFrictionless", "ALMContactFrictional",
                              "ALMContactFrictionalPureSlip", "PenaltyContactFrictional",
                              "ComponentsMeshTying", "ScalarMeshTying") \
        and (not solver_settings.Has("mpc_contact_settings")
             or solver_settings["mpc_contact_settings"]["contact_type"].GetString() in ("Frictionless", "Frictional"))
    if implemented:
        create_solver(mc.Model(), solver_settings)
    else:
        with pytest.raises(mc.NotImplementedFeatureError, match=r"contact|mortar_type"):
            create_solver(mc.Model(), solver_settings)
        # The settings themselves are valid: validation alone succeeds.
        validate_solver_settings(read_project_parameters(path)["solver_settings"])


@pytest.mark.parametrize("path", MDPA_FILES, ids=lambda p: os.path.relpath(p, CASE_DIR))
def test_mdpa_files_load(path):
    model = mc.Model()
    part = model.CreateModelPart("Structure", 2)
    for name in ("DISPLACEMENT", "REACTION", "LINE_LOAD", "SURFACE_LOAD", "POINT_LOAD", "VOLUME_ACCELERATION",
                 "POSITIVE_FACE_PRESSURE", "NEGATIVE_FACE_PRESSURE", "TEMPERATURE", "NORMAL"):
        part.AddNodalSolutionStepVariable(mc.GetVariable(name))
    mc.ReadModelPart(part, path, True)
    assert part.NumberOfNodes() > 0
    assert part.NumberOfElements() > 0
    with open(path, newline="") as f:
        text = f.read()
    node_lines = text.split("Begin Nodes")[1].split("End Nodes")[0].strip().splitlines()
    data_lines = [line for line in node_lines if line.strip() and not line.strip().startswith("//")]
    assert part.NumberOfNodes() == len(data_lines)


def test_materials_files_apply(csma_cases, monkeypatch):
    """Each case's materials file assigns its law and values to the parts it names."""
    monkeypatch.chdir(csma_cases)
    checked = 0
    for path in PARAMETER_FILES:
        params = read_project_parameters(path)
        settings = params["solver_settings"]
        materials_file = settings["material_import_settings"]["materials_filename"].GetString() \
            if settings.Has("material_import_settings") else ""
        if not materials_file:
            continue
        model = mc.Model()
        from mortarcontact.solvers.mechanical_solver import MechanicalSolver

        settings_copy = settings.Clone()
        for key in ("contact_settings", "mpc_contact_settings"):
            if settings_copy.Has(key):
                settings_copy.RemoveValue(key)
        validate_solver_settings(settings_copy)
        settings_copy["convergence_criterion"].SetString("residual_criterion")
        solver = MechanicalSolver(model, settings_copy, dynamic=False, explicit=False)
        solver.ImportModelPart()
        part = solver.main_model_part
        laws = {e.GetProperties().ConstitutiveLawName() for e in part.Elements}
        assert laws and "" not in laws, f"{path}: elements without a constitutive law"
        checked += 1
    assert checked >= 15
