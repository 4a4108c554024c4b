"""Convergence criteria of the contact solvers, composed from ``solver_settings`` as the Kratos
contact factory does (spec 3.2):

- a ``convergence_criterion`` containing ``contact`` builds a contact criterion (displacement /
  residual / mixed / and / or, with separate displacement, rotation and multiplier blocks) and
  wraps it with the mortar (active-set) criterion in a ``MortarAndConvergenceCriteria``, which
  prints the convergence table (``fancy_convergence_criterion``) and, with
  ``condn_convergence_criterion``, the condition number;
- any other name builds the structural criterion (spec 3.1); for a formulation with multipliers
  it is ANDed with the mortar criterion (no table).

Names are matched case-insensitively. The mortar criterion and the multiplier blocks are the
formulation's (``ContactFormulation``): with three blocks (frictional ALM) and
``frictional_decomposed`` the increment, residual and mixed criteria split the multipliers into
normal, stick and slip blocks, every tangential one counted as slip when the mortar criterion is
pure slip; ``contact_and_criterion`` and ``contact_or_criterion`` keep one multiplier block, as in
Kratos.
"""
from __future__ import annotations

from ..utilities import nearest

CONTACT_CRITERIA = ("contact_displacement_criterion", "contact_residual_criterion", "contact_mixed_criterion",
                    "contact_and_criterion", "contact_or_criterion")
STRUCTURAL_CRITERIA = ("displacement_criterion", "residual_criterion", "and_criterion", "or_criterion")
ALL_CRITERIA = CONTACT_CRITERIA + STRUCTURAL_CRITERIA + ("adaptative_remesh_criteria",)

#: The keys of contact_settings this factory reads (Kratos' names and defaults); the block criteria
#: and the active-set criteria declare and read theirs (see contact_settings_defaults()).
CRITERIA_SETTINGS = """{
    "condn_convergence_criterion": false,
    "fancy_convergence_criterion": true,
    "frictional_decomposed": true
}"""

#: multiplier_blocks of the frictional ALM formulations: normal, stick and slip.
FRICTIONAL_BLOCKS = 3


def _core_module(core):
    if core is None:
        from .. import _core as core  # imported here: the extension is only needed when building
    return core


def _contact_settings(solver_settings):
    return solver_settings["contact_settings"]


def _value(settings, key, kind):
    return getattr(settings[key], "Get" + kind)()


def _block_criterion(cls, solver_settings):
    """``cls`` reading its displacement tolerances from solver_settings, the rest from contact_settings."""
    return cls(solver_settings, _contact_settings(solver_settings))


def _contact_mechanical_criterion(name, solver_settings, formulation, mortar, core):
    s = solver_settings
    if formulation.multiplier_blocks == 0:
        # Penalty formulations have no multipliers: displacement (and rotation) blocks only; mixed
        # reuses the residual criterion, as Kratos does (whose factory leaves the rotation
        # tolerances at their defaults there; the user's are read here).
        displacement = lambda: _block_criterion(core.DisplacementContactCriteria, s)  # noqa: E731
        residual = lambda: _block_criterion(core.DisplacementResidualContactCriteria, s)  # noqa: E731
        mixed = residual
    else:
        displacement = lambda: _block_criterion(core.DisplacementLagrangeMultiplierContactCriteria, s)  # noqa: E731
        residual = lambda: _block_criterion(core.DisplacementLagrangeMultiplierResidualContactCriteria, s)  # noqa: E731
        mixed = lambda: _block_criterion(core.DisplacementLagrangeMultiplierMixedContactCriteria, s)  # noqa: E731

    criteria = {"contact_displacement_criterion": displacement,
                "contact_residual_criterion": residual,
                "contact_mixed_criterion": mixed,
                "contact_and_criterion": lambda: core.AndCriteria(residual(), displacement()),
                "contact_or_criterion": lambda: core.OrCriteria(residual(), displacement())}
    contact = _contact_settings(s)
    if formulation.multiplier_blocks == FRICTIONAL_BLOCKS and _value(contact, "frictional_decomposed", "Bool"):
        # The pure-slip choice is the formulation's, made once when its mortar criterion was built.
        pure_slip = mortar.PureSlip()

        def frictional(cls):
            return lambda: cls(s, contact, pure_slip=pure_slip)

        criteria.update({
            "contact_displacement_criterion":
                frictional(core.DisplacementLagrangeMultiplierFrictionalContactCriteria),
            "contact_residual_criterion":
                frictional(core.DisplacementLagrangeMultiplierResidualFrictionalContactCriteria),
            "contact_mixed_criterion":
                frictional(core.DisplacementLagrangeMultiplierMixedFrictionalContactCriteria)})
    return criteria[name]()


