"""Issue 11: each setting is declared once, by the class that reads it. The keys of
contact_settings come from five owners without overlap, and no Python module re-declares a key
whose owner is a C++ class (the defaults of search_parameters, the block and active-set criteria
and the contact strategy)."""
from __future__ import annotations

import pathlib
import re

from mortarcontact import _core
from mortarcontact.contact_strategies import CRITERIA_SETTINGS
from mortarcontact.solvers.contact_mechanical_solver import CONTACT_SETTINGS, contact_settings_defaults
from mortarcontact.solvers.convergence_history import ConvergenceHistory

REPO = pathlib.Path(__file__).resolve().parents[2]

def _owners():
    return {
        "contact solver": _core.Parameters(CONTACT_SETTINGS),
        "criteria factory": _core.Parameters(CRITERIA_SETTINGS),
        "block criteria": _core.BlockContactCriteria.GetContactSettingsDefaults(),
        "contact strategy": _core.ResidualBasedNewtonRaphsonContactStrategy.GetDefaultParameters(),
        "active-set criteria": _core.BaseMortarConvergenceCriteria.GetDefaultParameters(),
    }


def test_each_contact_settings_key_has_one_owner():
    owner_of = {}
    for owner, defaults in _owners().items():
        for key in defaults.Keys():
            assert key not in owner_of, f"contact_settings.{key} is declared by {owner_of[key]} and by {owner}"
            owner_of[key] = owner
    assert set(owner_of) == set(contact_settings_defaults().Keys())


def test_python_does_not_redeclare_keys_of_cpp_owners():
    cpp_owned = {key for owner, defaults in _owners().items() if owner not in ("contact solver", "criteria factory")
                 for key in defaults.Keys()}
    cpp_owned |= set(_core.ContactSearchProcess.GetDefaultParameters().Keys())
    sources = sorted((REPO / "python_scripts").rglob("*.py"))
    assert sources
    for path in sources:
        text = path.read_text()
        for key in sorted(cpp_owned):
            declaration = re.search(rf'"{key}"\s*:', text)
            assert declaration is None, f"{path.relative_to(REPO)} declares \"{key}\", which C++ owns"


def test_convergence_history_keys_have_one_owner():
    """solver_settings.convergence_history (ours: no Kratos setting has this name) is an empty block
    in STRUCTURAL_DEFAULTS whose keys ConvergenceHistory alone declares."""
    keys = ConvergenceHistory.GetDefaultParameters().Keys()
    assert sorted(keys) == ["file_name", "plot", "write_json"]
    owner = REPO / "python_scripts" / "solvers" / "convergence_history.py"
    for path in sorted((REPO / "python_scripts").rglob("*.py")):
        if path == owner:
            continue
        for key in keys:
            assert re.search(rf'"{key}"\s*:', path.read_text()) is None, f"{path.relative_to(REPO)} declares {key}"
    solver_settings = (REPO / "python_scripts" / "solvers" / "solver_settings.py").read_text()
    assert re.search(r'"convergence_history"\s*:\s*\{\}', solver_settings)
