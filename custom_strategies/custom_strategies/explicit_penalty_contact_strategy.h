// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/solving/explicit_strategy.h"
#include "custom_utilities/mortar_updater.h"

namespace mc {

/// Explicit central differences with penalty mortar contact, frictionless or Coulomb
/// (`explicit_penalty_contact_process` + `time_integration_method` "explicit"). Before every
/// step's residual, at u_n: the nodal normals of `Contact`, the weighted gaps and NODAL_AREA of
/// the pairs of `ComputingContact` (the pairs themselves come from the process's search, every
/// `database_step_update` steps), and the penalty active set (a slave node is ACTIVE while it
/// penetrates, g_j < 0). The residual then holds the penalty forces eps_j g_j (D w1 - M w2)_j . n_j
/// of the active nodes next to the elements' forces, and the lumped mass advances both. The
/// model part's CONTACT flag says whether any node is active (what delta_time_factor_for_contact
/// reads). No DYNAMIC_FACTOR is applied (1): each step has its own force. Right after the residual,
/// still at u_n, the contact outputs (CONTACT_FORCE, NORMAL_CONTACT_STRESS...; ComputeContactOutputs)
/// are those of the force that drives the step: at the end of the step, at u_{n+1}, they would
/// describe a force no step applied (on the bar impact, 11 % below rho c A v).
///
/// Friction (the model part is SLIP): the stick traction c_tau eps_j s_j needs the slip since the
/// node started to stick; one step's increment (what the implicit penalty takes, and what Kratos'
/// explicit contact would take) is of order v dt and would leave almost no friction. So the nodal
/// WEIGHTED_SLIP accumulates: each step adds its increment to the previous step's value (buffer
/// position 1) projected onto the current tangent plane; a node that slips is return-mapped,
/// s_j = t_j / (c_tau eps_j) with t_j its Coulomb traction (AUGMENTED_TANGENT_CONTACT_PRESSURE),
/// and an open node starts again from zero (ProcessInfo ACCUMULATED_WEIGHTED_SLIP tells the
/// conditions).
class ExplicitPenaltyContactStrategy : public ExplicitStrategy {
 public:
  ExplicitPenaltyContactStrategy(ModelPart& model_part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                                 std::shared_ptr<MortarUpdater> updater, bool compute_reactions = true,
                                 bool move_mesh_flag = true, bool pure_slip = false);

  std::string Name() const override { return "explicit_penalty_contact"; }
  /// Clears CONTACT: whether any node is in contact is known after the first update. Reads
  /// whether the problem is frictional (SLIP of the root model part, set by the contact process).
  void Initialize() override;

  /// The critical time step with the contact penalty: an active slave node j is a spring of
  /// stiffness eps_j A_j^2 (A_j its NODAL_AREA, the dual mortar D_jj; the penalty force is
  /// eps_j g_j D_jj with the weighted gap g_j = D_jj x the normal gap) between its lumped mass and
  /// the master side's, with omega_j^2 = eps_j A_j^2 (1 / m_j + 1 / m_master), m_master the
  /// smallest lumped mass of a master interface node. With the elements' omega_e the estimate is
  /// 2 / sqrt(omega_e^2 + max_j omega_j^2) (the largest eigenvalue of a sum is at most the sum of
  /// the largest ones; exact for the spring on a matching interface, an estimate where several
  /// slave nodes share master nodes). A_j is the slave node's share of its interface faces when
  /// it has no NODAL_AREA yet. With friction the spring is the stiffer of the normal one and the
  /// tangential one (c_tau eps_j). Call once the lumped masses exist (after InitializeSolutionStep).
  double ContactStableTimeStep(double element_time_step) const;

 protected:
  void UpdateBeforeResidual() override;
  void UpdateAfterResidual() override;

 private:
  /// The frictional active set on the accumulated weighted slip, and its return mapping.
  void UpdateFrictionalState(ModelPart& contact) const;

  std::shared_ptr<MortarUpdater> updater_;
  bool pure_slip_;
  bool frictional_ = false;
};

}  // namespace mc
