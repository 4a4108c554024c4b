// SPDX-License-Identifier: BSD-3-Clause
// Issue 2 (kernel, geometries): geometries compute Jacobians, global and local coordinates, lengths/areas/volumes,
// centres, unit normals and outward-oriented faces, in the initial or current configuration,
// without allocating in element loops.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <cstdlib>
#include <new>

#include "core/geometries/quadrature.h"
#include "geometry_test_utilities.h"
#include "tests/cpp/common/error_message.h"

// Counts heap allocations of this thread, to check that element loops do not allocate.
namespace {
thread_local long g_allocations = 0;
}  // namespace

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's buffer): otherwise the library's allocates what free
// releases (AddressSanitizer: alloc-dealloc-mismatch, make test-sanitize).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(size ? size : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mc {
namespace {

using GT = GeometryType;
using test::MappedGeometry;

// A positively oriented affine map; 2D working spaces stay in the xy-plane.
Eigen::Matrix3d AffineMatrix(int working_dim) {
  Eigen::Matrix3d A;
  if (working_dim == 2)
    A << 2.0, 0.5, 0.0, 0.3, 1.5, 0.0, 0.0, 0.0, 0.0;
  else
    A << 2.0, 0.5, 0.2, 0.3, 1.5, -0.4, 0.1, 0.2, 1.2;
  return A;
}
const Array3 kShift(0.7, -1.3, 0.4);

Array3 Affine(int working_dim, const Array3& x) {
  Array3 y = AffineMatrix(working_dim) * x + kShift;
  if (working_dim == 2) y[2] = 0.0;
  return y;
}

// A nonlinear term inside the polynomial space of each type, so the element reproduces it.
Array3 Distortion(GeometryType type, const Array3& x) {
  const ReferenceElement& ref = ReferenceElement::Get(type);
  const bool quadratic = ref.NodesNumber() > (ref.Family() == GeometryFamily::Line            ? 2
                                              : ref.Family() == GeometryFamily::Triangle      ? 3
                                              : ref.Family() == GeometryFamily::Quadrilateral ? 4
                                              : ref.Family() == GeometryFamily::Tetrahedron   ? 4
                                              : ref.Family() == GeometryFamily::Hexahedron    ? 8
                                                                                              : 6);
  const bool in_3d = ref.WorkingSpaceDimension() == 3;
  const double a = 0.1;
  Array3 d = Array3::Zero();
  switch (ref.Family()) {
    case GeometryFamily::Line:
      if (quadratic) d = Array3(a * x[0] * x[0], 2 * a * x[0] * x[0], in_3d ? a * x[0] * x[0] : 0.0);
      break;
    case GeometryFamily::Triangle:
      if (quadratic) d = Array3(a * x[1] * x[1], a * x[0] * x[0], in_3d ? 2 * a * x[0] * x[1] : 0.0);
      break;
    case GeometryFamily::Quadrilateral:
      d = Array3(a * x[0] * x[1], 0.0, in_3d ? a * x[0] * x[1] : 0.0);
      if (quadratic) d += Array3(a * x[1] * x[1], a * x[0] * x[0], in_3d ? a * x[0] * x[0] : 0.0);
      break;
    case GeometryFamily::Tetrahedron:
      if (quadratic) d = Array3(a * x[1] * x[1], a * x[2] * x[2], a * x[0] * x[0]);
      break;
    case GeometryFamily::Hexahedron:
      d = Array3(a * x[0] * x[1], a * x[1] * x[2], a * x[2] * x[0]);
      if (quadratic) d += Array3(a * x[1] * x[1], a * x[2] * x[2], a * x[0] * x[0]);
      break;
    case GeometryFamily::Prism: d = Array3(a * x[0] * x[2], a * x[1] * x[2], a * x[0]); break;
    default: break;
  }
  return d;
}

Array3 Distorted(GeometryType type, const Array3& x) {
  return Affine(ReferenceElement::Get(type).WorkingSpaceDimension(), x) + Distortion(type, x);
}

std::vector<Array3> InteriorPoints(GeometryType type) {
  const ReferenceElement& ref = ReferenceElement::Get(type);
  std::vector<Array3> points = {ref.LocalCenter()};
  for (const IntegrationPoint& p : ref.IntegrationPoints(3)) points.push_back(p.local);
  return points;
}

std::vector<GeometryType> TypesWithExtent() {
  std::vector<GeometryType> types;
  for (GeometryType t : test::AllGeometryTypes())
    if (ReferenceElement::Get(t).LocalSpaceDimension() > 0) types.push_back(t);
  return types;
}

// Measure density of the first `ld` columns of a 3 x 3 matrix.
double Density(const Eigen::Matrix3d& A, int ld) {
  const Eigen::MatrixXd B = A.leftCols(ld);
  return std::sqrt((B.transpose() * B).determinant());
}

}  // namespace

