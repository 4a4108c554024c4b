// SPDX-License-Identifier: BSD-3-Clause
#include "core/variables/data_value_container.h"

#include <algorithm>

#include "core/utilities/error.h"

namespace mc {

void DataValueContainer::Erase(const VariableData& var) {
  data_.erase(std::remove_if(data_.begin(), data_.end(), [&](const auto& item) { return item.first == &var; }),
              data_.end());
}

void DataValueContainer::SetGeneric(const VariableData& var, const Value& value) {
  if (var.IsComponent()) {
    if (!std::holds_alternative<double>(value)) throw InputError(Concat("variable ", var.Name(), " expects a number"));
    SetValue(static_cast<const Variable<double>&>(var), std::get<double>(value));
    return;
  }
  auto matches = [&](ValueType t) {
    switch (t) {
      case ValueType::Double: return std::holds_alternative<double>(value);
      case ValueType::Int: return std::holds_alternative<int>(value);
      case ValueType::Bool: return std::holds_alternative<bool>(value);
      case ValueType::String: return std::holds_alternative<std::string>(value);
      case ValueType::Array3: return std::holds_alternative<Array3>(value);
      case ValueType::Vector: return std::holds_alternative<Vector>(value);
      case ValueType::Matrix: return std::holds_alternative<Matrix>(value);
    }
    return false;
  };
  if (!matches(var.Type())) throw InputError(Concat("variable ", var.Name(), " expects a ", ValueTypeName(var.Type())));
  if (Value* v = Find(&var)) {
    *v = value;
  } else {
    data_.emplace_back(&var, value);
  }
}

}  // namespace mc
