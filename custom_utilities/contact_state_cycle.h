// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

namespace mc {

class ModelPart;
class Node;

/// A slave node's contact state: these bits of its entry in ContactStates.
inline constexpr char kActiveState = 1;
inline constexpr char kSlipState = 2;

/// A node's state: ACTIVE and SLIP.
char ContactState(const Node& node);
/// The states of the slave nodes of `contact`, in node order.
std::vector<char> ContactStates(const ModelPart& contact);
/// Sets ACTIVE and SLIP of the slave nodes of `contact` from `states` (the order of ContactStates).
void SetContactStates(ModelPart& contact, const std::vector<char>& states);
/// The active nodes among `states`.
int CountActive(const std::vector<char>& states);

/// Semi-smooth Newton's cycle guard: the contact states after each iteration of a step. The set
/// of one iteration can make the next iterate land in another set, which brings it back; when the
/// states come back to those of an earlier iteration, the cycle is closed by the union of the
/// states since then, on which Newton can converge (as in the simplified semi-smooth Newton).
class ContactStateCycle {
 public:
  /// The states the step starts from.
  explicit ContactStateCycle(std::vector<char> start) : seen_{std::move(start)} {}
  /// Records the states after an iteration (a repeat of the last ones is no change and is not
  /// recorded). Where they repeat those of an earlier iteration, replaces `states` by the union of
  /// the states since then, records it and returns that iteration's index (0: the step's start);
  /// otherwise -1.
  int Close(std::vector<char>& states);
  /// The states recorded last (after a closed cycle: its union).
  const std::vector<char>& Last() const noexcept { return seen_.back(); }

 private:
  std::vector<std::vector<char>> seen_;
};

}  // namespace mc
