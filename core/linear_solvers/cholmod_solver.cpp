// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/cholmod_solver.h"

#include <suitesparse/cholmod.h>

#include <cmath>

namespace mc {

namespace {

// A CHOLMOD header over Eigen's arrays (no copy); stype = 1 reads the upper triangle only.
cholmod_sparse View(const SparseMatrix& M) {
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(M.rows());
  view.ncol = static_cast<std::size_t>(M.cols());
  view.nzmax = static_cast<std::size_t>(M.nonZeros());
  view.p = const_cast<int*>(M.outerIndexPtr());
  view.i = const_cast<int*>(M.innerIndexPtr());
  view.x = const_cast<double*>(M.valuePtr());
  view.stype = 1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

// Largest |a_ij - a_ji| relative to the largest |a_ij|; CHOLMOD would silently use the upper
// triangle of a non-symmetric matrix.
double Asymmetry(const SparseMatrix& M) {
  const SparseMatrix transposed = M.transpose();
  double scale = 0.0;
  for (int k = 0; k < M.nonZeros(); ++k) scale = std::max(scale, std::abs(M.valuePtr()[k]));
  if (scale == 0.0) return 0.0;
  const SparseMatrix difference = M - transposed;
  return difference.nonZeros() > 0 ? difference.coeffs().cwiseAbs().maxCoeff() / scale : 0.0;
}

}  // namespace

struct CholmodSolver::Handles {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
};

CholmodSolver::CholmodSolver() : DirectSolver("CHOLMOD"), handles_(std::make_unique<Handles>()) {
  cholmod_start(&handles_->common);
  handles_->common.supernodal = CHOLMOD_SUPERNODAL;
  handles_->common.print = 0;
  handles_->common.error_handler = nullptr;  // failures are reported through status, below
}

CholmodSolver::~CholmodSolver() {
  Release();
  cholmod_finish(&handles_->common);
}

void CholmodSolver::Analyze(const SparseMatrix& M) {
  cholmod_sparse view = View(M);
  handles_->factor = cholmod_analyze(&view, &handles_->common);
  if (handles_->factor == nullptr) {
    throw SolutionError(
        Concat("CHOLMOD analysis of a ", M.rows(), "-equation matrix failed (status ", handles_->common.status, ")"));
  }
}

void CholmodSolver::Factorize(const SparseMatrix& M) {
  const double asymmetry = Asymmetry(M);
  if (asymmetry > 1e-12) {
    throw SolutionError(
        Concat("CHOLMOD needs a symmetric matrix; largest |a_ij - a_ji| is ", asymmetry, " of the largest entry"));
  }
  cholmod_common& common = handles_->common;
  cholmod_sparse view = View(M);
  cholmod_factorize(&view, handles_->factor, &common);
  if (common.status == CHOLMOD_NOT_POSDEF) {
    cholmod_factor* factor = handles_->factor;
    const long minor = static_cast<long>(factor->minor);
    const long equation =
        (minor < M.rows() && factor->Perm != nullptr) ? static_cast<int*>(factor->Perm)[minor] : minor;
    throw SingularMatrixError(Concat("CHOLMOD: matrix not positive definite, factorization failed at equation ",
                                     equation, " (pivot ", minor, " of the fill-reducing order)"),
                              equation);
  }
  if (common.status != CHOLMOD_OK)
    throw SolutionError(Concat("CHOLMOD factorization failed (status ", common.status, ")"));
}

void CholmodSolver::Substitute(Vector& x, const Vector& b) {
  cholmod_common& common = handles_->common;
  cholmod_dense rhs{};
  rhs.nrow = static_cast<std::size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = rhs.nrow;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* solution = cholmod_solve(CHOLMOD_A, handles_->factor, &rhs, &common);
  if (solution == nullptr) throw SolutionError(Concat("CHOLMOD solve failed (status ", common.status, ")"));
  x = Eigen::Map<const Vector>(static_cast<const double*>(solution->x), b.size());
  cholmod_free_dense(&solution, &common);
}

void CholmodSolver::Release() {
  if (handles_->factor != nullptr) cholmod_free_factor(&handles_->factor, &handles_->common);
  handles_->factor = nullptr;
}

}  // namespace mc
