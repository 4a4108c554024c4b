// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_contact_strategy.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/model/model_part.h"
#include "core/solving/singular_system_error.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"
#include "custom_utilities/contact_state_cycle.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

namespace {
/// The node's CONVERGED_CONTACT_STATES, -1 where it has none (the history is unknown).
int ConvergedContactStates(const Node& node) {
  return node.Has(CONVERGED_CONTACT_STATES) ? node.GetValue(CONVERGED_CONTACT_STATES) : -1;
}

/// The mortar criterion of `criteria` (itself, or the second of a MortarAndConvergenceCriteria), or null.
BaseMortarConvergenceCriteria* FindMortarCriterion(ConvergenceCriteria* criteria) {
  if (auto* both = dynamic_cast<MortarAndConvergenceCriteria*>(criteria)) criteria = &both->Mortar();
  return dynamic_cast<BaseMortarConvergenceCriteria*>(criteria);
}

/// What an evaluation of the active set writes on the contact nodes (flags, multipliers on
/// activation, weighted gap and slip, nodal area, augmented pressures), kept to be put back.
class ContactNodeSnapshot {
 public:
  explicit ContactNodeSnapshot(ModelPart& contact)
      : vector_multiplier_(contact.HasNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER)),
        scalar_multiplier_(contact.HasNodalSolutionStepVariable(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)),
        gap_(contact.HasNodalSolutionStepVariable(WEIGHTED_GAP)),
        slip_(contact.HasNodalSolutionStepVariable(WEIGHTED_SLIP)) {
    for (Node* node : contact.Nodes()) {
      Entry e{node, node->Is(ACTIVE), node->Is(SLIP), node->Is(ISOLATED)};
      if (vector_multiplier_) e.multiplier = node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER);
      if (scalar_multiplier_) e.pressure = node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
      if (gap_) e.gap = node->FastGetSolutionStepValue(WEIGHTED_GAP);
      if (slip_) e.slip = node->FastGetSolutionStepValue(WEIGHTED_SLIP);
      if (node->Has(NODAL_AREA)) e.area = node->GetValue(NODAL_AREA);
      if (node->Has(AUGMENTED_NORMAL_CONTACT_PRESSURE))
        e.normal_pressure = node->GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE);
      if (node->Has(AUGMENTED_TANGENT_CONTACT_PRESSURE))
        e.tangent_pressure = node->GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE);
      entries_.push_back(e);
    }
  }

  void Restore() const {
    for (const Entry& e : entries_) {
      Node& node = *e.node;
      node.Set(ACTIVE, e.active);
      node.Set(SLIP, e.slipping);
      node.Set(ISOLATED, e.isolated);
      if (vector_multiplier_) node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = e.multiplier;
      if (scalar_multiplier_) node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = e.pressure;
      if (gap_) node.FastGetSolutionStepValue(WEIGHTED_GAP) = e.gap;
      if (slip_) node.FastGetSolutionStepValue(WEIGHTED_SLIP) = e.slip;
      if (e.area) node.SetValue(NODAL_AREA, *e.area);
      if (e.normal_pressure) node.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, *e.normal_pressure);
      if (e.tangent_pressure) node.SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, *e.tangent_pressure);
    }
  }

 private:
  struct Entry {
    Node* node;
    bool active, slipping, isolated;
    Array3 multiplier = Array3::Zero();
    double pressure = 0.0;
    double gap = 0.0;
    Array3 slip = Array3::Zero();
    std::optional<double> area, normal_pressure;
    std::optional<Array3> tangent_pressure;
  };
  bool vector_multiplier_, scalar_multiplier_, gap_, slip_;
  std::vector<Entry> entries_;
};

/// Armijo's sufficient decrease: |F(x + s dx)| <= (1 - kArmijo s) |F(x)|.
constexpr double kArmijo = 1e-4;
}  // namespace

Parameters ResidualBasedNewtonRaphsonContactStrategy::GetDefaultParameters() {
  return Parameters(R"({
      "adaptative_strategy"   : false,
      "split_factor"          : 10.0,
      "max_number_splits"     : 3,
      "inner_loop_iterations" : 5,
      "active_set_line_search" : false
  })");
}

