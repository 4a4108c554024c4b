// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_set>

#include "core/utilities/error.h"
#include "core/utilities/logger.h"
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

template <class TValue>
Array3 MPCContactConstraints::Relative(const Node& node, const SlaveRow& row, TValue value) {
  Array3 relative = value(node);
  for (const auto& [master, m] : row.m) relative -= m / row.d * value(*master);
  return relative;
}

Array3 MPCContactConstraints::TangentialSlip(const Node& node) const {
  const auto it = rows_.find(const_cast<Node*>(&node));
  if (it == rows_.end() || !(it->second.d > 0.0)) return Array3::Zero();
  const Array3 relative = Relative(node, it->second, [](const Node& n) {
    return Array3(n.FastGetSolutionStepValue(DISPLACEMENT) - n.FastGetSolutionStepValue(DISPLACEMENT, 1));
  });
  const Array3 normal = RelationNormal(node);
  return relative - normal.dot(relative) * normal;
}

Array3 MPCContactConstraints::RelationNormal(const Node& node) const {
  const auto it = relation_normals_.find(&node);
  return it != relation_normals_.end() ? it->second : NormalCalculationUtilities::GetNodalNormal(node);
}

MPCContactConstraints::CoulombSystem MPCContactConstraints::CoulombTerms(
    const std::unordered_map<const Node*, Array3>& directions,
    const std::unordered_map<const Node*, double>& turn_stiffness) const {
  CoulombSystem system;
  for (const auto& [node, relation] : relations_) {
    const auto direction = directions.find(node);
    if (!node->Is(ACTIVE) || !node->Is(SLIP) || direction == directions.end()) continue;
    // The relation's operators, not a later Measure's: the force is transmitted as the tie is.
    const SlaveRow& row = related_rows_.at(node);
    const Array3 n = relation_normals_.at(node);
    const Array3 s = direction->second;
    const double mu = node->GetValue(FRICTION_COEFFICIENT);
    // The node (weight 1) and its masters (weight -P_ji): where the force and the relative motion act.
    std::vector<std::pair<Node*, double>> side{{node, 1.0}};
    for (const auto& [master, m] : row.m)
      if (m != 0.0) side.emplace_back(master, -m / row.d);
    for (int d = 0; d < dimension_; ++d) {
      if (n[d] == 0.0) continue;
      const Dof* from = &node->GetDof(*kDisplacement[d]);
      for (int c = 0; c < dimension_; ++c)
        if (s[c] != 0.0)
          for (const auto& [to, weight] : side)
            system.combination.push_back({&to->GetDof(*kDisplacement[c]), from, -mu * weight * s[c] * n[d]});
    }
    const auto turn = turn_stiffness.find(node);
    if (turn == turn_stiffness.end() || !(turn->second > 0.0)) continue;
    const Eigen::Matrix3d q = Eigen::Matrix3d::Identity() - n * n.transpose() - s * s.transpose();
    for (int c = 0; c < dimension_; ++c)
      for (int d = 0; d < dimension_; ++d) {
        if (std::abs(q(c, d)) < 1e-12) continue;  // 2D: s spans the tangent, nothing turns
        for (const auto& [row_node, row_weight] : side)
          for (const auto& [column_node, column_weight] : side)
            system.stiffness.push_back({&row_node->GetDof(*kDisplacement[c]), &column_node->GetDof(*kDisplacement[d]),
                                        turn->second * row_weight * column_weight * q(c, d)});
      }
  }
  return system;
}

void MPCContactConstraints::ClearRelations() {
  relations_.clear();
  relation_normals_.clear();
  related_rows_.clear();
  stick_relations_.clear();
}

