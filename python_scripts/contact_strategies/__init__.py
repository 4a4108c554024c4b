"""Contact solving: the convergence criteria composition (spec 3.2) and the contact strategy
built from ``solver_settings`` (spec 2.9).

Entry points for the contact solvers (``python_scripts/solvers``):

- ``create_contact_convergence_criteria(solver_settings, formulation, echo_level=0, mortar_updater=None)``
- ``create_contact_strategy(model_part, solver_settings, scheme, linear_solver, criteria, ...)``

Both take the validated ``solver_settings`` (with ``contact_settings`` merged with its defaults)
and an optional ``core`` module argument (default: ``mortarcontact._core``), so that the
composition rules can be unit-tested without the compiled extension.
"""
from __future__ import annotations

from .convergence_criteria_factory import CRITERIA_SETTINGS, create_contact_convergence_criteria  # noqa: F401
from .strategy_factory import create_contact_strategy  # noqa: F401
