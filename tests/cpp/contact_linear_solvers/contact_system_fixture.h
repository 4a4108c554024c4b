// SPDX-License-Identifier: BSD-3-Clause
// A real components contact system for the MixedULMLinearSolver tests (issue 3 part 7): one
// ALMFrictionlessComponentsMortarContactCondition pair whose master covers the whole slave
// element (D diagonal with the slave-element dual basis), random SPD couplings of the
// displacements of consecutive nodes (slave, master and two "other" nodes) so that the system
// is non-singular, and a dense assembly of all of it into a sparse matrix.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "../contact_conditions/contact_condition_test_utilities.h"
#include "core/linear_solvers/sparse_types.h"
#include "core/model/element.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"

namespace mc::test {

/// Couples the displacements of two nodes with a given SPD matrix; no right-hand side.
class TestStiffness : public Element {
 public:
  TestStiffness(IndexType id, Geometry geometry, Matrix k, int dimension)
      : Element(id, std::move(geometry), nullptr), k_(std::move(k)), dimension_(dimension) {}
  std::string Info() const override { return "TestStiffness"; }
  std::unique_ptr<Element> Create(IndexType, Geometry::NodesArray, Properties*) const override { return nullptr; }
  void GetDofList(DofsVectorType& dofs, const ProcessInfo&) const override {
    const Variable<double>* u[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    dofs.clear();
    for (std::size_t i = 0; i < 2; ++i)
      for (int c = 0; c < dimension_; ++c) dofs.push_back(&GetGeometry()[i].GetDof(*u[c]));
  }
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo&) override {
    lhs = k_;
    rhs.setZero(k_.rows());
  }
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo&) override { lhs = k_; }
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo&) override { rhs.setZero(k_.rows()); }

 private:
  Matrix k_;
  int dimension_;
};

/// A contact pair <D, S, M> plus SPD couplings; `active[i]` sets ACTIVE on slave node i. The
/// slave quadrilateral is a flat parallelogram: on a non-affine one (trapezoid, warped) the
/// shape functions are rational on the triangulated overlap, its quadrature is not exact and D
/// keeps off-diagonal terms of ~1e-5 relative.
template <int TDim, int TSlave, int TMaster>
struct ContactSystem {
  using PairCondition = ALMFrictionlessComponentsMortarContactCondition<TDim, TSlave, TMaster>;

  Model model;
  ModelPart& root = MakeContactModelPart(model);
  std::vector<Node*> slaves, masters, others;

