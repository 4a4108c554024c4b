"""``mpc_contact_process``: multipoint-constraint (MPC) mortar contact (spec 4.7). The interfaces and
searches are those of the other contact processes; the pairs are ``MPCMortarContactCondition<geometry>``,
which add nothing to the system: the MPC strategy ties each active slave node's normal displacement to
the mortar projection of the master (D^-1 M) with a master-slave constraint, and releases it when its
reaction pulls (``reaction_check_stiffness_factor``). ``contact_type`` Frictional (Coulomb): a
sticking node is tied in every component, a slipping one in the normal with its Coulomb force in the
system (MPCContactCriteria decides stick and slip from the reactions); FrictionalPureSlip: every active
node slips. With ``contact_type`` "MeshTying"
every displacement component of every slave node is tied from the first step, for good (mesh tying by
constraints, the multiplier-free counterpart of mesh_tying_process' ComponentsMeshTying)."""
from __future__ import annotations

import math

from .. import _core
from ..utilities import nearest, warn_about_keys_without_effect
from . import _settings
from .alm_contact_process import NORMAL_UPDATE, NORMAL_VARIATIONS
from .search_base_process import SearchBaseProcess

#: contact_type values Kratos recognises for MPC (spec 4.7): MeshTying (a formulation of its own, root flag RIGID)
#: and the suffix PureSlip
MESH_TYING = "MeshTying"
PURE_SLIP = "PureSlip"

_FRICTIONAL = "only frictional MPC contact reads it"
#: Keys accepted without effect (issue 18): (sub-block or "", key) -> why.
KEYS_WITHOUT_EFFECT = {
    ("", "not_normal_update_frictional"): "the relations are rebuilt from the nodal normals of the configuration "
                                          "they are built at, frictional or not",
    ("", "tangent_factor"): "a sticking node is tied exactly (no tangential penalty to scale) and a slipping one "
                            "carries the Coulomb force itself",
    ("", "normal_variation"): "the constraints are linear in the displacements, built from the nodal normals of the "
                              "configuration they are built at: there is no tangent of the normal to include",
    ("", "clear_inactive_for_post"): "an inactive node transmits no force: its CONTACT_FORCE and "
                                     "NORMAL_CONTACT_STRESS are zero either way",
    ("", "update_condition_relation_step"): "the relations are rebuilt at every step from its start "
                                            "configuration (and at every iteration with "
                                            "mpc_contact_settings.update_each_nl_iteration)",
}

#: Keys without effect with contact_type "MeshTying" only.
MESH_TYING_KEYS_WITHOUT_EFFECT = {
    ("", "reaction_check_stiffness_factor"): "mesh tying has no active set: a tie is never released (Kratos 10.4 "
                                             "releases a tie that pulls, a defect)",
}


def mpc_formulation(contact_type, where: str):
    """The formulation of an MPC ``contact_type`` (a Parameters string): Frictionless, Frictional or
    MeshTying (every displacement component tied, root flag RIGID), with Kratos' suffixes PureSlip
    (Frictional only: every active node slips, see is_mpc_pure_slip) and WithNormalUpdate (the normals
    are always those of the configuration the relations are built at)."""
    name = contact_type.GetString()
    base = name[:-len(NORMAL_UPDATE)] if name.endswith(NORMAL_UPDATE) else name
    if base.endswith(PURE_SLIP) and base != "Frictional" + PURE_SLIP:
        raise _core.InputError(f"{contact_type.Where()}: '{name}': {PURE_SLIP} is a variant of Frictional only "
                               f"(did you mean 'Frictional{PURE_SLIP}'?)")
    base = base.removesuffix(PURE_SLIP)
    return _core.ContactFormulation.OfProcess("mpc_contact_process", base, f"{where}: {contact_type.Where()} '{name}'")


def is_mpc_pure_slip(contact_type) -> bool:
    """Whether an MPC ``contact_type`` is FrictionalPureSlip (with or without WithNormalUpdate)."""
    return contact_type.GetString().removesuffix(NORMAL_UPDATE).endswith(PURE_SLIP)


