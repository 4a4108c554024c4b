// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/solving/convergence_criteria.h"

namespace mc {

/// Two criteria driven together (every call reaches both, so both log and keep their values);
/// AndCriteria and OrCriteria only differ in how the two answers combine. The residual is
/// refreshed after the update when either criterion asks for it.
class CombinedCriteria : public ConvergenceCriteria {
 public:
  CombinedCriteria(std::shared_ptr<ConvergenceCriteria> first, std::shared_ptr<ConvergenceCriteria> second);

  void Initialize(ModelPart& model_part) override;
  void SetPieceCommunicator(const AssemblyCommunicator* communicator) override;
  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                              const Vector& b) override;
  void InitializeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                    const Vector& dx, const Vector& b) override;
  bool PreCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                   const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  void FinalizeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                                  const Vector& b) override;
  void FinalizeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                            const Vector& b) override;
  std::vector<CriterionValue> LastValues() const override;
  void Check(const ModelPart& model_part) const override;
  /// Also sets the level of both criteria.
  void SetEchoLevels(int level);

  const ConvergenceCriteria& First() const noexcept { return *first_; }
  const ConvergenceCriteria& Second() const noexcept { return *second_; }

 protected:
  virtual bool Combine(bool a, bool b) const = 0;

 private:
  std::shared_ptr<ConvergenceCriteria> first_;
  std::shared_ptr<ConvergenceCriteria> second_;
};

}  // namespace mc
