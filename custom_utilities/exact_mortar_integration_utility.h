// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <array>

#include "custom_utilities/mortar_shape_functions.h"

namespace mc {

/// The vertex a 3D overlap's fan starts from, by what it is: kind 0 master node `index` inside
/// the slave, 1 slave node `index` inside the master, 2 the crossing of slave edge i and master
/// edge l (index i * master nodes + l), 3 none (the polygon's first vertex); -1 not chosen yet.
struct MortarFanStart {
  int kind = -1;
  int index = -1;
  bool operator==(const MortarFanStart&) const = default;
};

/// The fan starts of one pair within a step (TIME `time`): the current one and those it left.
/// ExactMortarIntegrationUtility::Compute follows Kratos' rule but never goes back to a start the
/// step has left: that is the Newton cycle of a vertex on the other face's edge (below). With
/// `hold`, the start of the step's first evaluation is kept through the step instead.
struct MortarFanHistory {
  double time = 0.0;
  bool hold = false;
  MortarFanStart current;
  std::array<MortarFanStart, 3> left{};
  int left_count = 0;
};

/// Settings of the mortar segmentation, filled from the contact process (spec 4.2).
struct MortarIntegrationSettings {
  /// INTEGRATION_ORDER_CONTACT, 1..5: Gauss points per overlap segment in 2D; in 3D the
  /// order of the triangle rule applied to every sub-triangle (order 2 = 3 points at
  /// barycentric (2/3, 1/6, 1/6) and permutations).
  int integration_order = 2;
  /// ZERO_TOLERANCE_FACTOR: scales the geometric epsilons (duplicate vertices, empty overlaps).
  double zero_tolerance_factor = 1.0;
  /// CONSIDER_TESSELLATION: Delaunay instead of a fan; not implemented (NotImplementedError).
  bool consider_tessellation = false;
  /// 2D only, x = radius, y = axis: the mortar integrals are taken over the surface of
  /// revolution, each weight times 2 pi r at the point (MortarPairKinematics applies it).
  bool axisymmetric = false;
  /// When set, the fan starts of this 3D pair in the step so far: Kratos' rule, except that a
  /// start the step has left is not taken again, or with `hold` the step's first start throughout
  /// (see ExactMortarIntegrationUtility::Compute).
  MortarFanHistory* fan_history = nullptr;
};

/// One mortar integration point of a (slave, master) pair.
template <class T, int TDim>
struct MortarIntegrationPoint {
  static constexpr int kLocalDim = TDim - 1;
  Eigen::Matrix<T, kLocalDim, 1> slave_local;   ///< slave local coordinates
  Eigen::Matrix<T, kLocalDim, 1> master_local;  ///< master local coordinates (see below)
  /// Physical measure: sum over the pair = overlap length (2D) or area (3D) measured on the
  /// slave line / slave triangle / lifted fan of a quadrilateral slave (below). Kratos' 2D
  /// convention is twice this value.
  T weight;
};

/// The integration points of one pair, fixed capacity (no heap).
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarIntegrationPoints {
  /// A convex n-gon clipped by a convex m-gon has at most n + m vertices -> n + m - 2
  /// fan triangles of at most 7 points (order 5); a 2D segment gets at most 5 points.
  static constexpr int kMaxPoints = TDim == 2 ? 5 : 7 * (TNumNodes + TNumNodesMaster - 2);
  std::array<MortarIntegrationPoint<T, TDim>, kMaxPoints> points;
  int size = 0;
  T area = T(0.0);  ///< sum of the weights (physical overlap measure)
};

/// Exact segmentation of one slave/master pair of linear interface conditions
/// (TDim = 2: Line2D2/Line2D2; TDim = 3: Triangle3D3 or Quadrilateral3D4 on either side).
///
/// Algorithm (Popp's segment-based integration as used in Kratos):
/// - The slave condition normal n_s is the geometric unit normal at the slave centre
///   (2D: n_s = (t_y, -t_x) with t the unit tangent from node 1 to node 2, as
///   Geometry::UnitNormal; 3D: normalised
///   dX/dxi x dX/deta). Its sign does not matter for the segmentation.
/// - 2D: the overlap is the set of slave points whose ray along the interpolated slave nodal
///   normal meets the master line, so its ends are the slave points whose ray passes through a
///   master node (Popp et al. 2009; Kratos 10.4) and the master end of every overlap is exactly at
///   a master node; Gauss points on it, ascending xi.
/// - 3D: slave and master nodes are projected along n_s onto the slave mean plane (through
///   the slave centroid, normal n_s); the master polygon is clipped by the (convex) slave
///   polygon (Sutherland-Hodgman, both oriented counter-clockwise about n_s, near-duplicate
///   vertices merged); it is cut into a fan from Kratos 10.4's first point (a master vertex inside
///   the slave, else a slave vertex inside the master, else an edge crossing: the integration
///   points, and so M, whose integrand is not polynomial, depend on it), and each sub-triangle
///   gets the triangle rule of the order. A quadrilateral slave, which may be warped, takes each
///   sub-triangle lifted onto it (its corners mapped to the slave along n_s): the rule of the
///   lifted triangle, its area, each point at the slave's closest point (Kratos 10.4).
/// - Slave local coordinates: inverse map of the slave geometry along n_s (triangles; the
///   corners of the lifted triangles), closest point (points of the lifted triangles).
///   Master local coordinates: the slave point x1(xi) is projected onto the master along the
///   interpolated slave nodal normal sum_i N_i(xi) n_i (Kratos), so they depend on the
///   nodal normals. Points projecting outside the master are kept (extrapolated), as Kratos.
///
/// T is double or an Eigen::AutoDiffScalar; all branch decisions use the values only, so the
/// derivatives are exact for the current segmentation pattern (including the clipping).
/// Templates are instantiated explicitly (double and the AutoDiff type of
/// MortarPairKinematics) for (2,2,2), (3,3,3), (3,3,4), (3,4,3), (3,4,4).
template <int TDim, int TNumNodes, int TNumNodesMaster>
class ExactMortarIntegrationUtility {
 public:
  template <class T>
  using SlaveMatrix = Eigen::Matrix<T, TNumNodes, TDim>;  ///< row i = node i
  template <class T>
  using MasterMatrix = Eigen::Matrix<T, TNumNodesMaster, TDim>;
  template <class T>
  using Points = MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster>;

  /// Segments the pair. slave_normals are the unit nodal normals (NORMAL) of the slave nodes,
  /// used only for the master local coordinates. Returns false (and size 0) if the overlap
  /// is empty or below the tolerance. Throws NotImplementedError for consider_tessellation
  /// and InputError for an integration order outside 1..5.
  template <class T>
  static bool Compute(const SlaveMatrix<T>& slave_coordinates, const MasterMatrix<T>& master_coordinates,
                      const SlaveMatrix<T>& slave_normals, const MortarIntegrationSettings& settings,
                      Points<T>& result);

  /// Geometric unit normal of the slave condition at its centre (see above).
  template <class T>
  static Eigen::Matrix<T, TDim, 1> SlaveConditionNormal(const SlaveMatrix<T>& slave_coordinates);
};

}  // namespace mc
