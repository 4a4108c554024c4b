// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "custom_conditions/paired_condition.h"

namespace mc {

/// Registry placeholder for a pair-condition name of the Kratos grammar (spec 6.2) that is not
/// implemented yet: the name resolves, and creating a pair from it raises NotImplementedError
/// naming the condition and what is missing, instead of a misleading "unknown name".
class NotImplementedPairCondition : public PairedCondition {
 public:
  NotImplementedPairCondition(std::string name, std::string reason, Geometry slave, Geometry master)
      : PairedCondition(0, std::move(slave), nullptr, std::move(master)),
        name_(std::move(name)),
        reason_(std::move(reason)) {}

  std::string Info() const override { return name_; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override { dofs.clear(); }

 private:
  [[noreturn]] void Fail() const;

  std::string name_;
  std::string reason_;
};

}  // namespace mc
