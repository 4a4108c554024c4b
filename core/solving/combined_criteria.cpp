// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/combined_criteria.h"

#include "core/utilities/error.h"

namespace mc {

namespace {

// Calls `step` on the first criterion, then on the second.
template <class... Params, class... Args>
void CallOnBoth(ConvergenceCriteria& first, ConvergenceCriteria& second, void (ConvergenceCriteria::*step)(Params...),
                Args&... args) {
  (first.*step)(args...);
  (second.*step)(args...);
}

}  // namespace

CombinedCriteria::CombinedCriteria(std::shared_ptr<ConvergenceCriteria> first,
                                   std::shared_ptr<ConvergenceCriteria> second)
    : first_(std::move(first)), second_(std::move(second)) {
  if (!first_ || !second_) throw Error("a combined convergence criterion needs two criteria");
  SetActualizeRHSFlag(first_->GetActualizeRHSFlag() || second_->GetActualizeRHSFlag());
}

void CombinedCriteria::Initialize(ModelPart& model_part) {
  CallOnBoth(*first_, *second_, &ConvergenceCriteria::Initialize, model_part);
  ConvergenceCriteria::Initialize(model_part);
}

void CombinedCriteria::SetPieceCommunicator(const AssemblyCommunicator* communicator) {
  first_->SetPieceCommunicator(communicator);
  second_->SetPieceCommunicator(communicator);
  ConvergenceCriteria::SetPieceCommunicator(communicator);
}

void CombinedCriteria::InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                              const Vector& dx, const Vector& b) {
  CallOnBoth(*first_, *second_, &ConvergenceCriteria::InitializeSolutionStep, model_part, dofs, A, dx, b);
}

void CombinedCriteria::InitializeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                    const Vector& dx, const Vector& b) {
  CallOnBoth(*first_, *second_, &ConvergenceCriteria::InitializeNonLinearIteration, model_part, dofs, A, dx, b);
}

bool CombinedCriteria::PreCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                   const Vector& dx, const Vector& b) {
  const bool a = first_->PreCriteria(model_part, dofs, A, dx, b);
  const bool c = second_->PreCriteria(model_part, dofs, A, dx, b);
  return Combine(a, c);
}

bool CombinedCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                    const Vector& dx, const Vector& b) {
  const bool a = first_->PostCriteria(model_part, dofs, A, dx, b);
  const bool c = second_->PostCriteria(model_part, dofs, A, dx, b);
  return Combine(a, c);
}

void CombinedCriteria::FinalizeNonLinearIteration(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                  const Vector& dx, const Vector& b) {
  CallOnBoth(*first_, *second_, &ConvergenceCriteria::FinalizeNonLinearIteration, model_part, dofs, A, dx, b);
}

void CombinedCriteria::FinalizeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                            const Vector& dx, const Vector& b) {
  CallOnBoth(*first_, *second_, &ConvergenceCriteria::FinalizeSolutionStep, model_part, dofs, A, dx, b);
}

std::vector<CriterionValue> CombinedCriteria::LastValues() const {
  auto values = first_->LastValues();
  const auto more = second_->LastValues();
  values.insert(values.end(), more.begin(), more.end());
  return values;
}

void CombinedCriteria::Check(const ModelPart& model_part) const {
  first_->Check(model_part);
  second_->Check(model_part);
}

void CombinedCriteria::SetEchoLevels(int level) {
  SetEchoLevel(level);
  first_->SetEchoLevel(level);
  second_->SetEchoLevel(level);
}

}  // namespace mc
