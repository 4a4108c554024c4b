"""Solver selection from ``solver_settings`` (spec 2.1)."""
from __future__ import annotations

from .. import _core
from ..utilities import nearest
from .contact_mechanical_solver import ContactMechanicalSolver
from .mechanical_solver import MechanicalSolver
from .mpc_contact_mechanical_solver import MPCContactMechanicalSolver
from .solver_settings import validate_solver_settings

SOLVER_TYPES = {"static": "static", "dynamic": "dynamic"}


def create_solver(model: _core.Model, settings: _core.Parameters, case_dir: str | None = None) -> MechanicalSolver:
    """The solver of spec 2.1: ``solver_type`` Static / Dynamic (any case), with
    ``time_integration_method`` implicit (default) or explicit. Contact variants are chosen by the
    presence of ``contact_settings`` / ``mpc_contact_settings``."""
    validate_solver_settings(settings)
    where = settings.Where()
    solver_type = settings["solver_type"].GetString()
    kind = SOLVER_TYPES.get(solver_type.lower())
    if kind is None:
        raise _core.InputError(f"{where}.solver_type: unknown solver \"{solver_type}\""
                               f"{nearest(solver_type, ['Static', 'Dynamic'])}; valid: \"Static\", \"Dynamic\"")
    method = settings["time_integration_method"].GetString()
    if kind == "dynamic" and method not in ("implicit", "explicit"):
        raise _core.InputError(f"{where}.time_integration_method: expected \"implicit\" or \"explicit\", "
                               f"got \"{method}\"")
    contact = settings["contact_settings"]
    solver_class = MechanicalSolver
    # contact_settings is checked first (spec 2.1): its presence wins over mpc_contact_settings.
    if contact.size() > 0 and contact["mortar_type"].GetString():
        solver_class = ContactMechanicalSolver
    elif settings["mpc_contact_settings"].size() > 0:
        solver_class = MPCContactMechanicalSolver
    return solver_class(model, settings, dynamic=(kind == "dynamic"),
                        explicit=(kind == "dynamic" and method == "explicit"), case_dir=case_dir)
