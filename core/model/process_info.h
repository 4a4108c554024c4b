// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/variables/data_value_container.h"
#include "core/variables/flags.h"

namespace mc {

/// Global state of a model shared by all its parts: TIME, DELTA_TIME, STEP, DOMAIN_SIZE,
/// iteration counters, scheme coefficients and any value an application puts there.
class ProcessInfo : public DataValueContainer {
 public:
  Flags& GetFlags() noexcept { return flags_; }
  const Flags& GetFlags() const noexcept { return flags_; }
  bool Is(const Flag& f) const noexcept { return flags_.Is(f); }
  void Set(const Flag& f, bool value = true) noexcept { flags_.Set(f, value); }

 private:
  Flags flags_;
};

}  // namespace mc
