// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc {

/// The mortar operators of one (slave, master) pair in the current configuration, as the MPC contact
/// constraints need them: per slave node j the lumped D_j (the dual basis makes D diagonal) and the row
/// M_jl over the master nodes l.
struct MPCPairOperators {
  Eigen::Matrix<double, 4, 1> d = Eigen::Matrix<double, 4, 1>::Zero();
  Eigen::Matrix<double, 4, 4> m = Eigen::Matrix<double, 4, 4>::Zero();
};

/// What the MPC contact constraints ask of any pair, whatever its geometry.
class MPCMortarContactConditionBase : public PairedCondition {
 public:
  using PairedCondition::PairedCondition;
  /// The pair's D and M at the current coordinates and nodal NORMALs of its slave nodes; false without
  /// overlap (or when only a sliver overlaps: its standard-basis D is not diagonal).
  virtual bool ComputeOperators(MPCPairOperators& operators, const ProcessInfo& info) const = 0;
};

/// `MPCMortarContactCondition<geometry token>` (spec 6.2): a contact pair of the multipoint-constraint
/// route. It adds nothing to the system itself: the contact is imposed by master-slave constraints that
/// MPCContactConstraints builds from the summed operators of all pairs (D^-1 M, the mortar projection of
/// the master onto the slave nodes). No DoFs of its own: the displacements are the elements'.
template <int TDim, int TNumNodes, int TNumNodesMaster>
class MPCMortarContactCondition : public MPCMortarContactConditionBase {
 public:
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;
  using MPCMortarContactConditionBase::MPCMortarContactConditionBase;

  /// "MPCMortarContactCondition" + geometry token ("2D2N", "3D3N4N", ...).
  std::string Info() const override;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override { dofs.clear(); }
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override { lhs.resize(0, 0); }
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override { rhs.resize(0); }
  /// Adds the pair's nodal areas (int N1_j over the overlap) to NODAL_AREA of its slave nodes
  /// (atomic; the caller zeroes it): a slave node outside every overlap keeps 0 and is ISOLATED.
  void AddExplicitContribution(const ProcessInfo& info) override;

  bool ComputeOperators(MPCPairOperators& operators, const ProcessInfo& info) const override;
};

#define MC_EXTERN(D, S, M) extern template class MPCMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
