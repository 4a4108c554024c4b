// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/linear_elastic_3d_law.h"

namespace mc {

/// Hooke law in plane strain (E_zz = 0), components (xx, yy, xy).
class LinearElasticPlaneStrain2DLaw : public LinearElastic3DLaw {
 public:
  LinearElasticPlaneStrain2DLaw() : LinearElastic3DLaw(StressState::PlaneStrain) {}
  std::string Name() const override { return "LinearElasticPlaneStrain2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override {
    return std::make_unique<LinearElasticPlaneStrain2DLaw>(*this);
  }
};

}  // namespace mc