ContactStrategySettings ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(Parameters settings) {
  settings.AddMissingParameters(GetDefaultParameters());
  ContactStrategySettings s;
  s.adaptative_strategy = settings["adaptative_strategy"].GetBool();
  s.split_factor = settings["split_factor"].GetDouble();
  s.max_number_splits = settings["max_number_splits"].GetInt();
  s.inner_loop_iterations = settings["inner_loop_iterations"].GetInt();
  s.active_set_line_search = settings["active_set_line_search"].GetBool();
  if (!(s.split_factor > 1.0))
    throw InputError(Concat(settings["split_factor"].Where(), ": ", s.split_factor, " must be greater than 1"));
  if (s.max_number_splits < 1)
    throw InputError(Concat(settings["max_number_splits"].Where(), ": ", s.max_number_splits, " must be at least 1"));
  if (s.inner_loop_iterations < 1)
    throw InputError(
        Concat(settings["inner_loop_iterations"].Where(), ": ", s.inner_loop_iterations, " must be at least 1"));
  return s;
}

ResidualBasedNewtonRaphsonContactStrategy::ResidualBasedNewtonRaphsonContactStrategy(
    ModelPart& model_part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
    std::shared_ptr<BuilderAndSolver> builder_and_solver, ContactStrategySettings settings, int max_iteration,
    bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh_flag)
    : NewtonRaphsonStrategy(model_part, std::move(scheme), std::move(criteria), std::move(builder_and_solver),
                            max_iteration, compute_reactions, reform_dofs_at_each_step, move_mesh_flag),
      settings_(settings) {
  if (settings_.adaptative_strategy) SetStepSplitting({settings_.max_number_splits, settings_.split_factor});
}

void ResidualBasedNewtonRaphsonContactStrategy::InitializeSolutionStep() {
  NewtonRaphsonStrategy::InitializeSolutionStep();
  flips_.clear();
}

void ResidualBasedNewtonRaphsonContactStrategy::Predict() {
  // The scheme's predictor first, as Kratos 10.4 does: it makes the velocities and accelerations
  // of a dynamic scheme consistent with the first guess. Without it they kept the last step's
  // values, and a body in free flight (no load, an initial velocity) had a zero residual at the
  // first iteration and stood still.
  // An extrapolation of the last step is sound only where the path was smooth in it. Across a
  // change of contact state it carries the kink on: a gap that closed in the last step is
  // extrapolated as a free approach, i.e. a penetration (measured: one or two more iterations in
  // the step after contact onset, benchmarks/hertz/results_predictor.md).
  if (!scheme_->Extrapolates() || LastStepKeptContactStates()) scheme_->Predict(model_part_, builder_->GetDofSet());
  // The active set stays the search's prediction at the last converged coordinates, also after
  // an extrapolation: the NCP evaluated at the extrapolated state (or its union with the
  // search's set) took as many or more iterations on the Hertz cases and made a penalty case
  // diverge (benchmarks/hertz/results_predictor.md).
  ModelPart* contact = FindContactModelPart(model_part_);
  if (contact && contact->HasNodalSolutionStepVariable(WEIGHTED_GAP)) {
    const bool slip = model_part_.Is(SLIP) && contact->HasNodalSolutionStepVariable(WEIGHTED_SLIP);
    for (Node* p_node : contact->Nodes()) {
      Node& node = *p_node;
      node.FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
      if (slip) node.FastGetSolutionStepValue(WEIGHTED_SLIP).setZero();
    }
    if (updater_) updater_->ComputeWeightedGap(model_part_);
  }
  if (move_mesh_) MoveMesh();
}

void ResidualBasedNewtonRaphsonContactStrategy::FinalizeSolutionStep() {
  NewtonRaphsonStrategy::FinalizeSolutionStep();
  if (!scheme_->Extrapolates()) return;  // only the extrapolating predictor reads them
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return;
  for (Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    // Before the first step every node is open, and so it is taken where the history is unknown.
    const int last = std::max(ConvergedContactStates(*node), 0) & 3;
    node->SetValue(CONVERGED_CONTACT_STATES, (last << 2) | ContactState(*node));
  }
}

bool ResidualBasedNewtonRaphsonContactStrategy::LastStepKeptContactStates() const {
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return true;
  for (const Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const int states = ConvergedContactStates(*node);
    if (states < 0 || (states & 3) != (states >> 2)) return false;
  }
  return true;
}

std::vector<char> ResidualBasedNewtonRaphsonContactStrategy::ContactStates() const {
  ModelPart* contact = FindContactModelPart(model_part_);
  return contact ? mc::ContactStates(*contact) : std::vector<char>{};
}

