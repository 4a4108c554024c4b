// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>

#include <optional>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/io/mdpa_mesh.h"
#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/linear_solver.h"
#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/model/model_part_partitioner.h"
#include "core/solving/and_criteria.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/explicit_central_differences_scheme.h"
#include "core/solving/explicit_strategy.h"
#include "core/solving/line_search_strategy.h"
#include "core/solving/linear_strategy.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/node_partition.h"
#include "core/solving/or_criteria.h"
#include "core/solving/residual_based_bdf_displacement_scheme.h"
#include "core/solving/residual_based_bossak_displacement_scheme.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/solving/residual_criteria.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddSolvingToPython(py::module_& m) {
  py::class_<Scheme, std::shared_ptr<Scheme>>(
      m, "Scheme",
      "Time integration of the unknowns: what is assembled per entity and how DoFs move with an increment.")
      .def("Name", &Scheme::Name, "The settings name, e.g. 'static', 'bossak', 'newmark'.");
  py::class_<ResidualBasedIncrementalUpdateStaticScheme, Scheme,
             std::shared_ptr<ResidualBasedIncrementalUpdateStaticScheme>>(
      m, "StaticScheme",
      "Incremental update u += du (static problems; Kratos ResidualBasedIncrementalUpdateStaticScheme).")
      .def(py::init<bool>(), py::arg("extrapolate") = false,
           "The static scheme; extrapolate: free DoFs start each step from the linear extrapolation of the last "
           "two steps (needs buffer_size 3).")
      .def("Extrapolates", &ResidualBasedIncrementalUpdateStaticScheme::Extrapolates,
           "Whether the predictor extrapolates the last two steps.");
  py::class_<ResidualBasedBossakDisplacementScheme, Scheme, std::shared_ptr<ResidualBasedBossakDisplacementScheme>>(
      m, "BossakScheme",
      "Bossak (alpha_m) implicit dynamics; Newmark for alpha_m = 0 (Kratos "
      "ResidualBasedBossakDisplacementScheme).")
      .def(py::init<double, std::optional<double>>(), py::arg("alpha_m") = -0.3, py::arg("newmark_beta") = py::none(),
           "alpha_m: damp_factor_m; newmark_beta: beta, (1 - alpha_m)^2 / 4 when None; gamma = 1/2 - alpha_m.")
      .def_static("Newmark", &ResidualBasedBossakDisplacementScheme::Newmark,
                  "Newmark's average acceleration (alpha_m 0, beta 1/4, gamma 1/2), scheme_type 'newmark'.")
      .def("Alpha", &ResidualBasedBossakDisplacementScheme::Alpha, "alpha_m.")
      .def("Beta", &ResidualBasedBossakDisplacementScheme::Beta, "Newmark beta.")
      .def("Gamma", &ResidualBasedBossakDisplacementScheme::Gamma, "Newmark gamma.");
  py::class_<ResidualBasedBDFDisplacementScheme, Scheme, std::shared_ptr<ResidualBasedBDFDisplacementScheme>>(
      m, "BDFScheme",
      "Backward differentiation formula of order 1 to 5 for implicit dynamics, variable step (Kratos "
      "ResidualBasedBDFDisplacementScheme; scheme_type 'bdf1'..'bdf5', 'backward_euler' = 'bdf1').")
      .def(py::init<int>(), py::arg("order") = 2, "order: 1 to 5; the model part needs buffer_size >= order + 1.")
      .def("Order", &ResidualBasedBDFDisplacementScheme::Order, "The order p.")
      .def("Coefficient", &ResidualBasedBDFDisplacementScheme::Coefficient, py::arg("i"),
           "c_i of the current step: v_{n+1} = sum_i c_i u_{n+1-i}.");
  py::class_<ExplicitCentralDifferencesScheme, Scheme, std::shared_ptr<ExplicitCentralDifferencesScheme>>(
      m, "ExplicitCentralDifferencesScheme",
      "Explicit central differences with a lumped mass and half-step velocities; stable for dt < 2 / omega_max.")
      .def(py::init<>(), "Without Rayleigh damping (the strategy reads RAYLEIGH_ALPHA from the ProcessInfo).");

  py::class_<CriterionValue>(m, "CriterionValue", "One measure of a convergence criterion at the last check.")
      .def_readonly("name", &CriterionValue::name, "What is measured, e.g. '|du|/|u|'.")
      .def_readonly("value", &CriterionValue::value, "The measured value.")
      .def_readonly("tolerance", &CriterionValue::tolerance, "Its tolerance.")
      .def("__repr__",
           [](const CriterionValue& v) { return Concat(v.name, " = ", v.value, " (tol ", v.tolerance, ")"); });
  py::class_<ConvergenceCriteria, std::shared_ptr<ConvergenceCriteria>>(
      m, "ConvergenceCriteria", "Decides when a Newton loop has converged (Kratos ConvergenceCriteria).")
      .def("Name", &ConvergenceCriteria::Name, "The settings name, e.g. 'displacement_criterion'.")
      .def("SetEchoLevel", &ConvergenceCriteria::SetEchoLevel, py::arg("level"),
           "Verbosity: 0 silent, higher prints more.")
      .def("LastValues", &ConvergenceCriteria::LastValues, "The CriterionValue measures of the last check.");
  py::class_<DisplacementCriteria, ConvergenceCriteria, std::shared_ptr<DisplacementCriteria>>(
      m, "DisplacementCriteria",
      "displacement_criterion: converged when |du|/|u| or |du|/sqrt(n) over the free DoFs is below its tolerance.")
      .def(py::init<double, double>(), py::arg("relative_tolerance") = 1e-4, py::arg("absolute_tolerance") = 1e-9,
           "Kratos' displacement_relative_tolerance and displacement_absolute_tolerance.");
  py::class_<ResidualCriteria, ConvergenceCriteria, std::shared_ptr<ResidualCriteria>>(
      m, "ResidualCriteria",
      "residual_criterion: converged when |r|/|r0| or |r|/sqrt(n) over the free DoFs is below its tolerance.")
      .def(py::init<double, double>(), py::arg("relative_tolerance") = 1e-4, py::arg("absolute_tolerance") = 1e-9,
           "Kratos' residual_relative_tolerance and residual_absolute_tolerance.");
  py::class_<AndCriteria, ConvergenceCriteria, std::shared_ptr<AndCriteria>>(
      m, "AndCriteria", "and_criterion: converged when both criteria are.")
      .def(py::init<std::shared_ptr<ConvergenceCriteria>, std::shared_ptr<ConvergenceCriteria>>(), py::arg("first"),
           py::arg("second"), "Drives both criteria at every call.");
  py::class_<OrCriteria, ConvergenceCriteria, std::shared_ptr<OrCriteria>>(
      m, "OrCriteria", "or_criterion: converged when either criterion is.")
      .def(py::init<std::shared_ptr<ConvergenceCriteria>, std::shared_ptr<ConvergenceCriteria>>(), py::arg("first"),
           py::arg("second"), "Drives both criteria at every call.");

  py::class_<BuilderAndSolver::Timings>(m, "BuilderTimings", "Cumulative wall-clock seconds of a builder-and-solver.")
      .def_readonly("dof_setup", &BuilderAndSolver::Timings::dof_setup, "DoF set-up and numbering (s).")
      .def_readonly("sparsity", &BuilderAndSolver::Timings::sparsity, "Sparsity pattern and constraint matrix (s).")
      .def_readonly("build", &BuilderAndSolver::Timings::build, "Assembly, constraints and Dirichlet conditions (s).")
      .def_readonly("solve", &BuilderAndSolver::Timings::solve, "Linear solver, symbolic and numeric (s).")
      .def_readonly("elements", &BuilderAndSolver::Timings::elements, "Element loop, part of build (s).")
      .def_readonly("conditions", &BuilderAndSolver::Timings::conditions,
                    "Condition loop (loads, contact pairs), part of build (s).");
  py::class_<BuilderAndSolver, std::shared_ptr<BuilderAndSolver>>(
      m, "BuilderAndSolver",
      "Numbers the DoFs, assembles the global system and solves it; eliminates master-slave constraints.")
      .def("Name", &BuilderAndSolver::Name, "The settings name, 'block' or 'elimination'.")
      .def("NumberOfDofs", &BuilderAndSolver::NumberOfDofs, "Number of DoFs of the DoF set (fixed ones included).")
      .def("SystemSize", &BuilderAndSolver::SystemSize, "Number of unknowns of the linear system solved.")
      .def("GetTimings", &BuilderAndSolver::GetTimings, py::return_value_policy::copy, "Its BuilderTimings so far.")
      .def(
          "GetLinearSolverCounters",
          [](const BuilderAndSolver& b) {
            LinearSolver::WorkCounters c;
            if (b.GetLinearSolver() != nullptr) c = b.GetLinearSolver()->Counters();
            return py::dict(py::arg("factorizations") = c.factorizations, py::arg("krylov_solves") = c.krylov_solves,
                            py::arg("krylov_iterations") = c.krylov_iterations, py::arg("fallbacks") = c.fallbacks,
                            py::arg("preconditioner_setups") = c.preconditioner_setups,
                            py::arg("kept_orderings") = c.kept_orderings);
          },
          "Work of its linear solver so far (LinearSolver.Counters).")
      .def("ResetLinearSolver", &BuilderAndSolver::ResetLinearSolver,
           "Frees the linear solver's factorizations and analyses: the next solve starts as in a new run.")
      .def(
          "SystemMatrixNonZeros", [](const BuilderAndSolver& b) { return b.SystemMatrix().nonZeros(); },
          "Non-zeros of the last system matrix.")
      .def(
          "GetSystemMatrix", [](const BuilderAndSolver& b) { return SparseMatrix(b.SystemMatrix()); },
          "A copy of the last system matrix (scipy.sparse CSC), e.g. to benchmark linear solvers on it.")
      .def(
          "AddConstraint",
          [](BuilderAndSolver& b, std::shared_ptr<MasterSlaveConstraint> c) { b.AddConstraint(std::move(c)); },
          py::arg("constraint"),
          "Adds a MasterSlaveConstraint; the DoF set and numbering are redone at the next build.")
      .def("ClearConstraints", &BuilderAndSolver::ClearConstraints, "Removes every constraint.");

  py::class_<MasterSlaveConstraint, std::shared_ptr<MasterSlaveConstraint>>(
      m, "MasterSlaveConstraint", "Linear constraint slave = sum_i weight_i * master_i + constant.")
      .def(py::init(
               [](IndexType id, Dof& slave, std::vector<Dof*> masters, std::vector<double> weights, double constant) {
                 return std::make_shared<MasterSlaveConstraint>(id, slave, std::move(masters), std::move(weights),
                                                                constant);
               }),
           py::arg("id"), py::arg("slave"), py::arg("masters"), py::arg("weights"), py::arg("constant") = 0.0,
           "InputError when masters and weights differ in size or the slave is also a master.")
      .def("Id", &MasterSlaveConstraint::Id, "The constraint's id.")
      .def("IsActive", &MasterSlaveConstraint::IsActive, "Whether the builders eliminate it.")
      .def("SetActive", &MasterSlaveConstraint::SetActive, py::arg("active"),
           "Switches it on or off; takes effect at the builder's next DoF set-up.");
  py::class_<BlockBuilderAndSolver, BuilderAndSolver, std::shared_ptr<BlockBuilderAndSolver>>(
      m, "BlockBuilderAndSolver",
      "block: every DoF is an unknown; fixed rows and columns are zeroed with a positive diagonal (Kratos "
      "ResidualBasedBlockBuilderAndSolver).")
      .def(py::init([](std::shared_ptr<LinearSolver> solver) {
             return std::make_shared<BlockBuilderAndSolver>(std::move(solver));
           }),
           py::arg("linear_solver"), "Solves with linear_solver.");
  py::class_<EliminationBuilderAndSolver, BuilderAndSolver, std::shared_ptr<EliminationBuilderAndSolver>>(
      m, "EliminationBuilderAndSolver",
      "elimination: only the free DoFs are unknowns (Kratos ResidualBasedEliminationBuilderAndSolver).")
      .def(py::init<std::shared_ptr<LinearSolver>>(), py::arg("linear_solver"), "Solves with linear_solver.");

  py::class_<IterationRecord>(m, "IterationRecord", "One Newton iteration as the strategy saw it.")
      .def_readonly("iteration", &IterationRecord::iteration, "Iteration number, from 1.")
      .def_readonly("time", &IterationRecord::time, "TIME of the step (of the sub-step when the step is split).")
      .def_readonly("residual_norm", &IterationRecord::residual_norm,
                    "|f_ext - f_int| over the free DoFs at the start of the iteration.")
      .def_readonly("increment_norm", &IterationRecord::increment_norm, "|du| applied in the iteration.")
      .def_readonly("step_length", &IterationRecord::step_length,
                    "Line-search factor applied to the increment (1: Newton).")
      .def_readonly("linear_tolerance", &IterationRecord::linear_tolerance,
                    "Relative residual the linear solve was asked to reach (0: a direct solve).")
      .def_readonly("linear_iterations", &IterationRecord::linear_iterations,
                    "Iterations of the linear solve (1: a direct solve).")
      .def_readonly("criteria", &IterationRecord::criteria, "The CriterionValue measures of the criteria.")
      .def_readonly("converged", &IterationRecord::converged, "Whether the criteria were met.")
      .def_readonly("active_nodes", &IterationRecord::active_nodes,
                    "Slave nodes in contact (ACTIVE) after the iteration; -1 without a contact interface.")
      .def("__repr__", [](const IterationRecord& r) {
        return Concat("iteration ", r.iteration, ": |r| = ", r.residual_norm, ", |du| = ", r.increment_norm);
      });

  py::class_<SolvingStrategy, std::shared_ptr<SolvingStrategy>>(
      m, "SolvingStrategy", "Advances one model part by one time or load step (Kratos SolvingStrategy).")
      .def("Name", &SolvingStrategy::Name, "The settings name: 'linear', 'newton_raphson', 'line_search', 'explicit'.")
      .def(
          "Initialize", [](SolvingStrategy& s) { WithoutGil([&] { s.Initialize(); }); }, "Once, before the first step.")
      .def(
          "InitializeSolutionStep", [](SolvingStrategy& s) { WithoutGil([&] { s.InitializeSolutionStep(); }); },
          "At the start of a step (DoF set-up on the first one).")
      .def(
          "Predict", [](SolvingStrategy& s) { WithoutGil([&] { s.Predict(); }); }, "First guess of the step.")
      .def("MoveMesh", &SolvingStrategy::MoveMesh,
           "Sets every node's coordinates to X0 + DISPLACEMENT, as after each Newton update (e.g. after setting "
           "DISPLACEMENT by hand).")
      .def(
          "SolveSolutionStep", [](SolvingStrategy& s) { return WithoutGil([&] { return s.SolveSolutionStep(); }); },
          "Solves the step; False when it did not converge (the model keeps the last iterate).")
      .def(
          "FinalizeSolutionStep", [](SolvingStrategy& s) { WithoutGil([&] { s.FinalizeSolutionStep(); }); },
          "At the end of a step (reactions, entities' finalization).")
      .def(
          "Solve", [](SolvingStrategy& s) { return WithoutGil([&] { return s.Solve(); }); },
          "Initialize (first time), InitializeSolutionStep, Predict, SolveSolutionStep, FinalizeSolutionStep; "
          "whether the step converged.")
      .def("Clear", &SolvingStrategy::Clear, "Frees the system and the DoF set; the next step sets them up again.")
      .def("Check", &SolvingStrategy::Check, "Validates the model (entities, variables) before the first step.")
      .def("SetEchoLevel", &SolvingStrategy::SetEchoLevel, py::arg("level"), "Verbosity: 0 silent, higher prints more.")
      .def(
          "GetIterationNumber",
          [](const SolvingStrategy& s) -> int {
            if (const auto* newton = dynamic_cast<const NewtonRaphsonStrategy*>(&s))
              return static_cast<int>(newton->IterationHistory().size());
            return 1;
          },
          "Iterations of the last step (1 for non-Newton strategies).")
      .def(
          "GetIterationHistory",
          [](const SolvingStrategy& s) {
            if (const auto* newton = dynamic_cast<const NewtonRaphsonStrategy*>(&s)) return newton->IterationHistory();
            return std::vector<IterationRecord>{};
          },
          "The IterationRecord of each iteration of the last step, the failed attempt and the sub-steps of a split "
          "step included (empty for non-Newton strategies).");
  py::class_<ImplicitSolvingStrategy, SolvingStrategy, std::shared_ptr<ImplicitSolvingStrategy>>(
      m, "ImplicitSolvingStrategy", "A strategy with a scheme, a builder-and-solver and a DoF set.")
      .def(
          "GetBuilderAndSolver",
          [](const ImplicitSolvingStrategy& s) -> BuilderAndSolver& { return s.GetBuilderAndSolver(); },
          py::return_value_policy::reference_internal, "Its BuilderAndSolver.")
      .def(
          "BuildSystem",
          [](ImplicitSolvingStrategy& s, ModelPart& part) {
            BuilderAndSolver& b = s.GetBuilderAndSolver();
            b.Build(s.GetScheme(), part);
            py::list dofs;
            for (const Dof* d : b.GetDofSet())
              dofs.append(py::make_tuple(d->equation_id, d->node->Id(), d->variable->Name(), d->fixed));
            return py::make_tuple(SparseMatrix(b.SystemMatrix()), Vector(b.Residual()), dofs);
          },
          py::arg("model_part"),
          "Builds the system at the current state, as a Newton iteration does (the caller refreshes what the "
          "strategy would first, e.g. the contact normals), and returns (A, b, dofs): the matrix (scipy.sparse "
          "CSC), the residual b (A = -db/du on the free DoFs) and (equation id, node id, variable, fixed) per DoF; "
          "for checking tangents against finite differences of the whole residual.");
  py::class_<LinearStrategy, ImplicitSolvingStrategy, std::shared_ptr<LinearStrategy>>(
      m, "LinearStrategy", "analysis_type linear: one build and solve per step (Kratos ResidualBasedLinearStrategy).")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<BuilderAndSolver> builder,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<LinearStrategy>(part, std::move(scheme), std::move(builder), compute_reactions,
                                                       reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("builder_and_solver"), py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = false, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>(), "Kratos' solver_settings of the same names (move_mesh: move_mesh_flag).");
  py::class_<NewtonRaphsonStrategy, ImplicitSolvingStrategy, std::shared_ptr<NewtonRaphsonStrategy>>(
      m, "NewtonRaphsonStrategy",
      "analysis_type non_linear: Newton-Raphson on the residual (Kratos "
      "ResidualBasedNewtonRaphsonStrategy).")
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
           py::arg("use_old_stiffness_in_first_iteration") = false, py::arg("echo_level") = 0, py::keep_alive<1, 2>(),
           "Kratos' solver_settings of the same names (move_mesh: move_mesh_flag).")
      .def(
          "SetStepSplitting",
          [](NewtonRaphsonStrategy& s, Parameters settings) { s.SetStepSplitting(StepSplitting::Read(settings)); },
          py::arg("settings"),
          "solver_settings.step_splitting: {max_number_splits (0: off), split_factor (2)}; a step that does not "
          "converge restarts as sub-steps of DELTA_TIME / split_factor^s, s = 1 .. max_number_splits.")
      .def(
          "SetSubStepCallbacks",
          [](NewtonRaphsonStrategy& s, py::object initialize_solution_step, py::object finalize_solution_step) {
            s.SetSubStepCallbacks({PythonCallback<>(std::move(initialize_solution_step)),
                                   PythonCallback<>(std::move(finalize_solution_step))});
          },
          py::arg("initialize_solution_step"), py::arg("finalize_solution_step") = py::none(),
          "Callables run around the sub-steps of a split step (processes, output).")
      .def("FailureReport", &NewtonRaphsonStrategy::FailureReport,
           "Why the last step failed ('' if it converged): step, time, and the nodes or elements at fault.")
      .def("SplitLevelUsed", &NewtonRaphsonStrategy::SplitLevelUsed,
           "Split level that made the last step converge (0: no split needed).");

  py::class_<LineSearchSettings>(m, "LineSearchSettings", "Settings of the line search (Kratos' line_search keys).")
      .def(py::init<>(), "Kratos' defaults.")
      .def_readwrite("max_line_search_iterations", &LineSearchSettings::max_line_search_iterations,
                     "Secant iterations after the two trial steps (5).")
      .def_readwrite("first_alpha_value", &LineSearchSettings::first_alpha_value, "First trial step length (0.5).")
      .def_readwrite("second_alpha_value", &LineSearchSettings::second_alpha_value, "Second trial step length (1).")
      .def_readwrite("min_alpha", &LineSearchSettings::min_alpha, "Smallest step length (0.1).")
      .def_readwrite("max_alpha", &LineSearchSettings::max_alpha, "Largest step length (2).")
      .def_readwrite("line_search_tolerance", &LineSearchSettings::line_search_tolerance,
                     "Stop when |phi(s)| <= tolerance |phi(0)| (0.5).");
  py::class_<LineSearchStrategy, NewtonRaphsonStrategy, std::shared_ptr<LineSearchStrategy>>(
      m, "LineSearchStrategy",
      "analysis_type line_search: Newton with the step length zeroing du . r(u + s du) "
      "(Kratos LineSearchStrategy).")
      .def(py::init([](ModelPart& part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
                       std::shared_ptr<BuilderAndSolver> builder, LineSearchSettings settings, int max_iteration,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<LineSearchStrategy>(part, std::move(scheme), std::move(criteria),
                                                           std::move(builder), settings, max_iteration,
                                                           compute_reactions, reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("criteria"), py::arg("builder_and_solver"),
           py::arg("settings") = LineSearchSettings{}, py::arg("max_iteration") = 10,
           py::arg("compute_reactions") = true, py::arg("reform_dofs_at_each_step") = false,
           py::arg("move_mesh") = true, py::arg("echo_level") = 0, py::keep_alive<1, 2>(),
           "Kratos' solver_settings of the same names (move_mesh: move_mesh_flag).");
  py::class_<ExplicitStrategy, SolvingStrategy, std::shared_ptr<ExplicitStrategy>>(
      m, "ExplicitStrategy", "Explicit dynamics: one residual assembly and a lumped-mass nodal update per step.")
      .def(py::init([](ModelPart& part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                       bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh, int echo_level) {
             auto s = std::make_shared<ExplicitStrategy>(part, std::move(scheme), compute_reactions,
                                                         reform_dofs_at_each_step, move_mesh);
             s->SetEchoLevel(echo_level);
             return s;
           }),
           py::arg("model_part"), py::arg("scheme"), py::arg("compute_reactions") = true,
           py::arg("reform_dofs_at_each_step") = false, py::arg("move_mesh") = true, py::arg("echo_level") = 0,
           py::keep_alive<1, 2>(), "Kratos' solver_settings of the same names (move_mesh: move_mesh_flag).")
      .def("ElementStableTimeStep", &ExplicitStrategy::ElementStableTimeStep,
           "Critical time step of central differences bounded element by element: 2 / omega_e, omega_e^2 the "
           "largest eigenvalue of M_e^-1 K_e (lumped mass); infinity without stiffness.")
      .def("SetUpDofsAndMass", &ExplicitStrategy::SetUpDofsAndMass,
           "The DoF set and the lumped mass (NODAL_MASS), before the first step (the first step does it too).");
  m.def(
      "CutModelPart",
      [](ModelPart& root, const LinearSolver& solver, const std::vector<const ModelPart*>& replicated) {
        const AssemblyCommunicator* communicator = solver.Communicator();
        if (!communicator) throw Error("CutModelPart: the linear solver solves on one process; nothing to cut");
        // Made once on the whole model (or on the file before a rank read its piece) and kept with
        // it: the builder numbers the piece with it (re-partitioning the piece would give other
        // owners on each rank).
        if (!root.GetNodePartition()) root.SetNodePartition(std::make_shared<const NodePartition>(root, *communicator));
        const ModelPartPartitioner::Piece piece =
            ModelPartPartitioner([&owners = *root.GetNodePartition()](const Node& node) { return owners.Owner(node); },
                                 communicator->Rank())
                .Cut(root, replicated);
#if defined(__GLIBC__)
        // The entities cut away are many small blocks amid the heap, which glibc keeps mapped; the
        // later large blocks (the system, the solver's factors) are mapped apart and would not
        // reuse them.
        malloc_trim(0);
#endif
        return py::dict(py::arg("owned_nodes") = piece.owned_nodes, py::arg("ghost_nodes") = piece.ghost_nodes,
                        py::arg("elements") = piece.elements, py::arg("conditions") = piece.conditions);
      },
      py::arg("root"), py::arg("linear_solver"), py::arg("replicated"),
      "Collective under mpirun (issue 17, step 3): partitions the nodes of the whole model `root` with METIS over "
      "the linear solver's processes, keeps the partition with the model and cuts it to this rank's piece (the "
      "entities touching its nodes, their nodes, the `replicated` sub model parts whole). Returns the piece's "
      "counts.");
  m.def(
      "PlanModelPartPiece",
      [](ModelPart& root, const std::string& filename, const LinearSolver& solver,
         const std::vector<std::string>& kept_whole) {
        const AssemblyCommunicator* communicator = solver.Communicator();
        if (!communicator) throw Error("PlanModelPartPiece: the linear solver solves on one process");
        MdpaMesh::Piece piece;
        std::pair<std::unordered_map<IndexType, std::size_t>, std::size_t> bodies;
        {
          py::gil_scoped_release release;
          const MdpaMesh mesh = MdpaMesh::Read(filename);
          auto partition = std::make_shared<NodePartition>(mesh, *communicator);
          piece = mesh.PieceOf([&owners = *partition](IndexType id) { return owners.OwnerOf(id); },
                               communicator->Rank(), root.Name(), kept_whole);
          bodies = mesh.Bodies(piece.interface_nodes);
          partition->KeepOnly(piece.nodes);
          root.SetNodePartition(std::move(partition));
        }
        return py::make_tuple(std::move(piece), std::move(bodies.first), bodies.second);
      },
      py::arg("root"), py::arg("filename"), py::arg("linear_solver"), py::arg("kept_whole"),
      "Collective under mpirun (issue 17): streams the mdpa's connectivity (no model built), partitions its nodes "
      "with METIS over the linear solver's processes as CutModelPart would the model read whole, keeps the "
      "partition (of this rank's nodes) with `root` and returns (piece, bodies, labels): what this rank reads "
      "(ReadModelPart's `piece`: the entities touching its nodes, the sub model parts `kept_whole` whole and what "
      "touches their nodes), and the bodies of those parts' nodes (ContactSearchProcess.SetBodies).");
  m.def(
      "AllGather",
      [](const LinearSolver& solver, const py::bytes& data) {
        const AssemblyCommunicator* communicator = solver.Communicator();
        if (!communicator) throw Error("AllGather: the linear solver solves on one process; nothing to gather");
        std::vector<std::string> gathered;
        {
          const std::string bytes = data;
          py::gil_scoped_release release;
          gathered = communicator->AllGather(bytes);
        }
        py::list result;
        for (const std::string& bytes : gathered) result.append(py::bytes(bytes));
        return result;
      },
      py::arg("linear_solver"), py::arg("data"),
      "Collective under mpirun: every rank's `data` (bytes), in rank order, on every rank.");
  m.def(
      "OwnedNodes",
      [](const ModelPart& part) {
        const NodePartition* partition = part.GetNodePartition();
        if (!partition) throw Error(Concat("OwnedNodes: model part '", part.FullName(), "' is not cut across ranks"));
        const int rank = AssemblyCommunicator::LaunchedRank();
        py::array_t<bool> owned(static_cast<py::ssize_t>(part.NumberOfNodes()));
        bool* out = owned.mutable_data();
        for (const Node* node : part.Nodes()) *out++ = partition->Owner(*node) == rank;
        return owned;
      },
      py::arg("model_part"),
      "Of a model cut across the ranks (CutModelPart): whether this rank owns each node of `model_part`, in "
      "the order of its nodes (node-id order).");
}

}  // namespace mc::python
