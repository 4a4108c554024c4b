// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/hyper_elastic_3d_law.h"

namespace mc {

/// Compressible Neo-Hookean in plane strain (E_zz = 0), components (xx, yy, xy).
class HyperElasticPlaneStrain2DLaw : public HyperElastic3DLaw {
 public:
  HyperElasticPlaneStrain2DLaw() : HyperElastic3DLaw(StressState::PlaneStrain) {}
  std::string Name() const override { return "HyperElasticPlaneStrain2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override {
    return std::make_unique<HyperElasticPlaneStrain2DLaw>(*this);
  }
};

}  // namespace mc
