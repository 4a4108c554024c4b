// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/register_contact_conditions.h"

#include <memory>
#include <mutex>
#include <string>

#include "core/model/registry.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/not_implemented_pair_condition.h"
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

void AddPlaceholder(const std::string& name, const std::string& reason, GT slave, GT master) {
  Registry<Condition>::Instance().Add(
      name, std::make_shared<const NotImplementedPairCondition>(name, reason, Geometry(slave, {}), Geometry(master, {})));
}

void RegisterAll() {
  AddAllGeometries<ALMFrictionlessMortarContactCondition>();
  AddAllGeometries<ALMFrictionlessComponentsMortarContactCondition>();
  AddAllGeometries<PenaltyFrictionlessMortarContactCondition>();

  const std::string nv_reason =
      "the normal variation (normal_variation: nodal_elemental_derivatives) needs the derivatives of the "
      "averaged nodal normals through the neighbouring interface conditions, which are not available yet; "
      "use the name without 'NV' (normal_variation: no_derivatives_computation)";
  const struct {
    const char* token;
    GT slave, master;
  } geometries[] = {{"2D2N", GT::Line2D2, GT::Line2D2},
                    {"3D3N", GT::Triangle3D3, GT::Triangle3D3},
                    {"3D4N", GT::Quadrilateral3D4, GT::Quadrilateral3D4},
                    {"3D3N4N", GT::Triangle3D3, GT::Quadrilateral3D4},
                    {"3D4N3N", GT::Quadrilateral3D4, GT::Triangle3D3}};
  for (const char* stem : {"ALMNVFrictionlessMortarContactCondition", "ALMNVFrictionlessComponentsMortarContactCondition",
                           "PenaltyNVFrictionlessMortarContactCondition"})
    for (const auto& g : geometries) AddPlaceholder(std::string(stem) + g.token, nv_reason, g.slave, g.master);

  const std::string axisym_reason =
      "the axisymmetric mortar operators (integrals weighted by 2 pi r) and their derivatives are not "
      "provided by MortarPairKinematics yet";
  for (const char* name : {"ALMFrictionlessAxisymMortarContactCondition2D2N", "ALMNVFrictionlessAxisymMortarContactCondition2D2N",
                           "PenaltyFrictionlessAxisymMortarContactCondition2D2N",
                           "PenaltyNVFrictionlessAxisymMortarContactCondition2D2N"})
    AddPlaceholder(name, axisym_reason, GT::Line2D2, GT::Line2D2);
}

}  // namespace

void RegisterContactConditions() {
  static std::once_flag once;
  std::call_once(once, RegisterAll);
}

}  // namespace mc
