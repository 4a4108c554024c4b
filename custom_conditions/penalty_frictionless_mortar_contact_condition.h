// SPDX-License-Identifier: BSD-3-Clause
// Signs: WEIGHTED_GAP g_j = -n_j . (D x1 - M x2)_j is positive when open; the contact pressure is
// negative in compression, so a node with augmented pressure k lambda_n + eps g < 0 is ACTIVE
// (penalty: eps g < 0). RHS = residual (external-force sign), LHS = -d RHS / d DoFs.
#pragma once

#include <memory>

#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// Penalty frictionless mortar contact (thesis eqs. 4.8, 4.34): displacement DoFs only. An active
/// slave node j (penetrating, set by the active-set utilities from the sign of the weighted gap)
/// carries the pressure eps_j g_j against n_j . (D du1 - M du2)_j; inactive nodes contribute nothing.
/// The local RHS and its exact tangent are generated (automatic_differentiation/, generated/).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class PenaltyFrictionlessMortarContactCondition : public MortarContactCondition<TDim, TNumNodes, TNumNodesMaster> {
 public:
  using Base = MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>;
  using Data = typename Base::Data;
  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

 protected:
  const char* Stem() const override { return "PenaltyFrictionlessMortarContactCondition"; }
  int MultiplierComponents() const override { return 0; }
  void AddRHS(const Data& data, Vector& rhs) const override;
  void AddLHS(const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const override;
};

#define MC_EXTERN(D, S, M) extern template class PenaltyFrictionlessMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