TEST(Geometry, PrototypeWithoutNodesAndWrongNodeCount) {
  const Geometry prototype(GT::Hexahedra3D20, {});
  EXPECT_EQ(prototype.PointsNumber(), 0u);
  EXPECT_STREQ(prototype.Name(), "Hexahedra3D20");
  EXPECT_EQ(prototype.IntegrationPoints(prototype.DefaultIntegrationOrder()).size(), 27u);

  MappedGeometry quad(GT::Quadrilateral2D4, [](const Array3& x) { return x; });
  Geometry::NodesArray three(quad->Nodes().begin(), quad->Nodes().begin() + 3);
  const std::string message = test::ErrorMessageOf([&] { Geometry wrong(GT::Quadrilateral2D4, three); });
  EXPECT_NE(message.find("Quadrilateral2D4"), std::string::npos) << message;
  EXPECT_NE(message.find("needs 4 nodes, got 3"), std::string::npos) << message;
  EXPECT_NE(message.find("1 2 3"), std::string::npos) << message;
}

TEST(Geometry, AffineJacobianAndDomainSizeAreExact) {
  for (GeometryType type : TypesWithExtent()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    const int wd = ref.WorkingSpaceDimension(), ld = ref.LocalSpaceDimension();
    MappedGeometry g(type, [wd](const Array3& x) { return Affine(wd, x); });
    const Eigen::Matrix3d A = AffineMatrix(wd);
    const double expected = test::ReferenceMeasure(ref.Family()) * Density(A, ld);
    EXPECT_NEAR(g->DomainSize(), expected, 1e-13 * expected) << ref.Name();
    Matrix J;
    for (const Matrix& dN : g->ShapeFunctionsLocalGradients(g->DefaultIntegrationOrder())) {
      g->Jacobian(dN, J);
      ASSERT_EQ(J.rows(), wd);
      ASSERT_EQ(J.cols(), ld);
      EXPECT_LT((J - A.topLeftCorner(wd, ld)).norm(), 1e-13) << ref.Name();
    }
    EXPECT_LT((g->Center() - Affine(wd, Array3::Zero()) -
               A *
                   [&] {
                     Array3 mean = Array3::Zero();
                     for (const Array3& x : ref.NodesLocalCoordinates()) mean += x;
                     return Array3(mean / ref.NodesNumber());
                   }())
                  .norm(),
              1e-13)
        << ref.Name();
  }
}

TEST(Geometry, InitialAndCurrentConfigurations) {
  for (GeometryType type : TypesWithExtent()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    const int wd = ref.WorkingSpaceDimension(), ld = ref.LocalSpaceDimension();
    MappedGeometry g(type, [type](const Array3& x) { return Distorted(type, x); });
    const double initial = g->DomainSize(Configuration::Initial);
    for (std::size_t i = 0; i < g->PointsNumber(); ++i) g.node(i).Coordinates() = 3.0 * g.node(i).X0();
    EXPECT_NEAR(g->DomainSize(Configuration::Current), std::pow(3.0, ld) * initial, 1e-12 * initial) << ref.Name();
    EXPECT_NEAR(g->DomainSize(Configuration::Initial), initial, 1e-15 * initial) << ref.Name();
    const Array3 x = ref.LocalCenter();
    EXPECT_LT((g->GlobalCoordinates(x) - 3.0 * g->GlobalCoordinates(x, Configuration::Initial)).norm(), 1e-13);
    Matrix J0, J;
    const Matrix& dN = g->ShapeFunctionsLocalGradients(1)[0];
    g->Jacobian(dN, J0, Configuration::Initial);
    g->Jacobian(dN, J);
    EXPECT_LT((J - 3.0 * J0).norm(), 1e-13) << ref.Name() << " wd " << wd;
  }
}

