// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/mesh_tying_utilities.h"

#include <array>
#include <unordered_map>

#include "core/variables/flags.h"
#include "custom_conditions/mesh_tying_mortar_condition.h"

namespace mc {

namespace {

struct TiedRows {
  std::array<bool, 3> free{};
  const MeshTyingMortarConditionBase* pair = nullptr;
};

}  // namespace

std::size_t MeshTyingUtilities::UpdateTiedSlaveNodes(ModelPart& computing_part) {
  const ProcessInfo& info = computing_part.GetProcessInfo();
  // Slave node -> which of its tied rows have a free DoF in some pair, and one pair that ties it.
  std::unordered_map<Node*, TiedRows> rows;
  for (Condition* condition : computing_part.Conditions()) {
    const auto* pair = dynamic_cast<const MeshTyingMortarConditionBase*>(condition);
    if (!pair || !pair->HasOverlap(info)) continue;
    const auto free = pair->SlaveRowsWithFreeDofs(info);
    for (std::size_t j = 0; j < free.size(); ++j) {
      TiedRows& node_rows = rows[&condition->GetGeometry()[j]];
      node_rows.pair = pair;
      for (int c = 0; c < 3; ++c) node_rows.free[c] = node_rows.free[c] || free[j][c];
    }
  }
  std::size_t fixed = 0;
  for (auto& [node, node_rows] : rows) {
    node->Set(ACTIVE, true);
    for (int c = 0; c < node_rows.pair->Components(); ++c) {
      Dof& dof = node->GetDof(node_rows.pair->MultiplierVariable(c));
      dof.fixed = !node_rows.free[c];
      if (dof.fixed) {
        dof.Value() = 0.0;
        ++fixed;
      }
    }
  }
  return fixed;
}

}  // namespace mc
