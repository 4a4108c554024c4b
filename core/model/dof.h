// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>

#include "core/variables/variable.h"

namespace mc {

class Node;

/// One degree of freedom: a double variable of a node, its reaction, fixity and equation id.
struct Dof {
  Node* node = nullptr;
  const Variable<double>* variable = nullptr;
  const Variable<double>* reaction = nullptr;
  bool fixed = false;
  std::int64_t equation_id = -1;

  double& Value(int step = 0) const;  ///< historical value of `variable`
  double& ReactionValue() const;      ///< historical value of `reaction` (current step)
  bool HasReaction() const noexcept { return reaction != nullptr; }
};

}  // namespace mc
