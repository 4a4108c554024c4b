// SPDX-License-Identifier: BSD-3-Clause
#include "structural/constitutive_laws/linear_elastic_3d_law.h"

namespace mc {

void LinearElastic3DLaw::Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                                    voigt::Matrix6& C) const {
  const auto [lambda, mu] = Lame(*values.properties);
  C.setZero();
  C.topLeftCorner<3, 3>().setConstant(lambda);
  C.topLeftCorner<3, 3>().diagonal().array() += 2.0 * mu;
  C.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  S = C * E;
}

double LinearElastic3DLaw::Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const {
  voigt::Vector6 S;
  voigt::Matrix6 C;
  Response3D(values, E, S, C);
  return 0.5 * E.dot(S);
}

}  // namespace mc
