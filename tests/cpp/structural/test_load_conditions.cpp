// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (structural substrate, loads): point, line and surface loads integrate to the exact
// total force on inclined and curved boundaries (2D, axisymmetric, 3D); face pressures act
// with sign NEGATIVE - POSITIVE along the surface normal (3D) or the tangent turned by +90
// degrees (2D); the stiffness of every load is the finite-difference derivative of the load, and
// none in a linear analysis (ProcessInfo LINEAR_ANALYSIS);
// skin conditions contribute nothing. Issue 10: the Kratos 10.4 conventions measured by
// benchmarks/structural_parity: no THICKNESS factor on any load, LINE_LOAD and SURFACE_LOAD per
// unit current length / area, axisymmetric loads times 2 pi r (current radius).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "structural_test_utilities.h"

namespace mc {
namespace {

using test::NodeSet;

std::unique_ptr<Condition> MakeCondition(const std::string& name, Geometry::NodesArray nodes, Properties* properties) {
  RegisterStructuralMechanics();
  auto condition = Registry<Condition>::Instance().Get(name).Create(5, std::move(nodes), properties);
  EXPECT_EQ(condition->Info(), name);
  return condition;
}

Array3 Total(const Vector& rhs, int dim) {
  Array3 total = Array3::Zero();
  for (Eigen::Index i = 0; i < rhs.size(); ++i) total[i % dim] += rhs[i];
  return total;
}

TEST(LoadConditions, PointLoadAddsNodalAndConditionValues) {
  NodeSet nodes;
  Node* node = nodes.Add({1, 2, 3});
  node->FastGetSolutionStepValue(POINT_LOAD) = Array3(1.0, -2.0, 3.0);
  auto condition = MakeCondition("PointLoadCondition3D1N", {node}, nullptr);
  condition->SetValue(POINT_LOAD, Array3(0.5, 0.5, 0.5));
  Matrix lhs;
  Vector rhs;
  condition->CalculateLocalSystem(lhs, rhs, ProcessInfo{});
  EXPECT_EQ(rhs, Vector((Vector(3) << 1.5, -1.5, 3.5).finished()));
  EXPECT_EQ(lhs.norm(), 0.0);
  auto condition2d = MakeCondition("PointLoadCondition2D1N", {node}, nullptr);
  condition2d->CalculateRightHandSide(rhs, ProcessInfo{});
  EXPECT_EQ(rhs, Vector((Vector(2) << 1.0, -2.0).finished()));
}

TEST(LoadConditions, LineLoadOnInclinedEdgeIsExactAndIgnoresThickness) {
  NodeSet nodes;
  auto properties = test::MakeProperties(1, "LinearElasticPlaneStrain2DLaw");
  properties->SetValue(THICKNESS, 0.3);  // a force per unit length: THICKNESS plays no part
  Node* a = nodes.Add({1, 1, 0});
  Node* b = nodes.Add({4, 5, 0});  // length 5
  Node* m = nodes.Add({2.5, 3, 0});
  a->FastGetSolutionStepValue(LINE_LOAD) = Array3(2.0, 0.0, 0.0);
  b->FastGetSolutionStepValue(LINE_LOAD) = Array3(4.0, 0.0, 0.0);
  m->FastGetSolutionStepValue(LINE_LOAD) = Array3(3.0, 0.0, 0.0);
  for (auto [name, geometry] : {std::pair<std::string, Geometry::NodesArray>{"LineLoadCondition2D2N", {a, b}},
                                {"LineLoadCondition2D3N", {a, b, m}}}) {
    auto condition = MakeCondition(name, geometry, properties.get());
    condition->SetValue(LINE_LOAD, Array3(0.0, -1.0, 0.0));
    Vector rhs;
    condition->CalculateRightHandSide(rhs, ProcessInfo{});
    const Array3 total = Total(rhs, 2);
    EXPECT_NEAR(total[0], 5 * 3.0, 1e-12) << name;  // mean of the linear nodal load
    EXPECT_NEAR(total[1], -5.0, 1e-12) << name;
    if (geometry.size() == 2) {
      EXPECT_NEAR(rhs[0], 5 * (2 * 2.0 + 4.0) / 6, 1e-12);  // linear load, node a
    }
  }
  auto line3d = MakeCondition("LineLoadCondition3D2N", {nodes.Add({0, 0, 0}), nodes.Add({1, 2, 2})}, properties.get());
  line3d->SetValue(LINE_LOAD, Array3(1.0, 2.0, 3.0));
  Vector rhs;
  line3d->CalculateRightHandSide(rhs, ProcessInfo{});
  EXPECT_LT((Total(rhs, 3) - 3.0 * Array3(1.0, 2.0, 3.0)).norm(), 1e-12);
  line3d->SetValue(POSITIVE_FACE_PRESSURE, 1.0);
  EXPECT_THROW(line3d->CalculateRightHandSide(rhs, ProcessInfo{}), InputError);
}

TEST(LoadConditions, LineAndSurfaceLoadsActOnTheCurrentMeasure) {
  NodeSet nodes;
  Node* a = nodes.Add({0, 0, 0});
  Node* b = nodes.Add({2, 0, 0});
  Node* c = nodes.Add({2, 1, 0});
  Node* d = nodes.Add({0, 1, 0});
  b->FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 0.0, 0.0);  // edge a-b: length 2 -> 3
  c->FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 0.0, 0.0);  // face: area 2 -> 3
  auto line = MakeCondition("LineLoadCondition2D2N", {a, b}, nullptr);
  line->SetValue(LINE_LOAD, Array3(0.0, -2.0, 0.0));
  Vector rhs;
  line->CalculateRightHandSide(rhs, ProcessInfo{});
  EXPECT_NEAR(Total(rhs, 2)[1], -2.0 * 3.0, 1e-12);
  auto face = MakeCondition("SurfaceLoadCondition3D4N", {a, b, c, d}, nullptr);
  face->SetValue(SURFACE_LOAD, Array3(0.5, 0.0, -2.0));
  face->CalculateRightHandSide(rhs, ProcessInfo{});
  EXPECT_LT((Total(rhs, 3) - 3.0 * Array3(0.5, 0.0, -2.0)).norm(), 1e-12);
}

