// SPDX-License-Identifier: BSD-3-Clause
#include "structural/constitutive_laws/hyper_elastic_3d_law.h"

#include <Eigen/LU>
#include <cmath>

#include "core/utilities/error.h"

namespace mc {

namespace {

// Right Cauchy-Green tensor C = I + 2E of a Voigt strain; throws when it is not positive.
Eigen::Matrix3d RightCauchyGreen(const voigt::Vector6& E, const ConstitutiveLaw& law, double& detC) {
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  for (int a = 0; a < 6; ++a) {
    const int i = voigt::kPairs[a][0], j = voigt::kPairs[a][1];
    if (i == j) {
      C(i, i) += 2.0 * E[a];
    } else {
      C(i, j) += E[a];
      C(j, i) += E[a];
    }
  }
  detC = C.determinant();
  if (!(detC > 0.0)) throw SolutionError(Concat(law.Name(), ": det C = ", detC, " is not positive (inverted material point)"));
  return C;
}

}  // namespace

namespace {

// ln J and d ln J / dE (a symmetric tensor; Voigt engineering shears differentiate to the
// off-diagonal entry). Finite strain: J = sqrt(det C), d ln J / dE = C^-1. Small-strain
// elements: J = det(I + eps) of the equivalent F, d ln J / d eps = (I + eps)^-1, as Kratos 10.4
// evaluates its Neo-Hookean law in SmallDisplacementElement (C = I + 2 eps, J = det F).
std::pair<double, Eigen::Matrix3d> VolumeChange(const ConstitutiveLawParameters& values, const Eigen::Matrix3d& Cinv,
                                                double detC) {
  if (values.small_strain) return {std::log(values.detF), values.F.inverse()};
  return {0.5 * std::log(detC), Cinv};
}

}  // namespace

void HyperElastic3DLaw::Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                                   voigt::Matrix6& C) const {
  const auto [lambda, mu] = Lame(*values.properties);
  double detC = 0.0;
  const Eigen::Matrix3d Cinv = RightCauchyGreen(E, *this, detC).inverse();
  const auto [lnJ, dlnJ] = VolumeChange(values, Cinv, detC);
  const double beta = mu - lambda * lnJ;
  for (int a = 0; a < 6; ++a) {
    const int i = voigt::kPairs[a][0], j = voigt::kPairs[a][1];
    S[a] = (i == j ? mu : 0.0) - beta * Cinv(i, j);
    for (int b = 0; b < 6; ++b) {
      const int k = voigt::kPairs[b][0], l = voigt::kPairs[b][1];
      C(a, b) = lambda * Cinv(i, j) * dlnJ(k, l) + beta * (Cinv(i, k) * Cinv(j, l) + Cinv(i, l) * Cinv(j, k));
    }
  }
}

double HyperElastic3DLaw::Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const {
  const auto [lambda, mu] = Lame(*values.properties);
  double detC = 0.0;
  const Eigen::Matrix3d C = RightCauchyGreen(E, *this, detC);
  const double lnJ = VolumeChange(values, Eigen::Matrix3d::Identity(), detC).first;
  return 0.5 * mu * (C.trace() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
}

}  // namespace mc
