// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/utilities/string_utilities.h"

namespace mc {

/// The geometry token ending a pair condition's name (spec 6.2): "2D2N", "3D4N", or with a master of
/// another geometry "3D3N4N" (slave nodes first).
inline std::string MortarGeometryToken(int dim, int slave_nodes, int master_nodes) {
  return slave_nodes == master_nodes ? Concat(dim, "D", slave_nodes, "N")
                                     : Concat(dim, "D", slave_nodes, "N", master_nodes, "N");
}

}  // namespace mc