def _structural_criterion(name, solver_settings, core):
    s = solver_settings
    displacement = lambda: core.DisplacementCriteria(_value(s, "displacement_relative_tolerance", "Double"),  # noqa: E731
                                                     _value(s, "displacement_absolute_tolerance", "Double"))
    residual = lambda: core.ResidualCriteria(_value(s, "residual_relative_tolerance", "Double"),  # noqa: E731
                                             _value(s, "residual_absolute_tolerance", "Double"))
    return {"displacement_criterion": displacement,
            "residual_criterion": residual,
            "and_criterion": lambda: core.AndCriteria(residual(), displacement()),
            "or_criterion": lambda: core.OrCriteria(residual(), displacement())}[name]()


def create_contact_convergence_criteria(solver_settings, formulation, echo_level: int = 0, mortar_updater=None,
                                        core=None):
    """The convergence criterion of a contact solver from its validated ``solver_settings`` and its
    ``formulation`` (``ContactFormulation``: the active-set criterion and the multiplier blocks).

    ``mortar_updater`` (a ``MortarUpdater``) is handed to the mortar criterion; it can also be
    set later with ``criteria.SetMortarUpdater`` on the returned ``MortarAndConvergenceCriteria``.
    """
    core = _core_module(core)
    raw = _value(solver_settings, "convergence_criterion", "String")
    name = raw.lower()
    where = "solver_settings.convergence_criterion"
    if name not in ALL_CRITERIA:
        raise core.InputError(f"{where}: unknown criterion \"{raw}\"{nearest(name, ALL_CRITERIA)}")
    if name == "adaptative_remesh_criteria":
        raise core.NotImplementedFeatureError(f"{where}: \"{raw}\" belongs to the adaptive remeshing analysis, "
                                              "which is not implemented")
    contact = _contact_settings(solver_settings)
    if name in CONTACT_CRITERIA:
        mortar = formulation.CreateActiveSetCriterion(contact)
        mechanical = _contact_mechanical_criterion(name, solver_settings, formulation, mortar, core)
        criteria = core.MortarAndConvergenceCriteria(
            mechanical, mortar,
            print_convergence_criterion=_value(contact, "print_convergence_criterion", "Bool"),
            condition_number=_value(contact, "condn_convergence_criterion", "Bool"),
            print_table=_value(contact, "fancy_convergence_criterion", "Bool"))
    else:
        criteria = _structural_criterion(name, solver_settings, core)
        if formulation.multiplier_blocks > 0:
            # As Kratos, the formulations with multipliers AND the structural criterion with their
            # active-set criterion (with the residual refreshed after the update: a mortar-and
            # criterion without its table); the penalty formulations keep the structural one alone.
            criteria = core.MortarAndConvergenceCriteria(criteria, formulation.CreateActiveSetCriterion(contact),
                                                         print_convergence_criterion=False, condition_number=False,
                                                         print_table=False)
    if mortar_updater is not None and hasattr(criteria, "SetMortarUpdater"):
        criteria.SetMortarUpdater(mortar_updater)
    if hasattr(criteria, "SetEchoLevel"):
        criteria.SetEchoLevel(echo_level)
    return criteria
