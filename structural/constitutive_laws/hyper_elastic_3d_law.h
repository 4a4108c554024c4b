// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/elastic_law.h"

namespace mc {

/// Compressible Neo-Hookean hyperelasticity with C = I + 2E and J = sqrt(det C):
///   W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
///   S = mu (I - C^-1) + lambda ln J C^-1,
///   dS/dE = lambda C^-1 (x) C^-1 + (mu - lambda ln J) (C^-1_IK C^-1_JL + C^-1_IL C^-1_JK).
/// The stress is a function of the strain vector, so the law also serves small-displacement
/// elements (with the infinitesimal strain standing in for E) with a consistent tangent.
class HyperElastic3DLaw : public ElasticLaw {
 public:
  HyperElastic3DLaw() : ElasticLaw(StressState::ThreeD) {}
  std::string Name() const override { return "HyperElastic3DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<HyperElastic3DLaw>(*this); }
  bool IsFiniteStrain() const override { return true; }

 protected:
  explicit HyperElastic3DLaw(StressState state) : ElasticLaw(state) {}
  void Response3D(const Properties& properties, const voigt::Vector6& E, voigt::Vector6& S,
                  voigt::Matrix6& C) const override;
  double Energy3D(const Properties& properties, const voigt::Vector6& E) const override;
};

}  // namespace mc
