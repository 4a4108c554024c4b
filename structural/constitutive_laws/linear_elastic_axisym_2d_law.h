// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/linear_elastic_3d_law.h"

namespace mc {

/// Hooke law in axisymmetry, components (rr, zz, rz, theta-theta).
class LinearElasticAxisym2DLaw : public LinearElastic3DLaw {
 public:
  LinearElasticAxisym2DLaw() : LinearElastic3DLaw(StressState::Axisymmetric) {}
  std::string Name() const override { return "LinearElasticAxisym2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<LinearElasticAxisym2DLaw>(*this); }
};

}  // namespace mc
