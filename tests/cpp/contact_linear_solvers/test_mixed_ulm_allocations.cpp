// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 part 7 (speed): once MixedULMLinearSolver has solved a system, the next
// ProvideAdditionalData + Solve with the same pattern and active set allocates nothing outside
// the inner solver (whose own allocations, e.g. UMFPACK's numeric factorization, are not
// counted). Allocations are counted by replacing operator new and malloc in this executable
// (tests/cpp/common/allocation_counter.h).
#include <gtest/gtest.h>

#include <iostream>

#include "contact_system_fixture.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "custom_linear_solvers/mixed_ulm_linear_solver.h"
#include "tests/cpp/common/allocation_counter.h"

namespace mc::test {
namespace {

/// Forwards to UMFPACK with the counter paused: its allocations are not ours.
class UncountedUmfpack : public LinearSolver {
 public:
  std::string Name() const override { return "umfpack"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix& A) override {
    Paused([&] { inner_.Initialize(A); });
  }
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override {
    Paused([&] { inner_.Solve(A, x, b); });
  }
  void Clear() override { inner_.Clear(); }

 private:
  template <class F>
  static void Paused(F&& f) {
    const bool counting = IsCounting();
    StopCounting();
    f();
    if (counting) StartCounting();
  }
  UmfpackSolver inner_;
};

long AllocationsOfOneSolve(MixedULMLinearSolver& solver, const SparseMatrix& A, const std::vector<Dof*>& dofs,
                           const Vector& b, Vector& x) {
  Reset();
  StartCounting();
  solver.ProvideAdditionalData(A, dofs);
  solver.Solve(A, x, b);
  StopCounting();
  return Allocations() + OpenMpAllocations();  // all of them, the OpenMP runtime's included
}

TEST(MixedULMAllocations, RepeatedSolveWithSamePatternAllocatesNothing) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, false, true, true});
  auto& [system, A, b, dofs] = assembled;
  b.setConstant(1.0);
  MixedULMLinearSolver solver(std::make_unique<UncountedUmfpack>());
  solver.Initialize(A);
  Vector x = Vector::Zero(b.size());
  const long first = AllocationsOfOneSolve(solver, A, dofs, b, x);
  ASSERT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
  A.coeffs() *= 1.5;  // new values, same pattern
  const long second = AllocationsOfOneSolve(solver, A, dofs, b, x);
  ASSERT_TRUE(solver.LastSolveWasCondensed());
  std::cout << "[ figures  ] allocations outside the inner solver: first solve " << first << ", next solve " << second
            << "\n";
  EXPECT_GT(first, 0);  // the counter works
  EXPECT_EQ(second, 0);
}

}  // namespace
}  // namespace mc::test
