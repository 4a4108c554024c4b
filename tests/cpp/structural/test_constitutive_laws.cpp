// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (structural substrate, constitutive laws): tangents are the exact derivative of the
// stress, Neo-Hookean reduces to Hooke at small strain and matches the uniaxial closed form,
// plane stress / Kirchhoff push-forward are consistent, Check reports id, variable and value.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>

#include "structural/constitutive_laws/elastic_law.h"
#include "structural/constitutive_laws/voigt_utilities.h"
#include "structural_test_utilities.h"

namespace mc {
namespace {

const char* const kLaws[] = {"LinearElastic3DLaw",
                             "LinearElasticPlaneStrain2DLaw",
                             "LinearElasticPlaneStress2DLaw",
                             "LinearElasticAxisym2DLaw",
                             "HyperElastic3DLaw",
                             "HyperElasticPlaneStrain2DLaw",
                             "HyperElasticAxisym2DLaw",
                             "KirchhoffSaintVenant3DLaw",
                             "KirchhoffSaintVenantPlaneStrain2DLaw",
                             "KirchhoffSaintVenantPlaneStress2DLaw"};

struct LawFixture {
  std::unique_ptr<Properties> properties;
  std::unique_ptr<ConstitutiveLaw> law;
  ConstitutiveLawParameters values;
  explicit LawFixture(const std::string& name, double young = 200.0, double nu = 0.3)
      : properties(test::MakeProperties(7, name, young, nu)), law(properties->GetConstitutiveLaw()->Clone()) {
    values.properties = properties.get();
  }
  Vector Stress(const Vector& strain) {
    values.strain = strain;
    law->CalculateMaterialResponse(values, ConstitutiveLaw::StressMeasure::PK2);
    return values.stress;
  }
};

Vector SampleStrain(int size, double scale) {
  Vector e(size);
  for (int i = 0; i < size; ++i) e[i] = scale * test::Pseudo(i + 3);
  return e;
}

TEST(ConstitutiveLaws, TangentEqualsFiniteDifferenceOfStress) {
  for (const char* name : kLaws) {
    LawFixture f(name);
    const Vector E = SampleStrain(f.law->StrainSize(), 0.08);
    f.Stress(E);
    const Matrix C = f.values.tangent;
    ASSERT_EQ(C.rows(), f.law->StrainSize()) << name;
    Matrix fd(C.rows(), C.cols());
    const double h = 1e-6;
    for (Eigen::Index j = 0; j < C.cols(); ++j) {
      Vector ep = E, em = E;
      ep[j] += h;
      em[j] -= h;
      fd.col(j) = (f.Stress(ep) - f.Stress(em)) / (2.0 * h);
    }
    EXPECT_LT(test::RelativeError(C, fd), 1e-6) << name;
  }
}

TEST(ConstitutiveLaws, StressIsDerivativeOfEnergy) {
  for (const char* name : kLaws) {
    LawFixture f(name);
    const Vector E = SampleStrain(f.law->StrainSize(), 0.05);
    const Vector S = f.Stress(E);
    Vector fd(S.size());
    const double h = 1e-6;
    for (Eigen::Index j = 0; j < S.size(); ++j) {
      Vector ep = E, em = E;
      ep[j] += h;
      em[j] -= h;
      f.values.strain = ep;
      const double wp = f.law->StrainEnergy(f.values);
      f.values.strain = em;
      const double wm = f.law->StrainEnergy(f.values);
      fd[j] = (wp - wm) / (2.0 * h);
    }
    EXPECT_LT(test::RelativeError(S, fd), 1e-7) << name;
  }
}

TEST(ConstitutiveLaws, NeoHookeanSmallStrainLimitIsHooke) {
  const std::pair<const char*, const char*> pairs[] = {
      {"HyperElastic3DLaw", "LinearElastic3DLaw"},
      {"HyperElasticPlaneStrain2DLaw", "LinearElasticPlaneStrain2DLaw"},
      {"HyperElasticAxisym2DLaw", "LinearElasticAxisym2DLaw"}};
  for (const auto& [hyper, linear] : pairs) {
    LawFixture h(hyper), l(linear);
    const Vector zero = Vector::Zero(h.law->StrainSize());
    h.Stress(zero);
    l.Stress(zero);
    EXPECT_LT(test::RelativeError(l.values.tangent, h.values.tangent), 1e-14) << hyper;
    const Vector E = SampleStrain(h.law->StrainSize(), 1e-7);
    EXPECT_LT(test::RelativeError(l.Stress(E), h.Stress(E)), 1e-6) << hyper;
  }
}

TEST(ConstitutiveLaws, NeoHookeanUniaxialStretchClosedForm) {
  const double young = 200.0, nu = 0.3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  for (const double stretch : {0.7, 1.0, 1.3, 2.0}) {
    LawFixture f("HyperElastic3DLaw", young, nu);
    Vector E = Vector::Zero(6);
    E[0] = 0.5 * (stretch * stretch - 1.0);
    const Vector S = f.Stress(E);
    const double lnJ = std::log(stretch);
    EXPECT_NEAR(S[0], mu * (1.0 - 1.0 / (stretch * stretch)) + lambda * lnJ / (stretch * stretch), 1e-12 * young);
    EXPECT_NEAR(S[1], lambda * lnJ, 1e-12 * young);
    EXPECT_NEAR(S[2], lambda * lnJ, 1e-12 * young);
    EXPECT_NEAR(S.tail(3).norm(), 0.0, 1e-14 * young);
    const double W = 0.5 * mu * (stretch * stretch - 1.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
    f.values.strain = E;
    EXPECT_NEAR(f.law->StrainEnergy(f.values), W, 1e-12 * young);
  }
}

TEST(ConstitutiveLaws, KirchhoffSaintVenantIsHookeInGreenLagrange) {
  LawFixture f("KirchhoffSaintVenant3DLaw", 200.0, 0.25);
  const double lambda = 200.0 * 0.25 / (1.25 * 0.5), mu = 200.0 / 2.5;
  const Vector E = SampleStrain(6, 0.3);
  const Vector S = f.Stress(E);
  const double tr = E.head(3).sum();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(S[i], lambda * tr + 2 * mu * E[i], 1e-12);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(S[i], mu * E[i], 1e-12);
}

TEST(ConstitutiveLaws, PlaneStressMatches3DWithZeroNormalStress) {
  const double young = 200.0, nu = 0.3;
  LawFixture ps("LinearElasticPlaneStress2DLaw", young, nu), full("LinearElastic3DLaw", young, nu);
  Vector e(3);
  e << 1e-3, -2e-3, 5e-4;
  const Vector s = ps.Stress(e);
  Vector e6 = Vector::Zero(6);
  e6[0] = e[0];
  e6[1] = e[1];
  e6[3] = e[2];
  e6[2] = -nu / (1.0 - nu) * (e[0] + e[1]);
  const Vector s6 = full.Stress(e6);
  EXPECT_NEAR(s6[2], 0.0, 1e-12);
  EXPECT_NEAR(s[0], s6[0], 1e-12);
  EXPECT_NEAR(s[1], s6[1], 1e-12);
  EXPECT_NEAR(s[2], s6[3], 1e-12);
}

TEST(ConstitutiveLaws, KirchhoffMeasureIsPushForwardOfPK2) {
  for (const char* name : {"HyperElastic3DLaw", "HyperElasticAxisym2DLaw", "LinearElasticPlaneStrain2DLaw"}) {
    LawFixture f(name);
    const int n = f.law->StrainSize();
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 0) = 1.1;
    F(0, 1) = 0.2;
    F(1, 0) = -0.05;
    F(1, 1) = 0.95;
    if (n == 6) F(2, 0) = 0.1, F(1, 2) = 0.07, F(2, 2) = 1.05;
    if (n == 4) F(2, 2) = 1.08;
    const Eigen::Matrix3d gl = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    const voigt::Vector6 e6 = voigt::StrainToVoigt(gl);
    Vector E(n);
    for (int a = 0; a < n; ++a) E[a] = e6[voigt::Components(n)[a]];
    const Eigen::Matrix3d S = voigt::StressToTensor(f.Stress(E));
    f.values.F = F;
    f.law->CalculateMaterialResponse(f.values, ConstitutiveLaw::StressMeasure::Kirchhoff);
    const Eigen::Matrix3d tau = voigt::StressToTensor(f.values.stress);
    EXPECT_LT((tau - F * S * F.transpose()).norm(), 1e-12 * S.norm()) << name;
    f.law->CalculateMaterialResponse(f.values, ConstitutiveLaw::StressMeasure::Cauchy);
    EXPECT_LT((voigt::StressToTensor(f.values.stress) * F.determinant() - tau).norm(), 1e-12 * S.norm()) << name;
  }
}

void ExpectCheckError(double young, double nu, const std::string& variable, const std::string& value) {
  for (const char* name : kLaws) {
    auto properties = test::MakeProperties(42, name, young, nu);
    try {
      properties->GetConstitutiveLaw()->Check(*properties);
      ADD_FAILURE() << name << " accepted E=" << young << " nu=" << nu;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("properties 42"), std::string::npos) << message;
      EXPECT_NE(message.find(variable), std::string::npos) << message;
      EXPECT_NE(message.find(value), std::string::npos) << message;
    }
  }
}

TEST(ConstitutiveLaws, CheckNamesPropertiesVariableAndValue) {
  ExpectCheckError(-5.0, 0.3, "YOUNG_MODULUS", "-5");
  ExpectCheckError(std::numeric_limits<double>::quiet_NaN(), 0.3, "YOUNG_MODULUS", "nan");
  ExpectCheckError(100.0, 0.5, "POISSON_RATIO", "0.5");
  ExpectCheckError(100.0, -1.0, "POISSON_RATIO", "-1");
  auto properties = test::MakeProperties(3, "LinearElastic3DLaw");
  properties->SetValue(DENSITY, -1.0);
  EXPECT_THROW(properties->GetConstitutiveLaw()->Check(*properties), InputError);
  properties->SetValue(DENSITY, 1.0);
  properties->SetValue(THICKNESS, 0.0);
  EXPECT_THROW(properties->GetConstitutiveLaw()->Check(*properties), InputError);
  properties->SetValue(THICKNESS, 0.1);
  EXPECT_NO_THROW(properties->GetConstitutiveLaw()->Check(*properties));
  Properties empty(9);
  try {
    properties->GetConstitutiveLaw()->Check(empty);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("properties 9"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("YOUNG_MODULUS is missing"), std::string::npos);
  }
}

TEST(ConstitutiveLaws, DimensionsAndStrainSizes) {
  RegisterStructuralMechanics();
  const auto& registry = Registry<ConstitutiveLaw>::Instance();
  EXPECT_EQ(registry.Get("LinearElastic3DLaw").StrainSize(), 6);
  EXPECT_EQ(registry.Get("LinearElasticAxisym2DLaw").StrainSize(), 4);
  EXPECT_EQ(registry.Get("HyperElasticPlaneStrain2DLaw").WorkingSpaceDimension(), 2);
  EXPECT_TRUE(registry.Get("HyperElastic3DLaw").IsFiniteStrain());
  EXPECT_FALSE(registry.Get("LinearElastic3DLaw").IsFiniteStrain());
  for (const char* name : kLaws) EXPECT_EQ(registry.Get(name).Name(), name);
  EXPECT_TRUE(registry.Get("KirchhoffSaintVenantPlaneStress2DLaw").IsFiniteStrain());
  EXPECT_TRUE(registry.Get("KirchhoffSaintVenant3DLaw").HasConstantTangent());
  EXPECT_FALSE(registry.Get("HyperElasticAxisym2DLaw").HasConstantTangent());
  EXPECT_EQ(ElasticLaw::Names().size(), std::size(kLaws));
  try {
    ElasticLaw law("LinearElastic3DLow");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'LinearElastic3DLaw'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mc