TEST(LoadConditions, PressureOnCurvedEdgeActsAlongTheLeftNormal) {
  NodeSet nodes;
  auto properties = test::MakeProperties(1, "LinearElasticPlaneStrain2DLaw");
  properties->SetValue(THICKNESS, 2.0);  // no factor: as LINE_LOAD
  Node* a = nodes.Add({0, 0, 0});
  Node* b = nodes.Add({3, 1, 0});
  Node* m = nodes.Add({1.2, 1.4, 0});  // bulged mid node: a curved edge
  auto condition = MakeCondition("LineLoadCondition2D3N", {a, b, m}, properties.get());
  a->FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 1.0;
  b->FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 1.0;
  m->FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 1.0;
  condition->SetValue(POSITIVE_FACE_PRESSURE, 4.0);  // net pressure 1 - 4 = -3
  Vector rhs;
  condition->CalculateRightHandSide(rhs, ProcessInfo{});
  // int n ds = chord turned by +90 degrees, whatever the curvature.
  const Array3 chord = b->X0() - a->X0();
  const Array3 left(-chord[1], chord[0], 0.0);
  EXPECT_LT((Total(rhs, 2) - -3.0 * left).norm(), 1e-12);
  // Kratos 10.4's 2D sign: opposite to Geometry::UnitNormal (which points right of the edge).
  auto straight = MakeCondition("LineLoadCondition2D2N", {a, b}, properties.get());
  straight->SetValue(NEGATIVE_FACE_PRESSURE, 1.0);
  straight->CalculateRightHandSide(rhs, ProcessInfo{});
  const Array3 n = straight->GetGeometry().UnitNormal(Array3::Zero());
  EXPECT_LT((Total(rhs, 2) + 2.0 * chord.norm() * n).norm(), 1e-12);  // net pressure 2
}

TEST(LoadConditions, AxisymmetricLineLoadIntegratesWithCircumference) {
  NodeSet nodes;
  auto properties = test::MakeProperties(1, "LinearElasticAxisym2DLaw");
  properties->SetValue(THICKNESS, 0.1);  // ignored in axisymmetry (Kratos 10.4 would divide by it)
  Node* a = nodes.Add({1, 0, 0});
  Node* b = nodes.Add({3, 0, 0});
  Node* m = nodes.Add({2, 0, 0});
  for (auto [name, geometry] : {std::pair<std::string, Geometry::NodesArray>{"AxisymLineLoadCondition2D2N", {a, b}},
                                {"AxisymLineLoadCondition2D3N", {a, b, m}}}) {
    auto condition = MakeCondition(name, geometry, properties.get());
    condition->SetValue(LINE_LOAD, Array3(0.0, 1.5, 0.0));
    Vector rhs;
    condition->CalculateRightHandSide(rhs, ProcessInfo{});
    EXPECT_NEAR(Total(rhs, 2)[1], 1.5 * std::numbers::pi * (9.0 - 1.0), 1e-12) << name;  // annulus area
  }
  Node* c = nodes.Add({2, 0, 0});
  Node* d = nodes.Add({2, 4, 0});
  auto wall = MakeCondition("AxisymLineLoadCondition2D2N", {c, d}, properties.get());
  wall->SetValue(NEGATIVE_FACE_PRESSURE, 0.5);
  Vector rhs;
  wall->CalculateRightHandSide(rhs, ProcessInfo{});
  // The (0, 1) tangent turned by +90 degrees is -x; cylinder area 2 pi r h.
  EXPECT_NEAR(Total(rhs, 2)[0], -0.5 * 2 * std::numbers::pi * 2 * 4, 1e-12);
  EXPECT_NEAR(Total(rhs, 2)[1], 0.0, 1e-12);
  // Moved to radius 3 and stretched to height 6: the current surface 2 pi 3 6.
  c->FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 0.0, 0.0);
  d->FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 2.0, 0.0);
  wall->CalculateRightHandSide(rhs, ProcessInfo{});
  EXPECT_NEAR(Total(rhs, 2)[0], -0.5 * 2 * std::numbers::pi * 3 * 6, 1e-12);
}

