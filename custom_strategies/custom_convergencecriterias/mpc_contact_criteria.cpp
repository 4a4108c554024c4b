// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/mpc_contact_criteria.h"

#include <algorithm>
#include <cmath>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

double YoungModulus(const ModelPart& root) {
  for (const Element* element : root.Elements())
    if (element->HasProperties() && element->GetProperties().Has(YOUNG_MODULUS))
      return element->GetProperties().GetValue(YOUNG_MODULUS);
  return 0.0;
}

/// The tangential reaction without its fixed components: the support carries those (on a symmetry
/// plane the reaction includes the plane's force, which friction neither bears nor can relieve).
Array3 FreeTangential(const Node& node, Array3 tangential) {
  const Variable<double>* const displacements[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  for (int c = 0; c < 3; ++c)
    if (node.IsFixed(*displacements[c])) tangential[c] = 0.0;
  return tangential;
}

}  // namespace

MPCContactCriteria::MPCContactCriteria(std::shared_ptr<const MPCContactConstraints> constraints)
    : constraints_(std::move(constraints)) {
  if (!constraints_) throw Error("mpc_contact_criteria needs the MPC contact constraints");
}

bool MPCContactCriteria::PostCriteria(ModelPart& model_part, const DofsArray&, const SparseMatrix&, const Vector&,
                                      const Vector&) {
  ModelPart* contact = FindContactModelPart(model_part);
  if (!contact) throw Error(Concat("mpc_contact_criteria: no Contact model part above ", model_part.FullName()));
  const ModelPart& root = model_part.GetRootModelPart();
  const ProcessInfo& info = root.GetProcessInfo();
  const double factor =
      info.Has(REACTION_CHECK_STIFFNESS_FACTOR) ? info.GetValue(REACTION_CHECK_STIFFNESS_FACTOR) : 1.0e-12;
  young_modulus_ = YoungModulus(root);
  const double threshold = -factor * young_modulus_;
  changes_ = 0;
  turn_ = 0.0;
  const bool frictional = constraints_->IsFrictional();
  for (Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const double area = node->GetValue(NODAL_MAUX);
    const Array3 normal =
        frictional ? constraints_->RelationNormal(*node) : NormalCalculationUtilities::GetNodalNormal(*node);
    const Array3 reaction = node->FastGetSolutionStepValue(REACTION);
    const double force = reaction.dot(normal);
    const double pressure = area > 0.0 ? force / area : 0.0;
    const bool was_active = node->Is(ACTIVE);
    bool active = area > 0.0 && (was_active ? pressure < threshold : constraints_->NodalGap(*node) < 0.0);
    // A sticking node outside the cone slips before it may be released: its pull can be the drag of its
    // tangential tie (released, it would penetrate again and stick again: a cycle).
    if (frictional && was_active && !active && area > 0.0 && !node->Is(SLIP) &&
        (reaction - force * normal).norm() > node->GetValue(FRICTION_COEFFICIENT) * std::abs(force))
      active = true;
    if (active != was_active) ++changes_;
    node->Set(ACTIVE, active);
    node->SetValue(CONTACT_FORCE, active ? Array3(force * normal) : Array3(Array3::Zero()));
    node->SetValue(NORMAL_CONTACT_STRESS, active ? pressure : 0.0);
    if (frictional) UpdateSlip(*node, was_active, FreeTangential(*node, reaction - force * normal), force);
  }
  if (pure_slip_) StopPureSlipCycle(info);
  return changes_ == 0 && turn_ <= kTurnTolerance;
}

void MPCContactCriteria::InitializeSolutionStep(ModelPart&, const DofsArray&, const SparseMatrix&, const Vector&,
                                                const Vector&) {
  reversals_.clear();
}

void MPCContactCriteria::SaveState(Parameters& state) const {
  std::vector<std::pair<IndexType, Array3>> directions;
  for (const auto& [node, direction] : directions_) directions.emplace_back(node->Id(), direction);
  std::sort(directions.begin(), directions.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<IndexType, double>> stiffness;
  for (const auto& [node, k] : turn_stiffness_) stiffness.emplace_back(node->Id(), k);
  std::sort(stiffness.begin(), stiffness.end());
  nlohmann::json& json = state.Json();
  json["directions"] = nlohmann::json::array();
  for (const auto& [id, s] : directions) json["directions"].push_back({id, s[0], s[1], s[2]});
  json["turn_stiffness"] = nlohmann::json::array();
  for (const auto& [id, k] : stiffness) json["turn_stiffness"].push_back({id, k});
}

void MPCContactCriteria::LoadState(const Parameters& state, const ModelPart& model_part) {
  const auto node = [&](const Parameters& row) -> const Node* {
    const IndexType id = static_cast<IndexType>(row[0].GetInt());
    if (!model_part.HasNode(id))
      throw InputError(Concat(row.Where(), ": node ", id, " of the restart state is not in ", model_part.FullName()));
    return &model_part.GetNode(id);
  };
  directions_.clear();
  turn_stiffness_.clear();
  const Parameters directions = state["directions"];
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const Parameters row = directions[i];
    directions_[node(row)] = Array3(row[1].GetDouble(), row[2].GetDouble(), row[3].GetDouble());
  }
  const Parameters stiffness = state["turn_stiffness"];
  for (std::size_t i = 0; i < stiffness.size(); ++i) turn_stiffness_[node(stiffness[i])] = stiffness[i][1].GetDouble();
}

