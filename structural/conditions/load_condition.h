// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/model/condition.h"

namespace mc {

/// The structural load conditions, Kratos' PointLoadCondition, LineLoadCondition and
/// SurfaceLoadCondition + "<dim>D<nodes>N", and their axisymmetric variants (prefix "Axisym",
/// x = radius). DoFs: DISPLACEMENT of the working dimension. Sign conventions as for elements:
/// RHS = f_ext, LHS = -d f_ext / du (load stiffness), left out in a linear analysis
/// (ProcessInfo LINEAR_ANALYSIS).
///
/// - Point: POINT_LOAD of the node (historical, when stored) plus the condition's own value.
///   Axisymmetric (a ring load, Kratos' AxisymPointLoadCondition2D1N): POINT_LOAD is a force
///   per unit length of the circle through the node, so the nodal force is 2 pi r POINT_LOAD
///   with r the current radius.
/// - Line (2D edge or 3D line): LINE_LOAD (nodal historical values interpolated plus the
///   condition's value) is a force per unit length of the current line, in a fixed direction.
///   The net face pressure p = NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE (nodal
///   historical interpolated plus condition value) is a follower load in 2D: it acts along
///   (-t_y, t_x), t the current tangent, on the current length. 3D lines have no normal: a
///   pressure on them is an InputError. Axisymmetric: both are per unit area of the current
///   surface of revolution, integrated with 2 pi r ds.
/// - Surface (3D): SURFACE_LOAD (force per unit area) acts on the current area in a fixed
///   direction; the face pressure is a follower load f_a = int N_a p (x_,xi x x_,eta) dxi deta on
///   the current surface (normal as Geometry::UnitNormal).
///
/// No load is multiplied by THICKNESS. Kratos 10.4 divides the axisymmetric loads by THICKNESS
/// when the properties have one, which its axisymmetric elements ignore: a 1/t error that is not
/// reproduced here.
class LoadCondition final : public Condition {
 public:
  enum class Load { kPoint, kLine, kSurface };

  LoadCondition(IndexType id, Geometry geometry, Properties* properties, Load load, bool axisymmetric)
      : Condition(id, std::move(geometry), properties), load_(load), axisymmetric_(axisymmetric) {}
  /// The same load on other nodes.
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;

  /// E.g. "LineLoadCondition2D2N", "AxisymPointLoadCondition2D1N".
  std::string Info() const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// Nodes carry DISPLACEMENT and its DoFs.
  void Check(const ProcessInfo& info) const override;

 private:
  /// The current configuration at one integration point of a line or surface.
  struct BoundaryPoint;

  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info);
  void CalculatePointLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const;
  void CalculateLineLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const;
  void CalculateSurfaceLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const;
  /// Tangents, radius, load `var` and face pressure at integration point g of `order`.
  BoundaryPoint Interpolate(const Variable<Array3>& var, int order, std::size_t g) const;

  int Dimension() const noexcept;
  /// Nodal historical value of `var` (zero when the nodes do not store it) of node a.
  Array3 NodalVector(const Variable<Array3>& var, std::size_t a) const;
  /// Net face pressure NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE of node a (historical).
  double NodalPressure(std::size_t a) const;
  /// Net face pressure set on the condition itself.
  double ConditionPressure() const;

  Load load_;
  bool axisymmetric_;
};

}  // namespace mc
