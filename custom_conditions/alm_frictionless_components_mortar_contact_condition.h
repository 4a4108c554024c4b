// SPDX-License-Identifier: BSD-3-Clause
// Signs: WEIGHTED_GAP g_j = -n_j . (D x1 - M x2)_j is positive when open; the contact pressure is
// negative in compression, so a node with augmented pressure k lambda_n + eps g < 0 is ACTIVE
// (penalty: eps g < 0). RHS = residual (external-force sign), LHS = -d RHS / d DoFs.
#pragma once

#include <memory>

#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// Vector (components) augmented Lagrangian frictionless mortar contact (thesis eqs. 4.16-4.17,
/// 4.36): VECTOR_LAGRANGE_MULTIPLIER_X/Y[/Z] DoFs per slave node (reaction WEIGHTED_VECTOR_RESIDUAL).
/// Per slave node j, with the augmented traction k lambda_j + eps_j g_j n_j:
///  - active: displacement rows carry the augmented traction against (D du1 - M du2)_j; the
///    multiplier rows k g_j n_j minus k^2/eps_j times the tangential part of lambda_j (penalised to zero);
///  - inactive: the multiplier rows are -k^2/eps_j lambda_j.
/// The local RHS and its exact tangent are generated (automatic_differentiation/, generated/).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class ALMFrictionlessComponentsMortarContactCondition
    : public MortarContactCondition<TDim, TNumNodes, TNumNodesMaster> {
 public:
  using Base = MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>;
  using Data = typename Base::Data;
  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

 protected:
  const char* Stem() const override { return "ALMFrictionlessComponentsMortarContactCondition"; }
  int MultiplierComponents() const override { return TDim; }
  const Variable<double>& MultiplierVariable(int c) const override { return Base::VectorMultiplierComponent(c); }
  void GatherMultipliers(Data& data) const override { this->GatherVectorMultipliers(data); }
  void AddRHS(const Data& data, Vector& rhs) const override;
  void AddLHS(const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const override;
};

#define MC_EXTERN(D, S, M) extern template class ALMFrictionlessComponentsMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
