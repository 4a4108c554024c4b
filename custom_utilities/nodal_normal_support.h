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
///   n_j = m_j / |m_j|,   m_j = P_j sum over the faces f holding node j of c_fj(x) / |c_fj(x)|,
///   dn_j/dx_k = (I - n_j n_j^T) / |m_j| . P_j sum_f (I - u_fj u_fj^T) / |c_fj| . dc_fj/dx_k,  u_fj = c_fj / |c_fj|,
///
/// nonzero for the nodes k of the faces around j that move a corner vector c_fj. Every face's
/// unit normal at the node counts once (Popp's nodal normal, and Kratos 10.4's, which evaluates
/// each face's normal at the node): weighted by area instead, a curved surface meshed with faces
/// of different sizes gets twice the first-order normal error. c_fj is the face normal at its
/// corner j: the rotated tangent of a line, and (x_next - x_j) x (x_previous - x_j) for a
/// triangle (its constant normal) or a bilinear quadrilateral (its normal at that corner, which
/// differs from the centre's on a warped face). NormalCalculationUtilities uses the same vectors,
/// so the stored NORMAL and this class agree. Normals point out of the body when the faces are
/// ordered as the interface builder generates them.
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

  /// c_fj of corner j (local index): 2D line: the tangent x1 - x0 rotated by -90 degrees;
  /// triangle and quadrilateral: (x_next - x_j) x (x_previous - x_j). Other geometries: the unit
  /// normal at the corner.
  static Array3 CornerVector(const Geometry& face, int j);
  /// The face's contribution to the normal sum of `node` (one of its nodes): c_fj / |c_fj|.
  static Array3 UnitCornerNormal(const Geometry& face, const Node& node);
  /// P_j, applied to m_j before normalising: 0 at the components a to which `node`'s
  /// VECTOR_LAGRANGE_MULTIPLIER is fixed, 1 elsewhere. A fixed multiplier component marks a symmetry
  /// plane of the contact (the half model of cases.cattaneo_mindlin: t_y = 0 on y = 0), where the
  /// mirrored faces missing from the model would cancel m_j's component across the plane; without
  /// P_j the normals of the plane's nodes tilt out of it (|n_y| 0.004 .. 0.026 on hertz3dgrid_15k).
  static Array3 SymmetryMask(const Node& node);

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
