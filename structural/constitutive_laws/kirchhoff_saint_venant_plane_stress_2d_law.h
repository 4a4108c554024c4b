// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/linear_elastic_plane_stress_2d_law.h"

namespace mc {

/// St. Venant-Kirchhoff in plane stress (S_zz = 0): the plane-stress Hooke matrix between the
/// Green-Lagrange strain and PK2, components (xx, yy, xy).
class KirchhoffSaintVenantPlaneStress2DLaw : public LinearElasticPlaneStress2DLaw {
 public:
  std::string Name() const override { return "KirchhoffSaintVenantPlaneStress2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override {
    return std::make_unique<KirchhoffSaintVenantPlaneStress2DLaw>(*this);
  }
  bool IsFiniteStrain() const override { return true; }
};

}  // namespace mc
