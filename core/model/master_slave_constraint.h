// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/model/dof.h"
#include "core/variables/value_types.h"

namespace mc {

/// A linear multipoint constraint u_slave = sum_i T_i u_master_i + c between DoFs. Builders
/// eliminate the slave (A -> T^T A T), so the constraint holds exactly after every solve.
/// A slave may be constrained once and may not be the master of another constraint.
class MasterSlaveConstraint {
 public:
  /// Throws InputError naming the constraint id when the sizes differ or the slave is also a
  /// master.
  MasterSlaveConstraint(IndexType id, Dof& slave, std::vector<Dof*> masters, std::vector<double> weights,
                        double constant = 0.0);

  IndexType Id() const noexcept { return id_; }
  Dof& Slave() const noexcept { return *slave_; }
  const std::vector<Dof*>& Masters() const noexcept { return masters_; }
  const std::vector<double>& Weights() const noexcept { return weights_; }
  double Constant() const noexcept { return constant_; }
  void SetConstant(double c) noexcept { constant_ = c; }
  bool IsActive() const noexcept { return active_; }
  void SetActive(bool active) noexcept { active_ = active; }

  /// sum_i T_i u_master_i + c - u_slave at the current values: the amount the next slave
  /// increment must add on top of the masters' contribution for the constraint to hold.
  double Violation() const;

 private:
  IndexType id_;
  Dof* slave_;
  std::vector<Dof*> masters_;
  std::vector<double> weights_;
  double constant_;
  bool active_ = true;
};

}  // namespace mc
