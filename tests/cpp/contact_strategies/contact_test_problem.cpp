// SPDX-License-Identifier: BSD-3-Clause
// The synthetic contact problem of the strategy tests (see contact_test_problem.h).
#include "contact_test_problem.h"

#include <cmath>

#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc::test {

namespace {
Array3 Displacement(const Node& node) {
  return Array3(node.FastGetSolutionStepValue(DISPLACEMENT_X), node.FastGetSolutionStepValue(DISPLACEMENT_Y), 0.0);
}
}  // namespace

std::unique_ptr<Element> AnchorSpring::Create(IndexType id, Geometry::NodesArray nodes, Properties*) const {
  return std::make_unique<AnchorSpring>(id, Geometry(GetGeometry().Type(), std::move(nodes)), k_, law_, force_);
}

void AnchorSpring::GetDofList(DofsVectorType& dofs, const ProcessInfo&) const {
  dofs = {&GetGeometry()[0].GetDof(DISPLACEMENT_X), &GetGeometry()[0].GetDof(DISPLACEMENT_Y)};
}

void AnchorSpring::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo&) {
  const Array3 u = Displacement(GetGeometry()[0]);
  lhs.setZero(2, 2);
  rhs.resize(2);
  for (int i = 0; i < 2; ++i) {
    const bool linear = law_ == Law::kLinear;
    rhs[i] = force_[i] - k_[i] * (linear ? u[i] : std::atan(u[i]));
    lhs(i, i) = k_[i] * (linear ? 1.0 : 1.0 / (1.0 + u[i] * u[i]));
  }
}

std::unique_ptr<Condition> ObstacleContact::Create(IndexType id, Geometry::NodesArray nodes, Properties*) const {
  return std::make_unique<ObstacleContact>(id, Geometry(GetGeometry().Type(), std::move(nodes)), obstacle_);
}

void ObstacleContact::GetDofList(DofsVectorType& dofs, const ProcessInfo&) const {
  const Node& n = GetGeometry()[0];
  dofs = {&n.GetDof(DISPLACEMENT_X), &n.GetDof(DISPLACEMENT_Y), &n.GetDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)};
}

void ObstacleContact::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  const Node& node = GetGeometry()[0];
  const double k = info.GetValue(SCALE_FACTOR);
  const double eps = info.GetValue(INITIAL_PENALTY);
  const double lambda = node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
  lhs.setZero(3, 3);
  rhs.setZero(3);
  if (!node.Is(ACTIVE)) {
    rhs[2] = -k * k / eps * lambda;
    lhs(2, 2) = k * k / eps;
    return;
  }
  const Array3 d = node.X0() + Displacement(node) - obstacle_.center;
  const double distance = d.norm();
  const Eigen::Vector2d n = d.head<2>() / distance;
  const double g = distance - obstacle_.radius;
  const double augmented = k * lambda + eps * g;
  const Eigen::Matrix2d hessian = (Eigen::Matrix2d::Identity() - n * n.transpose()) / distance;
  rhs.head<2>() = -augmented * n;
  rhs[2] = k * g;
  lhs.topLeftCorner<2, 2>() = eps * n * n.transpose() + augmented * hessian;
  lhs.block<2, 1>(0, 2) = k * n;
  lhs.block<1, 2>(2, 0) = -k * n.transpose();
}

ContactProblem::ContactProblem(double scale_factor, double penalty) : mp(model.CreateModelPart("Structure", 2)) {
  for (const VariableData* var :
       std::initializer_list<const VariableData*>{&DISPLACEMENT, &REACTION, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
                                                  &WEIGHTED_GAP, &WEIGHTED_SCALAR_RESIDUAL, &NORMAL})
    mp.AddNodalSolutionStepVariable(*var);
  mp.CreateSubModelPart("Contact");
  mp.GetProcessInfo().SetValue(SCALE_FACTOR, scale_factor);
  mp.GetProcessInfo().SetValue(INITIAL_PENALTY, penalty);
}

void ContactProblem::AddContactNode(IndexType id, const Array3& x0, const Array3& k, AnchorSpring::Law law,
                                    const Array3& force, const Obstacle& obstacle) {
  ModelPart& contact = mp.GetSubModelPart("Contact");
  Node& node = contact.CreateNewNode(id, x0[0], x0[1], 0.0);
  node.AddDof(DISPLACEMENT_X, &REACTION_X);
  node.AddDof(DISPLACEMENT_Y, &REACTION_Y);
  node.AddDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, &WEIGHTED_SCALAR_RESIDUAL);
  node.Set(SLAVE, true);
  node.Set(ACTIVE, false);
  auto spring = std::make_unique<AnchorSpring>(id, Geometry(GeometryType::Point2D, {&node}), k, law, force);
  springs[id] = spring.get();
  mp.AddElement(std::move(spring));
  mp.AddCondition(std::make_unique<ObstacleContact>(id, Geometry(GeometryType::Point2D, {&node}), obstacle));
  obstacles[id] = obstacle;
}

Array3 ContactProblem::U(IndexType id) const { return Displacement(mp.GetNode(id)); }

double ContactProblem::Lm(IndexType id) const {
  return mp.GetNode(id).FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
}

std::shared_ptr<MortarUpdater> ContactProblem::Updater() {
  return std::make_shared<CallbackMortarUpdater>([this](ModelPart& part) {
    for (const auto& [id, obstacle] : obstacles) {
      Node& node = mp.GetNode(id);
      node.FastGetSolutionStepValue(WEIGHTED_GAP) += obstacle.Gap(node.X0() + Displacement(node));
    }
  });
}

}  // namespace mc::test
