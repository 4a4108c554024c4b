// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/linear_elastic_3d_law.h"

namespace mc {

/// Hooke law in plane stress (S_zz = 0), components (xx, yy, xy):
/// D = E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]].
class LinearElasticPlaneStress2DLaw : public LinearElastic3DLaw {
 public:
  LinearElasticPlaneStress2DLaw() : LinearElastic3DLaw(StressState::PlaneStress) {}
  std::string Name() const override { return "LinearElasticPlaneStress2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override {
    return std::make_unique<LinearElasticPlaneStress2DLaw>(*this);
  }

 protected:
  void ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E, voigt::StrainVector& S,
                       voigt::TangentMatrix& C) const override;
  double ReducedEnergy(const ConstitutiveLawParameters& values, const voigt::StrainVector& E) const override;
};

}  // namespace mc
