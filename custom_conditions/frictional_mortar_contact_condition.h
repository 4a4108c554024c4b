// SPDX-License-Identifier: BSD-3-Clause
// Signs as in mortar_contact_condition.h; the weighted slip s_j (WEIGHTED_SLIP) is the weighted
// tangential motion of the master relative to the slave: a slave sliding by a over a fixed master
// gives s_j ~ -D_jj a, so that the stick traction c_tau eps s_j resists the motion.
#pragma once

#include <Eigen/Core>

#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// What the Coulomb frictional mortar conditions (ALM and penalty) add to MortarContactCondition
/// (Gitterle, Popp, Gee, Wall 2010; thesis of V. Mataix Ferrandiz 2020, sec. 4.3.4):
///  - the mortar operators D_n, M_n of the last converged configuration, stored by the pair at
///    InitializeSolutionStep (before the predictor, so from the converged coordinates; on the first
///    step those of the initial configuration). A pair created later in the step (a new search)
///    computes them on first use from the coordinates of the previous step (X0 + DISPLACEMENT at
///    buffer index 1, the current coordinates with a buffer of 1) and the current normals;
///  - the weighted slip s_j = T_j [(D - D_n) x1 - (M - M_n) x2]_j, T_j = I - n_j n_j^T, an input of
///    the kernels and, summed over the pairs of a node, the explicit nodal WEIGHTED_SLIP;
///  - the per-node branch: an ACTIVE node is slip if it is SLIP and its augmented tangent pressure
///    (the slip direction) is non-zero, else stick; an inactive node is inactive.
///
/// With ProcessInfo[ACCUMULATED_WEIGHTED_SLIP] (explicit contact) a step is too short for its slip
/// increment to carry the stick traction: the kernels take the pair's share of the nodal
/// WEIGHTED_SLIP, which the explicit strategy accumulates while the node sticks, and D_n, M_n are
/// those of the previous step's coordinates (the residual of an explicit step is evaluated at the
/// configuration of InitializeSolutionStep, where the increment would vanish).
///
/// Parameters: mu_j = the slave node's FRICTION_COEFFICIENT if it has one, else the pair's
/// properties' (an error if neither); c_tau = ProcessInfo[TANGENT_FACTOR] (required, positive);
/// c_slip = ProcessInfo[SLIP_AUGMENTATION_COEFFICIENT] (0 when absent).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class FrictionalMortarContactCondition : public MortarContactCondition<TDim, TNumNodes, TNumNodesMaster> {
 public:
  using Base = MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>;
  using Data = typename Base::Data;
  using Kinematics = typename Base::Kinematics;
  using Base::Base;

  /// Stores D_n, M_n from the current (last converged) configuration; with
  /// ACCUMULATED_WEIGHTED_SLIP, marks them for recomputation from the previous step's coordinates.
  void InitializeSolutionStep(const ProcessInfo& info) override;
  /// The base checks; slave nodes carry WEIGHTED_SLIP and a friction coefficient, c_tau > 0.
  void Check(const ProcessInfo& info) const override;

 protected:
  /// The weighted slip compares D and M with the step start's: both from one fan.
  bool HoldsFanStart() const override { return true; }
  /// Kratos' order 2 (degree 2) is not exact for quadrilaterals, so the integrals depend on the
  /// fan's sub-triangles. Where a slave and a master edge are nearly parallel and cross (matching
  /// meshes), their crossing vertex moves along the edges about 1/angle times faster than the
  /// nodes, and D, M with it: in the first-contact stick step of tests/cases/friction_stick the
  /// residual varied on a scale of 1e-7 (a crossing angle of 1.6e-6) and Newton converged
  /// linearly until its increments were that small. Exact, they do not depend on the fan.
  bool IntegratesQuadrilateralsExactly() const override { return true; }
  /// The augmented tangent pressure of slave node j, whose direction is the slip direction.
  virtual Eigen::Matrix<double, TDim, 1> AugmentedTangentPressure(const Data& data, int j) const = 0;

  void CompleteKernelData(Data& data, const ProcessInfo& info) override;
  /// Adds the pair's weighted slip to WEIGHTED_SLIP of its slave nodes (atomic; zeroed by the caller).
  void AddExplicitNodalValues(const Kinematics& kinematics, const ProcessInfo& info) override;

 private:
  /// D_n, M_n of the configuration x1, x2 (values only, a kinematics object of its own).
  void StorePreviousOperators(const typename Kinematics::SlaveMatrix& x1, const typename Kinematics::MasterMatrix& x2,
                              const ProcessInfo& info);
  /// Computes D_n, M_n from the previous step's coordinates if the pair has none yet.
  void EnsurePreviousOperators(const ProcessInfo& info);
  /// data.symmetry_mask from the slave nodes' fixed multiplier components.
  void SymmetryMasks(Data& data) const;
  /// ACCUMULATED_WEIGHTED_SLIP: the pair's share of each slave node's nodal WEIGHTED_SLIP.
  void AccumulatedWeightedSlip(Data& data) const;
  double FrictionCoefficient(const Node& node) const;
  double TangentFactor(const ProcessInfo& info) const;

  typename Kinematics::DMatrix previous_D_ = Kinematics::DMatrix::Zero();
  typename Kinematics::MMatrix previous_M_ = Kinematics::MMatrix::Zero();
  bool has_previous_ = false;
};

#define MC_EXTERN(D, S, M) extern template class FrictionalMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
