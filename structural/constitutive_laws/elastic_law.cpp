// SPDX-License-Identifier: BSD-3-Clause
#include "structural/constitutive_laws/elastic_law.h"

#include <Eigen/LU>
#include <cassert>
#include <cmath>

#include "core/model/properties.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

voigt::Vector6 Embed(const voigt::StrainVector& reduced) {
  voigt::Vector6 full = voigt::Vector6::Zero();
  const auto comps = voigt::Components(static_cast<int>(reduced.size()));
  for (std::size_t k = 0; k < comps.size(); ++k) full[comps[k]] = reduced[static_cast<Eigen::Index>(k)];
  return full;
}

}  // namespace

int ElasticLaw::StrainSize() const {
  switch (state_) {
    case StressState::ThreeD: return 6;
    case StressState::Axisymmetric: return 4;
    default: return 3;
  }
}

void ElasticLaw::Check(const Properties& properties) const {
  const auto fail = [&](const VariableData& var, const std::string& what, double value) {
    throw InputError(Concat("properties ", properties.Id(), " (", Name(), "): ", var.Name(), " = ", value, " ", what));
  };
  if (!properties.Has(YOUNG_MODULUS))
    throw InputError(Concat("properties ", properties.Id(), " (", Name(), "): YOUNG_MODULUS is missing"));
  if (!properties.Has(POISSON_RATIO))
    throw InputError(Concat("properties ", properties.Id(), " (", Name(), "): POISSON_RATIO is missing"));
  const double E = properties.GetValue(YOUNG_MODULUS);
  if (!(std::isfinite(E) && E > 0.0)) fail(YOUNG_MODULUS, "must be positive and finite", E);
  const double nu = properties.GetValue(POISSON_RATIO);
  if (!(nu > -1.0 && nu < 0.5)) fail(POISSON_RATIO, "must lie in (-1, 0.5)", nu);
  if (properties.Has(THICKNESS)) {
    const double t = properties.GetValue(THICKNESS);
    if (!(std::isfinite(t) && t > 0.0)) fail(THICKNESS, "must be positive and finite", t);
  }
  if (properties.Has(DENSITY)) {
    const double rho = properties.GetValue(DENSITY);
    if (!(std::isfinite(rho) && rho >= 0.0)) fail(DENSITY, "must be non-negative and finite", rho);
  }
}

std::pair<double, double> ElasticLaw::Lame(const Properties& properties) {
  const double E = properties.GetValue(YOUNG_MODULUS);
  const double nu = properties.GetValue(POISSON_RATIO);
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

void ElasticLaw::ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E,
                                 voigt::StrainVector& S, voigt::TangentMatrix& C) const {
  voigt::Vector6 S6;
  voigt::Matrix6 C6;
  Response3D(values, Embed(E), S6, C6);
  const auto comps = voigt::Components(static_cast<int>(E.size()));
  const auto n = static_cast<Eigen::Index>(comps.size());
  S.resize(n);
  C.resize(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    S[a] = S6[comps[a]];
    for (Eigen::Index b = 0; b < n; ++b) C(a, b) = C6(comps[a], comps[b]);
  }
}

double ElasticLaw::ReducedEnergy(const ConstitutiveLawParameters& values, const voigt::StrainVector& E) const {
  return Energy3D(values, Embed(E));
}

void ElasticLaw::CalculateMaterialResponse(ConstitutiveLawParameters& values, StressMeasure measure) {
  assert(values.properties);
  const int n = StrainSize();
  const auto comps = voigt::Components(n);
  voigt::StrainVector E(n);
  if (measure == StressMeasure::PK2) {
    assert(values.strain.size() == n);
    E = values.strain;
  } else {
    const Eigen::Matrix3d gl = 0.5 * (values.F.transpose() * values.F - Eigen::Matrix3d::Identity());
    const voigt::Vector6 e6 = voigt::StrainToVoigt(gl);
    for (int a = 0; a < n; ++a) E[a] = e6[comps[a]];
  }
  voigt::StrainVector S;
  voigt::TangentMatrix C;
  ReducedResponse(values, E, S, C);
  if (measure != StressMeasure::PK2) {
    const voigt::Matrix6 T6 = voigt::PushForwardMatrix(values.F);
    voigt::TangentMatrix T(n, n);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) T(a, b) = T6(comps[a], comps[b]);
    const double scale = measure == StressMeasure::Cauchy ? 1.0 / values.F.determinant() : 1.0;
    S = scale * (T * S);
    C = scale * (T * C * T.transpose());
  }
  if (values.compute_stress) values.stress = S;
  if (values.compute_tangent) values.tangent = C;
}

double ElasticLaw::StrainEnergy(ConstitutiveLawParameters& values) {
  assert(values.properties);
  return ReducedEnergy(values, values.strain);
}

}  // namespace mc
