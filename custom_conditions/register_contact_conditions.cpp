// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/register_contact_conditions.h"

#include <memory>
#include <mutex>
#include <string>

#include "core/model/registry.h"
#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/axisymmetric_mortar_contact_condition.h"
#include "custom_conditions/mesh_tying_mortar_condition.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "custom_conditions/normal_variation_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"

namespace mc {

namespace {

using GT = GeometryType;

template <template <int, int, int> class TCondition, int TDim, int TNumNodes, int TNumNodesMaster>
void Add(GT slave, GT master) {
  auto prototype = std::make_shared<const TCondition<TDim, TNumNodes, TNumNodesMaster>>(0, Geometry(slave, {}), nullptr,
                                                                                        Geometry(master, {}));
  Registry<Condition>::Instance().Add(prototype->Info(), prototype);
}

template <template <int, int, int> class TCondition>
void AddAllGeometries() {
  Add<TCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<TCondition, 3, 3, 3>(GT::Triangle3D3, GT::Triangle3D3);
  Add<TCondition, 3, 4, 4>(GT::Quadrilateral3D4, GT::Quadrilateral3D4);
  Add<TCondition, 3, 3, 4>(GT::Triangle3D3, GT::Quadrilateral3D4);
  Add<TCondition, 3, 4, 3>(GT::Quadrilateral3D4, GT::Triangle3D3);
}

void RegisterAll() {
  AddAllGeometries<ALMFrictionlessMortarContactCondition>();
  AddAllGeometries<ALMFrictionlessComponentsMortarContactCondition>();
  AddAllGeometries<PenaltyFrictionlessMortarContactCondition>();
  AddAllGeometries<ALMNVFrictionlessMortarContactCondition>();
  AddAllGeometries<ALMNVFrictionlessComponentsMortarContactCondition>();
  AddAllGeometries<PenaltyNVFrictionlessMortarContactCondition>();
  AddAllGeometries<ALMFrictionalMortarContactCondition>();
  AddAllGeometries<PenaltyFrictionalMortarContactCondition>();
  AddAllGeometries<ALMNVFrictionalMortarContactCondition>();
  AddAllGeometries<PenaltyNVFrictionalMortarContactCondition>();
  AddAllGeometries<MeshTyingMortarCondition>();
  AddAllGeometries<MPCMortarContactCondition>();

  Add<ALMFrictionlessAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<PenaltyFrictionlessAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<ALMNVFrictionlessAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<PenaltyNVFrictionlessAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<ALMFrictionalAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<PenaltyFrictionalAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<ALMNVFrictionalAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
  Add<PenaltyNVFrictionalAxisymMortarContactCondition, 2, 2, 2>(GT::Line2D2, GT::Line2D2);
}

}  // namespace

void RegisterContactConditions() {
  static std::once_flag once;
  std::call_once(once, RegisterAll);
}

}  // namespace mc
