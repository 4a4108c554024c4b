// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/direct_solver.h"

namespace mc {

/// Eigen's supernodal SparseLU, selected explicitly with "sparse_lu_eigen" (the Kratos names
/// "sparse_lu" / "eigen_sparse_lu" map to UMFPACK). The column ordering is COLAMD, or METIS
/// nested dissection with `ordering = "metis"`. Eigen reports no usable pivot index, so
/// SingularMatrixError carries equation -1 and Eigen's message.
class EigenSparseLUSolver : public DirectSolver {
 public:
  enum class Ordering { kColamd, kMetis };

  explicit EigenSparseLUSolver(Ordering ordering = Ordering::kColamd);
  ~EigenSparseLUSolver() override;

  std::string Name() const override { return "sparse_lu_eigen"; }

 private:
  void Analyze(const SparseMatrix& A) override;
  void Factorize(const SparseMatrix& A) override;
  void Substitute(Vector& x, const Vector& b) override;
  void Release() override;

  struct Backend;  // the SparseLU instantiation for the chosen ordering
  template <class OrderingType>
  struct BackendFor;

  Ordering ordering_;
  std::unique_ptr<Backend> backend_;
};

}  // namespace mc
