// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"

namespace mc {

/// The axisymmetric variant of a 2D mortar formulation
/// (alternative_formulations.axisymmetric, spec 4.4 and 6.2; x = radius, y = axis): the same
/// residual and exact tangent, with every mortar integral (D, M, weighted gap, nodal area) taken
/// over the surface of revolution, i.e. weighted by 2 pi r at each integration point, and the dual
/// basis biorthogonal in that inner product (MortarPairKinematics, settings.axisymmetric). The
/// axisymmetric solid elements integrate with the same 2 pi r, so a uniform pressure is
/// transmitted exactly across non-matching meshes.
template <class TFormulation>
class AxisymmetricMortarContactCondition : public TFormulation {
 public:
  using Base = TFormulation;
  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

 protected:
  const char* Stem() const override;
  bool IsAxisymmetric() const override { return true; }
};

template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMFrictionlessAxisymMortarContactCondition =
    AxisymmetricMortarContactCondition<ALMFrictionlessMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyFrictionlessAxisymMortarContactCondition =
    AxisymmetricMortarContactCondition<PenaltyFrictionlessMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMFrictionalAxisymMortarContactCondition =
    AxisymmetricMortarContactCondition<ALMFrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyFrictionalAxisymMortarContactCondition =
    AxisymmetricMortarContactCondition<PenaltyFrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;

extern template class AxisymmetricMortarContactCondition<ALMFrictionlessMortarContactCondition<2, 2, 2>>;
extern template class AxisymmetricMortarContactCondition<PenaltyFrictionlessMortarContactCondition<2, 2, 2>>;
extern template class AxisymmetricMortarContactCondition<ALMFrictionalMortarContactCondition<2, 2, 2>>;
extern template class AxisymmetricMortarContactCondition<PenaltyFrictionalMortarContactCondition<2, 2, 2>>;

}  // namespace mc
