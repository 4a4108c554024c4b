// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/variables/variable.h"

namespace mc {

/// Layout of the historical (solution-step) data of the nodes of one model: which variables
/// are stored and where. Doubles take one slot, Array3 three; components share their source's
/// slots. Owned by the root model part; all its nodes share it.
class VariablesList {
 public:
  /// Adds a double or Array3 variable (a component adds its source). Only allowed before
  /// nodes are created.
  void Add(const VariableData& var);
  bool Has(const VariableData& var) const noexcept {
    const VariableData& s = var.IsComponent() ? *var.Source() : var;
    return s.Key() < offsets_.size() && offsets_[s.Key()] >= 0;
  }
  /// Offset of the first double of `var` inside one step; -1 when absent.
  int Offset(const VariableData& var) const noexcept {
    if (var.IsComponent()) {
      const int base = Offset(*var.Source());
      return base < 0 ? -1 : base + var.ComponentIndex();
    }
    return var.Key() < offsets_.size() ? offsets_[var.Key()] : -1;
  }
  /// Doubles per step.
  std::size_t Stride() const noexcept { return stride_; }
  const std::vector<const VariableData*>& Variables() const noexcept { return variables_; }
  bool IsLocked() const noexcept { return locked_; }
  void Lock() noexcept { locked_ = true; }

 private:
  std::vector<int> offsets_;
  std::vector<const VariableData*> variables_;
  std::size_t stride_ = 0;
  bool locked_ = false;
};

}  // namespace mc
