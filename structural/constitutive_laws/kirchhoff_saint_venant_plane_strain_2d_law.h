// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/constitutive_laws/kirchhoff_saint_venant_3d_law.h"

namespace mc {

/// St. Venant-Kirchhoff in plane strain (E_zz = 0), components (xx, yy, xy).
class KirchhoffSaintVenantPlaneStrain2DLaw : public KirchhoffSaintVenant3DLaw {
 public:
  KirchhoffSaintVenantPlaneStrain2DLaw() : KirchhoffSaintVenant3DLaw(StressState::PlaneStrain) {}
  std::string Name() const override { return "KirchhoffSaintVenantPlaneStrain2DLaw"; }
  std::unique_ptr<ConstitutiveLaw> Clone() const override {
    return std::make_unique<KirchhoffSaintVenantPlaneStrain2DLaw>(*this);
  }
};

}  // namespace mc