void MPCContactCriteria::StopPureSlipCycle(const ProcessInfo& info) const {
  std::vector<IndexType> cycling;
  for (const auto& [node, reversals] : reversals_)
    if (reversals >= kReversals && node->Is(ACTIVE)) cycling.push_back(node->Id());
  if (cycling.empty()) return;
  std::sort(cycling.begin(), cycling.end());
  std::string nodes;
  for (std::size_t i = 0; i < cycling.size() && i < 10; ++i) nodes += Concat(i ? ", " : "", cycling[i]);
  if (cycling.size() > 10) nodes += Concat(" and ", cycling.size() - 10, " more");
  throw SolutionError(Concat(
      Name(), ": contact_type \"FrictionalPureSlip\": the slip direction of slave node(s) ", nodes,
      " reversed in each of the last ", kReversals, " iterations (step ", info.GetValue(STEP), ", time ",
      info.GetValue(TIME), "). Pure slip makes every node in contact slip, but this interface must stick in part ",
      "(the load is too small to slide it, e.g. against the body's own Poisson slip) and then pure slip has no ",
      "solution; use contact_type \"Frictional\" (Coulomb: stick and slip) in mpc_contact_process and ",
      "solver_settings.mpc_contact_settings"));
}

void MPCContactCriteria::UpdateSlip(Node& node, bool was_active, const Array3& tangential, double normal_force) {
  const bool active = node.Is(ACTIVE);
  const bool was_slipping = node.Is(SLIP);
  const double length = tangential.norm();
  const double mu = node.GetValue(FRICTION_COEFFICIENT);
  const double size = std::sqrt(node.GetValue(NODAL_MAUX));
  bool slip = false;
  turn_stiffness_.erase(&node);
  if (active) {
    const Array3 step_slip = constraints_->TangentialSlip(node);
    const double slid = step_slip.norm();
    const auto held = directions_.find(&node);
    const bool held_slip = was_active && was_slipping && held != directions_.end();
    if (!was_active)
      // A node touching down within the step while it moves slips the way it moves: tied where the step
      // started, it would be dragged back the whole way (a force far outside the cone, and the node
      // released and caught again: a cycle).
      slip = slid > kMovingSlip * size;
    else if (held_slip)
      slip = pure_slip_ || held->second.dot(step_slip) > 0.0;
    else
      slip = length > (pure_slip_ ? 0.0 : mu * std::abs(normal_force));
    if ((held_slip || (!was_active && slip)) && slid > 0.0) {
      // s is the direction of the slip of the step (in 2D the same or reversed; in 3D it may turn), also
      // for a node that turned back and sticks: if the cycle guard holds it slipping, it slips that way.
      const Array3 direction = step_slip / slid;
      if (held_slip && slip) turn_ = std::max(turn_, (direction - held->second).norm());
      if (pure_slip_ && held_slip) {
        int& reversals = reversals_[&node];
        reversals = direction.dot(held->second) < 0.0 ? reversals + 1 : 0;
      }
      directions_[&node] = direction;
      if (slip) turn_stiffness_[&node] = held_slip ? mu * std::abs(normal_force) / slid : young_modulus_ * size;
    } else if (length > 0.0) {
      directions_[&node] = -tangential / length;
      // A node that starts slipping has no slip yet for s to turn with: for one iteration its sideways
      // motion gets the stiffness of its share of the surface (the matrix only: without it a body whose
      // nodes all start slipping could turn freely).
      if (slip) turn_stiffness_[&node] = young_modulus_ * size;
    }
  } else {
    directions_.erase(&node);
  }
  if (slip != was_slipping) ++changes_;
  node.Set(SLIP, slip);
  if (active) node.SetValue(CONTACT_FORCE, Array3(node.GetValue(CONTACT_FORCE) + tangential));
  node.SetValue(TANGENTIAL_CONTACT_STRESS,
                active && node.GetValue(NODAL_MAUX) > 0.0 ? length / node.GetValue(NODAL_MAUX) : 0.0);
}

std::vector<CriterionValue> MPCContactCriteria::LastValues() const {
  if (!constraints_->IsFrictional()) return {{"active set changes", static_cast<double>(changes_), 0.0}};
  return {{"contact state changes", static_cast<double>(changes_), 0.0},
          {"slip direction turn", turn_, kTurnTolerance}};
}

}  // namespace mc
