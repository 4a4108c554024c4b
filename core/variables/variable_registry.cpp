// SPDX-License-Identifier: BSD-3-Clause
#include "core/variables/variable_registry.h"

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

const char* ValueTypeName(ValueType type) {
  switch (type) {
    case ValueType::Double: return "double";
    case ValueType::Int: return "int";
    case ValueType::Bool: return "bool";
    case ValueType::String: return "string";
    case ValueType::Array3: return "array of 3 doubles";
    case ValueType::Vector: return "vector";
    case ValueType::Matrix: return "matrix";
  }
  return "unknown";
}

VariableData::VariableData(std::string name, ValueType type, const VariableData* source, int component)
    : name_(std::move(name)), key_(0), type_(type), source_(source), component_(component) {
  key_ = VariableRegistry::Instance().Register(*this);
}

std::size_t VariableData::HistoricalSize() const noexcept { return type_ == ValueType::Array3 ? 3 : 1; }

VariableRegistry& VariableRegistry::Instance() {
  static VariableRegistry registry;
  return registry;
}

std::size_t VariableRegistry::Register(VariableData& variable) {
  if (by_name_.count(variable.Name())) throw Error(Concat("variable ", variable.Name(), " is defined twice"));
  by_key_.push_back(&variable);
  by_name_.emplace(variable.Name(), &variable);
  return by_key_.size() - 1;
}

bool VariableRegistry::Has(const std::string& name) const { return by_name_.count(name) > 0; }

const VariableData& VariableRegistry::Get(const std::string& name) const {
  const auto it = by_name_.find(name);
  if (it == by_name_.end()) throw InputError(Concat("unknown variable '", name, "'", DidYouMean(name, Names())));
  return *it->second;
}

template <class T>
const Variable<T>& VariableRegistry::GetTyped(const std::string& name) const {
  const VariableData& data = Get(name);
  if (data.Type() != ValueTypeOf<T>::value)
    throw InputError(Concat("variable ", name, " holds a ", ValueTypeName(data.Type()), ", not a ",
                            ValueTypeName(ValueTypeOf<T>::value)));
  return static_cast<const Variable<T>&>(data);
}

template const Variable<double>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<int>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<bool>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<std::string>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<Array3>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<Vector>& VariableRegistry::GetTyped(const std::string&) const;
template const Variable<Matrix>& VariableRegistry::GetTyped(const std::string&) const;

std::vector<std::string> VariableRegistry::Names() const {
  std::vector<std::string> names;
  names.reserve(by_key_.size());
  for (const auto* v : by_key_) names.push_back(v->Name());
  return names;
}

}  // namespace mc
