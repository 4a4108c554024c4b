// SPDX-License-Identifier: BSD-3-Clause
// Test entities shared by the solving tests (see test_elements.h).
#include "test_elements.h"

#include "core/variables/kernel_variables.h"

namespace mc::test {

std::unique_ptr<Element> TestSpring::Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const {
  return std::make_unique<TestSpring>(id, Geometry(GetGeometry().Type(), std::move(nodes)), k_, c_, dimension_);
}

void TestSpring::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  dofs.clear();
  for (std::size_t i = 0; i < 2; ++i) {
    dofs.push_back(&GetGeometry()[i].GetDof(DISPLACEMENT_X));
    if (dimension_ == 2) dofs.push_back(&GetGeometry()[i].GetDof(DISPLACEMENT_Y));
  }
}

void TestSpring::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  const int n = 2 * dimension_;
  Array3 axis = GetGeometry()[1].X0() - GetGeometry()[0].X0();
  if (dimension_ == 1) axis = Array3(1.0, 0.0, 0.0);
  axis.normalize();
  Vector d(n);
  for (int i = 0; i < dimension_; ++i) {
    d[i] = -axis[i];
    d[dimension_ + i] = axis[i];
  }
  Vector u(n);
  GetValuesVector(u);
  const double e = d.dot(u);
  const double force = k_ * e + c_ * e * e * e;
  lhs = (k_ + 3.0 * c_ * e * e) * d * d.transpose();
  rhs = -force * d;
}

std::unique_ptr<Element> TestMass::Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const {
  return std::make_unique<TestMass>(id, Geometry(GetGeometry().Type(), std::move(nodes)), m_, d_);
}

void TestMass::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  dofs.assign(1, &GetGeometry()[0].GetDof(DISPLACEMENT_X));
}

void TestMass::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  lhs.setZero(1, 1);
  rhs.setZero(1);
}
void TestMass::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) { lhs.setZero(1, 1); }
void TestMass::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) { rhs.setZero(1); }
void TestMass::CalculateMassMatrix(Matrix& mass, const ProcessInfo& info) { mass.setConstant(1, 1, m_); }
void TestMass::CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info) {
  if (d_ == 0.0)
    damping.resize(0, 0);
  else
    damping.setConstant(1, 1, d_);
}

std::unique_ptr<Condition> TestLoad::Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const {
  return std::make_unique<TestLoad>(id, Geometry(GetGeometry().Type(), std::move(nodes)), f_);
}

void TestLoad::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  dofs.assign(1, &GetGeometry()[0].GetDof(DISPLACEMENT_X));
}

void TestLoad::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  lhs.setZero(1, 1);
  rhs.setConstant(1, f_);
}
void TestLoad::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) { lhs.setZero(1, 1); }
void TestLoad::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) { rhs.setConstant(1, f_); }

ModelPart& MakeModelPart(Model& model, int buffer_size) {
  ModelPart& mp = model.CreateModelPart("Structure", buffer_size);
  mp.AddNodalSolutionStepVariable(DISPLACEMENT);
  mp.AddNodalSolutionStepVariable(REACTION);
  mp.AddNodalSolutionStepVariable(VELOCITY);
  mp.AddNodalSolutionStepVariable(ACCELERATION);
  return mp;
}

Node& AddNode(ModelPart& mp, IndexType id, double x, double y, int dimension) {
  Node& node = mp.CreateNewNode(id, x, y, 0.0);
  node.AddDof(DISPLACEMENT_X, &REACTION_X);
  if (dimension == 2) node.AddDof(DISPLACEMENT_Y, &REACTION_Y);
  return node;
}

TestSpring& AddSpring(ModelPart& mp, IndexType id, IndexType n1, IndexType n2, double k, double c, int dimension) {
  Geometry g(GeometryType::Line2D2, {&mp.GetNode(n1), &mp.GetNode(n2)});
  return static_cast<TestSpring&>(mp.AddElement(std::make_unique<TestSpring>(id, std::move(g), k, c, dimension)));
}

TestMass& AddMass(ModelPart& mp, IndexType id, IndexType node, double m, double d) {
  Geometry g(GeometryType::Point2D, {&mp.GetNode(node)});
  return static_cast<TestMass&>(mp.AddElement(std::make_unique<TestMass>(id, std::move(g), m, d)));
}

TestLoad& AddLoad(ModelPart& mp, IndexType id, IndexType node, double force) {
  Geometry g(GeometryType::Point2D, {&mp.GetNode(node)});
  return static_cast<TestLoad&>(mp.AddCondition(std::make_unique<TestLoad>(id, std::move(g), force)));
}

}  // namespace mc::test
