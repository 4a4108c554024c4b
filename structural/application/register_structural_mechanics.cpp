// SPDX-License-Identifier: BSD-3-Clause
#include "structural/application/register_structural_mechanics.h"

#include <mutex>

#include "core/geometries/reference_element.h"
#include "core/model/registry.h"
#include "structural/conditions/axisym_line_load_condition.h"
#include "structural/conditions/axisym_point_load_condition.h"
#include "structural/conditions/line_load_condition.h"
#include "structural/conditions/point_load_condition.h"
#include "structural/conditions/skin_condition.h"
#include "structural/conditions/surface_load_condition.h"
#include "structural/constitutive_laws/hyper_elastic_3d_law.h"
#include "structural/constitutive_laws/hyper_elastic_axisym_2d_law.h"
#include "structural/constitutive_laws/hyper_elastic_plane_strain_2d_law.h"
#include "structural/constitutive_laws/kirchhoff_saint_venant_3d_law.h"
#include "structural/constitutive_laws/kirchhoff_saint_venant_plane_strain_2d_law.h"
#include "structural/constitutive_laws/kirchhoff_saint_venant_plane_stress_2d_law.h"
#include "structural/constitutive_laws/linear_elastic_3d_law.h"
#include "structural/constitutive_laws/linear_elastic_axisym_2d_law.h"
#include "structural/constitutive_laws/linear_elastic_plane_strain_2d_law.h"
#include "structural/constitutive_laws/linear_elastic_plane_stress_2d_law.h"
#include "structural/elements/axisym_small_displacement_element.h"
#include "structural/elements/axisym_total_lagrangian_element.h"
#include "structural/elements/axisym_updated_lagrangian_element.h"
#include "structural/elements/membrane_element.h"
#include "structural/elements/small_displacement_element.h"
#include "structural/elements/total_lagrangian_element.h"
#include "structural/elements/updated_lagrangian_element.h"

namespace mc {

namespace {

using GT = GeometryType;

template <class T>
void AddLaw() {
  auto law = std::make_shared<const T>();
  Registry<ConstitutiveLaw>::Instance().Add(law->Name(), law);
}

// Registers one prototype per geometry under its own Info() name.
template <class E, class Base>
void AddAll(std::initializer_list<GT> types) {
  for (const GT type : types) {
    auto prototype = std::make_shared<const E>(0, Geometry(type, {}), nullptr);
    Registry<Base>::Instance().Add(prototype->Info(), prototype);
  }
}

void RegisterAll() {
  AddLaw<LinearElastic3DLaw>();
  AddLaw<LinearElasticPlaneStrain2DLaw>();
  AddLaw<LinearElasticPlaneStress2DLaw>();
  AddLaw<LinearElasticAxisym2DLaw>();
  AddLaw<HyperElastic3DLaw>();
  AddLaw<HyperElasticPlaneStrain2DLaw>();
  AddLaw<HyperElasticAxisym2DLaw>();
  AddLaw<KirchhoffSaintVenant3DLaw>();
  AddLaw<KirchhoffSaintVenantPlaneStrain2DLaw>();
  AddLaw<KirchhoffSaintVenantPlaneStress2DLaw>();

  const std::initializer_list<GT> solids_2d = {GT::Triangle2D3, GT::Triangle2D6, GT::Quadrilateral2D4,
                                               GT::Quadrilateral2D8, GT::Quadrilateral2D9};
  const std::initializer_list<GT> solids = {GT::Triangle2D3,   GT::Triangle2D6,   GT::Quadrilateral2D4,
                                            GT::Quadrilateral2D8, GT::Quadrilateral2D9, GT::Tetrahedra3D4,
                                            GT::Tetrahedra3D10, GT::Hexahedra3D8,  GT::Hexahedra3D20,
                                            GT::Hexahedra3D27,  GT::Prism3D6};
  AddAll<SmallDisplacementElement, Element>(solids);
  AddAll<TotalLagrangianElement, Element>(solids);
  AddAll<UpdatedLagrangianElement, Element>(solids);
  AddAll<AxisymSmallDisplacementElement, Element>(solids_2d);
  AddAll<AxisymTotalLagrangianElement, Element>(solids_2d);
  AddAll<AxisymUpdatedLagrangianElement, Element>(solids_2d);
  AddAll<MembraneElement, Element>({GT::Triangle3D3, GT::Quadrilateral3D4});

  AddAll<PointLoadCondition, Condition>({GT::Point2D, GT::Point3D});
  AddAll<AxisymPointLoadCondition, Condition>({GT::Point2D});
  AddAll<LineLoadCondition, Condition>({GT::Line2D2, GT::Line2D3, GT::Line3D2});
  AddAll<AxisymLineLoadCondition, Condition>({GT::Line2D2, GT::Line2D3});
  AddAll<SurfaceLoadCondition, Condition>(
      {GT::Triangle3D3, GT::Quadrilateral3D4, GT::Triangle3D6, GT::Quadrilateral3D8, GT::Quadrilateral3D9});
  AddAll<SkinCondition, Condition>({GT::Line2D2, GT::Line2D3, GT::Triangle3D3, GT::Quadrilateral3D4});
}

}  // namespace

void RegisterStructuralMechanics() {
  static std::once_flag once;
  std::call_once(once, RegisterAll);
}

}  // namespace mc
