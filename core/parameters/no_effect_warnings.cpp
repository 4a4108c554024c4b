// SPDX-License-Identifier: BSD-3-Clause
#include "core/parameters/no_effect_warnings.h"

#include <mutex>
#include <set>

#include "core/utilities/error.h"
#include "core/utilities/logger.h"

namespace mc {
namespace {

std::mutex& ReportedMutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& Reported() {
  static std::set<std::string> reported;
  return reported;
}

}  // namespace

bool NoEffectWarnings::IfGiven(const Parameters& settings, const Parameters& defaults, const std::string& key,
                               const std::string& why) {
  if (!settings.Has(key)) return false;
  // nlohmann compares numbers by value, so 1 equals 1.0.
  if (defaults.Has(key) && settings[key].Json() == defaults[key].Json()) return false;
  Warn(settings, key, why);
  return true;
}

void NoEffectWarnings::Warn(const Parameters& settings, const std::string& key, const std::string& why) {
  const Parameters value = settings[key];
  const std::string where = value.Where();
  {
    std::lock_guard<std::mutex> lock(ReportedMutex());
    if (!Reported().insert(where).second) return;
  }
  Logger::Warning(
      Concat("key '", key, "' = ", value.WriteJsonString(), " at ", where, " has no effect in mortarcontact: ", why));
}

void NoEffectWarnings::Reset() {
  std::lock_guard<std::mutex> lock(ReportedMutex());
  Reported().clear();
}

}  // namespace mc
