// SPDX-License-Identifier: BSD-3-Clause
// Signs as in mortar_contact_condition.h: RHS = residual (external-force sign), LHS = -d RHS / d DoFs.
#pragma once

#include <memory>
#include <vector>

#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/axisymmetric_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/nodal_normal_support.h"

namespace mc {

/// The NV variant of a mortar formulation (normal_variation:
/// "nodal_elemental_derivatives", spec 4.4 and 6.2): the same residual, with the slave nodal
/// normals n_j as functions of the current coordinates (NodalNormalSupport: normalised sum of
/// the area vectors of the interface faces around j), and the EXACT tangent including dn_j/du:
///
///   LHS = LHS(fixed normals) + S . dn/du,   S = -d rhs / d n   (generated, through D, M, g_j and
///                                                               the explicit n_j in the residual).
///
/// dn_j/du involves the displacements of every node of the faces around j, also of nodes outside
/// the pair, so the DoF list is the pair's [master u, slave u, slave multipliers] followed by the
/// displacement DoFs of those neighbour nodes (fixed order, set with the support); their rows of
/// the RHS and LHS are zero. The support comes from the contact search (SetNodalNormalSupport).
template <class TFormulation>
class NormalVariationMortarContactCondition final : public TFormulation {
 public:
  using Base = TFormulation;
  using Kinematics = typename Base::Kinematics;
  static constexpr int kDim = Kinematics::kDim;
  static constexpr int kNumSlaveNodes = Kinematics::kNumSlaveNodes;
  static constexpr int kNumMasterNodes = Kinematics::kNumMasterNodes;

  using Base::Base;

  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

  bool NeedsNodalNormalSupport() const override { return true; }
  /// Also fixes the neighbour nodes (the extra DoF columns).
  void SetNodalNormalSupport(std::shared_ptr<const NodalNormalSupport> support) override;
  const NodalNormalSupport* GetNodalNormalSupport() const noexcept { return support_.get(); }
  /// Nodes outside the pair whose displacements move the slave normals, in DoF order.
  const std::vector<Node*>& NeighbourNodes() const noexcept { return neighbours_; }

  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// The base checks, and the support must be set.
  void Check(const ProcessInfo& info) const override;

  /// LocalSize() of the pair plus the neighbour displacement DoFs.
  int ExtendedSize() const noexcept { return this->LocalSize() + kDim * static_cast<int>(neighbours_.size()); }

 protected:
  const char* Stem() const override;

 private:
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info);
  /// Local column of node k's first displacement component in the extended DoF list.
  int Column(const Node* node) const;
  const NodalNormalSupport& Support() const;

  std::shared_ptr<const NodalNormalSupport> support_;
  std::vector<Node*> neighbours_;
};

template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMNVFrictionlessMortarContactCondition =
    NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMNVFrictionlessComponentsMortarContactCondition = NormalVariationMortarContactCondition<
    ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMNVFrictionlessAxisymMortarContactCondition = NormalVariationMortarContactCondition<
    ALMFrictionlessAxisymMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyNVFrictionlessAxisymMortarContactCondition = NormalVariationMortarContactCondition<
    PenaltyFrictionlessAxisymMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyNVFrictionlessMortarContactCondition =
    NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMNVFrictionalMortarContactCondition =
    NormalVariationMortarContactCondition<ALMFrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyNVFrictionalMortarContactCondition =
    NormalVariationMortarContactCondition<PenaltyFrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using ALMNVFrictionalAxisymMortarContactCondition =
    NormalVariationMortarContactCondition<ALMFrictionalAxisymMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;
template <int TDim, int TNumNodes, int TNumNodesMaster>
using PenaltyNVFrictionalAxisymMortarContactCondition = NormalVariationMortarContactCondition<
    PenaltyFrictionalAxisymMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>>;

extern template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<2, 2, 2>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 3, 3>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 4, 4>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 3, 4>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessMortarContactCondition<3, 4, 3>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<2, 2, 2>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 3, 3>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 4, 4>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 3, 4>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessComponentsMortarContactCondition<3, 4, 3>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<2, 2, 2>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 3, 3>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 4, 4>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 3, 4>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessMortarContactCondition<3, 4, 3>>;
extern template class NormalVariationMortarContactCondition<ALMFrictionlessAxisymMortarContactCondition<2, 2, 2>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionlessAxisymMortarContactCondition<2, 2, 2>>;
#define MC_EXTERN(D, S, M)                                                                                   \
  extern template class NormalVariationMortarContactCondition<ALMFrictionalMortarContactCondition<D, S, M>>; \
  extern template class NormalVariationMortarContactCondition<PenaltyFrictionalMortarContactCondition<D, S, M>>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN
extern template class NormalVariationMortarContactCondition<ALMFrictionalAxisymMortarContactCondition<2, 2, 2>>;
extern template class NormalVariationMortarContactCondition<PenaltyFrictionalAxisymMortarContactCondition<2, 2, 2>>;

}  // namespace mc
