// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <utility>

#include "core/model/constitutive_law.h"
#include "structural/constitutive_laws/voigt_utilities.h"

namespace mc {

/// Base of the elastic laws (linear, Kirchhoff-Saint Venant, Neo-Hookean): a stress S(E) with
/// its material tangent dS/dE, written once in 3D and reduced to the law's stress state.
///
/// Contract with the elements:
/// - measure PK2: `strain` is the input (infinitesimal strain for small-displacement elements,
///   Green-Lagrange for total Lagrangian ones); `stress` = S, `tangent` = dS/dE.
/// - measure Kirchhoff (Cauchy): E is computed from `F`, then pushed forward:
///   tau = F S F^T, c = T C T^T (both divided by det F for Cauchy). Used by the updated
///   Lagrangian element, whose spatial tangent is then exactly consistent.
/// Plane strain and axisymmetric states embed the reduced strain in 3D (E_zz = 0 in plane
/// strain, E_zz = hoop strain in axisymmetry) and keep the reduced components.
class ElasticLaw : public ConstitutiveLaw {
 public:
  enum class StressState { ThreeD, PlaneStrain, PlaneStress, Axisymmetric };

  int WorkingSpaceDimension() const override { return state_ == StressState::ThreeD ? 3 : 2; }
  int StrainSize() const override;

  /// YOUNG_MODULUS > 0 finite, -1 < POISSON_RATIO < 0.5, THICKNESS > 0 and DENSITY >= 0 when
  /// present.
  void Check(const Properties& properties) const override;
  void CalculateMaterialResponse(ConstitutiveLawParameters& values, StressMeasure measure) override;
  /// Energy per unit reference volume at `values.strain`.
  double StrainEnergy(ConstitutiveLawParameters& values) override;

  StressState State() const noexcept { return state_; }

 protected:
  explicit ElasticLaw(StressState state) : state_(state) {}

  /// Lame parameters (lambda, mu) of the properties.
  static std::pair<double, double> Lame(const Properties& properties);

  /// S(E) and dS/dE in full 3D Voigt.
  virtual void Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                          voigt::Matrix6& C) const = 0;
  virtual double Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const = 0;

  /// The reduced response; the default embeds E in 3D. Plane stress laws override it.
  virtual void ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E,
                               voigt::StrainVector& S, voigt::TangentMatrix& C) const;
  virtual double ReducedEnergy(const ConstitutiveLawParameters& values, const voigt::StrainVector& E) const;

 private:
  StressState state_;
};

}  // namespace mc