TEST(Geometry, DistortedElementsReproduceTheirMapAndItsJacobian) {
  const double h = 1e-6;
  for (GeometryType type : TypesWithExtent()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    MappedGeometry g(type, [type](const Array3& x) { return Distorted(type, x); });
    Matrix dN, J;
    for (const Array3& x : InteriorPoints(type)) {
      EXPECT_LT((g->GlobalCoordinates(x) - Distorted(type, x)).norm(), 1e-14) << ref.Name();
      g->ShapeFunctionsLocalGradients(x, dN);
      g->Jacobian(dN, J);
      for (int k = 0; k < ref.LocalSpaceDimension(); ++k) {
        Array3 xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        const Array3 fd = (Distorted(type, xp) - Distorted(type, xm)) / (2 * h);
        for (int i = 0; i < ref.WorkingSpaceDimension(); ++i) EXPECT_NEAR(J(i, k), fd[i], 1e-8) << ref.Name();
      }
    }
  }
}

TEST(Geometry, DistortedDomainSizesAgainstClosedForms) {
  // Bilinear quadrilateral: shoelace formula.
  {
    const Array3 corners[4] = {Array3(0, 0, 0), Array3(3, 0, 0), Array3(2.5, 2, 0), Array3(0.5, 1.5, 0)};
    MappedGeometry g(GT::Quadrilateral2D4, [&](const Array3& x) {
      const int i = x[0] < 0 ? (x[1] < 0 ? 0 : 3) : (x[1] < 0 ? 1 : 2);
      return corners[i];
    });
    double shoelace = 0.0;
    for (int i = 0; i < 4; ++i)
      shoelace += corners[i][0] * corners[(i + 1) % 4][1] - corners[(i + 1) % 4][0] * corners[i][1];
    EXPECT_NEAR(g->DomainSize(), 0.5 * shoelace, 1e-14);
  }
  // Trilinear hexahedron between two parallel planar quadrilaterals: prismatoid formula.
  {
    const Array3 bottom[4] = {Array3(0, 0, 0), Array3(3, 0, 0), Array3(2.5, 2, 0), Array3(0.5, 1.5, 0)};
    const Array3 top[4] = {Array3(0.2, 0.1, 2), Array3(1.8, 0.3, 2), Array3(1.9, 1.2, 2), Array3(0.1, 1.0, 2)};
    const auto area = [](const Array3* p) {
      double s = 0.0;
      for (int i = 0; i < 4; ++i) s += p[i][0] * p[(i + 1) % 4][1] - p[(i + 1) % 4][0] * p[i][1];
      return 0.5 * s;
    };
    Array3 middle[4];
    for (int i = 0; i < 4; ++i) middle[i] = 0.5 * (bottom[i] + top[i]);
    MappedGeometry g(GT::Hexahedra3D8, [&](const Array3& x) {
      const int i = x[0] < 0 ? (x[1] < 0 ? 0 : 3) : (x[1] < 0 ? 1 : 2);
      return x[2] < 0 ? bottom[i] : top[i];
    });
    EXPECT_NEAR(g->DomainSize(), 2.0 / 6.0 * (area(bottom) + area(top) + 4.0 * area(middle)), 1e-13);
  }
  const double a = 0.2, b = 0.3;
  // x = xi (1 + a xi), y = eta: det J = 1 + 2 a xi, area = 1/2 + a/3.
  MappedGeometry tri6(GT::Triangle2D6, [&](const Array3& x) { return Array3(x[0] * (1 + a * x[0]), x[1], 0); });
  EXPECT_NEAR(tri6->DomainSize(), 0.5 + a / 3.0, 1e-14);
  // x = xi + a xi^2, y = eta + b xi eta: det J = (1 + 2 a xi)(1 + b xi), area = 4 + 8ab/3.
  for (GT q : {GT::Quadrilateral2D8, GT::Quadrilateral2D9}) {
    MappedGeometry g(q, [&](const Array3& x) { return Array3(x[0] + a * x[0] * x[0], x[1] + b * x[0] * x[1], 0); });
    EXPECT_NEAR(g->DomainSize(), 4.0 + 8.0 * a * b / 3.0, 1e-13) << g->Name();
  }
  // Same map with z = zeta on hexahedra: volume 8 + 16ab/3.
  for (GT h : {GT::Hexahedra3D20, GT::Hexahedra3D27}) {
    MappedGeometry g(h, [&](const Array3& x) { return Array3(x[0] + a * x[0] * x[0], x[1] + b * x[0] * x[1], x[2]); });
    EXPECT_NEAR(g->DomainSize(), 8.0 + 16.0 * a * b / 3.0, 1e-13) << g->Name();
  }
  // x_i = xi_i + a xi_i^2: det J cubic, volume 1/6 + a/4 + a^2/10 + a^3/90.
  MappedGeometry tet10(GT::Tetrahedra3D10, [&](const Array3& x) { return Array3(x.array() + a * x.array().square()); });
  EXPECT_NEAR(tet10->DomainSize(), 1.0 / 6.0 + a / 4.0 + a * a / 10.0 + a * a * a / 90.0, 1e-14);
  // x = xi (1 + a zeta): det J = 1 + a zeta, volume (1 + a/2) / 2.
  MappedGeometry prism(GT::Prism3D6, [&](const Array3& x) { return Array3(x[0] * (1 + a * x[2]), x[1], x[2]); });
  EXPECT_NEAR(prism->DomainSize(), 0.5 * (1.0 + a / 2.0), 1e-14);
  // A straight quadratic line with an off-centre middle node: length 2.
  MappedGeometry line3(GT::Line2D3, [&](const Array3& x) { return Array3(x[0] + a * x[0] * x[0], 0, 0); });
  EXPECT_NEAR(line3->DomainSize(), 2.0, 1e-14);
}

