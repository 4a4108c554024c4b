// SPDX-License-Identifier: BSD-3-Clause
// Sign conventions of every mortar contact condition (thesis ch. 4, Kratos CSMA):
//  - weighted gap g_j = -n_j . (D x1 - M x2)_j (WEIGHTED_GAP): positive when open, negative
//    when penetrating; n_j is the slave nodal NORMAL, pointing out of the slave body;
//  - contact pressure lambda_n (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, or NORMAL .
//    VECTOR_LAGRANGE_MULTIPLIER): negative in compression; the augmented pressure
//    k lambda_n + eps g_j < 0 means the node is ACTIVE (in contact);
//  - RHS = residual with the external-force sign, LHS = -d RHS / d DoFs.
#pragma once

#include <string>

#include "custom_conditions/mortar_kernel_data.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc {

/// What the mortar contact pair conditions share: a slave interface condition (own geometry)
/// paired with a master one, the mortar kinematics of the pair (MortarPairKinematics, one
/// thread-local instance, no heap allocation per pair), the DoF layout
/// [master u, slave u, slave multipliers], the contact parameters and the explicit update of
/// the nodal weighted gap.
///
/// Parameters: eps_j = nodal INITIAL_PENALTY if the node has one, else
/// ProcessInfo[INITIAL_PENALTY]; k = ProcessInfo[SCALE_FACTOR] (1 when absent); the nodal
/// DYNAMIC_FACTOR (1 when absent); INTEGRATION_ORDER_CONTACT (default 2) and
/// CONSIDER_TESSELLATION from the properties, ZERO_TOLERANCE_FACTOR from the ProcessInfo.
/// The current coordinates are the nodes' Coordinates() (X0 + DISPLACEMENT).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class MortarContactCondition : public PairedCondition {
 public:
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;
  using Data = MortarKernelData<TDim, TNumNodes, TNumNodesMaster>;
  static constexpr int kNumDisplacementDofs = Kinematics::kNumDisplacementDofs;

  using PairedCondition::PairedCondition;

  /// Stem + geometry token, e.g. "ALMFrictionlessMortarContactCondition3D3N4N".
  std::string Info() const override;
  /// "2D2N", "3D3N", "3D4N", "3D3N4N", "3D4N3N".
  static std::string GeometryToken();

  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// Nodes carry DISPLACEMENT, the multiplier variables and DoFs, WEIGHTED_GAP; eps and k positive.
  void Check(const ProcessInfo& info) const override;

  /// Adds this pair's weighted gap to the historical WEIGHTED_GAP of its slave nodes and its
  /// nodal areas to NODAL_AREA (non-historical; not for a sliver overlap, see MortarPairKinematics). Atomic
  /// accumulation, so pairs may be processed in parallel; the caller zeroes both variables on the slave nodes
  /// beforehand.
  void AddExplicitContribution(const ProcessInfo& info) override;

  int LocalSize() const noexcept { return kNumDisplacementDofs + TNumNodes * MultiplierComponents(); }

 protected:
  virtual const char* Stem() const = 0;
  /// Multiplier DoFs per slave node: 0 (penalty), 1 (scalar pressure) or TDim (vector).
  virtual int MultiplierComponents() const = 0;
  /// Multiplier DoF variable of component c.
  virtual const Variable<double>& MultiplierVariable(int c) const;
  /// Reads the formulation's nodal multipliers into data.
  virtual void GatherMultipliers(Data& data) const {}
  /// Fills the inputs that need the pair's kinematics (computed before the call; frictional: the
  /// weighted slip). Default: nothing.
  virtual void CompleteKernelData(Data& data, const ProcessInfo& info) {}
  /// Explicit update of further nodal quantities from the pair's values-only kinematics (frictional:
  /// WEIGHTED_SLIP), also for a pair without overlap. Default: nothing.
  virtual void AddExplicitNodalValues(const Kinematics& kinematics, const ProcessInfo& info) {}
  /// VECTOR_LAGRANGE_MULTIPLIER_X/Y/Z, for the formulations with a vector multiplier.
  static const Variable<double>& VectorMultiplierComponent(int c);
  /// Reads VECTOR_LAGRANGE_MULTIPLIER of the slave nodes into data.vector_multiplier.
  void GatherVectorMultipliers(Data& data) const;
  /// The generated kernels; rhs / lhs are sized and zeroed. Given normal_sensitivity (sized
  /// LocalSize() x TDim * TNumNodes, zeroed), AddLHS also adds -d rhs / d n to it (slave normal
  /// components, node-major), for the normal variation.
  virtual void AddRHS(const Data& data, Vector& rhs) const = 0;
  virtual void AddLHS(const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const = 0;

  /// Whether the mortar integrals are weighted by 2 pi r (axisymmetric variants).
  virtual bool IsAxisymmetric() const { return false; }
  /// Whether the 3D fan start of the step's first evaluation is kept through the step
  /// (MortarFanHistory::hold) rather than following Kratos' rule.
  virtual bool HoldsFanStart() const { return false; }
  /// Whether the overlap of a 3D pair with a quadrilateral is integrated at least with the
  /// degree-4 triangle rule (order 3), exact for the bilinear integrands of flat quadrilaterals,
  /// whatever INTEGRATION_ORDER_CONTACT asks (see FrictionalMortarContactCondition).
  virtual bool IntegratesQuadrilateralsExactly() const { return false; }
  /// Integration settings of the pair (properties, ProcessInfo, IsAxisymmetric()).
  MortarIntegrationSettings IntegrationSettings(const ProcessInfo& info) const;
  /// Current slave / master coordinates.
  void GatherCoordinates(typename Kinematics::SlaveMatrix& x1, typename Kinematics::MasterMatrix& x2) const;
  /// The slave nodal normals (NORMAL).
  void GatherSlaveNormals(typename Kinematics::SlaveMatrix& n1) const;
  /// Current slave / master coordinates and slave nodal normals.
  void GatherKinematicsInput(typename Kinematics::SlaveMatrix& x1, typename Kinematics::MasterMatrix& x2,
                             typename Kinematics::SlaveMatrix& n1) const;
  /// The pair's local system (LocalSize()) at the current coordinates and the given slave
  /// normals n1; with normal_sensitivity (needs lhs) also S = -d rhs / d n1 (LocalSize() x
  /// TDim * TNumNodes). Null outputs are skipped.
  void CalculatePairSystem(Matrix* lhs, Vector* rhs, const ProcessInfo& info,
                           const typename Kinematics::SlaveMatrix& n1, Matrix* normal_sensitivity);

 private:
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info);
  void FillData(Data& data, const ProcessInfo& info) const;
  /// min(0, WEIGHTED_GAP / NODAL_AREA) of the slave nodes, as last updated (0 where NODAL_AREA is
  /// not positive): the mean gaps MortarPairKinematics::SetMeanGaps holds the weights of.
  typename Kinematics::SlaveVector PenetratingMeanGaps() const;

  /// The fan starts of the pair's overlap in the current step (MortarIntegrationSettings).
  mutable MortarFanHistory fan_history_;
};

#define MC_EXTERN(D, S, M) extern template class MortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
