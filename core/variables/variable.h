// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/variables/value_types.h"

namespace mc {

/// Name, key and type of a variable, independent of its C++ value type. Keys are small dense
/// integers given in registration order, so lookups are array indexing.
class VariableData {
 public:
  VariableData(std::string name, ValueType type, const VariableData* source = nullptr, int component = -1);
  VariableData(const VariableData&) = delete;
  VariableData& operator=(const VariableData&) = delete;
  virtual ~VariableData() = default;

  const std::string& Name() const noexcept { return name_; }
  std::size_t Key() const noexcept { return key_; }
  ValueType Type() const noexcept { return type_; }

  /// DISPLACEMENT_X is the component 0 of DISPLACEMENT: its source is DISPLACEMENT.
  bool IsComponent() const noexcept { return source_ != nullptr; }
  const VariableData* Source() const noexcept { return source_; }
  int ComponentIndex() const noexcept { return component_; }

  /// Number of doubles taken in historical storage (1 for doubles, 3 for Array3).
  std::size_t HistoricalSize() const noexcept;

  bool operator==(const VariableData& other) const noexcept { return key_ == other.key_; }

 private:
  std::string name_;
  std::size_t key_;
  ValueType type_;
  const VariableData* source_;
  int component_;
};

/// A typed variable. Construction registers it by name in the VariableRegistry.
template <class T>
class Variable : public VariableData {
 public:
  using ValueType = T;
  explicit Variable(std::string name, T zero = T{})
      : VariableData(std::move(name), ValueTypeOf<T>::value), zero_(std::move(zero)) {}
  /// Component of an Array3 variable.
  Variable(std::string name, const Variable<Array3>& source, int component) requires std::is_same_v<T, double>
      : VariableData(std::move(name), mc::ValueType::Double, &source, component), zero_(0.0) {}

  const T& Zero() const noexcept { return zero_; }

 private:
  T zero_;
};

}  // namespace mc
