// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/utilities/error.h"

namespace mc {

/// Raised by the builder when the global system is singular at known DoFs (an empty column, or
/// a zero pivot the solver located); `Dofs()` names them as (node id, variable name), so that a
/// strategy can say in its own terms why they lost their equation.
class SingularSystemError : public SolutionError {
 public:
  using DofName = std::pair<std::size_t, std::string>;

  SingularSystemError(const std::string& what, std::vector<DofName> dofs)
      : SolutionError(what), dofs_(std::move(dofs)) {}
  const std::vector<DofName>& Dofs() const noexcept { return dofs_; }

 private:
  std::vector<DofName> dofs_;
};

}  // namespace mc
