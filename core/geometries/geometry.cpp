// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/geometry.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cassert>
#include <cmath>
#include <string>

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"

namespace mc {
namespace {

constexpr int kMaxNodes = ReferenceElement::kMaxNodes;

const Array3& Coordinates(const Node& node, Configuration c) {
  return c == Configuration::Initial ? node.X0() : node.Coordinates();
}

// Full 3 x 3 Jacobian from gradients laid out dN[3 * i + k]; columns past the local dimension
// are zero.
Eigen::Matrix3d Jacobian3(const Geometry& geometry, const double* dN, Configuration c) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)
    J += Coordinates(geometry[i], c) * Eigen::Map<const Eigen::RowVector3d>(dN + 3 * i);
  return J;
}

// Length, area or volume density of the map: |det J| for solids, sqrt(det(J^T J)) otherwise.
double Measure(const Eigen::Matrix3d& J, int local_dim, int working_dim) {
  switch (local_dim) {
    case 1: return J.col(0).norm();
    case 2: return working_dim == 2 ? std::abs(J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0)) : J.col(0).cross(J.col(1)).norm();
    case 3: return std::abs(J.determinant());
    default: return 0.0;
  }
}

}  // namespace

Geometry::Geometry(GeometryType type, NodesArray nodes)
    : reference_(&ReferenceElement::Get(type)), nodes_(std::move(nodes)) {
  const auto expected = static_cast<std::size_t>(reference_->NodesNumber());
  if (!nodes_.empty() && nodes_.size() != expected) {
    std::string ids;
    for (const Node* node : nodes_) {
      if (!ids.empty()) ids += ' ';
      ids += node ? std::to_string(node->Id()) : std::string("null");
    }
    throw InputError(
        Concat("geometry ", Name(), " needs ", expected, " nodes, got ", nodes_.size(), " (node ids ", ids, ")"));
  }
  for (const Node* node : nodes_)
    if (!node) throw InputError(Concat("geometry ", Name(), ": null node pointer"));
}

GeometryType Geometry::Type() const noexcept { return reference_->Type(); }
GeometryFamily Geometry::Family() const noexcept { return reference_->Family(); }
const char* Geometry::Name() const noexcept { return reference_->Name(); }
int Geometry::WorkingSpaceDimension() const noexcept { return reference_->WorkingSpaceDimension(); }
int Geometry::LocalSpaceDimension() const noexcept { return reference_->LocalSpaceDimension(); }
int Geometry::DefaultIntegrationOrder() const noexcept { return reference_->DefaultIntegrationOrder(); }

const std::vector<IntegrationPoint>& Geometry::IntegrationPoints(int order) const {
  return reference_->IntegrationPoints(order);
}

const Matrix& Geometry::ShapeFunctionsValues(int order) const { return reference_->ShapeFunctionsValues(order); }

const std::vector<Matrix>& Geometry::ShapeFunctionsLocalGradients(int order) const {
  return reference_->ShapeFunctionsLocalGradients(order);
}

void Geometry::ShapeFunctionsValues(const Array3& local, Vector& N) const {
  reference_->ShapeFunctionsValues(local, N);
}

void Geometry::ShapeFunctionsLocalGradients(const Array3& local, Matrix& dN) const {
  reference_->ShapeFunctionsLocalGradients(local, dN);
}

void Geometry::Jacobian(const Matrix& dN, Matrix& J, Configuration c) const {
  const int wd = WorkingSpaceDimension(), ld = LocalSpaceDimension();
  assert(dN.rows() == static_cast<Eigen::Index>(nodes_.size()) && dN.cols() == ld);
  if (J.rows() != wd || J.cols() != ld) J.resize(wd, ld);
  J.setZero();
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Array3& x = Coordinates(*nodes_[n], c);
    for (int k = 0; k < ld; ++k)
      for (int i = 0; i < wd; ++i) J(i, k) += x[i] * dN(n, k);
  }
}

