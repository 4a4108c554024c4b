// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/solving/convergence_criteria.h"
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"

namespace mc {

/// "mpc_contact_criteria": the active set of the MPC contact route, from the reactions (there are no
/// multipliers). For every SLAVE node of Contact the normal contact force is f_n = REACTION . NORMAL
/// (REACTION of the slave's free DoFs: the force the constraint transmits, written by the MPC strategy
/// before the check), the pressure p_n = f_n / NODAL_MAUX and the gap g = the constraints' nodal gap.
/// An active node stays active while it is pressed, p_n < -REACTION_CHECK_STIFFNESS_FACTOR * E (E the
/// YOUNG_MODULUS of the first element's properties; factor 1e-12 when the ProcessInfo has none); an
/// inactive node becomes active when it penetrates, g < 0. Active nodes get CONTACT_FORCE = f_n n and
/// NORMAL_CONTACT_STRESS = p_n; inactive ones 0. Converged when no node changed.
///
/// Differences from Kratos, by design: Kratos tests both conditions on every node, but an active
/// node's gap is the constraint's, zero up to round-off, whose sign would keep it (or not) at random;
/// Kratos adds the master reactions mapped onto the slave (times -1): in a master-slave elimination the
/// slave reaction is the whole contact force and the masters carry it again through T^T, so the sum
/// would count it twice (Kratos 10.4's own CONTACT_FORCE on mpc_contact_tests equals the slave
/// reaction); Kratos divides CONTACT_FORCE by NODAL_PAUX, here it is the nodal force itself.
class MPCContactCriteria : public ConvergenceCriteria {
 public:
  explicit MPCContactCriteria(std::shared_ptr<const MPCContactConstraints> constraints);

  std::string Name() const override { return "mpc_contact_criteria"; }
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  std::vector<CriterionValue> LastValues() const override;
  /// Active-set changes of the last PostCriteria.
  std::size_t Changes() const noexcept { return changes_; }

 private:
  std::shared_ptr<const MPCContactConstraints> constraints_;
  std::size_t changes_ = 0;
};

}  // namespace mc