void ResidualBasedNewtonRaphsonContactStrategy::SetContactStates(const std::vector<char>& states) {
  if (ModelPart* contact = FindContactModelPart(model_part_)) mc::SetContactStates(*contact, states);
}

std::size_t ResidualBasedNewtonRaphsonContactStrategy::CountFlips(const std::vector<char>& before) {
  std::size_t changes = 0;
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return 0;
  std::size_t i = 0;
  for (const Node* p_node : contact->Nodes()) {
    const Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    if (i < before.size() && ((before[i] & kActiveState) != 0) != node.Is(ACTIVE)) {
      ++flips_[node.Id()];
      ++changes;
    }
    ++i;
  }
  return changes;
}

bool ResidualBasedNewtonRaphsonContactStrategy::NewtonIteration(int iteration) {
  const std::vector<char> before = ContactStates();
  bool converged = false;
  try {
    converged = NewtonRaphsonStrategy::NewtonIteration(iteration);
  } catch (const SingularSystemError& e) {
    ExplainLostOverlap(e, iteration);
    throw;
  }
  last_changes_ = CountFlips(before);
  if (FindContactModelPart(model_part_)) history_.back().active_nodes = CountActive(ContactStates());
  if (splitting_.Enabled()) inverted_element_ = FindInvertedElement();
  return converged && inverted_element_ == 0;
}

void ResidualBasedNewtonRaphsonContactStrategy::ExplainLostOverlap(const SingularSystemError& error,
                                                                   int iteration) const {
  // An active slave node is active from the overlaps of the last mortar pass; the build after it
  // integrates the pairs under the nodal normals of the current iterate, where a large iterate can
  // have moved every face of the node off the master. Its multiplier then has no equation at all.
  // Said in those terms, the user learns what to change (the step), not which DoF to constrain.
  std::vector<IndexType> ids;
  for (const auto& [id, variable] : error.Dofs()) {
    const bool multiplier = variable.find("LAGRANGE_MULTIPLIER") != std::string::npos;
    if (!multiplier || !model_part_.HasNode(id)) return;
    const Node& node = model_part_.GetNode(id);
    if (!node.Is(SLAVE) || !node.Is(ACTIVE)) return;
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  if (ids.empty()) return;
  std::string nodes;
  for (std::size_t i = 0; i < ids.size(); ++i) nodes += Concat(i ? ", " : " ", ids[i]);
  const ProcessInfo& info = model_part_.GetProcessInfo();
  throw SingularSystemError(
      Concat(Name(), ": step ", info.GetValue(STEP), " (time ", info.GetValue(TIME), "), iteration ", iteration,
             ": the active slave node(s)", nodes,
             " lost every mortar overlap with the master under the current normals, so their contact "
             "multipliers have no equation (the last iterate moved their faces off the master surface). The "
             "load step is too large for the contact to follow: use a smaller time step, or let the solver "
             "split the step (contact_settings adaptative_strategy / max_number_splits)"),
      error.Dofs());
}

double ResidualBasedNewtonRaphsonContactStrategy::TrialMerit(BaseMortarConvergenceCriteria& mortar,
                                                             ModelPart& contact) {
  const ContactNodeSnapshot moved(contact);
  const ActiveSetUtilities::SetChanges changes = mortar.TrialActiveSet(model_part_);
  double changed = static_cast<double>(changes.active);
  if (const AssemblyCommunicator* ranks = builder_->PieceCommunicator()) ranks->SumToAll(&changed, 1);
  double merit = -1.0;
  if (changed > 0.0) {
    builder_->BuildRHS(*scheme_, model_part_);
    merit = builder_->Norm(builder_->Residual());
  }
  moved.Restore();
  return merit;
}

double ResidualBasedNewtonRaphsonContactStrategy::UpdateDatabase(int iteration) {
  BaseMortarConvergenceCriteria* mortar = FindMortarCriterion(criteria_.get());
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!settings_.active_set_line_search || !mortar || !contact || !model_part_.Is(INTERACTION))
    return NewtonRaphsonStrategy::UpdateDatabase(iteration);
  // Far from the solution a semi-smooth Newton increment can carry lightly pressed nodes across
  // the complementarity kink and back, the set never settling (the ironing drag, benchmarks/
  // robustness/README.md). The merit decides whether such an increment may decide the set.
  const Vector direction = builder_->Increment();
  const Vector residual = builder_->Residual();
  // Non-monotone: against the last iteration of this step too. The monotone test (|F| now alone)
  // cost contact-onset steps an iteration and failed a sweep case that converges with this one.
  double reference = builder_->Norm(residual);
  if (!history_.empty() && history_.back().time == model_part_.GetProcessInfo().GetValue(TIME))
    reference = std::max(reference, history_.back().residual_norm);
  double applied = 0.0;
  double best = 1.0;
  double best_merit = std::numeric_limits<double>::infinity();
  for (double s = 1.0;; s *= 0.5) {
    UpdateAndMoveMesh((s - applied) * direction);
    applied = s;
    const double merit = TrialMerit(*mortar, *contact);
    if (merit < 0.0 || merit <= (1.0 - kArmijo * s) * reference) {
      best = s;
      break;
    }
    if (merit < best_merit) {
      best_merit = merit;
      best = s;
    }
    if (s <= kMinStepLength) break;
  }
  if (best != applied) UpdateAndMoveMesh((best - applied) * direction);
  if (best != 1.0 && echo_level_ >= 1)
    Logger::Info(Concat(Name(), ": iteration ", iteration, ": increment damped to ", best,
                        " (it changed the active set and did not decrease the residual)"));
  builder_->Increment() = best * direction;
  builder_->Residual() = residual;
  return best;
}

