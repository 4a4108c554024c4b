// SPDX-License-Identifier: BSD-3-Clause
#include "structural/constitutive_laws/linear_elastic_plane_stress_2d_law.h"

#include "core/model/properties.h"
#include "core/variables/kernel_variables.h"

namespace mc {

void LinearElasticPlaneStress2DLaw::ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E,
                                                    voigt::StrainVector& S, voigt::TangentMatrix& C) const {
  const double young = values.properties->GetValue(YOUNG_MODULUS);
  const double nu = values.properties->GetValue(POISSON_RATIO);
  const double f = young / (1.0 - nu * nu);
  C.setZero(3, 3);
  C(0, 0) = C(1, 1) = f;
  C(0, 1) = C(1, 0) = f * nu;
  C(2, 2) = f * 0.5 * (1.0 - nu);
  S = C * E;
}

double LinearElasticPlaneStress2DLaw::ReducedEnergy(const ConstitutiveLawParameters& values, const voigt::StrainVector& E) const {
  voigt::StrainVector S;
  voigt::TangentMatrix C;
  ReducedResponse(values, E, S, C);
  return 0.5 * E.dot(S);
}

}  // namespace mc
