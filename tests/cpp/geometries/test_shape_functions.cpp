// SPDX-License-Identifier: BSD-3-Clause
// Issue 2 (kernel, geometries): shape functions of every geometry type interpolate their nodes, sum to one, have
// local gradients matching finite differences, follow the Kratos/GiD node ordering, and the
// per-order tables agree with point evaluation.
#include <gtest/gtest.h>

#include <random>

#include "core/geometries/quadrature.h"
#include "core/geometries/reference_element.h"
#include "geometry_test_utilities.h"

namespace mc {
namespace {

// Interior sample points of the reference element of `ref`.
std::vector<Array3> SamplePoints(const ReferenceElement& ref) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.95, 0.95), v(0.02, 0.9);
  std::vector<Array3> points;
  while (points.size() < 6) {
    Array3 x = Array3::Zero();
    for (int d = 0; d < ref.LocalSpaceDimension(); ++d) {
      const bool unit = ref.Family() == GeometryFamily::Triangle || ref.Family() == GeometryFamily::Tetrahedron ||
                        ref.Family() == GeometryFamily::Prism;
      x[d] = unit ? v(rng) : u(rng);
    }
    if (ref.IsInside(x, -0.01)) points.push_back(x);
  }
  return points;
}

struct TypeInfo {
  GeometryType type;
  GeometryFamily family;
  int working_dim, local_dim, nodes, default_order;
};

}  // namespace

TEST(ReferenceElement, DimensionsCountsAndDefaultOrders) {
  using GT = GeometryType;
  using GF = GeometryFamily;
  const std::vector<TypeInfo> table = {
      {GT::Point2D, GF::Point, 2, 0, 1, 1},
      {GT::Point3D, GF::Point, 3, 0, 1, 1},
      {GT::Line2D2, GF::Line, 2, 1, 2, 1},
      {GT::Line2D3, GF::Line, 2, 1, 3, 3},
      {GT::Line3D2, GF::Line, 3, 1, 2, 1},
      {GT::Line3D3, GF::Line, 3, 1, 3, 3},
      {GT::Triangle2D3, GF::Triangle, 2, 2, 3, 1},
      {GT::Triangle2D6, GF::Triangle, 2, 2, 6, 2},
      {GT::Quadrilateral2D4, GF::Quadrilateral, 2, 2, 4, 2},
      {GT::Quadrilateral2D8, GF::Quadrilateral, 2, 2, 8, 3},
      {GT::Quadrilateral2D9, GF::Quadrilateral, 2, 2, 9, 3},
      {GT::Triangle3D3, GF::Triangle, 3, 2, 3, 1},
      {GT::Triangle3D6, GF::Triangle, 3, 2, 6, 2},
      {GT::Quadrilateral3D4, GF::Quadrilateral, 3, 2, 4, 2},
      {GT::Quadrilateral3D8, GF::Quadrilateral, 3, 2, 8, 3},
      {GT::Quadrilateral3D9, GF::Quadrilateral, 3, 2, 9, 3},
      {GT::Tetrahedra3D4, GF::Tetrahedron, 3, 3, 4, 1},
      {GT::Tetrahedra3D10, GF::Tetrahedron, 3, 3, 10, 2},
      {GT::Hexahedra3D8, GF::Hexahedron, 3, 3, 8, 2},
      {GT::Hexahedra3D20, GF::Hexahedron, 3, 3, 20, 3},
      {GT::Hexahedra3D27, GF::Hexahedron, 3, 3, 27, 3},
      {GT::Prism3D6, GF::Prism, 3, 3, 6, 2},
  };
  ASSERT_EQ(table.size(), test::AllGeometryTypes().size());
  for (const TypeInfo& t : table) {
    const ReferenceElement& ref = ReferenceElement::Get(t.type);
    EXPECT_EQ(ref.Type(), t.type);
    EXPECT_EQ(ref.Family(), t.family) << ref.Name();
    EXPECT_EQ(ref.WorkingSpaceDimension(), t.working_dim) << ref.Name();
    EXPECT_EQ(ref.LocalSpaceDimension(), t.local_dim) << ref.Name();
    EXPECT_EQ(ref.NodesNumber(), t.nodes) << ref.Name();
    EXPECT_EQ(ref.DefaultIntegrationOrder(), t.default_order) << ref.Name();
  }
}

