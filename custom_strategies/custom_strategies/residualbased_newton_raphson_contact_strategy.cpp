// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_contact_strategy.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

Parameters ResidualBasedNewtonRaphsonContactStrategy::GetDefaultParameters() {
  return Parameters(R"({
      "adaptative_strategy"   : false,
      "split_factor"          : 10.0,
      "max_number_splits"     : 3,
      "inner_loop_iterations" : 5
  })");
}

ContactStrategySettings ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(Parameters settings) {
  settings.AddMissingParameters(GetDefaultParameters());
  ContactStrategySettings s;
  s.adaptative_strategy = settings["adaptative_strategy"].GetBool();
  s.split_factor = settings["split_factor"].GetDouble();
  s.max_number_splits = settings["max_number_splits"].GetInt();
  s.inner_loop_iterations = settings["inner_loop_iterations"].GetInt();
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
      settings_(settings) {}

void ResidualBasedNewtonRaphsonContactStrategy::InitializeSolutionStep() {
  // The iterations of the failed attempt and of the sub-steps all belong to the step's history.
  std::vector<IterationRecord> earlier = in_sub_step_ ? std::move(history_) : std::vector<IterationRecord>{};
  NewtonRaphsonStrategy::InitializeSolutionStep();
  history_.insert(history_.begin(), std::make_move_iterator(earlier.begin()), std::make_move_iterator(earlier.end()));
  flips_.clear();
  failure_.clear();
  if (!in_sub_step_) {
    split_level_ = 0;
    if (settings_.adaptative_strategy) SaveStepStart();
  }
}

void ResidualBasedNewtonRaphsonContactStrategy::Predict() {
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

namespace {
constexpr char kActiveBit = 1;
constexpr char kSlipBit = 2;
}  // namespace

std::vector<char> ResidualBasedNewtonRaphsonContactStrategy::ContactStates() const {
  std::vector<char> states;
  if (ModelPart* contact = FindContactModelPart(model_part_))
    for (const Node* node : contact->Nodes())
      if (node->Is(SLAVE))
        states.push_back(static_cast<char>((node->Is(ACTIVE) ? kActiveBit : 0) | (node->Is(SLIP) ? kSlipBit : 0)));
  return states;
}

void ResidualBasedNewtonRaphsonContactStrategy::SetContactStates(const std::vector<char>& states) {
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return;
  std::size_t i = 0;
  for (Node* node : contact->Nodes())
    if (node->Is(SLAVE)) {
      node->Set(ACTIVE, (states[i] & kActiveBit) != 0);
      node->Set(SLIP, (states[i] & kSlipBit) != 0);
      ++i;
    }
}

std::size_t ResidualBasedNewtonRaphsonContactStrategy::CountFlips(const std::vector<char>& before) {
  std::size_t changes = 0;
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return 0;
  std::size_t i = 0;
  for (const Node* p_node : contact->Nodes()) {
    const Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    if (i < before.size() && ((before[i] & kActiveBit) != 0) != node.Is(ACTIVE)) {
      ++flips_[node.Id()];
      ++changes;
    }
    ++i;
  }
  return changes;
}

bool ResidualBasedNewtonRaphsonContactStrategy::NewtonIteration(int iteration) {
  const std::vector<char> before = ContactStates();
  const bool converged = NewtonRaphsonStrategy::NewtonIteration(iteration);
  last_changes_ = CountFlips(before);
  if (FindContactModelPart(model_part_)) {
    const std::vector<char> after = ContactStates();
    history_.back().active_nodes =
        static_cast<int>(std::count_if(after.begin(), after.end(), [](char s) { return (s & kActiveBit) != 0; }));
  }
  if (settings_.adaptative_strategy) inverted_element_ = FindInvertedElement();
  return converged && inverted_element_ == 0;
}

bool ResidualBasedNewtonRaphsonContactStrategy::RunNewtonLoop() {
  inverted_element_ = settings_.adaptative_strategy ? FindInvertedElement() : 0;
  if (inverted_element_ != 0) return false;
  for (int it = 1; it <= max_iteration_; ++it) {
    if (NewtonIteration(it)) return true;
    if (inverted_element_ != 0) return false;
  }
  return false;
}

bool ResidualBasedNewtonRaphsonContactStrategy::RunFullNewtonLoop() {
  inverted_element_ = settings_.adaptative_strategy ? FindInvertedElement() : 0;
  if (inverted_element_ != 0) return false;
  // Semi-smooth Newton can cycle: the set of one iteration makes the next iterate land in another
  // set, which brings it back (a stiff penalty closing a gap: all contact nodes switch on, the
  // linearised push-back overshoots by a fraction of the step, all switch off, and so on; Kratos
  // has no guard and stops at max_iteration). When the set returns to one of an earlier
  // iteration, the union of the sets in the cycle is frozen and Newton converges on it, as in the
  // simplified semi-smooth Newton; the set is then checked at the converged state and, if it
  // changes, frozen again. The set is the active set with, in frictional contact, the stick / slip
  // set; a set that did not change in the iteration is no cycle (Newton is still converging on it).
  std::vector<std::vector<char>> seen{ContactStates()};
  bool frozen = false;
  for (int it = 1; it <= max_iteration_; ++it) {
    const bool converged = NewtonIteration(it);
    if (inverted_element_ != 0) return false;
    if (converged && (!frozen || RecheckActiveSet())) return true;
    if (frozen) continue;
    std::vector<char> states = ContactStates();
    if (states == seen.back()) continue;
    const auto earlier = std::find(seen.begin(), seen.end() - 1, states);
    if (earlier == seen.end() - 1) {
      seen.push_back(std::move(states));
      continue;
    }
    for (auto cycle = earlier; cycle != seen.end(); ++cycle)
      for (std::size_t i = 0; i < states.size(); ++i) states[i] = static_cast<char>(states[i] | (*cycle)[i]);
    SetContactStates(states);
    frozen = true;
    model_part_.Set(INTERACTION, false);
    if (echo_level_ >= 1)
      Logger::Info(Concat(Name(), ": the active set of iteration ", it, " is that of iteration ",
                          earlier - seen.begin(), "; the union of the sets of the cycle (",
                          std::count_if(states.begin(), states.end(), [](char s) { return (s & kActiveBit) != 0; }),
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
  const bool converged = criteria_->PostCriteria(model_part_, builder_->GetDofSet(), builder_->SystemMatrix(),
                                                 builder_->Increment(), builder_->Residual());
  criteria_->SetEchoLevel(echo);
  last_changes_ = CountFlips(before);
  return converged;
}

bool ResidualBasedNewtonRaphsonContactStrategy::SolveWithActiveSet() {
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

bool ResidualBasedNewtonRaphsonContactStrategy::TrySolveWithActiveSet() {
  solver_error_.clear();
  if (!settings_.adaptative_strategy) return SolveWithActiveSet();
  // A diverging iterate can make the system singular: with splitting on, that is one more
  // reason to split, not the end of the analysis.
  try {
    return SolveWithActiveSet();
  } catch (const SolutionError& e) {
    solver_error_ = e.what();
    return false;
  }
}

bool ResidualBasedNewtonRaphsonContactStrategy::SolveSolutionStep() {
  bool converged = TrySolveWithActiveSet();
  if (!converged && settings_.adaptative_strategy && !in_sub_step_) converged = AdaptiveStep();
  failure_ = converged ? std::string() : DescribeFailure();
  if (!converged) Logger::Warning(failure_);
  return converged;
}

bool ResidualBasedNewtonRaphsonContactStrategy::AdaptiveStep() {
  ModelPart& root = model_part_.GetRootModelPart();
  ProcessInfo& info = root.GetProcessInfo();
  const double end_time = start_time_;
  const double delta_time = start_delta_time_;
  const double begin_time = end_time - delta_time;
  std::string last_failure = DescribeFailure();
  if (!callbacks_.initialize_solution_step && echo_level_ >= 1)
    Logger::Warning(Concat(Name(),
                           ": no process callbacks were given; boundary conditions and loads are not "
                           "updated in the sub-steps of the adaptive splitting"));
  in_sub_step_ = true;
  for (int level = 1; level <= settings_.max_number_splits; ++level) {
    const double sub_dt = delta_time / std::pow(settings_.split_factor, level);
    if (echo_level_ >= 1)
      Logger::Info(Concat(Name(), ": step ", start_step_, " did not converge (", last_failure,
                          "); splitting it into sub-steps of ", sub_dt));
    RestoreStepStart();
    bool ok = true;
    double time = begin_time;
    const double tiny = 1e-9 * sub_dt;
    while (ok && time < end_time - tiny) {
      time = std::min(time + sub_dt, end_time);
      if (end_time - time < tiny) time = end_time;
      const bool last = time == end_time;
      root.CloneTimeStep(time);
      if (callbacks_.initialize_solution_step) callbacks_.initialize_solution_step();
      InitializeSolutionStep();
      Predict();
      ok = TrySolveWithActiveSet();
      if (ok && !last) {
        FinalizeSolutionStep();
        if (callbacks_.finalize_solution_step) callbacks_.finalize_solution_step();
      }
      if (!ok) last_failure = DescribeFailure();
    }
    if (ok) {
      in_sub_step_ = false;
      split_level_ = level;
      info.SetValue(STEP, start_step_);
      info.SetValue(DELTA_TIME, delta_time);
      return true;
    }
  }
  in_sub_step_ = false;
  info.SetValue(STEP, start_step_);
  info.SetValue(DELTA_TIME, delta_time);
  throw SolutionError(Concat(last_failure, "; the adaptive strategy split the step ", settings_.max_number_splits,
                             " times (smallest sub-step ",
                             delta_time / std::pow(settings_.split_factor, settings_.max_number_splits),
                             ") without convergence"));
}

void ResidualBasedNewtonRaphsonContactStrategy::SaveStepStart() {
  ModelPart& root = model_part_.GetRootModelPart();
  const ProcessInfo& info = root.GetProcessInfo();
  start_time_ = info.GetValue(TIME);
  start_delta_time_ = info.GetValue(DELTA_TIME);
  start_step_ = info.GetValue(STEP);
  start_.clear();
  start_.reserve(root.NumberOfNodes());
  for (Node* p_node : root.Nodes()) {
    Node& node = *p_node;
    const std::size_t size = node.SolutionStepVariables().Stride() * static_cast<std::size_t>(node.BufferSize());
    start_.push_back({&node, std::vector<double>(node.StepData(0), node.StepData(0) + size), node.Is(ACTIVE)});
  }
}

void ResidualBasedNewtonRaphsonContactStrategy::RestoreStepStart() {
  // The step started after the analysis cloned the time step (step 0 = copy of the converged
  // state, step k = converged state k-1 steps ago); going back one step shifts the history
  // forward, so that the sub-steps' CloneTimeStep rebuilds the same buffer.
  for (NodeStart& start : start_) {
    Node& node = *start.node;
    const std::size_t stride = node.SolutionStepVariables().Stride();
    const int buffer = node.BufferSize();
    for (int k = 0; k < buffer; ++k) {
      const int source = std::min(k + 1, buffer - 1);
      std::copy_n(start.history.begin() + static_cast<std::ptrdiff_t>(source * stride), stride, node.StepData(k));
    }
    node.Set(ACTIVE, start.active);
  }
  ProcessInfo& info = model_part_.GetRootModelPart().GetProcessInfo();
  info.SetValue(TIME, start_time_ - start_delta_time_);
  info.SetValue(STEP, start_step_ - 1);
  if (move_mesh_) MoveMesh();
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
