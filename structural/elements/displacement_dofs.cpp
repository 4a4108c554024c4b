// SPDX-License-Identifier: BSD-3-Clause
#include "structural/elements/displacement_dofs.h"

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {
const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
}  // namespace

void GetDisplacementDofList(const Geometry& geometry, DofsVectorType& dofs) {
  const int dim = geometry.Reference().WorkingSpaceDimension();
  dofs.resize(geometry.PointsNumber() * static_cast<std::size_t>(dim));
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a)
    for (int k = 0; k < dim; ++k) dofs[a * dim + k] = &geometry[a].GetDof(*kDisplacement[k]);
}

void CheckDisplacementDofs(const Geometry& geometry, const std::string& who) {
  const int dim = geometry.Reference().WorkingSpaceDimension();
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a) {
    const Node& node = geometry[a];
    if (!node.HasSolutionStepValue(DISPLACEMENT))
      throw InputError(Concat(who, ": node ", node.Id(), " has no solution-step variable DISPLACEMENT"));
    for (int k = 0; k < dim; ++k)
      if (!node.HasDofFor(*kDisplacement[k]))
        throw InputError(Concat(who, ": node ", node.Id(), " has no DoF ", kDisplacement[k]->Name()));
  }
}

std::string StructuralEntityName(std::string_view stem, bool axisymmetric, const Geometry& geometry) {
  const ReferenceElement& reference = geometry.Reference();
  return Concat(axisymmetric ? "Axisym" : "", stem, reference.WorkingSpaceDimension(), "D", reference.NodesNumber(),
                "N");
}

}  // namespace mc
