// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"

#include <cmath>
#include <unordered_set>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

}  // namespace

MPCContactConstraints::MPCContactConstraints(ModelPart& contact, ModelPart& computing_contact)
    : contact_(contact), computing_contact_(computing_contact) {
  const ProcessInfo& info = contact.GetRootModelPart().GetProcessInfo();
  if (info.Has(DOMAIN_SIZE) && info.GetValue(DOMAIN_SIZE) == 2) dimension_ = 2;
}

void MPCContactConstraints::Measure() {
  NormalCalculationUtilities::ComputeNodalNormals(contact_);
  const ProcessInfo& info = contact_.GetRootModelPart().GetProcessInfo();
  rows_.clear();
  std::unordered_map<Node*, std::unordered_set<const Condition*>> slave_conditions;
  MPCPairOperators operators;
  for (Condition* condition : computing_contact_.Conditions()) {
    auto* pair = dynamic_cast<MPCMortarContactConditionBase*>(condition);
    if (!pair)
      throw Error(Concat("MPC contact: condition ", condition->Id(), " of ", computing_contact_.FullName(), " is a ",
                         condition->Info(), ", not an MPCMortarContactCondition"));
    if (!pair->IsActive() || !pair->ComputeOperators(operators, info)) continue;
    const Geometry& slave = pair->GetGeometry();
    const Geometry& master = pair->GetPairedGeometry();
    for (std::size_t j = 0; j < slave.PointsNumber(); ++j) {
      Node* node = &const_cast<Node&>(slave[j]);
      SlaveRow& row = rows_[node];
      row.d += operators.d(static_cast<Eigen::Index>(j));
      for (std::size_t l = 0; l < master.PointsNumber(); ++l)
        row.m[&const_cast<Node&>(master[l])] += operators.m(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(l));
      slave_conditions[node].insert(pair->GetParentSlaveCondition());
    }
  }
  gaps_.clear();
  for (Node* node : contact_.Nodes()) {
    node->SetValue(NODAL_MAUX, 0.0);
    node->SetValue(NODAL_PAUX, 0.0);
  }
  for (auto& [node, row] : rows_) {
    row.slave_conditions = static_cast<int>(slave_conditions[node].size());
    double gap = 0.0;
    if (row.d > 0.0) {
      const Array3 normal = NormalCalculationUtilities::GetNodalNormal(*node);
      Array3 projection = Array3::Zero();
      for (const auto& [master, weight] : row.m) projection += weight / row.d * master->Coordinates();
      gap = normal.dot(projection - node->Coordinates());
    }
    gaps_[node] = gap;
    node->SetValue(NODAL_MAUX, row.d);
    node->SetValue(NODAL_PAUX, static_cast<double>(row.slave_conditions));
    if (node->HasSolutionStepValue(WEIGHTED_GAP)) node->FastGetSolutionStepValue(WEIGHTED_GAP) = row.d * gap;
  }
}

double MPCContactConstraints::NodalGap(const Node& node) const {
  const auto it = gaps_.find(&node);
  return it == gaps_.end() ? 0.0 : it->second;
}

void MPCContactConstraints::Relate() {
  relations_.clear();
  for (auto& [node, row] : rows_) {
    if (!(row.d > 0.0)) continue;
    const Array3 normal = NormalCalculationUtilities::GetNodalNormal(*node);
    // The eliminated component: the free one most aligned with the normal (a fixed DoF cannot be a
    // slave). A node whose normal components are all fixed is held by its support: no relation.
    int k = -1;
    for (int c = 0; c < dimension_; ++c)
      if (!node->GetDof(*kDisplacement[c]).fixed && (k < 0 || std::abs(normal[c]) > std::abs(normal[k]))) k = c;
    if (k < 0 || std::abs(normal[k]) < 1e-3 * normal.head(dimension_).norm()) continue;
    const Array3 u = node->FastGetSolutionStepValue(DISPLACEMENT);
    double constant = gaps_.at(node) + normal.head(dimension_).dot(u.head(dimension_));
    std::vector<Dof*> masters;
    std::vector<double> weights;
    for (int c = 0; c < dimension_; ++c) {
      if (c == k || normal[c] == 0.0) continue;
      masters.push_back(&node->GetDof(*kDisplacement[c]));
      weights.push_back(-normal[c] / normal[k]);
    }
    for (const auto& [master, m] : row.m) {
      const double p = m / row.d;
      if (p == 0.0) continue;
      const Array3 u_master = master->FastGetSolutionStepValue(DISPLACEMENT);
      constant -= p * normal.head(dimension_).dot(u_master.head(dimension_));
      for (int c = 0; c < dimension_; ++c) {
        if (normal[c] == 0.0) continue;
        masters.push_back(&master->GetDof(*kDisplacement[c]));
        weights.push_back(p * normal[c] / normal[k]);
      }
    }
    relations_.emplace_back(
        node, std::make_shared<MasterSlaveConstraint>(node->Id(), node->GetDof(*kDisplacement[k]), std::move(masters),
                                                      std::move(weights), constant / normal[k]));
  }
}

void MPCContactConstraints::Apply(BuilderAndSolver& builder) {
  std::vector<const MasterSlaveConstraint*> active;
  for (const auto& [node, relation] : relations_)
    if (node->Is(ACTIVE)) active.push_back(relation.get());
  // Unchanged relations keep the builder's numbering and pattern.
  if (active == applied_) return;
  builder.ClearConstraints();
  for (const auto& [node, relation] : relations_)
    if (node->Is(ACTIVE)) builder.AddConstraint(relation);
  applied_ = std::move(active);
}

}  // namespace mc
