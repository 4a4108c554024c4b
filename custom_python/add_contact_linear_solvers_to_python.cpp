// SPDX-License-Identifier: BSD-3-Clause
// Bindings of custom_linear_solvers: MixedULMLinearSolver, the static condensation of the dual
// multipliers of the components formulations around any linear solver.
#include "custom_linear_solvers/mixed_ulm_linear_solver.h"
#include "custom_python/python_module.h"

namespace mc::python {

namespace {

/// Gives a solver shared with Python to a wrapper that owns its inner solver.
class SharedLinearSolver : public LinearSolver {
 public:
  explicit SharedLinearSolver(std::shared_ptr<LinearSolver> solver) : solver_(std::move(solver)) {}
  std::string Name() const override { return solver_->Name(); }
  bool IsDirect() const override { return solver_->IsDirect(); }
  void Initialize(const SparseMatrix& A) override { solver_->Initialize(A); }
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override { solver_->Solve(A, x, b); }
  void Clear() override { solver_->Clear(); }
  int IterationsNumber() const override { return solver_->IterationsNumber(); }
  WorkCounters Counters() const override { return solver_->Counters(); }

 private:
  std::shared_ptr<LinearSolver> solver_;
};

}  // namespace

void AddContactLinearSolversToPython(py::module_& m) {
  py::class_<MixedULMLinearSolver, LinearSolver, std::shared_ptr<MixedULMLinearSolver>>(
      m, "MixedULMLinearSolver",
      "mixed_ulm_linear_solver (Kratos MixedULMLinearSolver): static condensation of the dual multipliers (thesis "
      "eqs. 4.37-4.40) around an inner solver.")
      .def_property_readonly("last_solve_was_condensed", &MixedULMLinearSolver::LastSolveWasCondensed,
                             "Whether the last solve went through the condensed system.")
      .def_property_readonly("fallback_reason", &MixedULMLinearSolver::FallbackReason,
                             "Why the last solve used the full system (empty when condensed).")
      .def_property_readonly("condensed_size", &MixedULMLinearSolver::CondensedSize,
                             "Size of the last condensed system.")
      .def_property_readonly("number_of_pairs", &MixedULMLinearSolver::NumberOfPairs,
                             "Number of (active slave displacement, active multiplier) pairs eliminated.");
  m.def(
      "CreateMixedULMLinearSolver",
      [](std::shared_ptr<LinearSolver> inner_linear_solver) {
        if (!inner_linear_solver) throw InputError("CreateMixedULMLinearSolver: inner_linear_solver is None");
        return std::make_shared<MixedULMLinearSolver>(
            std::make_unique<SharedLinearSolver>(std::move(inner_linear_solver)));
      },
      py::arg("inner_linear_solver"),
      "mixed_ulm_linear_solver: condenses the dual multipliers of the components contact system (thesis eqs. "
      "4.37-4.40) and solves the displacement system with inner_linear_solver; usable wherever a LinearSolver is.");
}

}  // namespace mc::python
