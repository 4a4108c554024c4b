// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mc {

class Element;
class Condition;
class ConstitutiveLaw;

/// Name -> prototype of elements, conditions and constitutive laws. The mdpa reader, the
/// materials reader and out-of-tree plugins all go through it; one instance per type lives in
/// the core shared library.
template <class T>
class Registry {
 public:
  static Registry& Instance();

  /// Registers a prototype; re-registering a name replaces it (plugins may override).
  void Add(const std::string& name, std::shared_ptr<const T> prototype) { items_[name] = std::move(prototype); }
  bool Has(const std::string& name) const { return items_.count(name) > 0; }
  /// Throws InputError naming the nearest registered names.
  const T& Get(const std::string& name) const;
  std::shared_ptr<const T> GetShared(const std::string& name) const;
  std::vector<std::string> Names() const;

 private:
  std::map<std::string, std::shared_ptr<const T>> items_;
};

extern template class Registry<Element>;
extern template class Registry<Condition>;
extern template class Registry<ConstitutiveLaw>;

}  // namespace mc
