// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/elastic_law.h"

namespace mc {

/// Isotropic Hooke law S = lambda tr(E) I + 2 mu E on the strain the element provides
/// (infinitesimal strain in small displacement; Green-Lagrange when used in finite strain).
class LinearElastic3DLaw : public ElasticLaw {
 public:
  LinearElastic3DLaw() : ElasticLaw(StressState::ThreeD) {}
  std::string Name() const override { return "LinearElastic3DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<LinearElastic3DLaw>(*this); }
  bool HasConstantTangent() const override { return true; }

 protected:
  explicit LinearElastic3DLaw(StressState state) : ElasticLaw(state) {}
  void Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                  voigt::Matrix6& C) const override;
  double Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const override;
};

}  // namespace mc
