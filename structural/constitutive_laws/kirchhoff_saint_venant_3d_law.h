// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/linear_elastic_3d_law.h"

namespace mc {

/// St. Venant-Kirchhoff hyperelasticity S = lambda tr(E) I + 2 mu E with E the Green-Lagrange
/// strain: Hooke's relation between the finite-strain measures.
class KirchhoffSaintVenant3DLaw : public LinearElastic3DLaw {
 public:
  KirchhoffSaintVenant3DLaw() : LinearElastic3DLaw(StressState::ThreeD) {}
  std::string Name() const override { return "KirchhoffSaintVenant3DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override { return std::make_unique<KirchhoffSaintVenant3DLaw>(*this); }
  bool IsFiniteStrain() const override { return true; }

 protected:
  explicit KirchhoffSaintVenant3DLaw(StressState state) : LinearElastic3DLaw(state) {}
};

}  // namespace mc
