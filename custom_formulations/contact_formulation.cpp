// SPDX-License-Identifier: BSD-3-Clause
#include "custom_formulations/contact_formulation.h"

#include <algorithm>
#include <map>
#include <mutex>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {

struct Store {
  std::mutex mutex;
  std::map<std::string, std::shared_ptr<const ContactFormulation>> by_name;
};

Store& TheStore() {
  static Store store;
  return store;
}

std::string Join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

const ContactFormulation& Implemented(const ContactFormulation& formulation, const std::string& where) {
  if (!formulation.IsImplemented())
    throw NotImplementedError(Concat(where, ": mortar_type ", formulation.MortarType(), " is not implemented yet (",
                                     formulation.Describe().not_implemented, ")"));
  return formulation;
}

}  // namespace

void ContactFormulation::Register(Description description) {
  Store& store = TheStore();
  std::lock_guard<std::mutex> lock(store.mutex);
  const std::string name = description.mortar_type;
  store.by_name[name] = std::make_shared<const ContactFormulation>(std::move(description));
}

const ContactFormulation& ContactFormulation::Get(const std::string& mortar_type, const std::string& where) {
  Store& store = TheStore();
  const ContactFormulation* found = nullptr;
  {
    std::lock_guard<std::mutex> lock(store.mutex);
    for (const auto& [name, formulation] : store.by_name)
      if (mortar_type.starts_with(name) && (!found || name.size() > found->MortarType().size()))
        found = formulation.get();
  }
  if (!found)
    throw InputError(Concat(where, ": unknown mortar_type \"", mortar_type, "\"", DidYouMean(mortar_type, Names()),
                            " (valid: ", Join(Names()), ")"));
  return Implemented(*found, where);
}

const ContactFormulation& ContactFormulation::OfProcess(const std::string& process, const std::string& contact_type,
                                                        const std::string& where) {
  Store& store = TheStore();
  const ContactFormulation* found = nullptr;
  {
    std::lock_guard<std::mutex> lock(store.mutex);
    for (const auto& [name, formulation] : store.by_name)
      if (formulation->d_.process == process && formulation->d_.contact_type == contact_type) found = formulation.get();
  }
  if (!found) {
    const std::vector<std::string> valid = ContactTypes(process);
    throw InputError(Concat(where, ": unknown contact_type", DidYouMean(contact_type, valid), " (valid for ", process,
                            ": ", Join(valid), ")"));
  }
  return Implemented(*found, where);
}

std::vector<std::string> ContactFormulation::Names() {
  Store& store = TheStore();
  std::lock_guard<std::mutex> lock(store.mutex);
  std::vector<std::string> names;
  for (const auto& [name, formulation] : store.by_name) names.push_back(name);
  return names;
}

std::vector<std::string> ContactFormulation::ContactTypes(const std::string& process) {
  Store& store = TheStore();
  std::lock_guard<std::mutex> lock(store.mutex);
  std::vector<std::string> types;
  for (const auto& [name, formulation] : store.by_name)
    if (formulation->d_.process == process) types.push_back(formulation->d_.contact_type);
  std::sort(types.begin(), types.end());
  return types;
}

std::string ContactFormulation::ConditionStem(bool normal_variation, bool axisymmetric) const {
  if (axisymmetric && !d_.axisymmetric)
    throw NotImplementedError(Concat("alternative_formulations.axisymmetric: ", d_.mortar_type,
                                     " has no axisymmetric conditions (Kratos has none either)"));
  return Concat(d_.enforcement, normal_variation ? "NV" : "", d_.contact_kind, axisymmetric ? "Axisym" : "",
                d_.condition_suffix);
}

std::shared_ptr<ConvergenceCriteria> ContactFormulation::CreateActiveSetCriterion(Parameters contact_settings) const {
  return d_.active_set_criterion(std::move(contact_settings));
}

}  // namespace mc
