// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/eigen_sparse_lu_solver.h"

#include <iostream>  // Eigen/MetisSupport uses std::cerr without including it

#include <Eigen/MetisSupport>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>

namespace mc {

struct EigenSparseLUSolver::Backend {
  virtual ~Backend() = default;
  virtual void Analyze(const SparseMatrix& A) = 0;
  /// Empty string on success, else Eigen's message.
  virtual std::string Factorize(const SparseMatrix& A) = 0;
  virtual void Solve(const Vector& b, Vector& x) = 0;
};

template <class OrderingType>
struct EigenSparseLUSolver::BackendFor : EigenSparseLUSolver::Backend {
  void Analyze(const SparseMatrix& A) override { lu.analyzePattern(A); }
  std::string Factorize(const SparseMatrix& A) override {
    lu.factorize(A);
    return lu.info() == Eigen::Success ? std::string() : lu.lastErrorMessage();
  }
  void Solve(const Vector& b, Vector& x) override { x = lu.solve(b); }
  Eigen::SparseLU<SparseMatrix, OrderingType> lu;
};

EigenSparseLUSolver::EigenSparseLUSolver(Ordering ordering) : DirectSolver("SparseLU"), ordering_(ordering) {}

EigenSparseLUSolver::~EigenSparseLUSolver() = default;

void EigenSparseLUSolver::Analyze(const SparseMatrix& M) {
  if (ordering_ == Ordering::kMetis) {
    backend_ = std::make_unique<BackendFor<Eigen::MetisOrdering<int>>>();
  } else {
    backend_ = std::make_unique<BackendFor<Eigen::COLAMDOrdering<int>>>();
  }
  backend_->Analyze(M);
}

void EigenSparseLUSolver::Factorize(const SparseMatrix& M) {
  const std::string failure = backend_->Factorize(M);
  if (!failure.empty()) throw SingularMatrixError(Concat("Eigen SparseLU: singular matrix: ", failure), -1);
}

void EigenSparseLUSolver::Substitute(Vector& x, const Vector& b) { backend_->Solve(b, x); }

void EigenSparseLUSolver::Release() { backend_.reset(); }

}  // namespace mc
