// SPDX-License-Identifier: BSD-3-Clause
#include "structural/constitutive_laws/elastic_law.h"

#include <Eigen/LU>
#include <array>
#include <cassert>
#include <cmath>

#include "core/model/properties.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"

namespace mc {

struct ElasticLaw::Row {
  const char* name;
  Model model;
  StressState state;
  bool finite_strain;
};

namespace {

using Model = ElasticLaw::Model;
using State = ElasticLaw::StressState;

/// The laws, by Kratos name.
constexpr std::array<ElasticLaw::Row, 10> kLaws = {{
    {"LinearElastic3DLaw", Model::kHooke, State::ThreeD, false},
    {"LinearElasticPlaneStrain2DLaw", Model::kHooke, State::PlaneStrain, false},
    {"LinearElasticPlaneStress2DLaw", Model::kHooke, State::PlaneStress, false},
    {"LinearElasticAxisym2DLaw", Model::kHooke, State::Axisymmetric, false},
    {"HyperElastic3DLaw", Model::kNeoHookean, State::ThreeD, true},
    {"HyperElasticPlaneStrain2DLaw", Model::kNeoHookean, State::PlaneStrain, true},
    {"HyperElasticAxisym2DLaw", Model::kNeoHookean, State::Axisymmetric, true},
    {"KirchhoffSaintVenant3DLaw", Model::kHooke, State::ThreeD, true},
    {"KirchhoffSaintVenantPlaneStrain2DLaw", Model::kHooke, State::PlaneStrain, true},
    {"KirchhoffSaintVenantPlaneStress2DLaw", Model::kHooke, State::PlaneStress, true},
}};

voigt::Vector6 Embed(const voigt::StrainVector& reduced) {
  voigt::Vector6 full = voigt::Vector6::Zero();
  const auto comps = voigt::Components(static_cast<int>(reduced.size()));
  for (std::size_t k = 0; k < comps.size(); ++k) full[comps[k]] = reduced[static_cast<Eigen::Index>(k)];
  return full;
}

/// Lame parameters (lambda, mu) of the properties.
std::pair<double, double> Lame(const Properties& properties) {
  const double E = properties.GetValue(YOUNG_MODULUS);
  const double nu = properties.GetValue(POISSON_RATIO);
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

void HookeResponse(const Properties& properties, const voigt::Vector6& E, voigt::Vector6& S, voigt::Matrix6& C) {
  const auto [lambda, mu] = Lame(properties);
  C.setZero();
  C.topLeftCorner<3, 3>().setConstant(lambda);
  C.topLeftCorner<3, 3>().diagonal().array() += 2.0 * mu;
  C.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  S = C * E;
}

void PlaneStressHookeResponse(const Properties& properties, const voigt::StrainVector& E, voigt::StrainVector& S,
                              voigt::TangentMatrix& C) {
  const double young = properties.GetValue(YOUNG_MODULUS);
  const double nu = properties.GetValue(POISSON_RATIO);
  const double f = young / (1.0 - nu * nu);
  C.setZero(3, 3);
  C(0, 0) = C(1, 1) = f;
  C(0, 1) = C(1, 0) = f * nu;
  C(2, 2) = f * 0.5 * (1.0 - nu);
  S = C * E;
}

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
  if (!(detC > 0.0))
    throw SolutionError(Concat(law.Name(), ": det C = ", detC, " is not positive (inverted material point)"));
  return C;
}

// ln J and d ln J / dE (a symmetric tensor; Voigt engineering shears differentiate to the
// off-diagonal entry). Finite strain: J = sqrt(det C), d ln J / dE = C^-1. Small-strain
// elements: J = det(I + eps) of the equivalent F, d ln J / d eps = (I + eps)^-1, as Kratos 10.4
// evaluates its Neo-Hookean law in SmallDisplacementElement (C = I + 2 eps, J = det F).
std::pair<double, Eigen::Matrix3d> VolumeChange(const ConstitutiveLawParameters& values, const Eigen::Matrix3d& Cinv,
                                                double detC) {
  if (values.small_strain) return {std::log(values.detF), values.F.inverse()};
  return {0.5 * std::log(detC), Cinv};
}

void NeoHookeanResponse(const ConstitutiveLawParameters& values, const ConstitutiveLaw& law, const voigt::Vector6& E,
                        voigt::Vector6& S, voigt::Matrix6& C) {
  const auto [lambda, mu] = Lame(*values.properties);
  double detC = 0.0;
  const Eigen::Matrix3d Cinv = RightCauchyGreen(E, law, detC).inverse();
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

double NeoHookeanEnergy(const ConstitutiveLawParameters& values, const ConstitutiveLaw& law, const voigt::Vector6& E) {
  const auto [lambda, mu] = Lame(*values.properties);
  double detC = 0.0;
  const Eigen::Matrix3d C = RightCauchyGreen(E, law, detC);
  const double lnJ = VolumeChange(values, Eigen::Matrix3d::Identity(), detC).first;
  return 0.5 * mu * (C.trace() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
}

}  // namespace

ElasticLaw::ElasticLaw(const std::string& name) : row_(nullptr) {
  for (const Row& row : kLaws)
    if (name == row.name) row_ = &row;
  if (!row_) throw InputError(Concat("unknown elastic law '", name, "'", DidYouMean(name, Names())));
}

std::vector<std::string> ElasticLaw::Names() {
  std::vector<std::string> names;
  for (const Row& row : kLaws) names.emplace_back(row.name);
  return names;
}

std::string ElasticLaw::Name() const { return row_->name; }
bool ElasticLaw::IsFiniteStrain() const { return row_->finite_strain; }
ElasticLaw::Model ElasticLaw::GetModel() const noexcept { return row_->model; }
ElasticLaw::StressState ElasticLaw::State() const noexcept { return row_->state; }

int ElasticLaw::StrainSize() const {
  switch (State()) {
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

void ElasticLaw::Response3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E, voigt::Vector6& S,
                            voigt::Matrix6& C) const {
  if (GetModel() == Model::kHooke)
    HookeResponse(*values.properties, E, S, C);
  else
    NeoHookeanResponse(values, *this, E, S, C);
}

double ElasticLaw::Energy3D(const ConstitutiveLawParameters& values, const voigt::Vector6& E) const {
  if (GetModel() == Model::kNeoHookean) return NeoHookeanEnergy(values, *this, E);
  voigt::Vector6 S;
  voigt::Matrix6 C;
  HookeResponse(*values.properties, E, S, C);
  return 0.5 * E.dot(S);
}

void ElasticLaw::ReducedResponse(const ConstitutiveLawParameters& values, const voigt::StrainVector& E,
                                 voigt::StrainVector& S, voigt::TangentMatrix& C) const {
  if (State() == StressState::PlaneStress) {
    assert(GetModel() == Model::kHooke);
    PlaneStressHookeResponse(*values.properties, E, S, C);
    return;
  }
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
  if (State() == StressState::PlaneStress) {
    voigt::StrainVector S;
    voigt::TangentMatrix C;
    PlaneStressHookeResponse(*values.properties, E, S, C);
    return 0.5 * E.dot(S);
  }
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
