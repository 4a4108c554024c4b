// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <string>
#include <vector>

#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc {

/// What the mesh-tying process asks of any tying pair, whatever its geometry.
class MeshTyingMortarConditionBase : public PairedCondition {
 public:
  using PairedCondition::PairedCondition;
  /// Tied components per node: TDim (array variable) or 1 (scalar).
  virtual int Components() const noexcept = 0;
  /// The multiplier DoF variable of component c.
  virtual const Variable<double>& MultiplierVariable(int c) const = 0;
  /// Whether the pair overlaps (only then does it list and tie its slave multipliers).
  virtual bool HasOverlap(const ProcessInfo& info) const = 0;
  /// Per slave node j and component c: whether this pair gives row (j, c) of the tie a coefficient on a
  /// free DoF (D_ji on a slave DoF, or a non-zero M_jl on a master DoF). A row without one anywhere
  /// (both sides fixed there, e.g. a roller through the interface) leaves its multiplier undetermined:
  /// the support takes that load (MeshTyingUtilities fixes such multipliers to zero).
  virtual std::vector<std::array<bool, 3>> SlaveRowsWithFreeDofs(const ProcessInfo& info) const = 0;
};

/// Dual-mortar mesh tying of one (slave, master) pair, `MeshTyingMortarCondition<geometry token>`
/// (spec 6.2): ties a nodal variable u across non-matching interface meshes. Summed over the pairs
/// of slave node j, one row per component c:
///   (D u_s - M u_m)_jc = 0,
/// with D, M the pair's mortar operators (MortarPairKinematics, dual basis: D is diagonal) and the
/// multiplier lambda_jc as the unknown of that row. The tied variable is the properties'
/// TYING_VARIABLE (DISPLACEMENT when absent, as Kratos' default): an array variable ties its TDim
/// components with VECTOR_LAGRANGE_MULTIPLIER (ComponentsMeshTying), a scalar one (TEMPERATURE)
/// itself with SCALAR_LAGRANGE_MULTIPLIER (ScalarMeshTying).
///
/// The operators are those of the pair's initial coordinates (X0) and of the slave nodal NORMALs at
/// the time they are first needed, kept for the pair's life: tying constrains the variable, not the
/// positions, so it is linear and its tangent constant (a tie does not slide). With Kratos'
/// database_step_update (never search again) that is the reference configuration. The clipped
/// polygons are cut as a fan whatever CONSIDER_TESSELLATION says (the sub-triangulation does not
/// change D and M of a flat interface; Kratos' Delaunay option is not implemented).
///
/// Sign convention, as the contact conditions (custom_conditions/mortar_contact_condition.h): with
/// k = ProcessInfo[SCALE_FACTOR] (1 when absent), k lambda_j is the traction of the master side on
/// the slave side, and the residual (external-force sign) is
///   master rows  -k M^T lambda,   slave rows  +k D^T lambda,   multiplier rows  +k (D u_s - M u_m),
/// LHS = -d RHS / d DoFs (symmetric). DoF order: [master u, slave u, slave lambda], node-major.
template <int TDim, int TNumNodes, int TNumNodesMaster>
class MeshTyingMortarCondition : public MeshTyingMortarConditionBase {
 public:
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;
  using DMatrix = typename Kinematics::DMatrix;
  using MMatrix = typename Kinematics::MMatrix;
  using SlaveVector = typename Kinematics::SlaveVector;

  /// Reads TYING_VARIABLE from `properties` (may be null: DISPLACEMENT).
  MeshTyingMortarCondition(IndexType id, Geometry slave_geometry, Properties* properties, Geometry paired_geometry);

  /// "MeshTyingMortarCondition" + geometry token ("2D2N", "3D3N4N", ...).
  std::string Info() const override;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  std::unique_ptr<PairedCondition> CreatePaired(IndexType id, Condition& slave, Condition& master,
                                                Properties* properties) const override;

  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void InitializeSolutionStep(const ProcessInfo& info) override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// The nodes carry the tied variable's DoFs and the multiplier DoFs; SCALE_FACTOR is positive.
  void Check(const ProcessInfo& info) const override;
  /// Adds the pair's nodal areas (int N1_j over the overlap) to NODAL_AREA of its slave nodes (atomic;
  /// the caller zeroes it): a slave node outside every overlap keeps 0 and is ISOLATED.
  void AddExplicitContribution(const ProcessInfo& info) override;

  int Components() const noexcept override { return components_; }
  const Variable<double>& MultiplierVariable(int c) const override { return *multiplier_[c]; }
  bool HasOverlap(const ProcessInfo& info) const override;
  std::vector<std::array<bool, 3>> SlaveRowsWithFreeDofs(const ProcessInfo& info) const override;
  /// (master + slave) * components, plus the slave multipliers when the pair overlaps: a pair without
  /// overlap ties nothing, and its multiplier rows would be empty (singular for a slave node that has
  /// no other pair).
  int LocalSize(const ProcessInfo& info) const;
  /// The pair's operators (computed on first use, see above).
  const DMatrix& D(const ProcessInfo& info) const;
  const MMatrix& M(const ProcessInfo& info) const;

 private:
  /// Computes the operators once; called from the const DoF listing too (the builder lists the DoFs
  /// before any other call), hence the mutable members. Each pair is touched by one thread at a time.
  void EnsureOperators(const ProcessInfo& info) const;
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info);

  int components_ = TDim;
  std::array<const Variable<double>*, 3> tied_{};        ///< tied DoF variable per component
  std::array<const Variable<double>*, 3> multiplier_{};  ///< multiplier DoF variable per component
  mutable bool operators_ready_ = false;
  mutable bool overlap_ = false;
  mutable DMatrix d_ = DMatrix::Zero();
  mutable MMatrix m_ = MMatrix::Zero();
  mutable SlaveVector nodal_area_ = SlaveVector::Zero();
};

#define MC_EXTERN(D, S, M) extern template class MeshTyingMortarCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
