// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_state_cycle.h"

#include <algorithm>

#include "core/model/model_part.h"
#include "core/variables/flags.h"

namespace mc {

char ContactState(const Node& node) {
  return static_cast<char>((node.Is(ACTIVE) ? kActiveState : 0) | (node.Is(SLIP) ? kSlipState : 0));
}

std::vector<char> ContactStates(const ModelPart& contact) {
  std::vector<char> states;
  for (const Node* node : contact.Nodes())
    if (node->Is(SLAVE)) states.push_back(ContactState(*node));
  return states;
}

void SetContactStates(ModelPart& contact, const std::vector<char>& states) {
  std::size_t i = 0;
  for (Node* node : contact.Nodes()) {
    if (!node->Is(SLAVE)) continue;
    node->Set(ACTIVE, (states[i] & kActiveState) != 0);
    node->Set(SLIP, (states[i] & kSlipState) != 0);
    ++i;
  }
}

int CountActive(const std::vector<char>& states) {
  return static_cast<int>(std::count_if(states.begin(), states.end(), [](char s) { return (s & kActiveState) != 0; }));
}

int ContactStateCycle::Close(std::vector<char>& states) {
  if (states == seen_.back()) return -1;
  const auto earlier = std::find(seen_.begin(), seen_.end() - 1, states);
  if (earlier == seen_.end() - 1) {
    seen_.push_back(states);
    return -1;
  }
  const int index = static_cast<int>(earlier - seen_.begin());
  for (auto cycle = earlier; cycle != seen_.end(); ++cycle)
    for (std::size_t i = 0; i < states.size(); ++i) states[i] = static_cast<char>(states[i] | (*cycle)[i]);
  seen_.push_back(states);
  return index;
}

}  // namespace mc
