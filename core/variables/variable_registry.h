// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "core/variables/variable.h"

namespace mc {

/// Every variable known to the program, by name and by key. Applications and out-of-tree
/// plugins add theirs simply by defining `Variable` objects.
class VariableRegistry {
 public:
  static VariableRegistry& Instance();

  std::size_t Register(VariableData& variable);
  bool Has(const std::string& name) const;
  /// Throws InputError naming the nearest registered names.
  const VariableData& Get(const std::string& name) const;
  template <class T>
  const Variable<T>& GetTyped(const std::string& name) const;
  const VariableData& GetByKey(std::size_t key) const { return *by_key_.at(key); }
  std::size_t Size() const noexcept { return by_key_.size(); }
  std::vector<std::string> Names() const;

 private:
  std::vector<const VariableData*> by_key_;
  std::unordered_map<std::string, const VariableData*> by_name_;
};

extern template const Variable<double>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<int>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<bool>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<std::string>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<Array3>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<Vector>& VariableRegistry::GetTyped(const std::string&) const;
extern template const Variable<Matrix>& VariableRegistry::GetTyped(const std::string&) const;

}  // namespace mc