bool ResidualBasedNewtonRaphsonContactStrategy::RunNewtonLoop() {
  inverted_element_ = splitting_.Enabled() ? FindInvertedElement() : 0;
  if (inverted_element_ != 0) return false;
  for (int it = 1; it <= max_iteration_; ++it) {
    if (NewtonIteration(it)) return true;
    if (inverted_element_ != 0) return false;
  }
  return false;
}

bool ResidualBasedNewtonRaphsonContactStrategy::RunFullNewtonLoop() {
  inverted_element_ = splitting_.Enabled() ? FindInvertedElement() : 0;
  if (inverted_element_ != 0) return false;
  // Semi-smooth Newton can cycle: the set of one iteration makes the next iterate land in another
  // set, which brings it back (a stiff penalty closing a gap: all contact nodes switch on, the
  // linearised push-back overshoots by a fraction of the step, all switch off, and so on; Kratos
  // has no guard and stops at max_iteration). When the set returns to one of an earlier
  // iteration, the union of the sets in the cycle is frozen and Newton converges on it, as in the
  // simplified semi-smooth Newton; the set is then checked at the converged state and, if it
  // changes, frozen again. A state is a node's contact and stick / slip flags: a node that slipped
  // in the cycle is frozen slipping, not as the stiff tangential spring of a stick node that
  // lost its SLIP flag while it was open (penalty slip patch: 14 iterations -> 7). A set that
  // does not change is no cycle.
  ContactStateCycle cycle(ContactStates());
  bool frozen = false;
  for (int it = 1; it <= max_iteration_; ++it) {
    const bool converged = NewtonIteration(it);
    if (inverted_element_ != 0) return false;
    if (converged && (!frozen || RecheckActiveSet())) return true;
    if (frozen) continue;
    std::vector<char> states = ContactStates();
    const int earlier = cycle.Close(states);
    if (earlier < 0) continue;
    SetContactStates(states);
    frozen = true;
    model_part_.Set(INTERACTION, false);
    if (echo_level_ >= 1)
      Logger::Info(Concat(Name(), ": the active set of iteration ", it, " is that of iteration ", earlier,
                          "; the union of the sets of the cycle (", CountActive(states),
                          " active slave nodes) is kept until Newton converges on it"));
  }
  return false;
}

bool ResidualBasedNewtonRaphsonContactStrategy::RecheckActiveSet() {
  // NL_ITERATION_NUMBER = 1 lets the mortar criterion update the set; the table row of this check
  // is not printed.
  model_part_.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
  const std::vector<char> before = ContactStates();
  const int echo = criteria_->GetEchoLevel();
  criteria_->SetEchoLevel(0);
  const bool converged = criteria_->PostCriteria(model_part_, builder_->OwnedDofs(), builder_->SystemMatrix(),
                                                 builder_->Increment(), builder_->Residual());
  criteria_->SetEchoLevel(echo);
  last_changes_ = CountFlips(before);
  return converged;
}

