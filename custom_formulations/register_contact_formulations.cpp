// SPDX-License-Identifier: BSD-3-Clause
#include "custom_formulations/register_contact_formulations.h"

#include <mutex>
#include <vector>

#include "core/linear_solvers/linear_solver.h"
#include "core/utilities/string_utilities.h"
#include "custom_formulations/contact_formulation.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_components_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/mesh_tying_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictionless_mortar_criteria.h"

namespace mc {

namespace {

template <class TCriterion>
ContactFormulation::CriterionFactory Criterion() {
  return [](Parameters settings) { return std::make_shared<TCriterion>(std::move(settings)); };
}

template <class TCriterion>
ContactFormulation::CriterionFactory FrictionalCriterion(bool pure_slip) {
  return [pure_slip](Parameters settings) { return std::make_shared<TCriterion>(std::move(settings), pure_slip); };
}

void RegisterAll() {
  using D = ContactFormulation::Description;
  const std::vector<std::pair<std::string, std::string>> vector_multiplier = {
      {"VECTOR_LAGRANGE_MULTIPLIER_X", "WEIGHTED_VECTOR_RESIDUAL_X"},
      {"VECTOR_LAGRANGE_MULTIPLIER_Y", "WEIGHTED_VECTOR_RESIDUAL_Y"},
      {"VECTOR_LAGRANGE_MULTIPLIER_Z", "WEIGHTED_VECTOR_RESIDUAL_Z"}};

  ContactFormulation::Register(D{
      .mortar_type = "ALMContactFrictionless",
      .process = "alm_contact_process",
      .contact_type = "Frictionless",
      .enforcement = "ALM",
      .contact_kind = "Frictionless",
      .variables = {"LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "WEIGHTED_GAP", "WEIGHTED_SCALAR_RESIDUAL"},
      .dofs = {{"LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "WEIGHTED_SCALAR_RESIDUAL"}},
      .multiplier = "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE",
      .multiplier_blocks = 1,
      // The scalar system's multiplier columns are n . D: the thesis solves it monolithically.
      .condensable = false,
      .axisymmetric = true,
      .active_set_criterion = Criterion<ALMFrictionlessMortarConvergenceCriteria>(),
  });
  ContactFormulation::Register(D{
      .mortar_type = "ALMContactFrictionlessComponents",
      .process = "alm_contact_process",
      .contact_type = "FrictionlessComponents",
      .enforcement = "ALM",
      .contact_kind = "FrictionlessComponents",
      .variables = {"VECTOR_LAGRANGE_MULTIPLIER", "WEIGHTED_GAP", "WEIGHTED_VECTOR_RESIDUAL"},
      .dofs = vector_multiplier,
      .multiplier = "VECTOR_LAGRANGE_MULTIPLIER",
      .multiplier_blocks = 1,
      .condensable = true,
      .axisymmetric = false,
      .active_set_criterion = Criterion<ALMFrictionlessComponentsMortarConvergenceCriteria>(),
  });
  ContactFormulation::Register(D{
      .mortar_type = "PenaltyContactFrictionless",
      .process = "penalty_contact_process",
      .contact_type = "Frictionless",
      .enforcement = "Penalty",
      .contact_kind = "Frictionless",
      .variables = {"WEIGHTED_GAP"},
      .dofs = {},
      .multiplier = "",
      .multiplier_blocks = 0,
      .condensable = false,
      .axisymmetric = true,
      .active_set_criterion = Criterion<PenaltyFrictionlessMortarConvergenceCriteria>(),
  });

  // Coulomb friction (spec 2.10): the same conditions for both, a node sticks or slips by its SLIP
  // flag; pure slip only makes every active node slip.
  for (const bool pure_slip : {false, true}) {
    const std::string suffix = pure_slip ? "PureSlip" : "";
    ContactFormulation::Register(D{
        .mortar_type = "ALMContactFrictional" + suffix,
        .process = "alm_contact_process",
        .contact_type = "Frictional" + suffix,
        .enforcement = "ALM",
        .contact_kind = "Frictional",
        .variables = {"VECTOR_LAGRANGE_MULTIPLIER", "WEIGHTED_GAP", "WEIGHTED_SLIP", "WEIGHTED_VECTOR_RESIDUAL"},
        .dofs = vector_multiplier,
        .multiplier = "VECTOR_LAGRANGE_MULTIPLIER",
        .multiplier_blocks = 3,
        .condensable = true,
        .axisymmetric = true,
        .pure_slip = pure_slip,
        .buffer_size = 3,
        .active_set_criterion = FrictionalCriterion<ALMFrictionalMortarConvergenceCriteria>(pure_slip),
    });
    ContactFormulation::Register(D{
        .mortar_type = "PenaltyContactFrictional" + suffix,
        .process = "penalty_contact_process",
        .contact_type = "Frictional" + suffix,
        .enforcement = "Penalty",
        .contact_kind = "Frictional",
        .variables = {"WEIGHTED_GAP", "WEIGHTED_SLIP"},
        .dofs = {},
        .multiplier = "",
        .multiplier_blocks = 0,
        .condensable = false,
        .axisymmetric = true,
        .pure_slip = pure_slip,
        .buffer_size = 3,
        .active_set_criterion = FrictionalCriterion<PenaltyFrictionalMortarConvergenceCriteria>(pure_slip),
    });
  }
  // Mesh tying (spec 2.10): no inequality, so no active set; the tied variable comes from the
  // process' variable_name, which must match (array -> components, scalar -> scalar). The condition
  // name has no enforcement / kind tokens: "MeshTyingMortarCondition" + geometry.
  const auto tying_criterion = [](Parameters) { return std::make_shared<MeshTyingMortarConvergenceCriteria>(); };
  ContactFormulation::Register(D{
      .mortar_type = "ComponentsMeshTying",
      .process = "mesh_tying_process",
      .contact_type = "Components",
      .enforcement = "MeshTying",
      .condition_suffix = "MortarCondition",
      .variables = {"VECTOR_LAGRANGE_MULTIPLIER", "WEIGHTED_VECTOR_RESIDUAL"},
      .dofs = vector_multiplier,
      .multiplier = "VECTOR_LAGRANGE_MULTIPLIER",
      .multiplier_blocks = 1,
      // Kratos solves the tie monolithically; its rows have the structure MixedULM condenses (slave rows
      // -k D_jj I per node, every tied slave node ACTIVE: MeshTyingUtilities), with the same solution.
      .condensable = true,
      .active_set_criterion = tying_criterion,
  });
  ContactFormulation::Register(D{
      .mortar_type = "ScalarMeshTying",
      .process = "mesh_tying_process",
      .contact_type = "Scalar",
      .enforcement = "MeshTying",
      .condition_suffix = "MortarCondition",
      .variables = {"SCALAR_LAGRANGE_MULTIPLIER", "WEIGHTED_SCALAR_RESIDUAL"},
      .dofs = {{"SCALAR_LAGRANGE_MULTIPLIER", "WEIGHTED_SCALAR_RESIDUAL"}},
      .multiplier = "SCALAR_LAGRANGE_MULTIPLIER",
      .multiplier_blocks = 1,
      .active_set_criterion = tying_criterion,
  });

  // Multipoint-constraint contact (spec 2.8, 4.7): no multipliers, master-slave constraints from D^-1 M,
  // chosen by solver_settings.mpc_contact_settings, never by a contact_settings.mortar_type. Its active
  // set is checked by its strategy (ResidualBasedNewtonRaphsonMPCContactStrategy owns the one
  // MPCContactCriteria), not by the criteria factory.
  const auto mpc_criterion = [](Parameters settings) -> std::shared_ptr<ConvergenceCriteria> {
    throw Error(Concat(settings.Where(), ": the MPC contact active set is checked by its strategy"));
  };
  ContactFormulation::Register(D{
      .mortar_type = "MPCContactFrictionless",
      .process = "mpc_contact_process",
      .contact_type = "Frictionless",
      .enforcement = "MPC",
      .variables = {"WEIGHTED_GAP"},
      .active_set_criterion = mpc_criterion,
  });
  ContactFormulation::Register(D{
      .mortar_type = "MPCContactFrictional",
      .process = "mpc_contact_process",
      .contact_type = "Frictional",
      .enforcement = "MPC",
      .variables = {"WEIGHTED_GAP"},
      .active_set_criterion = mpc_criterion,
  });
  // Mesh tying by constraints (spec 4.7, contact_type "MeshTying"; the process sets the root flag RIGID):
  // every displacement component of the slave nodes tied, no active set.
  ContactFormulation::Register(D{
      .mortar_type = "MPCMeshTying",
      .process = "mpc_contact_process",
      .contact_type = "MeshTying",
      .enforcement = "MPC",
      .variables = {"WEIGHTED_GAP"},
      .active_set_criterion = mpc_criterion,
  });

  // As in Kratos, the condensing solver wraps the solver of linear_solver_settings and is chosen
  // by contact_settings.mixed_ulm_solver_parameters; as a linear solver of its own it has nothing
  // to wrap.
  RegisterLinearSolver("mixed_ulm_linear_solver", [](const Parameters& settings) -> std::unique_ptr<LinearSolver> {
    throw InputError(Concat(settings.Where(),
                            ".solver_type: 'mixed_ulm_linear_solver' is only valid in "
                            "contact_settings.mixed_ulm_solver_parameters"));
  });
}

}  // namespace

void RegisterContactFormulations() {
  static std::once_flag once;
  std::call_once(once, RegisterAll);
}

}  // namespace mc