TEST(LoadConditions, AxisymmetricPointLoadIsARingLoadOnTheCurrentRadius) {
  NodeSet nodes;
  Node* node = nodes.Add({2, 1, 0});
  node->FastGetSolutionStepValue(POINT_LOAD) = Array3(0.5, -1.0, 0.0);
  node->FastGetSolutionStepValue(DISPLACEMENT) = Array3(0.5, 0.2, 0.0);
  auto condition = MakeCondition("AxisymPointLoadCondition2D1N", {node}, nullptr);
  condition->SetValue(POINT_LOAD, Array3(0.0, -1.0, 0.0));
  Matrix K;
  Vector rhs;
  condition->CalculateLocalSystem(K, rhs, ProcessInfo{});
  const double circle = 2.0 * std::numbers::pi * 2.5;
  EXPECT_LT((rhs - circle * Vector((Vector(2) << 0.5, -2.0).finished())).norm(), 1e-12);
  EXPECT_LT(test::RelativeError(K, test::FiniteDifferenceTangent(*condition, 1e-6)), 1e-8);
  ProcessInfo linear;
  linear.SetValue(LINEAR_ANALYSIS, true);
  condition->CalculateLocalSystem(K, rhs, linear);
  EXPECT_EQ(K.norm(), 0.0);
}

TEST(LoadConditions, SurfaceLoadsAreExactOnInclinedAndCurvedFaces) {
  NodeSet nodes;
  // Inclined triangle: area = |e1 x e2| / 2.
  Node* p0 = nodes.Add({0, 0, 0});
  Node* p1 = nodes.Add({2, 0, 1});
  Node* p2 = nodes.Add({0, 3, 1});
  auto triangle = MakeCondition("SurfaceLoadCondition3D3N", {p0, p1, p2}, nullptr);
  triangle->SetValue(SURFACE_LOAD, Array3(0.0, 0.0, -2.0));
  Vector rhs;
  triangle->CalculateRightHandSide(rhs, ProcessInfo{});
  const double area = 0.5 * (p1->X0() - p0->X0()).cross(p2->X0() - p0->X0()).norm();
  EXPECT_NEAR(Total(rhs, 3)[2], -2.0 * area, 1e-12);

  // Curved 9-node quadrilateral over the flat square [0,2]^2 with a raised centre: the total
  // pressure force is p times the projected (vector) area, for any bulge.
  for (GeometryType type : {GeometryType::Quadrilateral3D9, GeometryType::Quadrilateral3D8}) {
    Geometry::NodesArray quad;
    for (const Array3& xi : ReferenceElement::Get(type).NodesLocalCoordinates()) {
      const bool centre = xi.norm() < 1e-12;
      quad.push_back(nodes.Add(Array3(1 + xi[0], 1 + xi[1], centre ? 0.7 : 0.0)));
    }
    const std::string name = std::string("SurfaceLoadCondition3D") + std::to_string(quad.size()) + "N";
    if (type == GeometryType::Quadrilateral3D8) quad[4]->X0()[2] = 0.3;  // bulged mid-edge node
    auto condition = MakeCondition(name, quad, nullptr);
    condition->SetValue(NEGATIVE_FACE_PRESSURE, 2.5);
    condition->CalculateRightHandSide(rhs, ProcessInfo{});
    const Array3 n = condition->GetGeometry().UnitNormal(Array3::Zero(), Configuration::Initial);
    const Array3 total = Total(rhs, 3);
    EXPECT_GT(n[2], 0.0);
    if (type == GeometryType::Quadrilateral3D9) {
      EXPECT_LT((total - Array3(0, 0, 2.5 * 4.0)).norm(), 1e-12) << name;
    } else {
      // The bulged edge (y = 0) tilts the surface towards +y: vector area 1/2 closed-integral
      // of x cross dx gains 2/3 * 2 * 0.3 = 0.4 along +y.
      EXPECT_LT((total - 2.5 * Array3(0, 0.4, 4.0)).norm(), 1e-12) << name;
    }
  }
}

