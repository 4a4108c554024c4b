// SPDX-License-Identifier: BSD-3-Clause
// Small entities for the solving tests: springs (linear or cubic), a point mass and a point load,
// all on DISPLACEMENT DoFs, plus helpers that build model parts from them.
#pragma once

#include <memory>

#include "core/model/condition.h"
#include "core/model/element.h"
#include "core/model/model.h"
#include "tests/cpp/common/local_system_entity.h"

namespace mc::test {

/// Axial spring between two nodes, axis from the initial coordinates; axial force
/// N = k e + c e^3 with the elongation e = (u2 - u1) . n, exact tangent (k + 3 c e^2) n n^T.
/// DoFs: DISPLACEMENT_X (dimension 1) or DISPLACEMENT_X, _Y (dimension 2) of each node.
class TestSpring : public LocalSystemEntity<Element> {
 public:
  TestSpring(IndexType id, Geometry geometry, double k, double c, int dimension)
      : LocalSystemEntity(id, std::move(geometry), nullptr), k_(k), c_(c), dimension_(dimension) {}
  std::string Info() const override { return "TestSpring"; }
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  bool HasConstantLeftHandSide() const override { return c_ == 0.0; }

 private:
  double k_;
  double c_;
  int dimension_;
};

/// A point mass m (and dashpot d to the ground) on the DISPLACEMENT_X of one node; no stiffness.
class TestMass : public Element {
 public:
  TestMass(IndexType id, Geometry geometry, double m, double d = 0.0)
      : Element(id, std::move(geometry), nullptr), m_(m), d_(d) {}
  std::string Info() const override { return "TestMass"; }
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  void CalculateMassMatrix(Matrix& mass, const ProcessInfo& info) override;
  void CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info) override;

 private:
  double m_;
  double d_;
};

/// A constant force F on the DISPLACEMENT_X of one node.
class TestLoad : public Condition {
 public:
  TestLoad(IndexType id, Geometry geometry, double force) : Condition(id, std::move(geometry), nullptr), f_(force) {}
  std::string Info() const override { return "TestLoad"; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  void SetForce(double f) noexcept { f_ = f; }

 private:
  double f_;
};

/// A root model part "Structure" with DISPLACEMENT, REACTION, VELOCITY, ACCELERATION.
ModelPart& MakeModelPart(Model& model, int buffer_size = 2);
/// A node with DISPLACEMENT_X (and _Y for dimension 2) DoFs carrying REACTION_X (_Y).
Node& AddNode(ModelPart& mp, IndexType id, double x, double y, int dimension = 1);
TestSpring& AddSpring(ModelPart& mp, IndexType id, IndexType n1, IndexType n2, double k, double c = 0.0,
                      int dimension = 1);
TestMass& AddMass(ModelPart& mp, IndexType id, IndexType node, double m, double d = 0.0);
TestLoad& AddLoad(ModelPart& mp, IndexType id, IndexType node, double force);

}  // namespace mc::test
