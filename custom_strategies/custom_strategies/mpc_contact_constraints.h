// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/parameters/parameters.h"
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
/// Frictional (SetFrictional, Coulomb), an ACTIVE slave node that sticks (not SLIP) is tied in every
/// free component instead, to the mortar projection of the master with no tangential relative motion
/// since the step's start u^n:
///   u_j - sum_i P_ji u_i = (I - n n^T)(u_j^n - sum_i P_ji u_i^n) + n (g_j + n . (u_j* - sum_i P_ji u_i*)),
/// one relation per component (their normal part is the normal relation above). A slipping node keeps
/// the normal relation, and its Coulomb force is a combination of its residual rows (CoulombTerms).
/// Kratos 10.4 ties a frictional node's components to D^-1 M without the gap (u_j = P u) whatever its
/// reaction: every active node sticks, and an initial gap stays open.
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
  /// Mesh tying (mpc_contact_process contact_type "MeshTying"), instead of Relate: one relation per free
  /// displacement component c of every slave node an overlap reaches, tying it to the same component of
  /// the mortar projection of the master, in total displacements,
  ///   u_jc = sum_i P_ji u_ic,
  /// with P measured at the configuration of the last Measure (the initial one when the strategy ties at
  /// the first step): the faces are glued as they were meshed, any gap or offset between them kept (as
  /// Kratos 10.4 does). A fixed component is held by its support and gets no relation.
  void RelateAllComponents();
  /// Mesh tying: the operators the relations of the last RelateAllComponents were built from, as
  /// [[slave id, D_jj, [[master id, M_ji], ...]], ...] in node id order (a restart checkpoint's part: the
  /// tie is between the material points of the configuration it was measured at).
  Parameters TyingOperators() const;
  /// Mesh tying, instead of Measure and RelateAllComponents: the relations of the operators TyingOperators
  /// wrote (nodes looked up by id in the root model part).
  void RelateAllComponents(const Parameters& operators);
  /// Hands the relations of the ACTIVE slave nodes (frictional: a sticking node's per-component ones) to
  /// `builder` (replacing the earlier ones), with the
  /// dependent ties resolved (see TiedRelations).
  void Apply(BuilderAndSolver& builder);
  /// The relations of the ACTIVE slave nodes as the builder can take them (one slave per DoF, no
  /// chains), in node id order:
  ///  - a relation's master DoF that is the slave of another active relation (a node on two
  ///    interfaces, slave of one and master of the other) is replaced by that relation's right-hand
  ///    side (u_a = w u_b + ..., u_b = T_b u + c_b -> u_a = w T_b u + w c_b + ...): the same ties;
  ///  - relations that tie each other in a cycle (both faces of an interface slave in two slots: the
  ///    node a tied to b and b tied to a state the same closed gap twice, and the two rows make the
  ///    system singular) lose the relation that closes the cycle, the later one in node order; its
  ///    slave DoF stays a master of the others, and a warning names the node. The remaining relation
  ///    still closes the gap (exactly on matching meshes, to the discretisation otherwise).
  /// A fixed component is never a relation's slave (Relate chooses a free one, and drops the node when
  /// only components along the tangent are free: the support holds the normal then). A slave DoF that is
  /// also the slave or a master of one of the model part's own constraints is an InputError naming the
  /// node, the component and the constraint.
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> TiedRelations() const;

  /// Frictional contact: sticking nodes tied in every component, see the class comment.
  void SetFrictional(bool frictional) noexcept { frictional_ = frictional; }
  bool IsFrictional() const noexcept { return frictional_; }
  /// The tangential slip of the step at a slave node of the last Measure, (I - n n^T) of the relative
  /// displacement since u^n, (u_j - u_j^n) - sum_i P_ji (u_i - u_i^n), n its relation's normal; zero
  /// for a node no pair reaches.
  Array3 TangentialSlip(const Node& node) const;
  /// The normal of a slave node's relations (of the last Relate; the current nodal normal for a node
  /// without one): the normal / tangential split of its reaction must be the relation's, not that of
  /// the deformed configuration a later Measure sees.
  Array3 RelationNormal(const Node& node) const;
  /// The Coulomb force of the ACTIVE, SLIP nodes with a normal relation, as a combination of residual
  /// rows for BuilderAndSolver::SetResidualCombination. At such a node j, with n its relation's normal,
  /// s its unit slip direction (`directions`, held within an iteration), mu its FRICTION_COEFFICIENT
  /// and f_n = n . R_j its normal force (R_j = f_int - f_ext of its rows, negative when pressed), the
  /// force on j is mu f_n s = -mu |f_n| s and on each master node i it is -P_ji mu f_n s: in rows,
  /// r_jc += -mu s_c n_d r_jd and r_ic += mu P_ji s_c n_d r_jd (r = f_ext - f_int). Linear in the rows,
  /// so the builder's matrix (I + C) K is its exact tangent (the normal, P and s held); f_n is taken
  /// as signed (no |.|): an active node is pressed, and one that pulls is released by the criterion.
  ///
  /// `turn_stiffness` (3D) holds k = mu |f_n| / |slip| for a node whose s is the direction of its slip
  /// of the step: s turns with the slip, and the force's derivative through it, -mu f_n (I - n n^T -
  /// s s^T) / |slip| d(slip), is the stiffness k Q on the relative tangential motion (u_j - P u), on the
  /// node and (times -P_ji) on its masters: without it a block whose nodes all slip could turn freely.
  struct CoulombSystem {
    std::vector<BuilderAndSolver::ResidualTerm> combination;
    std::vector<BuilderAndSolver::ResidualTerm> stiffness;
  };
  CoulombSystem CoulombTerms(const std::unordered_map<const Node*, Array3>& directions,
                             const std::unordered_map<const Node*, double>& turn_stiffness) const;

  /// Nodal gap g_j = WEIGHTED_GAP / NODAL_MAUX of the last Measure (0 for a node no pair reaches).
  double NodalGap(const Node& node) const;
  /// (slave node, its relation) of the last Relate (a node has one per component after
  /// RelateAllComponents).
  const std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>>& Relations() const noexcept {
    return relations_;
  }

 private:
  struct SlaveRow {
    double d = 0.0;
    std::unordered_map<Node*, double> m;  ///< master node -> M_ji
    int slave_conditions = 0;
  };

  /// value(j) - sum_i P_ji value(i) for a slave node j of `row` (P = M / D): a nodal quantity relative
  /// to the mortar projection of the master.
  template <class TValue>
  static Array3 Relative(const Node& node, const SlaveRow& row, TValue value);
  /// Forgets the relations of the last Relate / RelateAllComponents (and their normals and operators).
  void ClearRelations();
  /// The per-component relations of a sticking node (frictional).
  void RelateStick(Node* node, const SlaveRow& row, const Array3& normal, double gap);
  /// Appends to `out` one relation per free displacement component c of `node`,
  /// u_jc = sum_i P_ji u_ic + constant_c (a sticking node's tie and mesh tying's).
  void TieEveryComponent(Node* node, const SlaveRow& row, const Array3& constant,
                         std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>>& out) const;
  /// (slave node, relation) of the ACTIVE nodes: the normal relation, or a sticking node's per-component
  /// ones (frictional).
  std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> ActiveRelations() const;

  ModelPart& contact_;
  ModelPart& computing_contact_;
  int dimension_ = 3;
  std::unordered_map<Node*, SlaveRow> rows_;
  std::unordered_map<const Node*, double> gaps_;
  std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> relations_;
  std::unordered_map<const Node*, Array3> relation_normals_;
  std::unordered_map<const Node*, SlaveRow> related_rows_;  ///< frictional: the operators of the last Relate
  /// Frictional: the per-component relations of every related node, applied while it sticks.
  std::vector<std::pair<Node*, std::shared_ptr<MasterSlaveConstraint>>> stick_relations_;
  bool frictional_ = false;
  std::vector<const MasterSlaveConstraint*> applied_;  ///< what the builder holds (Apply)
};

}  // namespace mc
