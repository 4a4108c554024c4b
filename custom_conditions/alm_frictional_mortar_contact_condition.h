// SPDX-License-Identifier: BSD-3-Clause
// Signs as in mortar_contact_condition.h and frictional_mortar_contact_condition.h.
#pragma once

#include <memory>

#include "custom_conditions/frictional_mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// Augmented Lagrangian Coulomb frictional mortar contact (thesis sec. 4.3.4; Gitterle et al. 2010):
/// VECTOR_LAGRANGE_MULTIPLIER_X/Y[/Z] DoFs per slave node (reaction WEIGHTED_VECTOR_RESIDUAL). With
/// lbar_n = k n_j . lambda_j + eps_j g_j, T_j the tangential projection and s_j the weighted slip:
///  - stick (ACTIVE, not SLIP): the traction lbar_n n_j + k T(lambda_j) + c_tau eps_j s_j against
///    (D du1 - M du2)_j; multiplier rows k g_j n_j + k T(s_j);
///  - slip (ACTIVE and SLIP): the Coulomb traction lbar_n (n_j - mu_j d_j), d_j the direction of
///    lbar_t = k T(lambda_j) + c_slip c_tau eps_j s_j; multiplier rows k g_j n_j and
///    -k^2/eps_j T(k T(lambda_j) + mu_j lbar_n d_j) / k (Kratos: k^2/(c_tau eps_j); formulation.py says why not);
///  - inactive: the multiplier rows are -k^2/eps_j lambda_j.
/// The local RHS and its exact tangent are generated (automatic_differentiation/, generated/).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class ALMFrictionalMortarContactCondition : public FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster> {
 public:
  using Base = FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>;
  using Data = typename Base::Data;
  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

 protected:
  const char* Stem() const override { return "ALMFrictionalMortarContactCondition"; }
  int MultiplierComponents() const override { return TDim; }
  const Variable<double>& MultiplierVariable(int c) const override { return Base::VectorMultiplierComponent(c); }
  void GatherMultipliers(Data& data) const override { this->GatherVectorMultipliers(data); }
  /// k T(lambda_j) + c_slip c_tau eps_j s_j.
  Eigen::Matrix<double, TDim, 1> AugmentedTangentPressure(const Data& data, int j) const override;
  void AddRHS(const Data& data, Vector& rhs) const override;
  void AddLHS(const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const override;
};

#define MC_EXTERN(D, S, M) extern template class ALMFrictionalMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
