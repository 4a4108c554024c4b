// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/model/dof.h"
#include "core/utilities/error.h"
#include "core/variables/data_value_container.h"
#include "core/variables/flags.h"
#include "core/variables/variables_list.h"

namespace mc {

/// A mesh node: initial and current coordinates, historical data in a ring of `buffer_size`
/// steps (step 0 is the current one), non-historical data, flags and degrees of freedom.
class Node {
 public:
  Node(IndexType id, const Array3& coordinates, const VariablesList& variables, int buffer_size);
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  IndexType Id() const noexcept { return id_; }
  void SetId(IndexType id) noexcept { id_ = id; }

  /// Coordinates in the reference (initial) configuration.
  const Array3& X0() const noexcept { return x0_; }
  Array3& X0() noexcept { return x0_; }
  /// Coordinates in the current configuration.
  const Array3& Coordinates() const noexcept { return x_; }
  Array3& Coordinates() noexcept { return x_; }
  double X() const noexcept { return x_[0]; }
  double Y() const noexcept { return x_[1]; }
  double Z() const noexcept { return x_[2]; }

  // Historical data -----------------------------------------------------------------------
  int BufferSize() const noexcept { return buffer_size_; }
  void SetBufferSize(int buffer_size);
  /// Step 0 becomes a copy of the previous current step; older steps shift back by one.
  void CloneSolutionStep();
  const VariablesList& SolutionStepVariables() const noexcept { return *variables_; }
  bool HasSolutionStepValue(const VariableData& var) const noexcept { return variables_->Has(var); }

  /// Unchecked access for hot loops (the variable must be in the VariablesList).
  double& FastGetSolutionStepValue(const Variable<double>& var, int step = 0) noexcept {
    return data_[step * stride_ + variables_->Offset(var)];
  }
  double FastGetSolutionStepValue(const Variable<double>& var, int step = 0) const noexcept {
    return data_[step * stride_ + variables_->Offset(var)];
  }
  Eigen::Map<Array3> FastGetSolutionStepValue(const Variable<Array3>& var, int step = 0) noexcept {
    return Eigen::Map<Array3>(&data_[step * stride_ + variables_->Offset(var)]);
  }
  Eigen::Map<const Array3> FastGetSolutionStepValue(const Variable<Array3>& var, int step = 0) const noexcept {
    return Eigen::Map<const Array3>(&data_[step * stride_ + variables_->Offset(var)]);
  }
  /// Checked access: throws naming the node and the variable.
  template <class T>
  decltype(auto) GetSolutionStepValue(const Variable<T>& var, int step = 0) {
    CheckHistorical(var, step);
    return FastGetSolutionStepValue(var, step);
  }
  template <class T>
  decltype(auto) GetSolutionStepValue(const Variable<T>& var, int step = 0) const {
    CheckHistorical(var, step);
    return FastGetSolutionStepValue(var, step);
  }
  /// Raw historical storage of one step (Stride() doubles).
  double* StepData(int step = 0) noexcept { return &data_[step * stride_]; }

  // Non-historical data -------------------------------------------------------------------
  DataValueContainer& Data() noexcept { return values_; }
  const DataValueContainer& Data() const noexcept { return values_; }
  template <class T>
  T GetValue(const Variable<T>& var) const {
    return values_.GetValue(var);
  }
  template <class T>
  T& GetValueRef(const Variable<T>& var) {
    return values_.GetValueRef(var);
  }
  template <class T, class U>
  void SetValue(const Variable<T>& var, U&& value) {
    values_.SetValue(var, std::forward<U>(value));
  }
  template <class T>
  bool Has(const Variable<T>& var) const noexcept {
    return values_.Has(var);
  }

  // Flags -------------------------------------------------------------------------------
  Flags& GetFlags() noexcept { return flags_; }
  const Flags& GetFlags() const noexcept { return flags_; }
  bool Is(const Flag& f) const noexcept { return flags_.Is(f); }
  void Set(const Flag& f, bool value = true) noexcept { flags_.Set(f, value); }

  // Degrees of freedom ------------------------------------------------------------------
  /// Adds (or returns the existing) DoF of `var`; `reaction` may be null.
  Dof& AddDof(const Variable<double>& var, const Variable<double>* reaction = nullptr);
  bool HasDofFor(const Variable<double>& var) const noexcept { return FindDof(var) != nullptr; }
  Dof* FindDof(const Variable<double>& var) const noexcept {
    for (const auto& d : dofs_)
      if (d->variable == &var) return d.get();
    return nullptr;
  }
  /// Throws naming the node and the variable.
  Dof& GetDof(const Variable<double>& var) const;
  const std::vector<std::unique_ptr<Dof>>& Dofs() const noexcept { return dofs_; }
  void Fix(const Variable<double>& var) { GetDof(var).fixed = true; }
  void Free(const Variable<double>& var) { GetDof(var).fixed = false; }
  bool IsFixed(const Variable<double>& var) const noexcept {
    const Dof* d = FindDof(var);
    return d && d->fixed;
  }

 private:
  void CheckHistorical(const VariableData& var, int step) const;

  IndexType id_;
  Array3 x0_;
  Array3 x_;
  const VariablesList* variables_;
  std::size_t stride_;
  int buffer_size_;
  std::vector<double> data_;
  DataValueContainer values_;
  Flags flags_;
  std::vector<std::unique_ptr<Dof>> dofs_;
};

inline double& Dof::Value(int step) const { return node->FastGetSolutionStepValue(*variable, step); }
inline double& Dof::ReactionValue() const { return node->FastGetSolutionStepValue(*reaction, 0); }

}  // namespace mc
