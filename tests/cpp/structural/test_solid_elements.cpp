// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (structural substrate, solid elements): for every kinematics x geometry, rigid-body
// motions give no internal force, the tangent is the finite-difference derivative of the
// internal force, the mass matrix holds density x volume, axisymmetric uniform expansion gives
// the exact stress, and Check / the solve report inverted elements.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "structural_test_utilities.h"

namespace mc {
namespace {

using test::NodeSet;

struct ElementCase {
  std::string stem;
  GeometryType type;
  std::string law;
};

std::vector<ElementCase> AllCases(bool hyperelastic) {
  std::vector<ElementCase> cases;
  for (const char* stem : {"SmallDisplacementElement", "TotalLagrangianElement", "UpdatedLagrangianElement"}) {
    for (GeometryType t : test::Solids2D())
      cases.push_back({stem, t, hyperelastic ? "HyperElasticPlaneStrain2DLaw" : "LinearElasticPlaneStrain2DLaw"});
    for (GeometryType t : test::Solids3D())
      cases.push_back({stem, t, hyperelastic ? "HyperElastic3DLaw" : "LinearElastic3DLaw"});
    for (GeometryType t : test::Solids2D())
      cases.push_back(
          {std::string("Axisym") + stem, t, hyperelastic ? "HyperElasticAxisym2DLaw" : "LinearElasticAxisym2DLaw"});
  }
  return cases;
}

struct ElementSetup {
  NodeSet nodes;
  std::unique_ptr<Properties> properties;
  std::unique_ptr<Element> element;
  std::string name;
  ElementSetup(const ElementCase& c, bool affine = false) {
    properties = test::MakeProperties(1, c.law);
    name = c.stem + test::Suffix(c.type);
    element =
        Registry<Element>::Instance().Get(name).Create(17, test::PlaceNodes(nodes, c.type, affine), properties.get());
    element->Initialize(ProcessInfo{});
  }
};

TEST(SolidElements, RegisteredNamesMatchInfo) {
  for (const auto& c : AllCases(false)) {
    ElementSetup s(c);
    EXPECT_EQ(s.element->Info(), s.name);
    EXPECT_NO_THROW(s.element->Check(ProcessInfo{})) << s.name;
  }
}

// The builder reuses the element matrix within a step only for elements whose stiffness cannot
// change: small displacement with a linear law, and that tangent is indeed state-independent.
TEST(SolidElements, ConstantLeftHandSideOnlyForSmallDisplacementWithLinearLaws) {
  for (bool hyperelastic : {false, true}) {
    for (const auto& c : AllCases(hyperelastic)) {
      ElementSetup s(c);
      const bool expected = !hyperelastic && c.stem.find("SmallDisplacement") != std::string::npos;
      ASSERT_EQ(s.element->HasConstantLeftHandSide(), expected) << s.name << " with " << c.law;
      if (!expected) continue;
      Matrix K0;
      s.element->CalculateLeftHandSide(K0, ProcessInfo{});
      test::SetDisplacements(s.element->GetGeometry(), [](const Array3&, int i) {
        return Array3(0.05 * test::Pseudo(3 * i), 0.05 * test::Pseudo(3 * i + 1), 0.05 * test::Pseudo(3 * i + 2));
      });
      Matrix K1;
      s.element->CalculateLeftHandSide(K1, ProcessInfo{});
      EXPECT_LT(test::RelativeError(K1, K0), 1e-14) << s.name;
    }
  }
}

TEST(SolidElements, RigidBodyMotionGivesNoInternalForce) {
  for (const auto& c : AllCases(false)) {
    ElementSetup s(c);
    const bool axisym = c.stem.starts_with("Axisym");
    const Array3 t = axisym ? Array3(0.0, 0.37, 0.0) : Array3(0.3, -0.2, 0.45);
    test::SetDisplacements(s.element->GetGeometry(), [&](const Array3&, int) { return t; });
    Vector rhs;
    ProcessInfo info;
    s.element->CalculateRightHandSide(rhs, info);
    EXPECT_LT(rhs.cwiseAbs().maxCoeff(), 1e-12) << s.name << " translation";
    if (c.stem.find("Lagrangian") != std::string::npos && !axisym) {
      // A finite rotation about z (and x in 3D) is rigid for the finite-strain kinematics.
      const int dim = s.element->GetGeometry().WorkingSpaceDimension();
      Eigen::Matrix3d Q = Eigen::AngleAxisd(0.6, Array3::UnitZ()).toRotationMatrix();
      if (dim == 3) Q = Q * Eigen::AngleAxisd(-0.4, Array3::UnitX()).toRotationMatrix();
      test::SetDisplacements(s.element->GetGeometry(), [&](const Array3& X, int) { return Array3(Q * X - X + t); });
      s.element->CalculateRightHandSide(rhs, info);
      EXPECT_LT(rhs.cwiseAbs().maxCoeff(), 1e-11) << s.name << " rotation";
    }
  }
}

void CheckTangent(bool hyperelastic) {
  for (const auto& c : AllCases(hyperelastic)) {
    ElementSetup s(c);
    test::SetDisplacements(s.element->GetGeometry(), [](const Array3& X, int a) {
      return Array3(0.04 * test::Pseudo(3 * a) + 0.05 * X[1], 0.04 * test::Pseudo(3 * a + 1) - 0.03 * X[0],
                    0.04 * test::Pseudo(3 * a + 2) + 0.02 * X[0]);
    });
    Matrix K;
    Vector rhs;
    ProcessInfo info;
    s.element->CalculateLocalSystem(K, rhs, info);
    ASSERT_GT(rhs.norm(), 1e-3) << s.name;
    const Matrix fd = test::FiniteDifferenceTangent(*s.element, 1e-6);
    EXPECT_LT(test::RelativeError(K, fd), 1e-6) << s.name << " with " << c.law;
    Matrix lhs_only;
    s.element->CalculateLeftHandSide(lhs_only, info);
    EXPECT_EQ((lhs_only - K).cwiseAbs().maxCoeff(), 0.0) << s.name;
  }
}

TEST(SolidElements, TangentEqualsFiniteDifferencesLinearElastic) { CheckTangent(false); }
TEST(SolidElements, TangentEqualsFiniteDifferencesHyperElastic) { CheckTangent(true); }

TEST(SolidElements, UpdatedAndTotalLagrangianAgree) {
  for (const auto& c : AllCases(true)) {
    if (c.stem.find("TotalLagrangian") == std::string::npos) continue;
    ElementCase ul = c;
    ul.stem.replace(ul.stem.find("Total"), 5, "Updated");
    ElementSetup a(c), b(ul);
    for (ElementSetup* s : {&a, &b})
      test::SetDisplacements(s->element->GetGeometry(), [](const Array3& X, int i) {
        return Array3(0.05 * test::Pseudo(i) + 0.1 * X[1], -0.04 * X[0], 0.03 * test::Pseudo(i + 9));
      });
    Matrix Ka, Kb;
    Vector ra, rb;
    a.element->CalculateLocalSystem(Ka, ra, ProcessInfo{});
    b.element->CalculateLocalSystem(Kb, rb, ProcessInfo{});
    EXPECT_LT(test::RelativeError(ra, rb), 1e-12) << b.name;
    EXPECT_LT(test::RelativeError(Ka, Kb), 1e-12) << b.name;
  }
}

double ReferenceMeasure(GeometryType type) {
  switch (ReferenceElement::Get(type).Family()) {
    case GeometryFamily::Triangle: return 0.5;
    case GeometryFamily::Quadrilateral: return 4.0;
    case GeometryFamily::Tetrahedron: return 1.0 / 6.0;
    case GeometryFamily::Hexahedron: return 8.0;
    default: return 0.5;  // prism: unit triangle x zeta in [0, 1]
  }
}

TEST(SolidElements, MassMatrixSumsToDensityTimesVolume) {
  for (const auto& c : AllCases(false)) {
    if (c.stem != "SmallDisplacementElement") continue;
    ElementSetup s(c, true);
    const int dim = s.element->GetGeometry().WorkingSpaceDimension();
    const double det = dim == 2 ? 1.1 * 0.9 + 0.2 * 0.15
                                : 1.1 * (0.9 * 1.2 - 0.05 * -0.1) - 0.2 * (-0.15 * 1.2 - 0.05 * 0.1) +
                                      0.1 * (-0.15 * -0.1 - 0.9 * 0.1);
    const double volume = det * ReferenceMeasure(c.type);
    s.properties->SetValue(THICKNESS, 0.2);
    const double thickness = dim == 2 ? 0.2 : 1.0;
    ProcessInfo info;
    Matrix M;
    s.element->CalculateMassMatrix(M, info);
    EXPECT_NEAR(M.sum(), 2.5 * volume * thickness * dim, 1e-12) << s.name;
    EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-14);
    info.SetValue(COMPUTE_LUMPED_MASS_MATRIX, true);
    s.element->CalculateMassMatrix(M, info);
    EXPECT_NEAR(M.sum(), 2.5 * volume * thickness * dim, 1e-12) << s.name;
    EXPECT_GT(M.diagonal().minCoeff(), 0.0) << s.name;
    EXPECT_EQ((M - Matrix(M.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(SolidElements, BodyForceIntegratesToWeight) {
  for (GeometryType type : {GeometryType::Quadrilateral2D8, GeometryType::Hexahedra3D20, GeometryType::Tetrahedra3D4}) {
    const int dim = ReferenceElement::Get(type).WorkingSpaceDimension();
    ElementSetup s({"TotalLagrangianElement", type, dim == 2 ? "LinearElasticPlaneStrain2DLaw" : "LinearElastic3DLaw"},
                   true);
    for (std::size_t a = 0; a < s.nodes.size(); ++a)
      s.nodes[a].FastGetSolutionStepValue(VOLUME_ACCELERATION) = Array3(1.0, -9.81, 0.5);
    Matrix M;
    s.element->CalculateMassMatrix(M, ProcessInfo{});
    const double mass = M.sum() / dim;
    Vector rhs;
    s.element->CalculateRightHandSide(rhs, ProcessInfo{});
    for (int k = 0; k < dim; ++k) {
      double total = 0.0;
      for (Eigen::Index i = k; i < rhs.size(); i += dim) total += rhs[i];
      EXPECT_NEAR(total, mass * Array3(1.0, -9.81, 0.5)[k], 1e-12) << s.name;
    }
  }
}

TEST(SolidElements, DampingIsRayleighCombination) {
  ElementSetup s({"TotalLagrangianElement", GeometryType::Quadrilateral2D4, "HyperElasticPlaneStrain2DLaw"});
  ProcessInfo info;
  info.SetValue(RAYLEIGH_ALPHA, 0.3);
  info.SetValue(RAYLEIGH_BETA, 0.01);
  s.properties->SetValue(RAYLEIGH_BETA, 0.02);
  Matrix C, M, K;
  s.element->CalculateDampingMatrix(C, info);
  s.element->CalculateMassMatrix(M, info);
  s.element->CalculateLeftHandSide(K, info);
  EXPECT_LT((C - 0.3 * M - 0.02 * K).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(SolidElements, HomogeneousStrainGivesExactStressOutputs) {
  const double young = 100.0, nu = 0.3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  ElementSetup s({"SmallDisplacementElement", GeometryType::Hexahedra3D8, "LinearElastic3DLaw"});
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, 0, -1e-4, -5e-4, 3e-4, 0, 1e-4, 2e-4;
  test::SetDisplacements(s.element->GetGeometry(), [&](const Array3& X, int) { return Array3(G * X); });
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d sigma = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  std::vector<Matrix> tensors;
  std::vector<Vector> vectors;
  std::vector<double> vm;
  ProcessInfo info;
  s.element->CalculateOnIntegrationPoints(CAUCHY_STRESS_TENSOR, tensors, info);
  s.element->CalculateOnIntegrationPoints(GREEN_LAGRANGE_STRAIN_VECTOR, vectors, info);
  s.element->CalculateOnIntegrationPoints(VON_MISES_STRESS, vm, info);
  ASSERT_EQ(tensors.size(), 8u);
  const Eigen::Matrix3d dev = sigma - sigma.trace() / 3 * Eigen::Matrix3d::Identity();
  for (std::size_t g = 0; g < 8; ++g) {
    EXPECT_LT((tensors[g] - sigma).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_NEAR(vectors[g][3], 2 * eps(0, 1), 1e-15);
    EXPECT_NEAR(vm[g], std::sqrt(1.5 * dev.squaredNorm()), 1e-13);
  }
}

TEST(SolidElements, SmallDisplacementNeoHookeanTakesJFromTheEquivalentF) {
  // Kratos 10.4 evaluates its Neo-Hookean law in a small-displacement element with C = I + 2 eps
  // and J = det(I + eps) (the element's symmetric "equivalent" F).
  const double young = 100.0, nu = 0.3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  ElementSetup s({"SmallDisplacementElement", GeometryType::Quadrilateral2D4, "HyperElasticPlaneStrain2DLaw"});
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  G.topLeftCorner<2, 2>() << 0.1, 0.05, 0.02, -0.04;
  test::SetDisplacements(s.element->GetGeometry(), [&](const Array3& X, int) { return Array3(G * X); });
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d Cinv = (Eigen::Matrix3d::Identity() + 2 * eps).inverse();
  const double lnJ = std::log((Eigen::Matrix3d::Identity() + eps).determinant());
  const Eigen::Matrix3d S = mu * (Eigen::Matrix3d::Identity() - Cinv) + lambda * lnJ * Cinv;
  std::vector<Vector> stress;
  s.element->CalculateOnIntegrationPoints(PK2_STRESS_VECTOR, stress, ProcessInfo{});
  for (const Vector& v : stress) {
    EXPECT_LT((v - Vector((Vector(3) << S(0, 0), S(1, 1), S(0, 1)).finished())).cwiseAbs().maxCoeff(), 1e-12);
    // Kratos 10.4, same element, law and strain (its PK2_STRESS_VECTOR, scaled to E = 100).
    EXPECT_LT((v - Vector((Vector(3) << 8.842616483, -0.171838033, 2.253613629).finished())).cwiseAbs().maxCoeff(),
              1e-8);
  }
}

TEST(SolidElements, AxisymmetricUniformExpansionExactStress) {
  const double young = 100.0, nu = 0.3, c = 2e-3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  for (GeometryType type : test::Solids2D()) {
    ElementSetup s({"AxisymSmallDisplacementElement", type, "LinearElasticAxisym2DLaw"});
    test::SetDisplacements(s.element->GetGeometry(), [&](const Array3& X, int) { return Array3(c * X[0], 0, 0); });
    std::vector<Vector> stress;
    s.element->CalculateOnIntegrationPoints(CAUCHY_STRESS_VECTOR, stress, ProcessInfo{});
    for (const Vector& v : stress) {
      EXPECT_NEAR(v[0], 2 * lambda * c + 2 * mu * c, 1e-13) << s.name;  // rr
      EXPECT_NEAR(v[1], 2 * lambda * c, 1e-13) << s.name;               // zz
      EXPECT_NEAR(v[2], 0.0, 1e-13) << s.name;                          // rz
      EXPECT_NEAR(v[3], 2 * lambda * c + 2 * mu * c, 1e-13) << s.name;  // theta-theta
    }
    // Total Lagrangian with a Neo-Hookean law: F = diag(1 + c, 1, 1 + c) exactly.
    ElementSetup t({"AxisymTotalLagrangianElement", type, "HyperElasticAxisym2DLaw"});
    test::SetDisplacements(t.element->GetGeometry(), [&](const Array3& X, int) { return Array3(0.1 * X[0], 0, 0); });
    t.element->CalculateOnIntegrationPoints(PK2_STRESS_VECTOR, stress, ProcessInfo{});
    const double J = 1.1 * 1.1, S_rr = mu * (1 - 1 / J) + lambda * std::log(J) / J;
    for (const Vector& v : stress) {
      EXPECT_NEAR(v[0], S_rr, 1e-12) << t.name;
      EXPECT_NEAR(v[1], lambda * std::log(J), 1e-12) << t.name;
      EXPECT_NEAR(v[3], S_rr, 1e-12) << t.name;
    }
  }
}

TEST(SolidElements, AxisymmetricRingVolume) {
  // A quadrilateral ring section r in [1, 2], z in [0, 1]: volume pi (4 - 1) = 3 pi.
  NodeSet nodes;
  auto properties = test::MakeProperties(1, "LinearElasticAxisym2DLaw");
  Geometry::NodesArray quad = {nodes.Add({1, 0, 0}), nodes.Add({2, 0, 0}), nodes.Add({2, 1, 0}), nodes.Add({1, 1, 0})};
  auto element =
      Registry<Element>::Instance().Get("AxisymSmallDisplacementElement2D4N").Create(1, quad, properties.get());
  Matrix M;
  element->CalculateMassMatrix(M, ProcessInfo{});
  EXPECT_NEAR(M.sum(), 2.5 * 3 * std::numbers::pi * 2, 1e-12);
}

TEST(SolidElements, CheckReportsInvertedAndMismatchedElements) {
  ElementSetup s({"TotalLagrangianElement", GeometryType::Quadrilateral2D4, "LinearElasticPlaneStrain2DLaw"});
  std::swap(s.element->GetGeometry().Nodes()[1], s.element->GetGeometry().Nodes()[3]);
  try {
    s.element->Check(ProcessInfo{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("element 17 (TotalLagrangianElement2D4N) is inverted"), std::string::npos) << m;
    EXPECT_NE(m.find("det J = -"), std::string::npos) << m;
  }
  ElementSetup t({"SmallDisplacementElement", GeometryType::Hexahedra3D8, "LinearElasticPlaneStrain2DLaw"});
  try {
    t.element->Check(ProcessInfo{});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("LinearElasticPlaneStrain2DLaw"), std::string::npos) << e.what();
  }
  ElementSetup a({"AxisymSmallDisplacementElement", GeometryType::Triangle2D3, "LinearElasticPlaneStrain2DLaw"});
  EXPECT_THROW(a.element->Check(ProcessInfo{}), InputError);
}

TEST(SolidElements, InversionDuringSolveIsSolutionError) {
  for (const char* stem : {"TotalLagrangianElement", "UpdatedLagrangianElement"}) {
    ElementSetup s({stem, GeometryType::Quadrilateral2D4, "HyperElasticPlaneStrain2DLaw"});
    test::SetDisplacements(s.element->GetGeometry(), [](const Array3& X, int) { return Array3(-2.0 * X[0], 0, 0); });
    Vector rhs;
    try {
      s.element->CalculateRightHandSide(rhs, ProcessInfo{});
      ADD_FAILURE();
    } catch (const SolutionError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("element 17 (" + std::string(stem) + "2D4N) is inverted at integration point"),
                std::string::npos)
          << m;
      EXPECT_NE(m.find("det F = -"), std::string::npos) << m;
    }
  }
}

TEST(SolidElements, MembranePlaceholderThrowsNamingItself) {
  RegisterStructuralMechanics();
  NodeSet nodes;
  Geometry::NodesArray tri = {nodes.Add({0, 0, 0}), nodes.Add({1, 0, 0}), nodes.Add({0, 1, 0})};
  auto element = Registry<Element>::Instance().Get("MembraneElement3D3N").Create(4, tri, nullptr);
  DofsVectorType dofs;
  element->GetDofList(dofs, ProcessInfo{});
  EXPECT_TRUE(dofs.empty());
  Matrix lhs;
  Vector rhs;
  try {
    element->CalculateLocalSystem(lhs, rhs, ProcessInfo{});
    ADD_FAILURE();
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("MembraneElement3D3N"), std::string::npos);
  }
  EXPECT_TRUE(Registry<Element>::Instance().Has("MembraneElement3D4N"));
}

}  // namespace
}  // namespace mc