TEST(Geometry, PointLocalCoordinatesRoundTrip) {
  for (GeometryType type : TypesWithExtent()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    const bool embedded = ref.LocalSpaceDimension() < ref.WorkingSpaceDimension();
    MappedGeometry g(type, [type](const Array3& x) { return Distorted(type, x); });
    for (const Array3& x : InteriorPoints(type)) {
      Array3 global = g->GlobalCoordinates(x);
      // Off a line or surface, the closest point is the foot of the normal.
      if (embedded) global += 0.05 * g->UnitNormal(x);
      Array3 local;
      ASSERT_TRUE(g->PointLocalCoordinates(global, local)) << ref.Name();
      EXPECT_LT((local - x).norm(), 1e-10) << ref.Name() << " at " << x.transpose();
      EXPECT_TRUE(g->IsInsideLocal(local, 1e-9)) << ref.Name();
    }
    // A point beyond the element maps outside the reference element.
    if (!embedded || ref.Family() == GeometryFamily::Line) {
      Array3 local;
      const Array3 outside = Distorted(type, ref.NodesLocalCoordinates()[1]) +
                             0.5 * (Distorted(type, ref.NodesLocalCoordinates()[1]) - g->Center());
      if (g->PointLocalCoordinates(outside, local)) {
        EXPECT_FALSE(g->IsInsideLocal(local, 1e-9)) << ref.Name();
      }
    }
  }
}

