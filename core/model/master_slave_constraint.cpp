// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/master_slave_constraint.h"

#include "core/model/node.h"
#include "core/utilities/error.h"

namespace mc {

MasterSlaveConstraint::MasterSlaveConstraint(IndexType id, Dof& slave, std::vector<Dof*> masters,
                                             std::vector<double> weights, double constant)
    : id_(id), slave_(&slave), masters_(std::move(masters)), weights_(std::move(weights)), constant_(constant) {
  if (masters_.size() != weights_.size())
    throw InputError(
        Concat("master-slave constraint ", id_, ": ", masters_.size(), " masters but ", weights_.size(), " weights"));
  for (const Dof* m : masters_) {
    if (m == nullptr) throw InputError(Concat("master-slave constraint ", id_, ": null master DoF"));
    if (m == slave_)
      throw InputError(Concat("master-slave constraint ", id_, ": ", slave.variable->Name(), " of node ",
                              slave.node->Id(), " is both the slave and a master"));
  }
}

double MasterSlaveConstraint::Violation() const {
  double value = constant_ - slave_->Value();
  for (std::size_t i = 0; i < masters_.size(); ++i) value += weights_[i] * masters_[i]->Value();
  return value;
}

}  // namespace mc
