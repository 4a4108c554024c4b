// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/normal_calculation_utilities.h"

#include <unordered_map>
#include <vector>

#include "core/geometries/reference_element.h"
#include "core/model/parallel_utilities.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/nodal_normal_support.h"

namespace mc {

void NormalCalculationUtilities::ComputeConditionsNormals(ModelPart& part) {
  // A degenerate (e.g. collapsed) face throws: the helper carries the error out of the threads.
  ParallelForEachEntity(part.Conditions(), [](Condition& condition) {
    const Geometry& geometry = condition.GetGeometry();
    condition.SetValue(NORMAL, geometry.UnitNormal(geometry.Reference().LocalCenter()));
  });
}

void NormalCalculationUtilities::ComputeNodalNormals(ModelPart& part) {
  // The condition normals are kept for the search and the interface checks. Conditions are few
  // per node: the area vectors are accumulated serially in a map keyed by node, which stays
  // simple and deterministic.
  ComputeConditionsNormals(part);
  std::unordered_map<Node*, Array3> sums;
  sums.reserve(part.NumberOfNodes());
  for (Condition* condition : part.Conditions()) {
    const Geometry& geometry = condition->GetGeometry();
    // The same unit normals as NodalNormalSupport, whose derivatives the NV conditions use.
    for (Node* node : geometry.Nodes()) {
      auto [it, inserted] = sums.try_emplace(node, Array3::Zero());
      it->second += NodalNormalSupport::UnitCornerNormal(geometry, *node);
    }
  }
  for (auto& [node, sum] : sums) {
    sum = sum.cwiseProduct(NodalNormalSupport::SymmetryMask(*node));
    const double norm = sum.norm();
    SetNodalNormal(*node, norm > 0.0 ? Array3(sum / norm) : Array3::Zero());
  }
}

Array3 NormalCalculationUtilities::GetNodalNormal(const Node& node) {
  if (node.HasSolutionStepValue(NORMAL)) return node.FastGetSolutionStepValue(NORMAL);
  return node.GetValue(NORMAL);
}

void NormalCalculationUtilities::SetNodalNormal(Node& node, const Array3& normal) {
  if (node.HasSolutionStepValue(NORMAL))
    node.FastGetSolutionStepValue(NORMAL) = normal;
  else
    node.SetValue(NORMAL, normal);
}

}  // namespace mc
