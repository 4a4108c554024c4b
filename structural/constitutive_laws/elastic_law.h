// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/model/constitutive_law.h"
#include "structural/constitutive_laws/voigt_utilities.h"

namespace mc {

/// The elastic laws: a stress S(E) with its material tangent dS/dE, written once in 3D per
/// material model and reduced to the law's stress state. Each Kratos law is a row of the table
/// in elastic_law.cpp (name, model, stress state, finite strain):
///
///   LinearElastic{3D, PlaneStrain2D, PlaneStress2D, Axisym2D}Law    Hooke, small strain
///   KirchhoffSaintVenant{3D, PlaneStrain2D, PlaneStress2D}Law       Hooke, finite strain
///   HyperElastic{3D, PlaneStrain2D, Axisym2D}Law                    Neo-Hookean, finite strain
///
/// Models:
/// - Hooke: S = lambda tr(E) I + 2 mu E on the strain the element provides (infinitesimal in
///   small displacement, Green-Lagrange in finite strain: St. Venant-Kirchhoff). In plane
///   stress (S_zz = 0): D = E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]].
/// - Neo-Hookean (compressible), C = I + 2E and J = sqrt(det C):
///     W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
///     S = mu (I - C^-1) + lambda ln J C^-1,
///     dS/dE = lambda C^-1 (x) C^-1 + (mu - lambda ln J) (C^-1_IK C^-1_JL + C^-1_IL C^-1_JK).
///   Small-displacement elements get Kratos 10.4's reading: the infinitesimal strain stands in
///   for E while J = det(I + eps) (their equivalent F), so d ln J / d eps = (I + eps)^-1
///   replaces the first C^-1 of the tangent.
///
/// Contract with the elements:
/// - measure PK2: `strain` is the input (infinitesimal strain for small-displacement elements,
///   Green-Lagrange for total Lagrangian ones); `stress` = S, `tangent` = dS/dE.
/// - measure Kirchhoff (Cauchy): E is computed from `F`, then pushed forward:
///   tau = F S F^T, c = T C T^T (both divided by det F for Cauchy). Used by the updated
///   Lagrangian element, whose spatial tangent is then exactly consistent.
/// Plane strain and axisymmetric states embed the reduced strain in 3D (E_zz = 0 in plane
/// strain, E_zz = hoop strain in axisymmetry) and keep the reduced components: (xx, yy, xy),
/// or (rr, zz, rz, theta-theta) in axisymmetry.
class ElasticLaw final : public ConstitutiveLaw {
 public:
  enum class Model { kHooke, kNeoHookean };
  enum class StressState { ThreeD, PlaneStrain, PlaneStress, Axisymmetric };
  struct Row;  ///< a row of the table

  /// The law of the table named `name` (a Kratos law name); InputError for any other name.
  explicit ElasticLaw(const std::string& name);
  /// The names of the table, in its order.
  static std::vector<std::string> Names();

  std::string Name() const override;
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<ElasticLaw>(*this); }
  int WorkingSpaceDimension() const override { return State() == StressState::ThreeD ? 3 : 2; }
  int StrainSize() const override;
  bool IsFiniteStrain() const override;
  /// Hooke's tangent does not depend on the strain.
  bool HasConstantTangent() const override { return GetModel() == Model::kHooke; }

  /// YOUNG_MODULUS > 0 finite, -1 < POISSON_RATIO < 0.5, THICKNESS > 0 and DENSITY >= 0 when
  /// present.
  void Check(const Properties& properties) const override;
  void CalculateMaterialResponse(ConstitutiveLawParameters& values, StressMeasure measure) override;
  /// Energy per unit reference volume at `values.strain`.
  double StrainEnergy(ConstitutiveLawParameters& values) override;

  Model GetModel() const noexcept;
  StressState State() const noexcept;

 private:
  /// The reduced response: the 3D one on the embedded strain, or plane-stress Hooke.
  void ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E, voigt::StrainVector& S,
                       voigt::TangentMatrix& C) const;
  double ReducedEnergy(const ConstitutiveLawParameters& values, const voigt::StrainVector& E) const;
  /// S(E) and dS/dE in full 3D Voigt.
  void Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                  voigt::Matrix6& C) const;
  double Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const;

  const Row* row_;
};

}  // namespace mc
