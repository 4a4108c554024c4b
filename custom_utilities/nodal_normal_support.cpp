// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/nodal_normal_support.h"

#include <Eigen/Geometry>

#include "core/geometries/reference_element.h"
#include "core/model/model_part.h"
#include "core/utilities/error.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

namespace {

/// S(v) w = v x w.
Eigen::Matrix3d Skew(const Array3& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

const Array3& X(const Geometry& face, int i) { return face[static_cast<std::size_t>(i)].Coordinates(); }

/// The position of `node` in `face`.
int LocalIndex(const Geometry& face, const Node& node) {
  for (std::size_t i = 0; i < face.PointsNumber(); ++i)
    if (&face[i] == &node) return static_cast<int>(i);
  throw Error(Concat("nodal normal: node ", node.Id(), " is not a node of the face"));
}

/// Calls add(local node, dc/dx of that node) for every node that moves the corner vector c of
/// corner `j` (NodalNormalSupport::CornerVector).
template <class TAdd>
void ForEachCornerVectorDerivative(const Geometry& face, int j, TAdd&& add) {
  switch (face.Type()) {
    case GeometryType::Line2D2: {
      // c = (t_y, -t_x, 0) with t = x1 - x0.
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
      r(0, 1) = 1.0;
      r(1, 0) = -1.0;
      add(0, Eigen::Matrix3d(-r));
      add(1, r);
      return;
    }
    case GeometryType::Triangle3D3:
    case GeometryType::Quadrilateral3D4: {
      // c = u x v, u = x_next - x_j, v = x_previous - x_j: dc/du = -S(v), dc/dv = S(u).
      const int n = static_cast<int>(face.PointsNumber());
      const int next = (j + 1) % n, previous = (j + n - 1) % n;
      const Eigen::Matrix3d su = Skew(X(face, next) - X(face, j));
      const Eigen::Matrix3d sv = Skew(X(face, previous) - X(face, j));
      add(j, Eigen::Matrix3d(sv - su));
      add(next, Eigen::Matrix3d(-sv));
      add(previous, su);
      return;
    }
    default:
      throw Error(Concat("nodal normal derivatives: no closed-form corner vector for ", face.Name(),
                         " faces (Line2D2, Triangle3D3 and Quadrilateral3D4 have one)"));
  }
}

}  // namespace

Array3 NodalNormalSupport::UnitCornerNormal(const Geometry& face, const Node& node) {
  const Array3 c = CornerVector(face, LocalIndex(face, node));
  const double norm = c.norm();
  return norm > 0.0 ? Array3(c / norm) : Array3::Zero();
}

Array3 NodalNormalSupport::SymmetryMask(const Node& node) {
  return {node.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X) ? 0.0 : 1.0,
          node.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_Y) ? 0.0 : 1.0,
          node.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_Z) ? 0.0 : 1.0};
}

NodalNormalSupport::NodalNormalSupport(const std::vector<const Geometry*>& faces) {
  for (const Geometry* face : faces) Add(face);
}

NodalNormalSupport::NodalNormalSupport(const ModelPart& interface) {
  for (const Condition* condition : interface.Conditions()) Add(&condition->GetGeometry());
}

void NodalNormalSupport::Add(const Geometry* face) {
  for (const Node* node : face->Nodes()) faces_of_[node].push_back(face);
}

Array3 NodalNormalSupport::CornerVector(const Geometry& face, int j) {
  switch (face.Type()) {
    case GeometryType::Line2D2: {
      const Array3 t = X(face, 1) - X(face, 0);
      return {t.y(), -t.x(), 0.0};
    }
    case GeometryType::Triangle3D3:
    case GeometryType::Quadrilateral3D4: {
      const int n = static_cast<int>(face.PointsNumber());
      return (X(face, (j + 1) % n) - X(face, j)).cross(X(face, (j + n - 1) % n) - X(face, j));
    }
    default: return face.UnitNormal(face.Reference().NodesLocalCoordinates()[static_cast<std::size_t>(j)]);
  }
}

const std::vector<const Geometry*>& NodalNormalSupport::Faces(const Node& node) const {
  static const std::vector<const Geometry*> none;
  const auto it = faces_of_.find(&node);
  return it == faces_of_.end() ? none : it->second;
}

Array3 NodalNormalSupport::Normal(const Node& node) const {
  Array3 m = Array3::Zero();
  for (const Geometry* face : Faces(node)) m += UnitCornerNormal(*face, node);
  m = m.cwiseProduct(SymmetryMask(node));
  const double norm = m.norm();
  return norm > 0.0 ? Array3(m / norm) : Array3::Zero();
}

void NodalNormalSupport::Compute(const Node& node, Derivatives& out) const {
  out.nodes.clear();
  out.dn_dx.clear();
  Array3 m = Array3::Zero();
  for (const Geometry* face : Faces(node)) {
    const int j = LocalIndex(*face, node);
    const Array3 a = CornerVector(*face, j);
    const double norm_a = a.norm();
    if (!(norm_a > 0.0)) throw SolutionError(Concat("nodal normal of node ", node.Id(), ": a degenerate face corner"));
    const Array3 unit_a = a / norm_a;
    m += unit_a;
    // d(a/|a|)/da = (I - a^ a^T) / |a|, chained with da/dx_k and accumulated per distinct node
    // (a node's faces share it and its neighbours).
    const Eigen::Matrix3d chain = (Eigen::Matrix3d::Identity() - unit_a * unit_a.transpose()) / norm_a;
    ForEachCornerVectorDerivative(*face, j, [&](int local, const Eigen::Matrix3d& da_raw) {
      const Eigen::Matrix3d da = chain * da_raw;
      Node* k = face->pGetNode(static_cast<std::size_t>(local));
      std::size_t i = 0;
      while (i < out.nodes.size() && out.nodes[i] != k) ++i;
      if (i == out.nodes.size()) {
        out.nodes.push_back(k);
        out.dn_dx.push_back(da);
      } else {
        out.dn_dx[i] += da;
      }
    });
  }
  const Array3 mask = SymmetryMask(node);
  m = m.cwiseProduct(mask);
  const double norm = m.norm();
  if (!(norm > 0.0))
    throw SolutionError(Concat("nodal normal of node ", node.Id(), ": the unit normals of its ", Faces(node).size(),
                               " interface faces sum to zero"));
  out.normal = m / norm;
  const Eigen::Matrix3d projector =
      (Eigen::Matrix3d::Identity() - out.normal * out.normal.transpose()) / norm * mask.asDiagonal();
  for (Eigen::Matrix3d& d : out.dn_dx) d = projector * d;
}

}  // namespace mc
