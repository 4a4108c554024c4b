// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/eigen.h>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/solve_clocks.h"
#include "core/parameters/parameters.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddLinearSolversToPython(py::module_& m) {
  py::class_<LinearSolver, std::shared_ptr<LinearSolver>>(
      m, "LinearSolver", "Solves A x = b for the global system (direct solvers reuse their symbolic analysis).")
      .def("Name", &LinearSolver::Name, "The normalised name from the settings, e.g. 'umfpack', 'cg'.")
      .def("IsDirect", &LinearSolver::IsDirect, "Whether it factorizes (rather than iterates).")
      .def(
          "Solve",
          [](LinearSolver& solver, const SparseMatrix& A, const Vector& b, bool initialize) {
            Vector x = Vector::Zero(b.size());
            if (initialize) solver.Initialize(A);
            solver.Solve(A, x, b);
            return x;
          },
          py::arg("A"), py::arg("b"), py::arg("initialize") = true,
          "Solves A x = b for a scipy.sparse matrix A (converted to CSC); initialize=False keeps the symbolic "
          "analysis of the previous call (A with the same pattern).")
      .def("IterationsNumber", &LinearSolver::IterationsNumber, "Iterations of the last solve (1 for direct solvers).")
      .def(
          "Counters",
          [](const LinearSolver& solver) {
            const LinearSolver::WorkCounters c = solver.Counters();
            return py::dict(py::arg("factorizations") = c.factorizations, py::arg("krylov_solves") = c.krylov_solves,
                            py::arg("krylov_iterations") = c.krylov_iterations, py::arg("fallbacks") = c.fallbacks,
                            py::arg("preconditioner_setups") = c.preconditioner_setups,
                            py::arg("kept_orderings") = c.kept_orderings);
          },
          "Work done so far: numeric factorizations, Krylov solves with kept factors, their iterations, fallbacks to "
          "a fresh factorization, symbolic analyses from the ordering of the factors held (kept_orderings).")
      .def(
          "Processes",
          [](const LinearSolver& solver) {
            const AssemblyCommunicator* communicator = solver.Communicator();
            return communicator ? communicator->Size() : 1;
          },
          "How many processes the system is distributed over (1: solved within this process).");
  m.def(
      "LinearSolveClocks",
      [] {
        const SolveClocks& c = SolveClocks::Process();
        return py::dict(py::arg("phase") = c.phase, py::arg("analysis") = c.analysis,
                        py::arg("pattern_check") = c.pattern_check, py::arg("factorization") = c.factorization,
                        py::arg("direct_substitution") = c.direct_substitution,
                        py::arg("krylov_substitution") = c.krylov_substitution,
                        py::arg("krylov_other") = c.krylov_other, py::arg("comparison") = c.comparison);
      },
      "CPU seconds of the parts of the linear-solve phase so far in this process (SolveClocks): the builder's "
      "whole solve phase, symbolic analyses, pattern checks, numeric factorizations, substitutions after a "
      "factorization and inside GMRES, the rest of GMRES, the comparison with the factorized matrix.");
  m.def("LaunchedProcesses", &AssemblyCommunicator::LaunchedSize,
        "How many processes mpirun (or mpiexec, srun) started this one among, from its environment; 1 without.");
  m.def("LaunchedRank", &AssemblyCommunicator::LaunchedRank,
        "This process's rank among those mpirun started (0 without mpirun).");
  m.def(
      "CreateLinearSolver",
      [](const Parameters& settings) { return std::shared_ptr<LinearSolver>(CreateLinearSolver(settings)); },
      py::arg("settings"), "A linear solver from Kratos-style linear_solver_settings (spec section 7).");
  m.def("NormalizeLinearSolverName", &NormalizeLinearSolverName, py::arg("name"),
        "The normalised solver name of a Kratos spelling, e.g. 'SkylineLUFactorizationSolver' (spec 7.1).");
}

}  // namespace mc::python