Array3 Geometry::GlobalCoordinates(const Array3& local, Configuration c) const {
  double N[kMaxNodes], dN[3 * kMaxNodes];
  reference_->Evaluate(local, N, dN);
  Array3 x = Array3::Zero();
  for (std::size_t n = 0; n < nodes_.size(); ++n) x += N[n] * Coordinates(*nodes_[n], c);
  return x;
}

bool Geometry::PointLocalCoordinates(const Array3& global, Array3& local, Configuration c) const {
  const int ld = LocalSpaceDimension();
  local = reference_->LocalCenter();
  if (ld == 0) return true;
  // Gauss-Newton on |x(xi) - global|^2: Newton for solids, the closest point (least squares)
  // for lines and surfaces embedded in a higher dimension.
  double N[kMaxNodes], dN[3 * kMaxNodes];
  for (int iteration = 0; iteration < 100; ++iteration) {
    reference_->Evaluate(local, N, dN);
    Array3 x = Array3::Zero();
    for (std::size_t n = 0; n < nodes_.size(); ++n) x += N[n] * Coordinates(*nodes_[n], c);
    const Eigen::Matrix3d J = Jacobian3(*this, dN, c);
    // Normal equations padded to 3 x 3: unit diagonal on the unused local directions.
    Eigen::Matrix3d A = J.transpose() * J;
    const double scale = A.trace();
    for (int k = ld; k < 3; ++k) A(k, k) = scale;
    const Array3 b = J.transpose() * (global - x);
    if (!(scale > 0.0) || std::abs(A.determinant()) <= 1e-14 * std::pow(scale, 3)) return false;
    const Array3 step = A.partialPivLu().solve(b);
    local += step;
    if (!local.allFinite() || local.norm() > 1e6) return false;
    if (step.norm() < 1e-13) return true;
  }
  return false;
}

bool Geometry::IsInsideLocal(const Array3& local, double tolerance) const {
  return reference_->IsInside(local, tolerance);
}

double Geometry::DomainSize(Configuration c) const {
  const int ld = LocalSpaceDimension(), wd = WorkingSpaceDimension();
  if (ld == 0) return 0.0;
  const int order = reference_->MeasureIntegrationOrder();
  const std::vector<IntegrationPoint>& points = reference_->IntegrationPoints(order);
  const std::vector<Matrix>& gradients = reference_->ShapeFunctionsLocalGradients(order);
  double size = 0.0;
  for (std::size_t g = 0; g < points.size(); ++g) {
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    for (std::size_t n = 0; n < nodes_.size(); ++n) J.leftCols(ld) += Coordinates(*nodes_[n], c) * gradients[g].row(n);
    size += points[g].weight * Measure(J, ld, wd);
  }
  return size;
}

Array3 Geometry::Center(Configuration c) const {
  Array3 center = Array3::Zero();
  for (const Node* node : nodes_) center += Coordinates(*node, c);
  return nodes_.empty() ? center : Array3(center / static_cast<double>(nodes_.size()));
}

Array3 Geometry::UnitNormal(const Array3& local, Configuration c) const {
  double N[kMaxNodes], dN[3 * kMaxNodes];
  reference_->Evaluate(local, N, dN);
  const Eigen::Matrix3d J = Jacobian3(*this, dN, c);
  Array3 normal;
  switch (LocalSpaceDimension()) {
    case 1: normal = Array3(J(1, 0), -J(0, 0), 0.0); break;
    case 2: normal = J.col(0).cross(J.col(1)); break;
    default: throw Error(Concat("UnitNormal is defined for lines and surfaces, not for geometry ", Name()));
  }
  const double norm = normal.norm();
  if (!(norm > 0.0)) throw SolutionError(Concat("degenerate ", Name(), ": zero normal"));
  return normal / norm;
}

std::vector<std::vector<int>> Geometry::Faces() const {
  std::vector<std::vector<int>> faces;
  faces.reserve(reference_->Faces().size());
  for (const ReferenceElement::Face& face : reference_->Faces()) faces.push_back(face.nodes);
  return faces;
}

GeometryType Geometry::FaceType(std::size_t face) const {
  assert(face < reference_->Faces().size());
  return reference_->Faces()[face].type;
}

}  // namespace mc