  /// `warped` lifts two nodes of a quadrilateral slave out of plane.
  explicit ContactSystem(const std::vector<bool>& active, bool warped = false, unsigned seed = 7) {
    std::vector<Array3> xs, xm;
    if (TDim == 2) {
      xs = {{0.0, 0.0, 0.0}, {1.0, 0.05, 0.0}};
      xm = {{1.4, 0.03, 0.0}, {-0.4, -0.02, 0.0}};
    } else {
      if (TSlave == 3)
        xs = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.02}, {0.2, 0.9, -0.01}};
      else
        xs = {{0.0, 0.0, 0.0}, {1.0, 0.05, warped ? 0.02 : 0.0}, {1.1, 1.05, 0.0}, {0.1, 1.0, warped ? -0.01 : 0.0}};
      // Master clockwise seen from the slave, large enough to cover the slave element.
      if (TMaster == 3)
        xm = {{-0.6, -0.6, 0.02}, {-0.4, 2.2, -0.01}, {2.2, -0.4, 0.01}};
      else
        xm = {{-0.3, -0.3, 0.02}, {-0.3, 1.4, -0.01}, {1.5, 1.4, 0.015}, {1.5, -0.3, -0.02}};
    }
    const Array3 tilts[4] = {{0.05, -0.03, 1.0}, {-0.04, 0.02, 1.0}, {0.03, 0.06, 1.0}, {-0.02, -0.05, 1.0}};
    Geometry::NodesArray slave_nodes, master_nodes;
    for (int i = 0; i < TSlave; ++i) {
      Node& node = MakeNode(root, 1 + i, xs[i]);
      Array3 normal = TDim == 2 ? Array3(tilts[i][0], 1.0, 0.0) : tilts[i];
      NormalCalculationUtilities::SetNodalNormal(node, normal.normalized());
      Array3 lm(0.1 * i - 0.05, 0.2 - 0.1 * i, -0.8 - 0.1 * i);
      if (TDim == 2) lm[2] = 0.0;
      node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = lm;
      node.SetValue(INITIAL_PENALTY, 12.0 + 3.0 * i);
      node.SetValue(DYNAMIC_FACTOR, 1.0);
      node.Set(SLAVE, true);
      node.Set(MASTER, false);
      node.Set(ACTIVE, active[static_cast<std::size_t>(i)]);
      slave_nodes.push_back(&node);
    }
    for (int l = 0; l < TMaster; ++l) {
      Node& node = MakeNode(root, 10 + l, xm[l]);
      node.Set(MASTER, true);
      node.Set(SLAVE, false);
      master_nodes.push_back(&node);
    }
    for (int o = 0; o < 2; ++o) others.push_back(&MakeNode(root, 20 + o, Array3(3.0 + o, 1.0, 0.5 * o)));
    slaves = slave_nodes;
    masters = master_nodes;

    const auto surface = [](const Geometry::NodesArray& nodes, int count) {
      if (TDim == 2) return Geometry(GeometryType::Line2D2, nodes);
      return Geometry(count == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4, nodes);
    };
    Properties& properties = root.GetOrCreateProperties(1);
    properties.SetValue(INTEGRATION_ORDER_CONTACT, 3);
    root.AddCondition(
        std::make_unique<PairCondition>(1, surface(slave_nodes, TSlave), &properties, surface(master_nodes, TMaster)));
    ProcessInfo& info = root.GetProcessInfo();
    info.SetValue(INITIAL_PENALTY, 1.0);
    info.SetValue(SCALE_FACTOR, 2.5);

    // SPD couplings of consecutive nodes along slave, master, others (closed loop).
    std::vector<Node*> chain = slaves;
    chain.insert(chain.end(), masters.begin(), masters.end());
    chain.insert(chain.end(), others.begin(), others.end());
    std::mt19937 generator(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const int n = 2 * TDim;
    for (std::size_t e = 0; e < chain.size(); ++e) {
      Matrix b(n, n);
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) b(r, c) = uniform(generator);
      Matrix k = b * b.transpose() + 0.5 * Matrix::Identity(n, n);
      Geometry::NodesArray pair_nodes = {chain[e], chain[(e + 1) % chain.size()]};
      root.AddElement(std::make_unique<TestStiffness>(100 + e, CouplingGeometry(pair_nodes), std::move(k), TDim));
    }
  }

  static Geometry CouplingGeometry(const Geometry::NodesArray& nodes) {
    return Geometry(TDim == 2 ? GeometryType::Line2D2 : GeometryType::Line3D2, nodes);
  }

  /// Dense assembly of every element and condition; DoFs sorted by node id and variable key
  /// (as the block builder numbers them). Fixed DoFs get an identity row and column.
  void Assemble(SparseMatrix& A, Vector& rhs, std::vector<Dof*>& dofs) {
    const ProcessInfo& info = root.GetProcessInfo();
    std::vector<Entity*> entities;
    for (Element* e : root.Elements()) entities.push_back(e);
    for (Condition* c : root.Conditions()) entities.push_back(c);
    dofs.clear();
    DofsVectorType local_dofs;
    for (Entity* e : entities) {
      e->GetDofList(local_dofs, info);
      dofs.insert(dofs.end(), local_dofs.begin(), local_dofs.end());
    }
    const auto less = [](const Dof* a, const Dof* b) {
      return a->node->Id() != b->node->Id() ? a->node->Id() < b->node->Id() : a->variable->Key() < b->variable->Key();
    };
    std::sort(dofs.begin(), dofs.end(), less);
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    std::map<const Dof*, Eigen::Index> row;
    for (std::size_t i = 0; i < dofs.size(); ++i) row[dofs[i]] = static_cast<Eigen::Index>(i);
    const auto n = static_cast<Eigen::Index>(dofs.size());
    Matrix dense = Matrix::Zero(n, n);
    rhs.setZero(n);
    Matrix lhs;
    Vector local_rhs;
    for (Entity* e : entities) {
      e->GetDofList(local_dofs, info);
      e->CalculateLocalSystem(lhs, local_rhs, info);
      for (std::size_t i = 0; i < local_dofs.size(); ++i) {
        rhs[row[local_dofs[i]]] += local_rhs[static_cast<Eigen::Index>(i)];
        for (std::size_t j = 0; j < local_dofs.size(); ++j)
          dense(row[local_dofs[i]], row[local_dofs[j]]) +=
              lhs(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      }
    }
    for (Eigen::Index i = 0; i < n; ++i)
      if (dofs[static_cast<std::size_t>(i)]->fixed) {
        dense.row(i).setZero();
        dense.col(i).setZero();
        dense(i, i) = 1.0;
        rhs[i] = 0.0;
      }
    A = dense.sparseView();
    A.makeCompressed();
  }
};

/// A ContactSystem built from `args` and assembled: A, the residual b and the DoFs in row order.
template <class System>
struct AssembledSystem {
  System system;
  SparseMatrix A;
  Vector b;
  std::vector<Dof*> dofs;
  template <class... Args>
  explicit AssembledSystem(Args&&... args) : system(std::forward<Args>(args)...) {
    system.Assemble(A, b, dofs);
  }
};

}  // namespace mc::test
