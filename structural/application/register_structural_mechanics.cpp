// SPDX-License-Identifier: BSD-3-Clause
#include "structural/application/register_structural_mechanics.h"

#include <mutex>

#include "core/geometries/reference_element.h"
#include "core/model/registry.h"
#include "structural/conditions/load_condition.h"
#include "structural/conditions/skin_condition.h"
#include "structural/constitutive_laws/elastic_law.h"
#include "structural/elements/membrane_element.h"
#include "structural/elements/solid_element.h"

namespace mc {

namespace {

using GT = GeometryType;

// Registers one prototype per geometry under its own Info() name; `args` follow the geometry
// and properties in E's constructor.
template <class E, class Base, class... Args>
void AddAll(std::initializer_list<GT> types, Args... args) {
  for (const GT type : types) {
    auto prototype = std::make_shared<const E>(0, Geometry(type, {}), nullptr, args...);
    Registry<Base>::Instance().Add(prototype->Info(), prototype);
  }
}

void AddSolids(std::initializer_list<GT> types, bool axisymmetric) {
  using K = SolidElement::Kinematics;
  for (const K kinematics : {K::SmallDisplacement, K::TotalLagrangian, K::UpdatedLagrangian})
    AddAll<SolidElement, Element>(types, kinematics, axisymmetric);
}

void RegisterAll() {
  for (const std::string& name : ElasticLaw::Names())
    Registry<ConstitutiveLaw>::Instance().Add(name, std::make_shared<const ElasticLaw>(name));

  const std::initializer_list<GT> solids_2d = {GT::Triangle2D3, GT::Triangle2D6, GT::Quadrilateral2D4,
                                               GT::Quadrilateral2D8, GT::Quadrilateral2D9};
  const std::initializer_list<GT> solids = {GT::Triangle2D3,      GT::Triangle2D6,      GT::Quadrilateral2D4,
                                            GT::Quadrilateral2D8, GT::Quadrilateral2D9, GT::Tetrahedra3D4,
                                            GT::Tetrahedra3D10,   GT::Hexahedra3D8,     GT::Hexahedra3D20,
                                            GT::Hexahedra3D27,    GT::Prism3D6};
  AddSolids(solids, false);
  AddSolids(solids_2d, true);
  AddAll<MembraneElement, Element>({GT::Triangle3D3, GT::Quadrilateral3D4});

  using Load = LoadCondition::Load;
  AddAll<LoadCondition, Condition>({GT::Point2D, GT::Point3D}, Load::kPoint, false);
  AddAll<LoadCondition, Condition>({GT::Point2D}, Load::kPoint, true);
  AddAll<LoadCondition, Condition>({GT::Line2D2, GT::Line2D3, GT::Line3D2}, Load::kLine, false);
  AddAll<LoadCondition, Condition>({GT::Line2D2, GT::Line2D3}, Load::kLine, true);
  AddAll<LoadCondition, Condition>(
      {GT::Triangle3D3, GT::Quadrilateral3D4, GT::Triangle3D6, GT::Quadrilateral3D8, GT::Quadrilateral3D9},
      Load::kSurface, false);
  AddAll<SkinCondition, Condition>({GT::Line2D2, GT::Line2D3, GT::Triangle3D3, GT::Quadrilateral3D4});
}

}  // namespace

void RegisterStructuralMechanics() {
  static std::once_flag once;
  std::call_once(once, RegisterAll);
}

}  // namespace mc