bool ResidualBasedNewtonRaphsonContactStrategy::SolveStepAttempt() {
  ProcessInfo& info = model_part_.GetProcessInfo();
  if (model_part_.Is(INTERACTION)) {
    passes_ = 1;
    info.SetValue(INNER_LOOP_ITERATION, 1);
    const bool converged = RunFullNewtonLoop();
    model_part_.Set(INTERACTION, true);
    return converged;
  }
  for (passes_ = 1; passes_ <= settings_.inner_loop_iterations; ++passes_) {
    info.SetValue(INNER_LOOP_ITERATION, passes_);
    if (!RunNewtonLoop()) return false;
    if (RecheckActiveSet()) return true;
  }
  passes_ = settings_.inner_loop_iterations;
  return false;
}

void ResidualBasedNewtonRaphsonContactStrategy::ReportNonConvergence() const { Logger::Warning(FailureReport()); }

void ResidualBasedNewtonRaphsonContactStrategy::SaveStepStart() {
  NewtonRaphsonStrategy::SaveStepStart();
  start_flags_.clear();
  for (Node* node : model_part_.GetRootModelPart().Nodes())
    start_flags_.push_back({node, node->Is(ACTIVE), node->Is(SLIP), ConvergedContactStates(*node)});
}

void ResidualBasedNewtonRaphsonContactStrategy::RestoreStepStart() {
  for (const auto& [node, active, slip, converged_states] : start_flags_) {
    node->Set(ACTIVE, active);
    node->Set(SLIP, slip);
    // The sub-steps of a failed split level must not count as the history of the next attempt.
    if (converged_states >= 0 || node->Has(CONVERGED_CONTACT_STATES))
      node->SetValue(CONVERGED_CONTACT_STATES, converged_states);
  }
  NewtonRaphsonStrategy::RestoreStepStart();
}

IndexType ResidualBasedNewtonRaphsonContactStrategy::FindInvertedElement() const {
  Matrix J;
  for (const Element* p_element : model_part_.Elements()) {
    const Element& element = *p_element;
    const Geometry& geometry = element.GetGeometry();
    const int dimension = geometry.LocalSpaceDimension();
    if (dimension != geometry.WorkingSpaceDimension() || geometry.PointsNumber() < 2) continue;
    for (const Matrix& dN : geometry.ShapeFunctionsLocalGradients(geometry.DefaultIntegrationOrder())) {
      geometry.Jacobian(dN, J);
      if (J.topLeftCorner(dimension, dimension).determinant() <= 0.0) return element.Id();
    }
  }
  return 0;
}

std::string ResidualBasedNewtonRaphsonContactStrategy::DescribeFailure() const {
  const ProcessInfo& info = model_part_.GetProcessInfo();
  std::string message = Concat(Name(), ": step ", info.GetValue(STEP), " (time ", info.GetValue(TIME), ")");
  if (!solver_error_.empty()) return Concat(message, ": ", solver_error_);
  if (inverted_element_ != 0)
    return Concat(message, ": element ", inverted_element_,
                  " is inverted (non-positive Jacobian determinant) after the update");
  const bool simplified = !model_part_.Is(INTERACTION);
  if (last_changes_ > 0) {
    // The nodes that switched more than once keep the set from settling; most frequent first.
    std::vector<std::pair<IndexType, int>> nodes;
    for (const auto& [id, count] : flips_)
      if (count > 1) nodes.emplace_back(id, count);
    if (nodes.empty()) nodes.assign(flips_.begin(), flips_.end());
    std::stable_sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::string list;
    const std::size_t shown = std::min<std::size_t>(nodes.size(), 10);
    for (std::size_t i = 0; i < shown; ++i)
      list += Concat(i ? ", " : "", nodes[i].first, " (", nodes[i].second, " changes)");
    if (nodes.size() > shown) list += Concat(" and ", nodes.size() - shown, " more");
    return Concat(message, ": the active set did not settle after ",
                  simplified ? Concat(passes_, " active-set passes") : Concat(max_iteration_, " iterations"),
                  "; slave nodes still switching between contact and separation: ", list,
                  ". A smaller time step, simplified_semi_smooth_newton or a different penalty may help");
  }
  std::string values;
  if (!history_.empty())
    for (const auto& v : history_.back().criteria)
      values += Concat(values.empty() ? "" : ", ", v.name, " = ", v.value, " (tol ", v.tolerance, ")");
  return Concat(message, ": not converged in ", max_iteration_, " iterations",
                values.empty() ? "" : Concat("; last values: ", values));
}

}  // namespace mc
