// SPDX-License-Identifier: BSD-3-Clause
// Signs as in mortar_contact_condition.h and frictional_mortar_contact_condition.h.
#pragma once

#include <memory>

#include "custom_conditions/frictional_mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// Penalty Coulomb frictional mortar contact (thesis sec. 4.3.4): displacement DoFs only. Per
/// active slave node j, against (D du1 - M du2)_j: stick (not SLIP) the traction
/// eps_j g_j n_j + c_tau eps_j s_j, slip (SLIP) the Coulomb traction eps_j g_j (n_j - mu_j s_j/|s_j|);
/// inactive nodes contribute nothing. The local RHS and its exact tangent are generated
/// (automatic_differentiation/, generated/).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class PenaltyFrictionalMortarContactCondition
    : public FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster> {
 public:
  using Base = FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>;
  using Data = typename Base::Data;
  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

 protected:
  const char* Stem() const override { return "PenaltyFrictionalMortarContactCondition"; }
  int MultiplierComponents() const override { return 0; }
  /// c_tau eps_j s_j.
  Eigen::Matrix<double, TDim, 1> AugmentedTangentPressure(const Data& data, int j) const override;
  void AddRHS(const Data& data, Vector& rhs) const override;
  void AddLHS(const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const override;
};

#define MC_EXTERN(D, S, M) extern template class PenaltyFrictionalMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
