// SPDX-License-Identifier: BSD-3-Clause
// A synthetic contact problem for the strategy tests: a node tied to its initial position by a
// spring of stiffness (k_x, k_y) (linear, or k atan(u) per component: Newton diverges from
// |u| > 1.39 on it), loaded by
// F, and a rigid circular obstacle enforced by the scalar ALM with the exact tangent:
//   gap g = |x - c| - R, n = (x - c) / |x - c|, lambda_bar = k lambda + eps g;
//   active:   r_u = -lambda_bar n,  r_lm = k g;
//   inactive: r_u = 0,              r_lm = -(k^2 / eps) lambda.
#pragma once

#include <map>
#include <memory>

#include "core/model/condition.h"
#include "core/model/element.h"
#include "core/model/model.h"
#include "custom_utilities/mortar_updater.h"
#include "tests/cpp/common/local_system_entity.h"

namespace mc::test {

class AnchorSpring : public LocalSystemEntity<Element> {
 public:
  enum class Law { kLinear, kArcTangent };
  AnchorSpring(IndexType id, Geometry geometry, Array3 k, Law law, Array3 force)
      : LocalSystemEntity(id, std::move(geometry), nullptr), k_(k), law_(law), force_(force) {}
  std::string Info() const override { return "AnchorSpring"; }
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void SetForce(const Array3& force) { force_ = force; }

 private:
  Array3 k_;
  Law law_;
  Array3 force_;
};

struct Obstacle {
  Array3 center = Array3::Zero();
  double radius = 1.0;
  double Gap(const Array3& x) const { return (x - center).norm() - radius; }
};

class ObstacleContact : public LocalSystemEntity<Condition> {
 public:
  ObstacleContact(IndexType id, Geometry geometry, Obstacle obstacle)
      : LocalSystemEntity(id, std::move(geometry), nullptr), obstacle_(obstacle) {}
  std::string Info() const override { return "ObstacleContact"; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* p) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;

 private:
  Obstacle obstacle_;
};

/// Model "Structure" (DISPLACEMENT, REACTION, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, WEIGHTED_GAP,
/// WEIGHTED_SCALAR_RESIDUAL, NORMAL; buffer 2) with a "Contact" sub-model-part, k and eps in
/// the ProcessInfo, and one slave node per AddContactNode call.
struct ContactProblem {
  Model model;
  ModelPart& mp;
  std::map<IndexType, Obstacle> obstacles;
  std::map<IndexType, AnchorSpring*> springs;
  ContactProblem(double scale_factor, double penalty);
  void AddContactNode(IndexType id, const Array3& x0, const Array3& k, AnchorSpring::Law law, const Array3& force,
                      const Obstacle& obstacle);
  Array3 U(IndexType id) const;
  double Lm(IndexType id) const;
  /// The updater the criteria and the strategy use: WEIGHTED_GAP += g(x) on the slave nodes.
  std::shared_ptr<MortarUpdater> Updater();
};

}  // namespace mc::test