TEST(Geometry, UnitNormalsOfACounterClockwiseSquarePointOutwards) {
  MappedGeometry square(GT::Quadrilateral2D4,
                        [](const Array3& x) { return Array3(0.5 * (x[0] + 1), 0.5 * (x[1] + 1), 0); });
  const Array3 expected[4] = {Array3(0, -1, 0), Array3(1, 0, 0), Array3(0, 1, 0), Array3(-1, 0, 0)};
  const auto faces = square->Faces();
  ASSERT_EQ(faces.size(), 4u);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    EXPECT_EQ(square->FaceType(f), GT::Line2D2);
    Geometry::NodesArray nodes;
    for (int i : faces[f]) nodes.push_back(square->pGetNode(i));
    const Geometry edge(square->FaceType(f), nodes);
    EXPECT_LT((edge.UnitNormal(Array3::Zero()) - expected[f]).norm(), 1e-15) << "edge " << f;
    EXPECT_NEAR(edge.DomainSize(), 1.0, 1e-15);
  }
  // A triangle in 3D: normal by the right-hand rule.
  MappedGeometry tri(GT::Triangle3D3, [](const Array3& x) { return Array3(x[1], 0, x[0]); });
  EXPECT_LT((tri->UnitNormal(Array3(0.2, 0.2, 0)) - Array3(0, 1, 0)).norm(), 1e-15);
  EXPECT_THROW(MappedGeometry(GT::Tetrahedra3D4, [](const Array3& x) { return x; })->UnitNormal(Array3::Zero()), Error);
}

TEST(Geometry, FacesCloseTheBoundaryAndPointOutwards) {
  for (GeometryType type : TypesWithExtent()) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    if (ref.LocalSpaceDimension() != ref.WorkingSpaceDimension()) continue;
    MappedGeometry g(type, [type](const Array3& x) { return Distorted(type, x); });
    const Array3 center = g->Center();
    const auto faces = g->Faces();
    ASSERT_FALSE(faces.empty()) << ref.Name();
    Array3 total = Array3::Zero();
    double face_area = 0.0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      Geometry::NodesArray nodes;
      for (int i : faces[f]) nodes.push_back(g->pGetNode(i));
      const Geometry face(g->FaceType(f), nodes);
      // Integral of the area-weighted normal, exact at order 5 for these polynomial faces.
      Matrix J;
      const auto& points = face.IntegrationPoints(5);
      for (std::size_t q = 0; q < points.size(); ++q) {
        face.Jacobian(face.ShapeFunctionsLocalGradients(5)[q], J);
        const Array3 n = face.LocalSpaceDimension() == 1 ? Array3(J(1, 0), -J(0, 0), 0.0)
                                                         : Array3(Array3(J.col(0)).cross(Array3(J.col(1))));
        total += points[q].weight * n;
      }
      face_area += face.DomainSize();
      const Array3 local_center = face.Reference().LocalCenter();
      const Array3 outward = face.GlobalCoordinates(local_center) - center;
      EXPECT_GT(face.UnitNormal(local_center).dot(outward), 0.1 * outward.norm()) << ref.Name() << " face " << f;
    }
    EXPECT_LT(total.norm(), 1e-13 * face_area) << ref.Name();
  }
}

TEST(Geometry, TablesAndEvaluationDoNotAllocate) {
  MappedGeometry g(GT::Hexahedra3D27, [](const Array3& x) { return Distorted(GT::Hexahedra3D27, x); });
  MappedGeometry s(GT::Quadrilateral3D9, [](const Array3& x) { return Distorted(GT::Quadrilateral3D9, x); });
  Matrix J(3, 3), dN(27, 3);
  Vector N(27);
  const Array3 x(0.1, -0.2, 0.3);
  double sink = g->DomainSize();
  const long before = g_allocations;
  for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
    const auto& points = g->IntegrationPoints(order);
    const Matrix& values = g->ShapeFunctionsValues(order);
    const auto& gradients = g->ShapeFunctionsLocalGradients(order);
    for (std::size_t q = 0; q < points.size(); ++q) {
      g->Jacobian(gradients[q], J);
      sink += points[q].weight * J.determinant() * values(q, 0);
    }
  }
  g->ShapeFunctionsValues(x, N);
  g->ShapeFunctionsLocalGradients(x, dN);
  Array3 local;
  sink += g->PointLocalCoordinates(g->GlobalCoordinates(x), local) ? local[0] : 0.0;
  sink += g->DomainSize() + g->Center()[0] + s->UnitNormal(x)[2] + s->DomainSize();
  EXPECT_EQ(g_allocations - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace mc
