// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/model_part.h"

namespace mc {

/// Normals of interface conditions and nodes, always in the current configuration.
///
/// Condition normal: the unit normal at the condition's local centre (Geometry::UnitNormal, so a
/// line in 2D uses the tangent rotated by -90 degrees and a face generated from an element
/// points out of it). Nodal normal: the average of the unit normals at the node of the part's
/// conditions that hold it, each counted once (n_i = normalise(sum_c n_c(x_i)), Popp's definition
/// and Kratos 10.4's); NodalNormalSupport::UnitCornerNormal gives the contribution and
/// NodalNormalSupport the exact derivatives of the same n_i.
class NormalCalculationUtilities {
 public:
  /// Writes condition value NORMAL on every condition of `part` (lines in 2D, surfaces in 3D).
  static void ComputeConditionsNormals(ModelPart& part);
  /// Writes condition NORMAL and nodal NORMAL on every node of `part` that belongs to one of
  /// its conditions. NORMAL goes to the historical data when the model has it (spec 5.1), to
  /// the node's non-historical data otherwise.
  static void ComputeNodalNormals(ModelPart& part);
  /// The nodal normal written by ComputeNodalNormals.
  static Array3 GetNodalNormal(const Node& node);
  static void SetNodalNormal(Node& node, const Array3& normal);
};

}  // namespace mc