TEST(ReferenceElement, KroneckerPropertyAndPartitionOfUnity) {
  for (GeometryType type : test::AllGeometryTypes()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    const int n = ref.NodesNumber();
    Vector N;
    for (int j = 0; j < n; ++j) {
      ref.ShapeFunctionsValues(ref.NodesLocalCoordinates()[j], N);
      ASSERT_EQ(N.size(), n);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(N[i], i == j ? 1.0 : 0.0, 1e-14) << ref.Name() << " N" << i << " at node " << j;
    }
    for (const Array3& x : SamplePoints(ref)) {
      ref.ShapeFunctionsValues(x, N);
      EXPECT_NEAR(N.sum(), 1.0, 1e-14) << ref.Name();
      // Linear completeness: the nodes' local coordinates are reproduced.
      Array3 y = Array3::Zero();
      for (int i = 0; i < n; ++i) y += N[i] * ref.NodesLocalCoordinates()[i];
      EXPECT_LT((y - x).norm(), 1e-14) << ref.Name();
    }
  }
}

TEST(ReferenceElement, LocalGradientsMatchCentralDifferences) {
  const double h = 1e-6;
  for (GeometryType type : test::AllGeometryTypes()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    Vector Np, Nm;
    Matrix dN;
    for (const Array3& x : SamplePoints(ref)) {
      ref.ShapeFunctionsLocalGradients(x, dN);
      ASSERT_EQ(dN.rows(), ref.NodesNumber());
      ASSERT_EQ(dN.cols(), ref.LocalSpaceDimension());
      for (int k = 0; k < ref.LocalSpaceDimension(); ++k) {
        Array3 xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        ref.ShapeFunctionsValues(xp, Np);
        ref.ShapeFunctionsValues(xm, Nm);
        const Vector fd = (Np - Nm) / (2.0 * h);
        for (int i = 0; i < ref.NodesNumber(); ++i)
          EXPECT_NEAR(dN(i, k), fd[i], 1e-8) << ref.Name() << " dN" << i << "/dx" << k;
      }
    }
  }
}

TEST(ReferenceElement, TablesMatchPointEvaluationAndAreShared) {
  for (GeometryType type : test::AllGeometryTypes()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    EXPECT_EQ(&ref, &ReferenceElement::Get(type));
    Vector N;
    Matrix dN;
    for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
      const auto& points = ref.IntegrationPoints(order);
      const Matrix& table = ref.ShapeFunctionsValues(order);
      const auto& gradients = ref.ShapeFunctionsLocalGradients(order);
      ASSERT_EQ(table.rows(), static_cast<Eigen::Index>(points.size()));
      ASSERT_EQ(gradients.size(), points.size());
      for (std::size_t g = 0; g < points.size(); ++g) {
        ref.ShapeFunctionsValues(points[g].local, N);
        ref.ShapeFunctionsLocalGradients(points[g].local, dN);
        EXPECT_LT((table.row(g).transpose() - N).norm(), 1e-15) << ref.Name();
        EXPECT_LT((gradients[g] - dN).norm(), 1e-15) << ref.Name();
      }
    }
  }
}

