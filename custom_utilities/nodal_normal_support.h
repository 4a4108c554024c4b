// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <unordered_map>
#include <vector>

#include "core/geometries/geometry.h"

namespace mc {

class ModelPart;

/// The averaged nodal normals of an interface as functions of the current coordinates, with
/// their exact derivatives (the normal variation of the NV mortar conditions).
///
///   n_j = m_j / |m_j|,   m_j = sum over the faces f holding node j of a_f(x) / |a_f(x)|,
///   dn_j/dx_k = (I - n_j n_j^T) / |m_j| . sum_f (I - u_f u_f^T) / |a_f| . da_f/dx_k,  u_f = a_f / |a_f|,
///
/// nonzero for every node k of the faces around j. Every face's unit normal counts once (Popp's
/// nodal normal, and Kratos 10.4's): weighted by area instead, a curved surface meshed with faces
/// of different sizes gets twice the first-order normal error. The area vector a_f is |f| times the unit normal for
/// lines and triangles, and the closed form (x2 - x0) x (x3 - x1) / 2 for bilinear quads (the
/// exact area of a planar quad, and the normal at its centre); NormalCalculationUtilities uses
/// the same weighted vectors, so the stored NORMAL and this class agree. Normals point out of
/// the body when the faces are ordered as the interface builder generates them.
///
/// Built once per contact search from the interface conditions (the faces must outlive it);
/// read-only afterwards, so the pair conditions of all threads share one instance.
class NodalNormalSupport {
 public:
  /// n_j and dn_j/dx_k for the nodes k its faces hold (own node included, each node once).
  struct Derivatives {
    Array3 normal = Array3::Zero();
    std::vector<Node*> nodes;
    std::vector<Eigen::Matrix3d> dn_dx;  ///< dn_dx[i](a, b) = d n_a / d x_b of nodes[i]
  };

  /// The faces of `faces` (lines in 2D, triangles or quadrilaterals in 3D) around each node.
  explicit NodalNormalSupport(const std::vector<const Geometry*>& faces);
  /// Every condition of `interface` is a face.
  explicit NodalNormalSupport(const ModelPart& interface);

  /// a_f: 2D line: the tangent x1 - x0 rotated by -90 degrees; triangle: (x1-x0) x (x2-x0) / 2;
  /// quadrilateral: (x2-x0) x (x3-x1) / 2. Other geometries: DomainSize() x UnitNormal at the centre.
  static Array3 AreaVector(const Geometry& face);
  /// The face's contribution to the nodal normal sums: its unit normal a_f / |a_f|.
  static Array3 WeightedVector(const Geometry& face);
  /// Whether AreaVector has closed-form derivatives for this face (Line2D2, Triangle3D3,
  /// Quadrilateral3D4).
  static bool HasAreaVectorDerivatives(const Geometry& face);

  bool Contains(const Node& node) const { return faces_of_.count(&node) > 0; }
  /// The faces holding `node` (empty when none).
  const std::vector<const Geometry*>& Faces(const Node& node) const;
  /// n_j at the current coordinates (zero when the node has no face).
  Array3 Normal(const Node& node) const;
  /// n_j and its derivatives; `out` is refilled (its capacity is reused: no allocation once warm).
  /// Throws mc::Error for a face without closed-form derivatives or a zero m_j.
  void Compute(const Node& node, Derivatives& out) const;

 private:
  void Add(const Geometry* face);

  std::unordered_map<const Node*, std::vector<const Geometry*>> faces_of_;
};

}  // namespace mc
