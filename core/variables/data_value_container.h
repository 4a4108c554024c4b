// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/variables/variable.h"

namespace mc {

/// Non-historical values of a node, element, condition, properties or ProcessInfo: a small
/// list of (variable, value) pairs. Components of Array3 variables read and write their source.
class DataValueContainer {
 public:
  using Value = std::variant<double, int, bool, std::string, Array3, Vector, Matrix>;

  template <class T>
  bool Has(const Variable<T>& var) const noexcept {
    return Find(Storage(var)) != nullptr;
  }

  /// The value, or the variable's zero when absent.
  template <class T>
  T GetValue(const Variable<T>& var) const {
    if constexpr (std::is_same_v<T, double>) {
      if (var.IsComponent()) {
        const Value* v = Find(var.Source());
        return v ? std::get<Array3>(*v)[var.ComponentIndex()] : 0.0;
      }
    }
    const Value* v = Find(&var);
    return v ? std::get<T>(*v) : var.Zero();
  }

  /// Mutable access; inserts the zero value when absent.
  template <class T>
  T& GetValueRef(const Variable<T>& var) {
    if constexpr (std::is_same_v<T, double>) {
      if (var.IsComponent()) {
        const auto& source = static_cast<const Variable<Array3>&>(*var.Source());
        return GetValueRef(source)[var.ComponentIndex()];
      }
    }
    if (Value* v = Find(&var)) return std::get<T>(*v);
    data_.emplace_back(&var, Value(var.Zero()));
    return std::get<T>(data_.back().second);
  }

  template <class T, class U>
  void SetValue(const Variable<T>& var, U&& value) {
    GetValueRef(var) = std::forward<U>(value);
  }

  void Erase(const VariableData& var);
  void Clear() noexcept { data_.clear(); }
  std::size_t Size() const noexcept { return data_.size(); }
  const std::vector<std::pair<const VariableData*, Value>>& Items() const noexcept { return data_; }

  /// Sets a value of any registered type from a generic value (used by readers and bindings).
  void SetGeneric(const VariableData& var, const Value& value);

 private:
  static const VariableData* Storage(const VariableData& var) noexcept {
    return var.IsComponent() ? var.Source() : &var;
  }
  const Value* Find(const VariableData* var) const noexcept {
    for (const auto& [key, value] : data_)
      if (key == var) return &value;
    return nullptr;
  }
  Value* Find(const VariableData* var) noexcept {
    for (auto& [key, value] : data_)
      if (key == var) return &value;
    return nullptr;
  }

  std::vector<std::pair<const VariableData*, Value>> data_;
};

}  // namespace mc
