// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/nodal_normal_support.h"

#include <Eigen/Geometry>

#include "core/geometries/reference_element.h"
#include "core/model/model_part.h"
#include "core/utilities/error.h"

namespace mc {

namespace {

/// S(v) w = v x w.
Eigen::Matrix3d Skew(const Array3& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

const Array3& X(const Geometry& face, int i) { return face[static_cast<std::size_t>(i)].Coordinates(); }

/// Calls add(local node, da/dx of that node) for every node of a face with a closed-form area vector.
template <class TAdd>
void ForEachAreaVectorDerivative(const Geometry& face, TAdd&& add) {
  switch (face.Type()) {
    case GeometryType::Line2D2: {
      // a = (t_y, -t_x, 0) with t = x1 - x0.
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
      r(0, 1) = 1.0;
      r(1, 0) = -1.0;
      add(0, Eigen::Matrix3d(-r));
      add(1, r);
      return;
    }
    case GeometryType::Triangle3D3: {
      // a = u x v / 2, u = x1 - x0, v = x2 - x0: da/du = -S(v)/2, da/dv = S(u)/2.
      const Eigen::Matrix3d su = 0.5 * Skew(X(face, 1) - X(face, 0));
      const Eigen::Matrix3d sv = 0.5 * Skew(X(face, 2) - X(face, 0));
      add(0, Eigen::Matrix3d(sv - su));
      add(1, Eigen::Matrix3d(-sv));
      add(2, su);
      return;
    }
    case GeometryType::Quadrilateral3D4: {
      // a = u x v / 2 with the diagonals u = x2 - x0, v = x3 - x1.
      const Eigen::Matrix3d su = 0.5 * Skew(X(face, 2) - X(face, 0));
      const Eigen::Matrix3d sv = 0.5 * Skew(X(face, 3) - X(face, 1));
      add(0, sv);
      add(1, Eigen::Matrix3d(-su));
      add(2, Eigen::Matrix3d(-sv));
      add(3, su);
      return;
    }
    default:
      throw Error(Concat("nodal normal derivatives: no closed-form area vector for ", face.Name(),
                         " faces (Line2D2, Triangle3D3 and Quadrilateral3D4 have one)"));
  }
}

}  // namespace

Array3 NodalNormalSupport::WeightedVector(const Geometry& face) {
  const Array3 a = AreaVector(face);
  const double norm = a.norm();
  return norm > 0.0 ? Array3(a / norm) : Array3::Zero();
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

Array3 NodalNormalSupport::AreaVector(const Geometry& face) {
  switch (face.Type()) {
    case GeometryType::Line2D2: {
      const Array3 t = X(face, 1) - X(face, 0);
      return {t.y(), -t.x(), 0.0};
    }
    case GeometryType::Triangle3D3:
      return 0.5 * (X(face, 1) - X(face, 0)).cross(X(face, 2) - X(face, 0));
    case GeometryType::Quadrilateral3D4:
      return 0.5 * (X(face, 2) - X(face, 0)).cross(X(face, 3) - X(face, 1));
    default:
      return face.DomainSize() * face.UnitNormal(face.Reference().LocalCenter());
  }
}

bool NodalNormalSupport::HasAreaVectorDerivatives(const Geometry& face) {
  const GeometryType type = face.Type();
  return type == GeometryType::Line2D2 || type == GeometryType::Triangle3D3 || type == GeometryType::Quadrilateral3D4;
}

const std::vector<const Geometry*>& NodalNormalSupport::Faces(const Node& node) const {
  static const std::vector<const Geometry*> none;
  const auto it = faces_of_.find(&node);
  return it == faces_of_.end() ? none : it->second;
}

Array3 NodalNormalSupport::Normal(const Node& node) const {
  Array3 m = Array3::Zero();
  for (const Geometry* face : Faces(node)) m += WeightedVector(*face);
  const double norm = m.norm();
  return norm > 0.0 ? Array3(m / norm) : Array3::Zero();
}

void NodalNormalSupport::Compute(const Node& node, Derivatives& out) const {
  out.nodes.clear();
  out.dn_dx.clear();
  Array3 m = Array3::Zero();
  for (const Geometry* face : Faces(node)) {
    const Array3 a = AreaVector(*face);
    const double norm_a = a.norm();
    if (!(norm_a > 0.0)) throw SolutionError(Concat("nodal normal of node ", node.Id(), ": a face of zero area"));
    const Array3 unit_a = a / norm_a;
    m += unit_a;
    // d(a/|a|)/da = (I - a^ a^T) / |a|, chained with da/dx_k and accumulated per distinct node
    // (a node's faces share it and its neighbours).
    const Eigen::Matrix3d chain = (Eigen::Matrix3d::Identity() - unit_a * unit_a.transpose()) / norm_a;
    ForEachAreaVectorDerivative(*face, [&](int local, const Eigen::Matrix3d& da_raw) {
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
  const double norm = m.norm();
  if (!(norm > 0.0))
    throw SolutionError(Concat("nodal normal of node ", node.Id(), ": the unit normals of its ", Faces(node).size(),
                               " interface faces sum to zero"));
  out.normal = m / norm;
  const Eigen::Matrix3d projector = (Eigen::Matrix3d::Identity() - out.normal * out.normal.transpose()) / norm;
  for (Eigen::Matrix3d& d : out.dn_dx) d = projector * d;
}

}  // namespace mc
