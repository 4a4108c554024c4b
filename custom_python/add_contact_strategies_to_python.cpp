// SPDX-License-Identifier: BSD-3-Clause
// Bindings of custom_strategies: the contact convergence criteria, the contact mortar updater
// and the contact strategies. Python names are the Kratos class names.
#include <array>

#include "core/model/model_part.h"
#include "core/solving/builder_and_solver.h"
#include "core/solving/scheme.h"
#include "custom_python/python_module.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_components_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"
#include "custom_strategies/custom_convergencecriterias/mesh_tying_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictional_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/penalty_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_strategies/contact_mortar_updater.h"
#include "custom_strategies/custom_strategies/explicit_penalty_contact_strategy.h"
#include "custom_strategies/custom_strategies/line_search_contact_strategy.h"
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_contact_strategy.h"
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_mpc_contact_strategy.h"

namespace mc::python {

namespace {

template <class Criteria>
void BindBlockCriteria(py::module_& m, const char* name, const char* doc) {
  py::class_<Criteria, BlockContactCriteria, std::shared_ptr<Criteria>>(m, name, doc)
      .def(py::init<Parameters>(), py::arg("settings") = Parameters(),
           "Validates settings against its defaults (unknown keys rejected with the nearest valid one).")
      .def(py::init<const Parameters&, const Parameters&, bool>(), py::arg("solver_settings"),
           py::arg("contact_settings"), py::arg("pure_slip") = false,
           "The criterion of a contact solver: displacement tolerances from solver_settings, the rest from "
           "contact_settings; pure_slip (frictional criteria): every tangential multiplier counts as slip.")
      .def_static("GetDefaultParameters", &Criteria::GetDefaultParameters, "Kratos' keys and defaults.");
}

template <class Criteria>
void BindMortarCriteria(py::module_& m, const char* name, const char* doc) {
  py::class_<Criteria, BaseMortarConvergenceCriteria, std::shared_ptr<Criteria>>(m, name, doc)
      .def(py::init<Parameters>(), py::arg("settings") = Parameters(),
           "Reads its keys of contact_settings (missing ones get their defaults).");
}

template <class Criteria>
void BindFrictionalMortarCriteria(py::module_& m, const char* name, const char* doc) {
  py::class_<Criteria, BaseMortarConvergenceCriteria, std::shared_ptr<Criteria>>(m, name, doc)
      .def(py::init<Parameters, bool>(), py::arg("settings") = Parameters(), py::arg("pure_slip") = false,
           "Reads its keys of contact_settings (missing ones get their defaults); pure_slip: every active node "
           "slips (the PureSlip formulations).")
      .def("PureSlip", &Criteria::PureSlip, "Whether every active node is kept slipping.");
}

}  // namespace

void AddContactStrategiesToPython(py::module_& m) {
  py::class_<ContactMortarUpdater, MortarUpdater, std::shared_ptr<ContactMortarUpdater>>(
      m, "ContactMortarUpdater",
      "The MortarUpdater of the ALM and penalty contact processes: normals of the Contact interface and weighted gap "
      "(and NODAL_AREA) of the ComputingContact pair conditions.")
      .def(py::init<>(), "An updater with zeroed timings.")
      .def(
          "GetTimings",
          [](const ContactMortarUpdater& self) {
            const auto& t = self.GetTimings();
            py::dict timings;
            timings["weighted_gap"] = t.weighted_gap;
            timings["normals"] = t.normals;
            timings["weighted_gap_calls"] = t.weighted_gap_calls;
            timings["normals_calls"] = t.normals_calls;
            return timings;
          },
          "Cumulative wall-clock seconds and calls of ComputeWeightedGap and UpdateNormals.");

  py::class_<BlockContactCriteria, ConvergenceCriteria, std::shared_ptr<BlockContactCriteria>>(
      m, "BlockContactCriteria", "Contact criteria measuring displacements, rotations and multipliers separately.")
      .def("EnsureContact", &BlockContactCriteria::EnsureContact,
           "ensure_contact: whether all-zero multipliers (no contact) are an error rather than converged.")
      .def(
          "Tolerances",
          [](const BlockContactCriteria& c) {
            static constexpr std::array<const char*, kDofFamilies> kNames = {"displacement", "rotation", "multiplier",
                                                                             "stick", "slip"};
            py::dict tolerances;
            for (std::size_t f = 0; f < kDofFamilies; ++f)
              if (const auto& block = c.Configuration(static_cast<DofFamily>(f)))
                tolerances[kNames[f]] = py::make_tuple(
                    block->measure == BlockContactCriteria::Measure::kIncrement ? "increment" : "residual",
                    block->relative_tolerance, block->absolute_tolerance);
            return tolerances;
          },
          "{family: (measure, relative tolerance, absolute tolerance)} of the families the criterion measures "
          "(frictional criteria: multiplier is the normal block, stick and slip the tangential ones).")
      .def("PureSlip", &BlockContactCriteria::PureSlip,
           "Frictional criteria: whether every tangential multiplier counts as slip.")
      .def("RatioNormalTangentThreshold", &BlockContactCriteria::RatioNormalTangentThreshold,
           "Frictional criteria: tangential blocks below this fraction of the normal one are accepted (0 otherwise).")
      .def_static("Create", &BlockContactCriteria::Create, py::arg("settings"),
                  "The criterion named by settings['name'] (Kratos' names; the residual frictional one in both "
                  "spellings), validated against its defaults.")
      .def_static("GetContactSettingsDefaults", &BlockContactCriteria::GetContactSettingsDefaults,
                  "The keys of contact_settings the block criteria read (ensure_contact, rotation and multiplier "
                  "tolerances) with Kratos' defaults.");
  BindBlockCriteria<DisplacementContactCriteria>(
      m, "DisplacementContactCriteria", "displacement_contact_criteria: displacement (and rotation) increments");
  BindBlockCriteria<DisplacementResidualContactCriteria>(
      m, "DisplacementResidualContactCriteria", "displacement_residual_contact_criteria: displacement residuals");
  BindBlockCriteria<DisplacementLagrangeMultiplierContactCriteria>(
      m, "DisplacementLagrangeMultiplierContactCriteria",
      "displacement_lagrangemultiplier_contact_criteria: displacement and multiplier increments");
  BindBlockCriteria<DisplacementLagrangeMultiplierResidualContactCriteria>(
      m, "DisplacementLagrangeMultiplierResidualContactCriteria",
      "displacement_lagrangemultiplier_residual_contact_criteria: displacement and multiplier residuals");
  BindBlockCriteria<DisplacementLagrangeMultiplierMixedContactCriteria>(
      m, "DisplacementLagrangeMultiplierMixedContactCriteria",
      "displacement_lagrange_multiplier_mixed_contact_criteria: displacement residual, multiplier increment");
  BindBlockCriteria<DisplacementLagrangeMultiplierFrictionalContactCriteria>(
      m, "DisplacementLagrangeMultiplierFrictionalContactCriteria",
      "displacement_lagrangemultiplier_frictional_contact_criteria: displacement increment; multiplier increment "
      "split into normal, stick-tangent and slip-tangent blocks");
  BindBlockCriteria<DisplacementLagrangeMultiplierResidualFrictionalContactCriteria>(
      m, "DisplacementLagrangeMultiplierResidualFrictionalContactCriteria",
      "displacement_lagrangemultiplier_ressidual_frictional_contact_criteria (sic): residuals, the multiplier split "
      "into normal, stick-tangent and slip-tangent blocks");
  BindBlockCriteria<DisplacementLagrangeMultiplierMixedFrictionalContactCriteria>(
      m, "DisplacementLagrangeMultiplierMixedFrictionalContactCriteria",
      "displacement_lagrangemultiplier_mixed_frictional_contact_criteria: displacement residual; multiplier "
      "increments in normal, stick-tangent and slip-tangent blocks");

  py::class_<BaseMortarConvergenceCriteria, ConvergenceCriteria, std::shared_ptr<BaseMortarConvergenceCriteria>>(
      m, "BaseMortarConvergenceCriteria", "base_mortar_criteria: mortar quantities refresh, no active set.")
      .def(py::init<Parameters>(), py::arg("settings") = Parameters(),
           "Reads its keys of contact_settings (missing ones get their defaults).")
      .def("SetMortarUpdater", &BaseMortarConvergenceCriteria::SetMortarUpdater, py::arg("updater"),
           "The MortarUpdater refreshing normals, weighted gap, dynamic factor and penalty.")
      .def("LastChangedNodes", &BaseMortarConvergenceCriteria::LastChangedNodes,
           "Ids of the slave nodes that changed state (ACTIVE or SLIP) at the last evaluation of the active set.")
      .def("LastChangeCount", &BaseMortarConvergenceCriteria::LastChangeCount,
           "Slave nodes that switched ACTIVE at the last evaluation.")
      .def("LastSlipChangeCount", &BaseMortarConvergenceCriteria::LastSlipChangeCount,
           "Active nodes that switched between stick and slip at the last evaluation (0 without friction).")
      .def("HasSlipSet", &BaseMortarConvergenceCriteria::HasSlipSet,
           "Whether the criterion also updates a stick/slip set (frictional formulations).")
      .def_static("GetDefaultParameters", &BaseMortarConvergenceCriteria::GetDefaultParameters,
                  "Its keys of contact_settings with their defaults.");
  BindMortarCriteria<ALMFrictionlessMortarConvergenceCriteria>(
      m, "ALMFrictionlessMortarConvergenceCriteria",
      "alm_frictionless_mortar_criteria: a node is active when k lambda_n + eps g < 0 (thesis eqs. 4.41-4.44).");
  BindMortarCriteria<ALMFrictionlessComponentsMortarConvergenceCriteria>(
      m, "ALMFrictionlessComponentsMortarConvergenceCriteria",
      "alm_frictionless_components_mortar_criteria: a node is active when k n . lambda + eps g < 0.");
  BindMortarCriteria<PenaltyFrictionlessMortarConvergenceCriteria>(
      m, "PenaltyFrictionlessMortarConvergenceCriteria",
      "penalty_frictionless_mortar_criteria: a node is active when its weighted gap is negative.");
  BindFrictionalMortarCriteria<ALMFrictionalMortarConvergenceCriteria>(
      m, "ALMFrictionalMortarConvergenceCriteria",
      "alm_frictional_mortar_criteria: active set (k n . lambda + eps g < 0) and Coulomb stick/slip set (thesis eqs. "
      "4.75-4.77), converged when neither changed; ACTIVE_SET_CONVERGED and SLIP_SET_CONVERGED reported separately.");
  BindFrictionalMortarCriteria<PenaltyFrictionalMortarConvergenceCriteria>(
      m, "PenaltyFrictionalMortarConvergenceCriteria",
      "penalty_frictional_mortar_criteria: active set (negative weighted gap) and Coulomb stick/slip set, converged "
      "when the changes of both sum to zero.");
  py::class_<MeshTyingMortarConvergenceCriteria, ConvergenceCriteria,
             std::shared_ptr<MeshTyingMortarConvergenceCriteria>>(m, "MeshTyingMortarConvergenceCriteria",
                                                                  "mesh_tying_mortar_criteria: always converged")
      .def(py::init<>(), "Mesh tying has no active set.");

  py::class_<MortarAndConvergenceCriteria, AndCriteria, std::shared_ptr<MortarAndConvergenceCriteria>>(
      m, "MortarAndConvergenceCriteria",
      "mortar_and_criteria: mechanical AND mortar criterion, with the convergence table.")
      .def(py::init([](std::shared_ptr<ConvergenceCriteria> mechanical, std::shared_ptr<ConvergenceCriteria> mortar,
                       bool print_convergence_criterion, bool condition_number, bool print_table) {
             return std::make_shared<MortarAndConvergenceCriteria>(
                 std::move(mechanical), std::move(mortar), print_convergence_criterion,
                 condition_number ? std::optional<ConditionNumberUtility>(ConditionNumberUtility{}) : std::nullopt,
                 print_table);
           }),
           py::arg("mechanical"), py::arg("mortar"), py::arg("print_convergence_criterion") = false,
           py::arg("condition_number") = false, py::arg("print_table") = true,
           "print_convergence_criterion: list the slave nodes that changed; condition_number: "
           "condn_convergence_criterion (slow); print_table: fancy_convergence_criterion.")
      .def("SetMortarUpdater", &MortarAndConvergenceCriteria::SetMortarUpdater, py::arg("updater"),
           "Forwards the MortarUpdater to the mortar criterion.")
      .def("Mechanical", &MortarAndConvergenceCriteria::Mechanical, py::return_value_policy::reference_internal,
           "The mechanical criterion.")
      .def("Mortar", &MortarAndConvergenceCriteria::Mortar, py::return_value_policy::reference_internal,
           "The mortar (active-set) criterion.")
      .def("TableHeader", &MortarAndConvergenceCriteria::TableHeader,
           "Column titles of the convergence table for the current DoF set.")
      .def("LastTableRow", &MortarAndConvergenceCriteria::LastTableRow, "Cells of the last row of the table.");

  py::class_<ExplicitPenaltyContactStrategy, ExplicitStrategy, std::shared_ptr<ExplicitPenaltyContactStrategy>>(
      m, "ExplicitPenaltyContactStrategy",
      "Explicit central differences with penalty mortar contact, frictionless or Coulomb (the slip accumulated "
      "while sticking): normals, weighted gaps and the penalty active set updated before every residual.")
      .def(py::init([](ModelPart& part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                       std::shared_ptr<MortarUpdater> updater, bool compute_reactions, bool move_mesh, int echo_level,
                       bool pure_slip) {
             auto s = std::make_shared<ExplicitPenaltyContactStrategy>(part, std::move(scheme), std::move(updater),
                                                                       compute_reactions, move_mesh, pure_slip);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("mortar_updater"), py::arg("compute_reactions") = true,
           py::arg("move_mesh") = true, py::arg("echo_level") = 0, py::arg("pure_slip") = false, py::keep_alive<1, 2>(),
           "Kratos' solver_settings of the same names (move_mesh: move_mesh_flag); pure_slip: every active node "
           "slips (the PureSlip formulations).")
      .def("ContactStableTimeStep", &ExplicitPenaltyContactStrategy::ContactStableTimeStep,
           py::arg("element_time_step"),
           "Critical time step with the penalty springs of the slave nodes: 2 / sqrt(omega_e^2 + max_j eps_j A_j^2 "
           "(1/m_j + 1/m_master)).");

  using ContactNewton = ResidualBasedNewtonRaphsonContactStrategy;
  py::class_<ContactNewton, NewtonRaphsonStrategy, std::shared_ptr<ContactNewton>>(
      m, "ResidualBasedNewtonRaphsonContactStrategy",
      "newton_raphson_contact_strategy: semi-smooth Newton for mortar contact (thesis Algorithm 2; full when the "
      "model part Is(INTERACTION), simplified otherwise), contact predictor, adaptive step splitting.")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, Parameters settings, int max_iteration,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<ContactNewton>(part, std::move(scheme), std::move(criteria), std::move(builder),
                                                      ContactNewton::ReadSettings(settings), max_iteration,
                                                      compute_reactions, reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("settings") = Parameters(), py::arg("max_iteration") = 10, py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>(),
           "settings: contact_settings (adaptative_strategy, split_factor, max_number_splits, inner_loop_iterations); "
           "the others as NewtonRaphsonStrategy.")
      .def_static("GetDefaultParameters", &ContactNewton::GetDefaultParameters,
                  "Its keys of contact_settings with their defaults.")
      .def("SetMortarUpdater", &ContactNewton::SetMortarUpdater, py::arg("updater"),
           "The MortarUpdater of the contact predictor (weighted gap at the last converged coordinates).")
      .def("SetMaxIterationNumber", &ContactNewton::SetMaxIterationNumber, py::arg("max_iteration"),
           "Newton iterations allowed per step (per pass in simplified semi-smooth Newton).")
      .def("GetMaxIterationNumber", &ContactNewton::GetMaxIterationNumber, "Newton iterations allowed per step.")
      .def("ActiveSetFlipCounts", &ContactNewton::ActiveSetFlipCounts,
           "{slave node id: times it changed state} during the last step.")
      .def("InnerLoopIterations", &ContactNewton::InnerLoopIterations,
           "Active-set passes of the last step (1 in full semi-smooth Newton).");

  using LineSearchSplitStep = LineSearchContactStrategy::SplitStep;
  py::class_<LineSearchSplitStep>(m, "LineSearchSplitStep", "The two step lengths of one line-search iteration.")
      .def_readonly("iteration", &LineSearchSplitStep::iteration, "Newton iteration, from 1.")
      .def_readonly("displacement", &LineSearchSplitStep::displacement, "Step length of the displacement block.")
      .def_readonly("multiplier", &LineSearchSplitStep::multiplier, "Step length of the multiplier block.");
  py::class_<LineSearchContactStrategy, ContactNewton, std::shared_ptr<LineSearchContactStrategy>>(
      m, "LineSearchContactStrategy",
      "line_search_contact_strategy: contact Newton with separate line-search step lengths for the "
      "displacement and the multiplier blocks.")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, Parameters settings, int max_iteration,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, double min_step,
                       int echo_level) {
             auto s = std::make_shared<LineSearchContactStrategy>(
                 part, std::move(scheme), std::move(criteria), std::move(builder),
                 ContactNewton::ReadSettings(settings), max_iteration, compute_reactions, reform_dofs_at_each_step,
                 move_mesh, min_step);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("settings") = Parameters(), py::arg("max_iteration") = 10, py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true, py::arg("min_step") = 0.1,
           py::arg("echo_level") = 0, py::keep_alive<1, 2>(),
           "min_step: the smallest step length of a block; the others as ResidualBasedNewtonRaphsonContactStrategy.")
      .def("SplitSteps", &LineSearchContactStrategy::SplitSteps,
           "The LineSearchSplitStep of each iteration of the last step.");

  using MPCNewton = ResidualBasedNewtonRaphsonMPCContactStrategy;
  py::class_<MPCNewton, NewtonRaphsonStrategy, std::shared_ptr<MPCNewton>>(
      m, "ResidualBasedNewtonRaphsonMPCContactStrategy",
      "newton_raphson_mpc_contact_strategy: Newton with the contact imposed by master-slave constraints built "
      "from D^-1 M on the active slave nodes; the active set from the reactions (mpc_contact_criteria), after a "
      "predictor solve.")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, Parameters settings, int max_iteration,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<MPCNewton>(part, std::move(scheme), std::move(criteria), std::move(builder),
                                                  MPCNewton::ReadSettings(settings), max_iteration, compute_reactions,
                                                  reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("settings") = Parameters(), py::arg("max_iteration") = 10, py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = true, py::arg("move_mesh") = true, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>(),
           "settings: mpc_contact_settings (simplified_semi_smooth_newton, inner_loop_iterations, "
           "update_each_nl_iteration); criteria: the mechanical criterion; the others as NewtonRaphsonStrategy.")
      .def_static("GetDefaultParameters", &MPCNewton::GetDefaultParameters,
                  "Its keys of mpc_contact_settings with their defaults.")
      .def("InnerLoopIterations", &MPCNewton::InnerLoopIterations,
           "Active-set passes of the last step (1 without simplified_semi_smooth_newton).")
      .def("NumberOfActiveNodes", &MPCNewton::NumberOfActiveNodes, "ACTIVE slave nodes now.")
      .def("RestartState", &MPCNewton::RestartState,
           "What the next step takes from the steps before beyond the nodal state (slip directions, the tie's "
           "operators), as Parameters, for a restart checkpoint.")
      .def("LoadRestartState", &MPCNewton::LoadRestartState, py::arg("state"),
           "Takes back RestartState's Parameters in a resumed run (after Initialize).");
}

}  // namespace mc::python
