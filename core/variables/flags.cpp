// SPDX-License-Identifier: BSD-3-Clause
#include "core/variables/flags.h"

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {
namespace {
std::vector<const Flag*>& FlagList() {
  static std::vector<const Flag*> list;
  return list;
}
}  // namespace

Flag::Flag(std::string name) : name_(std::move(name)) {
  auto& list = FlagList();
  if (list.size() >= 64) throw Error(Concat("cannot define flag ", name_, ": all 64 flag bits are taken"));
  bit_ = std::uint64_t{1} << list.size();
  list.push_back(this);
}

const Flag& Flag::Get(const std::string& name) {
  std::vector<std::string> names;
  for (const Flag* f : FlagList()) {
    if (f->Name() == name) return *f;
    names.push_back(f->Name());
  }
  throw InputError(Concat("unknown flag '", name, "'", DidYouMean(name, names)));
}

std::vector<const Flag*> Flag::All() { return FlagList(); }

const Flag ACTIVE("ACTIVE");
const Flag SLAVE("SLAVE");
const Flag MASTER("MASTER");
const Flag INTERFACE("INTERFACE");
const Flag ISOLATED("ISOLATED");
const Flag SLIP("SLIP");
const Flag MARKER("MARKER");
const Flag CONTACT("CONTACT");
const Flag INTERACTION("INTERACTION");
const Flag MODIFIED("MODIFIED");
const Flag BLOCKED("BLOCKED");
const Flag RIGID("RIGID");
const Flag TO_SPLIT("TO_SPLIT");
const Flag TO_ERASE("TO_ERASE");
const Flag VISITED("VISITED");
const Flag SELECTED("SELECTED");
const Flag BOUNDARY("BOUNDARY");
const Flag STRUCTURE("STRUCTURE");

}  // namespace mc
