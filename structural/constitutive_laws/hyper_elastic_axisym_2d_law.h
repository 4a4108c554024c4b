// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/hyper_elastic_3d_law.h"

namespace mc {

/// Compressible Neo-Hookean in axisymmetry, components (rr, zz, rz, theta-theta).
class HyperElasticAxisym2DLaw : public HyperElastic3DLaw {
 public:
  HyperElasticAxisym2DLaw() : HyperElastic3DLaw(StressState::Axisymmetric) {}
  std::string Name() const override { return "HyperElasticAxisym2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<HyperElasticAxisym2DLaw>(*this); }
};

}  // namespace mc