class MPCContactProcess(SearchBaseProcess):
    """Builds the contact interfaces and searches (MPC pairs) and hands the release threshold to the
    MPC strategy."""

    python_module = "mpc_contact_process"

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        common = _settings.common_defaults()
        common.update({
            "contact_type": "Frictionless",
            "not_normal_update_frictional": False,
            "normal_variation": "no_derivatives_computation",
            "frictional_law": "Coulomb",
            "tangent_factor": 1.0e-1,
            "zero_tolerance_factor": 1.0e2,
            "reaction_check_stiffness_factor": 1.0e-10,
            "integration_order": 2,
            "clear_inactive_for_post": True,
            "update_condition_relation_step": False,
        })
        return _settings.to_parameters(common)

    def __init__(self, model, settings=None):
        if settings is not None and settings.Has("variable_name"):
            raise _core.NotImplementedFeatureError(
                f"{settings['variable_name'].Where()}: mpc_contact_process ties the displacements only (contact_type "
                "\"MeshTying\" ties every component); a nodal scalar is tied by mesh_tying_process (its "
                "variable_name, solver_settings.contact_settings.mortar_type \"ScalarMeshTying\")")
        super().__init__(model, settings)

    def _check_types(self) -> None:
        s = self.settings
        self.formulation = mpc_formulation(s["contact_type"], self.python_module)
        self.frictional = self.formulation.contact_type == "Frictional"
        self.pure_slip = is_mpc_pure_slip(s["contact_type"])
        self.condition_stem = self.formulation.ConditionStem(False, False)
        variation = s["normal_variation"].GetString().lower()
        if variation not in NORMAL_VARIATIONS:
            raise _core.InputError(f"{s['normal_variation'].Where()}: unknown value '{variation}'"
                                   f"{nearest(variation, NORMAL_VARIATIONS)}")
        law = s["frictional_law"].GetString()
        if law != "Coulomb":
            raise _core.InputError(f"{s['frictional_law'].Where()}: '{law}' is not a frictional law of MPC contact"
                                   f"{nearest(law, ['Coulomb'])} (valid: Coulomb)")
        factor = s["reaction_check_stiffness_factor"]
        if not 0.0 <= factor.GetDouble() < math.inf:
            raise _core.InputError(f"{factor.Where()}: must be a non-negative number, got {factor.GetDouble()!r}")
        if not 0.0 < s["tangent_factor"].GetDouble() < math.inf:
            raise _core.InputError(f"{s['tangent_factor'].Where()}: must be a positive number, "
                                   f"got {s['tangent_factor'].GetDouble()!r}")
        without_effect = dict(KEYS_WITHOUT_EFFECT)
        if not self.frictional:
            without_effect.update({("", "friction_coefficients"): _FRICTIONAL, ("", "frictional_law"): _FRICTIONAL})
        if self.formulation.contact_type == MESH_TYING:
            without_effect.update(MESH_TYING_KEYS_WITHOUT_EFFECT)
        warn_about_keys_without_effect(s, self.GetDefaultParameters(), without_effect)

    def check_solver_variables(self) -> None:
        """The solver must be the MPC contact solver (solver_settings.mpc_contact_settings)."""
        solver = self.root.GetProcessInfo().GetValue(_core.MORTAR_TYPE)
        if solver != self.formulation.mortar_type:
            found = "contact_settings" if solver else "neither contact_settings nor mpc_contact_settings"
            raise _core.InputError(
                f"{self.python_module} needs solver_settings.mpc_contact_settings (contact_type "
                f"\"{self.formulation.contact_type}\"); the solver has {found}")

    def ExecuteInitialize(self) -> None:
        super().ExecuteInitialize()
        info = self.root.GetProcessInfo()
        info.SetValue(_core.REACTION_CHECK_STIFFNESS_FACTOR,
                      self.settings["reaction_check_stiffness_factor"].GetDouble())
        info.SetValue(_core.PURE_SLIP, self.pure_slip)
        # SLIP of the root tells the MPC strategy the contact is frictional.
        for part in (self.root, self.root.GetSubModelPart("Contact"), self.root.GetSubModelPart("ComputingContact")):
            part.Set(_core.CONTACT, True)
            part.Set(_core.SLIP, self.frictional)
        # As Kratos: the root flag RIGID makes the MPC strategy tie every component, with no active set.
        self.root.Set(_core.RIGID, self.formulation.contact_type == MESH_TYING)

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Nothing: CONTACT_FORCE and NORMAL_CONTACT_STRESS are written by the MPC strategy's active-set
        check, from the reactions of the converged state."""