TEST(LoadConditions, LoadStiffnessEqualsFiniteDifferences) {
  auto properties = test::MakeProperties(1, "LinearElastic3DLaw");
  const std::pair<const char*, GeometryType> cases[] = {{"LineLoadCondition2D2N", GeometryType::Line2D2},
                                                        {"LineLoadCondition2D3N", GeometryType::Line2D3},
                                                        {"AxisymLineLoadCondition2D2N", GeometryType::Line2D2},
                                                        {"AxisymLineLoadCondition2D3N", GeometryType::Line2D3},
                                                        {"SurfaceLoadCondition3D3N", GeometryType::Triangle3D3},
                                                        {"SurfaceLoadCondition3D4N", GeometryType::Quadrilateral3D4},
                                                        {"SurfaceLoadCondition3D6N", GeometryType::Triangle3D6},
                                                        {"SurfaceLoadCondition3D8N", GeometryType::Quadrilateral3D8},
                                                        {"SurfaceLoadCondition3D9N", GeometryType::Quadrilateral3D9}};
  for (const auto& [name, type] : cases) {
    NodeSet nodes;
    Geometry::NodesArray geometry;
    int i = 0;
    for (const Array3& xi : ReferenceElement::Get(type).NodesLocalCoordinates()) {
      Node* node =
          nodes.Add(Array3(2.0 + xi[0] + 0.3 * xi[1], 1.0 + 0.8 * xi[1] + 0.1 * xi[0] * xi[0],
                           ReferenceElement::Get(type).WorkingSpaceDimension() == 3 ? 0.2 * xi[0] * xi[1] : 0.0));
      node->FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 1.0 + 0.5 * test::Pseudo(i);
      node->FastGetSolutionStepValue(DISPLACEMENT) =
          0.1 * Array3(test::Pseudo(3 * i + 1), test::Pseudo(3 * i + 2), test::Pseudo(3 * i + 3));
      if (ReferenceElement::Get(type).WorkingSpaceDimension() == 2) node->FastGetSolutionStepValue(DISPLACEMENT_Z) = 0;
      geometry.push_back(node);
      ++i;
    }
    auto condition = MakeCondition(name, geometry, properties.get());
    condition->SetValue(POSITIVE_FACE_PRESSURE, 0.3);
    condition->SetValue(LINE_LOAD, Array3(0.1, 0.2, 0.0));
    condition->SetValue(SURFACE_LOAD, Array3(0.1, 0.2, 0.3));
    Matrix K;
    Vector rhs;
    condition->CalculateLocalSystem(K, rhs, ProcessInfo{});
    ASSERT_GT(K.norm(), 0.0) << name;
    EXPECT_LT(test::RelativeError(K, test::FiniteDifferenceTangent(*condition, 1e-6)), 1e-8) << name;
    // A linear analysis solves with the elastic stiffness alone (Kratos' loads have none at all).
    ProcessInfo linear;
    linear.SetValue(LINEAR_ANALYSIS, true);
    Vector rhs_linear;
    condition->CalculateLocalSystem(K, rhs_linear, linear);
    EXPECT_EQ(K.norm(), 0.0) << name;
    EXPECT_EQ(rhs_linear, rhs) << name;
  }
}

TEST(LoadConditions, SkinConditionsContributeNothing) {
  NodeSet nodes;
  for (const char* name : {"LineCondition2D2N", "LineCondition2D3N", "SurfaceCondition3D3N", "SurfaceCondition3D4N"}) {
    RegisterStructuralMechanics();
    const Condition& prototype = Registry<Condition>::Instance().Get(name);
    Geometry::NodesArray geometry;
    for (int i = 0; i < prototype.GetGeometry().Reference().NodesNumber(); ++i)
      geometry.push_back(nodes.Add({1.0 * i, 0.5 * i * i, 0}));
    auto condition = MakeCondition(name, geometry, nullptr);
    Matrix lhs(2, 2);
    Vector rhs(2);
    DofsVectorType dofs;
    condition->GetDofList(dofs, ProcessInfo{});
    condition->CalculateLocalSystem(lhs, rhs, ProcessInfo{});
    EXPECT_TRUE(dofs.empty());
    EXPECT_EQ(lhs.size(), 0);
    EXPECT_EQ(rhs.size(), 0);
  }
}

}  // namespace
}  // namespace mc
