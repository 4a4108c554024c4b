// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/model/constitutive_law.h"
#include "core/model/element.h"

namespace mc {

/// Displacement-based solid element for every 2D (plane, axisymmetric) and 3D geometry. The
/// kinematic variants differ only in three choices made per integration point, so they share
/// this one implementation:
///
/// | variant              | B-matrix                         | law input / output        | geometric stiffness |
/// |----------------------|----------------------------------|---------------------------|---------------------|
/// | small displacement   | reference gradients, F = I       | eps = B u -> sigma        | none                |
/// | total Lagrangian     | reference gradients, current F   | Green-Lagrange E -> PK2 S | grad N . S . grad N |
/// | updated Lagrangian   | spatial gradients (dN/dx), F = I | F -> Kirchhoff tau        | grad N . tau . grad N |
///
/// Integrals are over the reference volume (dV0, times THICKNESS in plane problems, times
/// 2 pi R in axisymmetry with x = radius); the updated Lagrangian form is the spatial
/// rewriting of the total one (f = int B_x^T tau dV0), so both give the same equilibrium for
/// path-independent (elastic) laws. Axisymmetric hoop strain rows: N/R (small displacement),
/// F_thth N/R (total), N/r (updated).
///
/// Sign conventions: RHS = f_ext - f_int, LHS = d(f_int - f_ext)/du (tangent stiffness).
///
/// Registered names (Kratos'): SmallDisplacementElement, TotalLagrangianElement and
/// UpdatedLagrangianElement + "<dim>D<nodes>N", with the prefix "Axisym" in axisymmetry.
class SolidElement final : public Element {
 public:
  enum class Kinematics { SmallDisplacement, TotalLagrangian, UpdatedLagrangian };

  SolidElement(IndexType id, Geometry geometry, Properties* properties, Kinematics kinematics, bool axisymmetric)
      : Element(id, std::move(geometry), properties), kinematics_(kinematics), axisymmetric_(axisymmetric) {}
  /// The same variant on other nodes.
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;

  /// E.g. "TotalLagrangianElement2D4N", "AxisymSmallDisplacementElement2D3N".
  std::string Info() const override;
  Kinematics GetKinematics() const noexcept { return kinematics_; }
  bool IsAxisymmetric() const noexcept { return axisymmetric_; }

  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;

  /// Clones the properties' law once per integration point.
  void Initialize(const ProcessInfo& info) override;
  /// Small displacement with linear laws at every integration point.
  bool HasConstantLeftHandSide() const override;
  void FinalizeSolutionStep(const ProcessInfo& info) override;

  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// Consistent mass (DENSITY), or its diagonal scaling (HRZ) when ProcessInfo
  /// COMPUTE_LUMPED_MASS_MATRIX is true; both keep the total mass.
  void CalculateMassMatrix(Matrix& mass, const ProcessInfo& info) override;
  /// RAYLEIGH_ALPHA M + RAYLEIGH_BETA K; properties values override the ProcessInfo ones.
  void CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info) override;

  /// Properties with a law that fits the element, nodal DISPLACEMENT and its DoFs, and a
  /// non-inverted initial configuration.
  void Check(const ProcessInfo& info) const override;

  using Element::CalculateOnIntegrationPoints;
  /// VON_MISES_STRESS, STRAIN_ENERGY (density per reference volume).
  void CalculateOnIntegrationPoints(const Variable<double>& var, std::vector<double>& out,
                                    const ProcessInfo& info) override;
  /// CAUCHY_STRESS_VECTOR, PK2_STRESS_VECTOR, GREEN_LAGRANGE_STRAIN_VECTOR (the infinitesimal
  /// strain for small displacement), in the law's Voigt order.
  void CalculateOnIntegrationPoints(const Variable<Vector>& var, std::vector<Vector>& out,
                                    const ProcessInfo& info) override;
  /// CAUCHY_STRESS_TENSOR, PK2_STRESS_TENSOR: dim x dim, 3 x 3 in axisymmetry.
  void CalculateOnIntegrationPoints(const Variable<Matrix>& var, std::vector<Matrix>& out,
                                    const ProcessInfo& info) override;

 private:
  struct PointState;
  struct PointResults;

  int Dimension() const noexcept;
  int StrainSize() const noexcept;
  void EnsureLaws();
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info);
  /// Stress state of one point for outputs: PK2 (and strain) from the law, Cauchy pushed forward.
  void EvaluateResults(int g, PointResults& results, const ProcessInfo& info);
  /// out[g] = extract(results of integration point g), for every point.
  template <class T, class Extract>
  void CollectResults(std::vector<T>& out, const ProcessInfo& info, Extract extract);

  Kinematics kinematics_;
  bool axisymmetric_;
  std::vector<std::unique_ptr<ConstitutiveLaw>> laws_;
};

}  // namespace mc
