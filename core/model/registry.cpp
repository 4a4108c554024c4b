// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/registry.h"

#include "core/model/condition.h"
#include "core/model/constitutive_law.h"
#include "core/model/element.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {
template <class T>
const char* KindName();
template <>
const char* KindName<Element>() {
  return "element";
}
template <>
const char* KindName<Condition>() {
  return "condition";
}
template <>
const char* KindName<ConstitutiveLaw>() {
  return "constitutive law";
}
}  // namespace

template <class T>
Registry<T>& Registry<T>::Instance() {
  static Registry registry;
  return registry;
}

template <class T>
std::shared_ptr<const T> Registry<T>::GetShared(const std::string& name) const {
  const auto it = items_.find(name);
  if (it == items_.end())
    throw InputError(Concat("unknown ", KindName<T>(), " '", name, "'", DidYouMean(name, Names())));
  return it->second;
}

template <class T>
const T& Registry<T>::Get(const std::string& name) const {
  return *GetShared(name);
}

template <class T>
std::vector<std::string> Registry<T>::Names() const {
  std::vector<std::string> names;
  for (const auto& [name, item] : items_) names.push_back(name);
  return names;
}

template class Registry<Element>;
template class Registry<Condition>;
template class Registry<ConstitutiveLaw>;

}  // namespace mc
