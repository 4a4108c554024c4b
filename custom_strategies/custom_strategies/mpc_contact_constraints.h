// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/solving/builder_and_solver.h"

namespace mc {

/// The contact constraints of the multipoint-constraint (MPC) route: one linear master-slave
/// constraint per active slave node j, tying its normal displacement to the mortar projection of the
/// master side and closing its gap,
///   n_j . u_j - sum_i P_ji n_j . u_i = g_j + n_j . u_j* - sum_i P_ji n_j . u_i*,   P = D^-1 M,
/// with D (diagonal: dual basis) and M summed over the MPCMortarContactCondition pairs of the slave
/// node, n_j its nodal normal, g_j = n_j . (sum_i P_ji x_i - x_j) its mortar gap and u* the
/// displacements, all at the configuration the relation is built at (Relate): after the solve the
/// linearised gap is zero. The constraint eliminates the free displacement component k of node j with
/// the largest |n_jk|; the other components of the node are masters with weight -n_l / n_k.
///
/// Kratos 10.4 ties the displacements without the gap (u_n slave = P u_n master): an initial gap
/// stays open and an initial penetration stays; its own older reference (mpc_contact_tests 3D, whose
/// interface starts 1e-5 inside) shows the gap closed, as here.
class MPCContactConstraints {
 public:
  /// The pairs are those of `computing_contact` (ComputingContact), the nodes of `contact` (Contact).
  MPCContactConstraints(ModelPart& contact, ModelPart& computing_contact);

  /// At the current configuration: the nodal normals of Contact, the summed D and M of every slave node,
  /// and the nodal values NODAL_MAUX (D_jj: the slave node's share of the overlap), NODAL_PAUX (the slave
  /// conditions of its pairs) and WEIGHTED_GAP (D_jj g_j; 0 for a node no pair reaches, which is
  /// ISOLATED).
  void Measure();
  /// The relation of every slave node an overlap reaches, from the last Measure, at the current
  /// displacements.
  void Relate();
  /// Hands the relations of the ACTIVE slave nodes to `builder` (replacing the earlier ones).
  void Apply(BuilderAndSolver& builder);

  /// Nodal gap g_j = WEIGHTED_GAP / NODAL_MAUX of the last Measure (0 for a node no pair reaches).
  double NodalGap(const Node& node) const;
  /// (slave node, its relation) of the last Relate.
  const std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>>& Relations() const noexcept {
    return relations_;
  }

 private:
  struct SlaveRow {
    double d = 0.0;
    std::unordered_map<Node*, double> m;  ///< master node -> M_ji
    int slave_conditions = 0;
  };

  ModelPart& contact_;
  ModelPart& computing_contact_;
  int dimension_ = 3;
  std::unordered_map<Node*, SlaveRow> rows_;
  std::unordered_map<const Node*, double> gaps_;
  std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> relations_;
  std::vector<const MasterSlaveConstraint*> applied_;  ///< what the builder holds (Apply)
};

}  // namespace mc
