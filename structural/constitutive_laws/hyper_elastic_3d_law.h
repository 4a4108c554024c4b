// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/elastic_law.h"

namespace mc {

/// Compressible Neo-Hookean hyperelasticity with C = I + 2E and J = sqrt(det C):
///   W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
///   S = mu (I - C^-1) + lambda ln J C^-1,
///   dS/dE = lambda C^-1 (x) C^-1 + (mu - lambda ln J) (C^-1_IK C^-1_JL + C^-1_IL C^-1_JK).
/// Small-displacement elements get Kratos 10.4's reading: the infinitesimal strain stands in
/// for E while J = det(I + eps) (their equivalent F), so d ln J / d eps = (I + eps)^-1 replaces
/// the first C^-1 of the tangent.
class HyperElastic3DLaw : public ElasticLaw {
 public:
  HyperElastic3DLaw() : ElasticLaw(StressState::ThreeD) {}
  std::string Name() const override { return "HyperElastic3DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<HyperElastic3DLaw>(*this); }
  bool IsFiniteStrain() const override { return true; }

 protected:
  explicit HyperElastic3DLaw(StressState state) : ElasticLaw(state) {}
  void Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                  voigt::Matrix6& C) const override;
  double Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const override;
};

}  // namespace mc
