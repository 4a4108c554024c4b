// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/linear_solvers/sparse_types.h"
#include "core/model/dof.h"

namespace mc {

class AssemblyCommunicator;
class ModelPart;

/// One measure of a criterion at the last check: e.g. {"|du|/|u|", 1.2e-7, 1e-4}.
struct CriterionValue {
  std::string name;
  double value = 0.0;
  double tolerance = 0.0;
};

/// Decides when a Newton loop has converged. The strategy calls PreCriteria before each build
/// and PostCriteria after each update, with the DoF set, the system matrix and the full-size
/// increment and residual vectors (indexed by Dof::equation_id, zero at fixed DoFs).
///
/// `b` is the residual assembled for the iteration (before the update) unless the criterion
/// asks for the residual at the updated state with SetActualizeRHSFlag(true).
///
/// On a model cut to a piece per rank the strategy passes the rank's owned DoFs and the ranks
/// (SetPieceCommunicator): a criterion sums over its DoFs, then SumOverRanks, so that every rank
/// takes the same decision.
class ConvergenceCriteria {
 public:
  using DofsArray = std::vector<Dof*>;

  virtual ~ConvergenceCriteria() = default;
  /// The settings name ("displacement_criterion", ...).
  virtual std::string Name() const = 0;

  void SetEchoLevel(int level) noexcept { echo_level_ = level; }
  int GetEchoLevel() const noexcept { return echo_level_; }
  bool GetActualizeRHSFlag() const noexcept { return actualize_rhs_; }
  void SetActualizeRHSFlag(bool value) noexcept { actualize_rhs_ = value; }

  virtual void Initialize(ModelPart& model_part) { initialized_ = true; }
  /// The ranks of a cut model (BuilderAndSolver::PieceCommunicator), null otherwise.
  virtual void SetPieceCommunicator(const AssemblyCommunicator* communicator) { communicator_ = communicator; }
  bool IsInitialized() const noexcept { return initialized_; }
  virtual void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                      const Vector& dx, const Vector& b) {}
  virtual void InitializeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                            const Vector& dx, const Vector& b) {}
  virtual bool PreCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                           const Vector& b) {
    return true;
  }
  virtual bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                            const Vector& b) = 0;
  virtual void FinalizeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                          const Vector& dx, const Vector& b) {}
  virtual void FinalizeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                    const Vector& dx, const Vector& b) {}
  /// The measures of the last PostCriteria, for histories and tables.
  virtual std::vector<CriterionValue> LastValues() const = 0;
  virtual void Check(const ModelPart& model_part) const {}

 protected:
  /// "  it 3  |du|/|u| = 1.2e-07 (tol 1e-04)  |du| = 3.4e-11 (tol 1e-09)  converged"
  static std::string FormatLine(int iteration, const std::vector<CriterionValue>& values, bool converged);
  int echo_level_ = 0;
  /// values[i] summed over the ranks of a cut model (nothing otherwise).
  void SumOverRanks(double* values, std::size_t count) const;

 private:
  const AssemblyCommunicator* communicator_ = nullptr;
  bool actualize_rhs_ = false;
  bool initialized_ = false;
};

}  // namespace mc