TEST(ReferenceElement, KratosNodeOrdering) {
  const auto node = [](GeometryType t, int i) { return ReferenceElement::Get(t).NodesLocalCoordinates()[i]; };
  const auto mid = [&](GeometryType t, int a, int b) { return Array3(0.5 * (node(t, a) + node(t, b))); };
  using GT = GeometryType;
  EXPECT_EQ(node(GT::Line2D3, 2), Array3(0, 0, 0));
  EXPECT_EQ(node(GT::Triangle2D6, 3), mid(GT::Triangle2D6, 0, 1));
  EXPECT_EQ(node(GT::Triangle2D6, 4), mid(GT::Triangle2D6, 1, 2));
  EXPECT_EQ(node(GT::Triangle2D6, 5), mid(GT::Triangle2D6, 2, 0));
  for (GT q : {GT::Quadrilateral2D8, GT::Quadrilateral2D9})
    for (int e = 0; e < 4; ++e) EXPECT_EQ(node(q, 4 + e), mid(q, e, (e + 1) % 4));
  EXPECT_EQ(node(GT::Quadrilateral2D9, 8), Array3(0, 0, 0));
  const int tet_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e)
    EXPECT_EQ(node(GT::Tetrahedra3D10, 4 + e), mid(GT::Tetrahedra3D10, tet_edges[e][0], tet_edges[e][1]));
  // Corners counter-clockwise at the bottom, then the top.
  EXPECT_EQ(node(GT::Hexahedra3D8, 0), Array3(-1, -1, -1));
  EXPECT_EQ(node(GT::Hexahedra3D8, 2), Array3(1, 1, -1));
  EXPECT_EQ(node(GT::Hexahedra3D8, 6), Array3(1, 1, 1));
  const int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  for (GT h : {GT::Hexahedra3D20, GT::Hexahedra3D27})
    for (int e = 0; e < 12; ++e) EXPECT_EQ(node(h, 8 + e), mid(h, hex_edges[e][0], hex_edges[e][1])) << e;
  const Array3 face_centres[6] = {Array3(0, 0, -1), Array3(0, -1, 0), Array3(1, 0, 0),
                                  Array3(0, 1, 0),  Array3(-1, 0, 0), Array3(0, 0, 1)};
  for (int f = 0; f < 6; ++f) EXPECT_EQ(node(GT::Hexahedra3D27, 20 + f), face_centres[f]);
  EXPECT_EQ(node(GT::Hexahedra3D27, 26), Array3(0, 0, 0));
  EXPECT_EQ(node(GT::Prism3D6, 4), Array3(1, 0, 1));
}

TEST(ReferenceElement, FacesListTheNodesOfTheirTypeInTheirOrdering) {
  // With the element's nodes at their local coordinates, every face is straight: each face
  // node must sit where the face's corners interpolate it at that node's face coordinates.
  for (GeometryType type : test::AllGeometryTypes()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    for (const ReferenceElement::Face& face : ref.Faces()) {
      const ReferenceElement& face_ref = ReferenceElement::Get(face.type);
      ASSERT_EQ(static_cast<int>(face.nodes.size()), face_ref.NodesNumber()) << ref.Name();
      ASSERT_EQ(face_ref.LocalSpaceDimension(), ref.LocalSpaceDimension() - 1) << ref.Name();
      ASSERT_EQ(face_ref.WorkingSpaceDimension(), ref.WorkingSpaceDimension()) << ref.Name();
      double N[ReferenceElement::kMaxNodes], dN[3 * ReferenceElement::kMaxNodes];
      for (int j = 0; j < face_ref.NodesNumber(); ++j) {
        Array3 expected = Array3::Zero();
        const int corners = face_ref.Family() == GeometryFamily::Triangle        ? 3
                            : face_ref.Family() == GeometryFamily::Quadrilateral ? 4
                            : face_ref.Family() == GeometryFamily::Line          ? 2
                                                                                 : 1;
        const GeometryType linear = corners == 3   ? GeometryType::Triangle3D3
                                    : corners == 4 ? GeometryType::Quadrilateral3D4
                                    : corners == 2 ? GeometryType::Line3D2
                                                   : GeometryType::Point3D;
        ReferenceElement::Get(linear).Evaluate(face_ref.NodesLocalCoordinates()[j], N, dN);
        for (int c = 0; c < corners; ++c) expected += N[c] * ref.NodesLocalCoordinates()[face.nodes[c]];
        EXPECT_LT((expected - ref.NodesLocalCoordinates()[face.nodes[j]]).norm(), 1e-15)
            << ref.Name() << " face node " << j;
      }
    }
  }
}

}  // namespace mc
