// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/parameters/parameters.h"

namespace mc {

/// The one route for settings that are accepted (Kratos inputs carry them) but do nothing here
/// (issue 18): nothing the user writes is ignored silently. The class that owns a key and does not
/// act on it calls `IfGiven` with its reason; the message reads
///   key 'dynamic_search' = true at case.json: processes...search_parameters.dynamic_search has no
///   effect in mortarcontact: <why>
/// and goes through Logger::Warning, once per key (file and path) per run: a search per interface
/// slot or a criterion rebuilt per step reads the same key again. `Reset` starts a run.
class NoEffectWarnings {
 public:
  /// Warns when `settings[key]` differs from `defaults[key]`, so that a default copied from a
  /// Kratos template stays quiet. Returns whether the value differs.
  static bool IfGiven(const Parameters& settings, const Parameters& defaults, const std::string& key,
                      const std::string& why);
  /// Warns whatever the value: for a value (not a key) that changes nothing, e.g. a search type
  /// that runs as another one.
  static void Warn(const Parameters& settings, const std::string& key, const std::string& why);
  /// Forgets the keys already reported (a new run reports them again).
  static void Reset();
};

}  // namespace mc
