// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/eigen.h>

#include "core/linear_solvers/linear_solver.h"
#include "core/parameters/parameters.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddLinearSolversToPython(py::module_& m) {
  py::class_<LinearSolver, std::shared_ptr<LinearSolver>>(m, "LinearSolver")
      .def("Name", &LinearSolver::Name)
      .def("IsDirect", &LinearSolver::IsDirect)
      .def("Solve", [](LinearSolver& solver, const SparseMatrix& A, const Vector& b) {
        Vector x = Vector::Zero(b.size());
        solver.Initialize(A);
        solver.Solve(A, x, b);
        return x;
      }, py::arg("A"), py::arg("b"), "Solves A x = b for a scipy.sparse matrix A (converted to CSC).")
      .def("IterationsNumber", &LinearSolver::IterationsNumber);
  m.def("CreateLinearSolver",
        [](const Parameters& settings) { return std::shared_ptr<LinearSolver>(CreateLinearSolver(settings)); },
        py::arg("settings"), "A linear solver from Kratos-style linear_solver_settings (spec section 7).");
  m.def("NormalizeLinearSolverName", &NormalizeLinearSolverName, py::arg("name"));
}

}  // namespace mc::python
