// SPDX-License-Identifier: BSD-3-Clause
// A linear spring tying each node of the condition to the ground: f = -k u, with k the
// property SPRING_STIFFNESS. It shows the whole extension path: a new variable, a condition
// class, registration by name, and use from an mdpa file through mortarcontact.load_plugin().
#include "core/model/condition.h"
#include "core/model/registry.h"
#include "core/variables/kernel_variables.h"

namespace spring_plugin {

MC_DEFINE_VARIABLE(double, SPRING_STIFFNESS);

class GroundSpringCondition : public mc::Condition {
 public:
  GroundSpringCondition(mc::IndexType id, mc::Geometry geometry, mc::Properties* properties, int dimension)
      : Condition(id, std::move(geometry), properties), dimension_(dimension) {}

  std::string Info() const override { return "GroundSpringCondition"; }

  std::unique_ptr<mc::Condition> Create(mc::IndexType id, mc::Geometry::NodesArray nodes,
                                        mc::Properties* properties) const override {
    return std::make_unique<GroundSpringCondition>(id, mc::Geometry(GetGeometry().Type(), std::move(nodes)), properties,
                                                   dimension_);
  }

  void GetDofList(mc::DofsVectorType& dofs, const mc::ProcessInfo&) const override {
    static const mc::Variable<double>* components[3] = {&mc::DISPLACEMENT_X, &mc::DISPLACEMENT_Y, &mc::DISPLACEMENT_Z};
    dofs.clear();
    for (const mc::Node* node : GetGeometry().Nodes())
      for (int k = 0; k < dimension_; ++k) dofs.push_back(&node->GetDof(*components[k]));
  }

  void CalculateLocalSystem(mc::Matrix& lhs, mc::Vector& rhs, const mc::ProcessInfo& info) override {
    CalculateLeftHandSide(lhs, info);
    CalculateRightHandSide(rhs, info);
  }

  void CalculateLeftHandSide(mc::Matrix& lhs, const mc::ProcessInfo&) override {
    const auto n = static_cast<Eigen::Index>(GetGeometry().PointsNumber() * dimension_);
    lhs = Stiffness() * mc::Matrix::Identity(n, n);
  }

  void CalculateRightHandSide(mc::Vector& rhs, const mc::ProcessInfo&) override {
    const std::size_t n = GetGeometry().PointsNumber();
    rhs.resize(static_cast<Eigen::Index>(n * dimension_));
    for (std::size_t i = 0; i < n; ++i) {
      const auto u = GetGeometry()[i].FastGetSolutionStepValue(mc::DISPLACEMENT);
      for (int k = 0; k < dimension_; ++k) rhs[static_cast<Eigen::Index>(i * dimension_ + k)] = -Stiffness() * u[k];
    }
  }

  void Check(const mc::ProcessInfo&) const override { GetProperties().GetPositive(SPRING_STIFFNESS); }

 private:
  double Stiffness() const { return GetProperties().GetValue(SPRING_STIFFNESS); }
  int dimension_;
};

}  // namespace spring_plugin

/// Entry point called by mortarcontact.load_plugin().
extern "C" void mortarcontact_register_plugin() {
  using spring_plugin::GroundSpringCondition;
  auto& registry = mc::Registry<mc::Condition>::Instance();
  registry.Add("GroundSpringCondition2D1N",
               std::make_shared<GroundSpringCondition>(0, mc::Geometry(mc::GeometryType::Point2D, {}), nullptr, 2));
  registry.Add("GroundSpringCondition3D1N",
               std::make_shared<GroundSpringCondition>(0, mc::Geometry(mc::GeometryType::Point3D, {}), nullptr, 3));
}