void MPCContactConstraints::Relate() {
  ClearRelations();
  for (auto& [node, row] : rows_) {
    if (!(row.d > 0.0)) continue;
    const Array3 normal = NormalCalculationUtilities::GetNodalNormal(*node);
    // The eliminated component: the free one most aligned with the normal (a fixed DoF cannot be a
    // slave). A node whose normal components are all fixed is held by its support: no relation.
    int k = -1;
    for (int c = 0; c < dimension_; ++c)
      if (!node->GetDof(*kDisplacement[c]).fixed && (k < 0 || std::abs(normal[c]) > std::abs(normal[k]))) k = c;
    if (k < 0 || std::abs(normal[k]) < 1e-3 * normal.head(dimension_).norm()) continue;
    relation_normals_[node] = normal;
    if (frictional_) {
      related_rows_[node] = row;
      RelateStick(node, row, normal, gaps_.at(node));
    }
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

void MPCContactConstraints::RelateStick(Node* node, const SlaveRow& row, const Array3& normal, double gap) {
  // (u_j - P u) at the step's start (its tangential part kept) and now (its normal part closed by the gap).
  const Array3 start = Relative(*node, row, [](const Node& n) { return n.FastGetSolutionStepValue(DISPLACEMENT, 1); });
  const Array3 now = Relative(*node, row, [](const Node& n) { return n.FastGetSolutionStepValue(DISPLACEMENT); });
  const Array3 constant = start - normal.dot(start) * normal + (gap + normal.dot(now)) * normal;
  TieEveryComponent(node, row, constant, stick_relations_);
}

void MPCContactConstraints::TieEveryComponent(
    Node* node, const SlaveRow& row, const Array3& constant,
    std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>>& out) const {
  for (int c = 0; c < dimension_; ++c) {
    Dof& slave = node->GetDof(*kDisplacement[c]);
    if (slave.fixed) continue;  // the support holds this component
    std::vector<Dof*> masters;
    std::vector<double> weights;
    for (const auto& [master, m] : row.m) {
      if (m == 0.0) continue;
      masters.push_back(&master->GetDof(*kDisplacement[c]));
      weights.push_back(m / row.d);
    }
    out.emplace_back(node, std::make_shared<MasterSlaveConstraint>(node->Id(), slave, std::move(masters),
                                                                   std::move(weights), constant[c]));
  }
}

std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> MPCContactConstraints::ActiveRelations() const {
  std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> active;
  const auto sticks = [&](const Node* node) { return frictional_ && !node->Is(SLIP); };
  for (const auto& entry : relations_)
    if (entry.first->Is(ACTIVE) && !sticks(entry.first)) active.push_back(entry);
  for (const auto& entry : stick_relations_)
    if (entry.first->Is(ACTIVE) && sticks(entry.first)) active.push_back(entry);
  return active;
}

void MPCContactConstraints::RelateAllComponents() {
  ClearRelations();
  for (auto& [node, row] : rows_)
    if (row.d > 0.0) TieEveryComponent(node, row, Array3::Zero(), relations_);
}

Parameters MPCContactConstraints::TyingOperators() const {
  std::vector<const Node*> tied;
  for (const auto& [node, relation] : relations_)
    if (tied.empty() || tied.back() != node) tied.push_back(node);
  std::sort(tied.begin(), tied.end(), [](const Node* a, const Node* b) { return a->Id() < b->Id(); });
  tied.erase(std::unique(tied.begin(), tied.end()), tied.end());
  Parameters operators("[]");
  for (const Node* node : tied) {
    const SlaveRow& row = rows_.at(const_cast<Node*>(node));
    // In id order: the checkpoint does not depend on where the run put its nodes in memory.
    std::vector<std::pair<IndexType, double>> masters;
    for (const auto& [master, m] : row.m) masters.emplace_back(master->Id(), m);
    std::sort(masters.begin(), masters.end());
    nlohmann::json m = nlohmann::json::array();
    for (const auto& [id, value] : masters) m.push_back({id, value});
    operators.Json().push_back({node->Id(), row.d, m});
  }
  return operators;
}

void MPCContactConstraints::RelateAllComponents(const Parameters& operators) {
  const ModelPart& root = contact_.GetRootModelPart();
  const auto node = [&](const Parameters& id) {
    if (!root.HasNode(static_cast<IndexType>(id.GetInt())))
      throw InputError(Concat(id.Where(), ": node ", id.GetInt(), " of the restart state is not in ", root.Name()));
    return &root.GetNode(static_cast<IndexType>(id.GetInt()));
  };
  rows_.clear();
  for (std::size_t i = 0; i < operators.size(); ++i) {
    const Parameters row = operators[i];
    SlaveRow& restored = rows_[node(row[0])];
    restored.d = row[1].GetDouble();
    for (std::size_t l = 0; l < row[2].size(); ++l) restored.m[node(row[2][l][0])] = row[2][l][1].GetDouble();
  }
  RelateAllComponents();
}

void MPCContactConstraints::Apply(BuilderAndSolver& builder) {
  std::vector<const MasterSlaveConstraint*> active;
  for (const auto& [node, relation] : ActiveRelations()) active.push_back(relation.get());
  // Unchanged relations keep the builder's numbering and pattern.
  if (active == applied_) return;
  const auto tied = TiedRelations();
  builder.ClearConstraints();
  for (const auto& relation : tied) builder.AddConstraint(relation);
  applied_ = std::move(active);
}

std::vector<std::shared_ptr<const MasterSlaveConstraint>> MPCContactConstraints::TiedRelations() const {
  auto active = ActiveRelations();
  // Stable: a node's relations (one per component in mesh tying or while it sticks) keep their
  // component order.
  std::stable_sort(active.begin(), active.end(),
                   [](const auto& a, const auto& b) { return a.first->Id() < b.first->Id(); });
  const auto where = [&](std::size_t i) {
    return Concat("MPC contact: slave node ", active[i].first->Id(), ", ", active[i].second->Slave().variable->Name());
  };
  const ModelPart& root = contact_.GetRootModelPart();
  std::unordered_map<const Dof*, IndexType> model_slaves, model_masters;
  for (const auto& constraint : root.MasterSlaveConstraints()) {
    model_slaves.emplace(&constraint->Slave(), constraint->Id());
    for (const Dof* master : constraint->Masters()) model_masters.emplace(master, constraint->Id());
  }
  std::unordered_map<const Dof*, std::size_t> slave_index;
  for (std::size_t i = 0; i < active.size(); ++i) {
    const Dof* slave = &active[i].second->Slave();
    if (const auto it = model_slaves.find(slave); it != model_slaves.end())
      throw InputError(Concat(where(i), ": the contact ties it, and so does master-slave constraint ", it->second,
                              " of ", root.Name(), "; a DoF can be tied once (take the node out of that constraint or ",
                              "out of the contact interface)"));
    if (const auto it = model_masters.find(slave); it != model_masters.end())
      throw InputError(Concat(where(i), ": the contact ties it, and it is a master of master-slave constraint ",
                              it->second, " of ", root.Name(), " (chained constraints are not supported)"));
    slave_index.emplace(slave, i);
  }
  // i -> j: relation i has a master that is relation j's slave.
  std::vector<std::vector<std::size_t>> depends(active.size());
  for (std::size_t i = 0; i < active.size(); ++i)
    for (const Dof* master : active[i].second->Masters())
      if (const auto it = slave_index.find(master); it != slave_index.end()) depends[i].push_back(it->second);
  // Break the cycles: in each, the relation of the largest node id goes (on two faces slave of each
  // other, the face with the smaller ids keeps its ties).
  std::vector<char> dropped(active.size(), 0);
  for (;;) {
    std::vector<char> colour(active.size(), 0);
    std::vector<std::size_t> path, cycle;
    const std::function<bool(std::size_t)> visit = [&](std::size_t i) {
      colour[i] = 1;
      path.push_back(i);
      for (const std::size_t j : depends[i]) {
        if (dropped[j]) continue;
        if (colour[j] == 1) {
          cycle.assign(std::find(path.begin(), path.end(), j), path.end());
          return true;
        }
        if (colour[j] == 0 && visit(j)) return true;
      }
      colour[i] = 2;
      path.pop_back();
      return false;
    };
    bool found = false;
    for (std::size_t i = 0; i < active.size() && !found; ++i)
      if (!dropped[i] && colour[i] == 0) found = visit(i);
    if (!found) break;
    const std::size_t last = *std::max_element(cycle.begin(), cycle.end());
    dropped[last] = 1;
    std::string others;
    for (const std::size_t i : cycle)
      if (i != last) others += Concat(others.empty() ? "" : ", ", active[i].first->Id());
    Logger::Warning(Concat(where(last), ": its relation and those of node(s) ", others,
                           " tie each other (both faces of the interface are slave there): it is dropped, the others "
                           "close the gap"));
  }
  // Substitution along the (now acyclic) chains.
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> tied(active.size());
  const std::function<void(std::size_t)> substitute = [&](std::size_t i) {
    const MasterSlaveConstraint& relation = *active[i].second;
    std::vector<Dof*> masters;
    std::vector<double> weights;
    double constant = relation.Constant();
    bool substituted = false;
    for (std::size_t k = 0; k < relation.Masters().size(); ++k) {
      Dof* master = relation.Masters()[k];
      const double weight = relation.Weights()[k];
      const auto found = slave_index.find(master);
      if (found == slave_index.end() || dropped[found->second]) {
        masters.push_back(master);
        weights.push_back(weight);
        continue;
      }
      if (!tied[found->second]) substitute(found->second);
      const MasterSlaveConstraint& other = *tied[found->second];
      for (std::size_t l = 0; l < other.Masters().size(); ++l) {
        masters.push_back(other.Masters()[l]);
        weights.push_back(weight * other.Weights()[l]);
      }
      constant += weight * other.Constant();
      substituted = true;
    }
    tied[i] = substituted ? std::make_shared<const MasterSlaveConstraint>(
                                relation.Id(), relation.Slave(), std::move(masters), std::move(weights), constant)
                          : active[i].second;
  };
  for (std::size_t i = 0; i < active.size(); ++i)
    if (!dropped[i] && !tied[i]) substitute(i);
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> result;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (!dropped[i]) result.push_back(tied[i]);
  return result;
}

}  // namespace mc
