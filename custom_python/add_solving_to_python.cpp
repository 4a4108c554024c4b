// SPDX-License-Identifier: BSD-3-Clause
#include <optional>

#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/solving/and_criteria.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/explicit_central_differences_scheme.h"
#include "core/solving/explicit_strategy.h"
#include "core/solving/line_search_strategy.h"
#include "core/solving/linear_strategy.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/or_criteria.h"
#include "core/solving/residual_based_bossak_displacement_scheme.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/solving/residual_criteria.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddSolvingToPython(py::module_& m) {
  py::class_<Scheme, std::shared_ptr<Scheme>>(m, "Scheme").def("Name", &Scheme::Name);
  py::class_<ResidualBasedIncrementalUpdateStaticScheme, Scheme, std::shared_ptr<ResidualBasedIncrementalUpdateStaticScheme>>(
      m, "StaticScheme", "Incremental update u += du (static problems).")
      .def(py::init<>());
  py::class_<ResidualBasedBossakDisplacementScheme, Scheme, std::shared_ptr<ResidualBasedBossakDisplacementScheme>>(
      m, "BossakScheme", "Bossak (alpha_m) implicit dynamics; Newmark for alpha_m = 0.")
      .def(py::init<double, std::optional<double>>(), py::arg("alpha_m") = -0.3, py::arg("newmark_beta") = py::none())
      .def_static("Newmark", &ResidualBasedBossakDisplacementScheme::Newmark)
      .def("Alpha", &ResidualBasedBossakDisplacementScheme::Alpha)
      .def("Beta", &ResidualBasedBossakDisplacementScheme::Beta)
      .def("Gamma", &ResidualBasedBossakDisplacementScheme::Gamma);
  py::class_<ExplicitCentralDifferencesScheme, Scheme, std::shared_ptr<ExplicitCentralDifferencesScheme>>(
      m, "ExplicitCentralDifferencesScheme")
      .def(py::init<>());

  py::class_<CriterionValue>(m, "CriterionValue")
      .def_readonly("name", &CriterionValue::name)
      .def_readonly("value", &CriterionValue::value)
      .def_readonly("tolerance", &CriterionValue::tolerance)
      .def("__repr__", [](const CriterionValue& v) { return Concat(v.name, " = ", v.value, " (tol ", v.tolerance, ")"); });
  py::class_<ConvergenceCriteria, std::shared_ptr<ConvergenceCriteria>>(m, "ConvergenceCriteria")
      .def("Name", &ConvergenceCriteria::Name)
      .def("SetEchoLevel", &ConvergenceCriteria::SetEchoLevel)
      .def("LastValues", &ConvergenceCriteria::LastValues);
  py::class_<DisplacementCriteria, ConvergenceCriteria, std::shared_ptr<DisplacementCriteria>>(m, "DisplacementCriteria")
      .def(py::init<double, double>(), py::arg("relative_tolerance") = 1e-4, py::arg("absolute_tolerance") = 1e-9);
  py::class_<ResidualCriteria, ConvergenceCriteria, std::shared_ptr<ResidualCriteria>>(m, "ResidualCriteria")
      .def(py::init<double, double>(), py::arg("relative_tolerance") = 1e-4, py::arg("absolute_tolerance") = 1e-9);
  py::class_<AndCriteria, ConvergenceCriteria, std::shared_ptr<AndCriteria>>(m, "AndCriteria")
      .def(py::init<std::shared_ptr<ConvergenceCriteria>, std::shared_ptr<ConvergenceCriteria>>());
  py::class_<OrCriteria, ConvergenceCriteria, std::shared_ptr<OrCriteria>>(m, "OrCriteria")
      .def(py::init<std::shared_ptr<ConvergenceCriteria>, std::shared_ptr<ConvergenceCriteria>>());

  py::class_<BuilderAndSolver::Timings>(m, "BuilderTimings")
      .def_readonly("dof_setup", &BuilderAndSolver::Timings::dof_setup)
      .def_readonly("sparsity", &BuilderAndSolver::Timings::sparsity)
      .def_readonly("build", &BuilderAndSolver::Timings::build)
      .def_readonly("solve", &BuilderAndSolver::Timings::solve)
      .def_readonly("elements", &BuilderAndSolver::Timings::elements)
      .def_readonly("conditions", &BuilderAndSolver::Timings::conditions);
  py::class_<BuilderAndSolver, std::shared_ptr<BuilderAndSolver>>(m, "BuilderAndSolver")
      .def("Name", &BuilderAndSolver::Name)
      .def("NumberOfDofs", &BuilderAndSolver::NumberOfDofs)
      .def("SystemSize", &BuilderAndSolver::SystemSize)
      .def("GetTimings", &BuilderAndSolver::GetTimings, py::return_value_policy::copy)
      .def("SystemMatrixNonZeros", [](const BuilderAndSolver& b) { return b.SystemMatrix().nonZeros(); })
      .def("AddConstraint", [](BuilderAndSolver& b, std::shared_ptr<MasterSlaveConstraint> c) { b.AddConstraint(std::move(c)); })
      .def("ClearConstraints", &BuilderAndSolver::ClearConstraints);

  py::class_<MasterSlaveConstraint, std::shared_ptr<MasterSlaveConstraint>>(
      m, "MasterSlaveConstraint", "Linear constraint slave = sum_i weight_i * master_i + constant.")
      .def(py::init([](IndexType id, Dof& slave, std::vector<Dof*> masters, std::vector<double> weights, double constant) {
             return std::make_shared<MasterSlaveConstraint>(id, slave, std::move(masters), std::move(weights), constant);
           }),
           py::arg("id"), py::arg("slave"), py::arg("masters"), py::arg("weights"), py::arg("constant") = 0.0)
      .def("Id", &MasterSlaveConstraint::Id);
  py::class_<BlockBuilderAndSolver, BuilderAndSolver, std::shared_ptr<BlockBuilderAndSolver>>(m, "BlockBuilderAndSolver")
      .def(py::init([](std::shared_ptr<LinearSolver> solver) { return std::make_shared<BlockBuilderAndSolver>(std::move(solver)); }),
           py::arg("linear_solver"));
  py::class_<EliminationBuilderAndSolver, BuilderAndSolver, std::shared_ptr<EliminationBuilderAndSolver>>(
      m, "EliminationBuilderAndSolver")
      .def(py::init<std::shared_ptr<LinearSolver>>(), py::arg("linear_solver"));

  py::class_<IterationRecord>(m, "IterationRecord")
      .def_readonly("iteration", &IterationRecord::iteration)
      .def_readonly("residual_norm", &IterationRecord::residual_norm)
      .def_readonly("increment_norm", &IterationRecord::increment_norm)
      .def_readonly("step_length", &IterationRecord::step_length)
      .def_readonly("criteria", &IterationRecord::criteria)
      .def_readonly("converged", &IterationRecord::converged)
      .def("__repr__", [](const IterationRecord& r) {
        return Concat("iteration ", r.iteration, ": |r| = ", r.residual_norm, ", |du| = ", r.increment_norm);
      });

  py::class_<SolvingStrategy, std::shared_ptr<SolvingStrategy>>(m, "SolvingStrategy")
      .def("Name", &SolvingStrategy::Name)
      .def("Initialize", [](SolvingStrategy& s) { WithoutGil([&] { s.Initialize(); }); })
      .def("InitializeSolutionStep", [](SolvingStrategy& s) { WithoutGil([&] { s.InitializeSolutionStep(); }); })
      .def("Predict", [](SolvingStrategy& s) { WithoutGil([&] { s.Predict(); }); })
      .def("SolveSolutionStep", [](SolvingStrategy& s) { return WithoutGil([&] { return s.SolveSolutionStep(); }); })
      .def("FinalizeSolutionStep", [](SolvingStrategy& s) { WithoutGil([&] { s.FinalizeSolutionStep(); }); })
      .def("Solve", [](SolvingStrategy& s) { return WithoutGil([&] { return s.Solve(); }); })
      .def("Clear", &SolvingStrategy::Clear)
      .def("Check", &SolvingStrategy::Check)
      .def("SetEchoLevel", &SolvingStrategy::SetEchoLevel)
      .def("GetIterationNumber", [](const SolvingStrategy& s) -> int {
        if (const auto* newton = dynamic_cast<const NewtonRaphsonStrategy*>(&s))
          return static_cast<int>(newton->IterationHistory().size());
        return 1;
      })
      .def("GetIterationHistory", [](const SolvingStrategy& s) {
        if (const auto* newton = dynamic_cast<const NewtonRaphsonStrategy*>(&s)) return newton->IterationHistory();
        return std::vector<IterationRecord>{};
      });
  py::class_<ImplicitSolvingStrategy, SolvingStrategy, std::shared_ptr<ImplicitSolvingStrategy>>(m, "ImplicitSolvingStrategy")
      .def("GetBuilderAndSolver", [](const ImplicitSolvingStrategy& s) -> BuilderAndSolver& { return s.GetBuilderAndSolver(); },
           py::return_value_policy::reference_internal);
  py::class_<LinearStrategy, ImplicitSolvingStrategy, std::shared_ptr<LinearStrategy>>(m, "LinearStrategy")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<BuilderAndSolver> builder,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<LinearStrategy>(part, std::move(scheme), std::move(builder), compute_reactions,
                                                       reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("builder_and_solver"), py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = false, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>());
  py::class_<NewtonRaphsonStrategy, ImplicitSolvingStrategy, std::shared_ptr<NewtonRaphsonStrategy>>(m, "NewtonRaphsonStrategy")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, int max_iteration, bool compute_reactions,
                       bool reform_dofs_at_each_step, bool move_mesh, bool use_old_stiffness, int echo_level) {
             auto s = std::make_shared<NewtonRaphsonStrategy>(part, std::move(scheme), std::move(criteria),
                                                              std::move(builder), max_iteration, compute_reactions,
                                                              reform_dofs_at_each_step, move_mesh, use_old_stiffness);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("max_iteration") = 10, py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true,
           py::arg("use_old_stiffness_in_first_iteration") = false, py::arg("echo_level") = 0, py::keep_alive<1, 2>());

  py::class_<LineSearchSettings>(m, "LineSearchSettings")
      .def(py::init<>())
      .def_readwrite("max_line_search_iterations", &LineSearchSettings::max_line_search_iterations)
      .def_readwrite("first_alpha_value", &LineSearchSettings::first_alpha_value)
      .def_readwrite("second_alpha_value", &LineSearchSettings::second_alpha_value)
      .def_readwrite("min_alpha", &LineSearchSettings::min_alpha)
      .def_readwrite("max_alpha", &LineSearchSettings::max_alpha)
      .def_readwrite("line_search_tolerance", &LineSearchSettings::line_search_tolerance);
  py::class_<LineSearchStrategy, NewtonRaphsonStrategy, std::shared_ptr<LineSearchStrategy>>(m, "LineSearchStrategy")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, LineSearchSettings settings, int max_iteration,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<LineSearchStrategy>(part, std::move(scheme), std::move(criteria), std::move(builder),
                                                           settings, max_iteration, compute_reactions,
                                                           reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("settings") = LineSearchSettings{}, py::arg("max_iteration") = 10, py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>());
  py::class_<ExplicitStrategy, SolvingStrategy, std::shared_ptr<ExplicitStrategy>>(m, "ExplicitStrategy")
      .def(py::init([](ModelPart& part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme, bool compute_reactions,
                       bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<ExplicitStrategy>(part, std::move(scheme), compute_reactions,
                                                         reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>());
}

}  // namespace mc::python
