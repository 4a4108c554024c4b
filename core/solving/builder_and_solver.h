// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/row_partition.h"
#include "core/linear_solvers/sparse_types.h"
#include "core/model/dof.h"
#include "core/solving/distributed_dof_numbering.h"
#include "core/solving/node_partition.h"

namespace mc {

class Entity;
class ModelPart;
class ProcessInfo;
class Scheme;
class MasterSlaveConstraint;

/// Collects the DoFs, numbers them, assembles the global system from the entities' local
/// contributions and solves it. Derived classes decide the numbering and how fixed DoFs are
/// imposed (BlockBuilderAndSolver, EliminationBuilderAndSolver).
///
/// Vectors seen by strategies, schemes and criteria (`Residual`, `Increment`) are full-size
/// and indexed by Dof::equation_id, fixed and slave DoFs included, whatever the numbering of
/// the system actually solved.
///
/// The sparsity pattern is built once after each SetUpSystem (DoF set or numbering change)
/// and reused: later builds zero the values and accumulate into them in parallel (OpenMP over
/// elements then conditions, per-column binary search, atomic adds).
///
/// Master-slave constraints u_s = T u_m + c are eliminated: with T the map from the system
/// unknowns to the assembled ones and g the current constraint violation,
///   A = T^T K T,  b = T^T (r - K g),  dx = T x + g,
/// so every constraint holds exactly after each solve.
///
/// Distributed (a linear solver with a Communicator(): PETSc under `mpirun -n N`): every rank
/// holds the whole model and the whole DoF set, and owns the DoFs of its nodes (a METIS partition
/// of the mesh, NodePartition). The DoFs are numbered rank by rank, so each rank's rows are one
/// block (Partition()). Each rank keeps and assembles only its own rows: the pattern, the matrix
/// SystemMatrix() (Partition().LocalRows() rows, every column; row i is equation Begin() + i), the
/// kept element matrix and the Dirichlet rows. It computes every element and condition that has
/// an equation in its rows (those on the rank's border are computed by each rank they touch) and
/// adds only the entries of its rows, so a row holds the serial sum in the serial order. The
/// residual rows are summed over the ranks, so Residual(), Increment() and the reactions are whole
/// and identical on every rank, and the criteria, the contact search and the active set run as in
/// a serial run. With one process nothing of this runs and the matrix is square.
///
/// A model cut to a piece per rank (the root model part holds the NodePartition it was cut with,
/// ModelPart::GetNodePartition): the rank's DoF set is its piece's, owned DoFs first, then the
/// ghosts (DoFs of nodes other ranks own), each group in the order of `dofs_`. Dof::equation_id
/// is then the DoF's position in that order, and every vector here (Residual(), Increment(), ...)
/// is indexed by it; the system's row of a DoF (DistributedDofNumbering: the replicated run's
/// numbering) is Partition().ColumnRows()[equation_id]. The matrix keeps the owned rows, with a
/// column per DoF of the piece. A row is complete on its owner (the piece holds every entity
/// touching an owned node), so nothing is summed over the ranks; the solver returns the owned rows
/// of the increment and the ghosts' come from their owners. Quantities over the DoFs (the
/// criteria's norms) sum OwnedDofs() and then over the ranks (PieceCommunicator()). Only the
/// block builder, and neither master-slave constraints nor residual combinations, run so.
class BuilderAndSolver {
 public:
  /// Cumulative wall-clock seconds, for benchmarks.
  struct Timings {
    double dof_setup = 0.0;   ///< SetUpDofSet and numbering
    double sparsity = 0.0;    ///< pattern (and constraint matrix) construction
    double build = 0.0;       ///< assembly, constraint reduction and Dirichlet conditions
    double solve = 0.0;       ///< linear solver (symbolic and numeric)
    double elements = 0.0;    ///< part of `build`: the element loop of the assembly
    double conditions = 0.0;  ///< part of `build`: the condition loop (loads, contact pairs)
  };

  /// `linear_solver` may be null for builders that only assemble residuals (explicit).
  explicit BuilderAndSolver(std::shared_ptr<LinearSolver> linear_solver);
  BuilderAndSolver(const BuilderAndSolver&) = delete;
  BuilderAndSolver& operator=(const BuilderAndSolver&) = delete;
  virtual ~BuilderAndSolver();

  /// The settings name ("block", "elimination").
  virtual std::string Name() const = 0;
  void SetEchoLevel(int level) noexcept { echo_level_ = level; }
  int GetEchoLevel() const noexcept { return echo_level_; }

  // DoFs ----------------------------------------------------------------------------------------
  /// The DoFs of every active element and condition (and of the active constraints: those
  /// added here and those of the model part), sorted by node id and variable, without
  /// duplicates.
  void SetUpDofSet(ModelPart& model_part, const Scheme& scheme);
  /// Equation ids, constraint bookkeeping; the pattern is rebuilt on the next build.
  void SetUpSystem();
  const std::vector<Dof*>& GetDofSet() const noexcept { return dofs_; }
  /// The DoFs whose rows this rank completes: GetDofSet() unless the model is cut to a piece per
  /// rank, then this rank's owned DoFs (a sum over them and over the ranks counts each DoF once).
  const std::vector<Dof*>& OwnedDofs() const noexcept { return piece_owners_ ? owned_dofs_ : dofs_; }
  /// The ranks to sum OwnedDofs()' quantities over: non-null only when the model is cut.
  const AssemblyCommunicator* PieceCommunicator() const noexcept { return piece_owners_ ? communicator_ : nullptr; }
  /// The 2-norm of a vector indexed by equation id, over every rank's owned rows when the model is
  /// cut (the same value on every rank).
  double Norm(const Vector& v) const;
  std::size_t NumberOfDofs() const noexcept { return dofs_.size(); }
  /// Number of unknowns of the linear system solved.
  std::size_t SystemSize() const noexcept { return n_system_; }
  /// The DoF with this equation id.
  const Dof& DofOfEquation(std::size_t equation_id) const { return *dofs_by_equation_[equation_id]; }

  // Constraints ---------------------------------------------------------------------------------
  /// Their DoFs join the DoF set at the next SetUpDofSet; the numbering is redone at the next
  /// build. The model part's own constraints (ModelPart::MasterSlaveConstraints) join them at
  /// each SetUpDofSet.
  void AddConstraint(std::shared_ptr<const MasterSlaveConstraint> constraint);
  /// Removes the constraints added here (the model part's come back at the next SetUpDofSet).
  void ClearConstraints();
  const std::vector<std::shared_ptr<const MasterSlaveConstraint>>& Constraints() const noexcept { return constraints_; }

  /// One term of a linear combination of the assembled residual rows: the row of `to` receives
  /// `weight` times the row of `from` (see SetResidualCombination).
  struct ResidualTerm {
    const Dof* to;
    const Dof* from;
    double weight;
  };
  /// A force that is a linear combination of the entities' residual rows, r <- (I + C) r, with its
  /// exact matrix (I + C) K: A = T^T (I + C) K T, b = T^T (I + C) (r - K g). Only with constraints
  /// (frictional MPC contact: a slipping node's Coulomb force is mu times its normal reaction, a
  /// combination of its own rows, and its masters take the opposite force). RawResidual() stays the
  /// entities'; Residual() and the reactions include the force. `stiffness` (row `to`, column `from`,
  /// value `weight`) is added to the matrix (I + C) K: the derivative of the force through what the rows
  /// do not carry (a Coulomb force's slip direction). The terms replace the earlier ones (empty lists
  /// remove them) and hold for the next builds; their DoFs must be in the DoF set.
  void SetResidualCombination(std::vector<ResidualTerm> terms, std::vector<ResidualTerm> stiffness = {});

  // Build and solve -----------------------------------------------------------------------------
  void Build(Scheme& scheme, ModelPart& model_part);
  void BuildLHS(Scheme& scheme, ModelPart& model_part);
  void BuildRHS(Scheme& scheme, ModelPart& model_part);
  /// Solves the system last built (A x = b), fills Increment(). Throws SolutionError naming the
  /// DoFs when the system is singular.
  void SolveSystem();
  void BuildAndSolve(Scheme& scheme, ModelPart& model_part);
  /// Rebuilds the residual only and solves with the matrix of the last build.
  void BuildRHSAndSolve(Scheme& scheme, ModelPart& model_part);
  /// Rebuilds the residual at the current state and writes REACTION = -(f_ext - f_int) at the
  /// fixed DoFs: the force the support exerts, which balances the loads.
  void CalculateReactions(Scheme& scheme, ModelPart& model_part);
  /// Reactions from the residual of the last build (no rebuild).
  void WriteReactions();

  /// The whole system, or in a distributed run this rank's rows of it (see the class comment).
  const SparseMatrix& SystemMatrix() const noexcept { return A_; }
  const Vector& SystemRhs() const noexcept { return b_system_; }
  /// f_ext - f_int of the last build with constraint forces moved to the masters, zero at
  /// fixed and slave DoFs: what residual criteria measure.
  const Vector& Residual() const noexcept { return residual_; }
  Vector& Residual() noexcept { return residual_; }
  /// f_ext - f_int of the last build at every DoF, before the constraints move the slaves' share to
  /// their masters: at a slave DoF, minus the force its constraint transmits.
  const Vector& RawResidual() const noexcept { return rhs_raw_; }
  /// The increment of every DoF from the last solve (zero at fixed DoFs).
  const Vector& Increment() const noexcept { return dx_; }
  Vector& Increment() noexcept { return dx_; }

  LinearSolver* GetLinearSolver() const noexcept { return linear_solver_.get(); }
  /// Null in a serial run; see the class comment.
  const AssemblyCommunicator* Communicator() const noexcept { return communicator_; }
  /// The rows each rank owns (distributed runs; updated by SetUpSystem).
  const RowPartition& Partition() const noexcept { return partition_; }
  /// The owner of each node (distributed runs; updated by SetUpDofSet).
  const NodePartition& NodeOwners() const noexcept { return node_partition_; }
  /// The equation id of the matrix's first row: Partition().Begin() in a distributed run of the
  /// whole model, else 0 (the owned DoFs come first in a piece).
  std::int64_t FirstRow() const noexcept { return communicator_ && !piece_owners_ ? partition_.Begin() : 0; }
  /// Frees what the linear solver keeps between solves (factorizations, analyses): the next
  /// solve starts as in a new run. Restart checkpoints call it, so that a resumed run repeats the
  /// uninterrupted one bit for bit although the solver reuses factorizations across steps.
  void ResetLinearSolver();
  const Timings& GetTimings() const noexcept { return timings_; }
  void ResetTimings() noexcept { timings_ = Timings{}; }
  /// Number of times the sparsity pattern has been built (tests check the reuse).
  int PatternBuildCount() const noexcept { return pattern_builds_; }
  /// Forces a new pattern at the next build (e.g. after contact pairs changed the connectivity).
  void InvalidatePattern() noexcept { pattern_valid_ = false; }
  /// Drops the element matrix kept for reuse (see ElementMatrixReuses); strategies call it at
  /// every InitializeSolutionStep, as properties, loads or the reference geometry may change
  /// between steps. Within a step, when the scheme passes element matrices through unchanged
  /// and every active element HasConstantLeftHandSide (small displacement, linear laws), the
  /// elements' part K of the matrix is assembled at the first build and copied at the next
  /// ones. Their residual is then affine, f - K u: with every DoF in the matrix (block
  /// builder) f is kept from that first build and later residuals cost one product with K
  /// instead of an element loop.
  void ForgetElementMatrix() noexcept { element_matrix_valid_ = false; }
  /// Number of builds that reused the element matrix (tests check the reuse).
  int ElementMatrixReuses() const noexcept { return element_matrix_reuses_; }
  /// Frees the system, the DoF set and the factorization.
  virtual void Clear();

 protected:
  /// `dofs_` in the order of numbering: grouped by owning rank in a distributed run (each group
  /// sorted as `dofs_`), `dofs_` itself in a serial one.
  const std::vector<Dof*>& NumberingOrder() const noexcept { return communicator_ ? ordered_dofs_ : dofs_; }
  /// Sets Dof::equation_id for every DoF of NumberingOrder() and `n_assembled_` (DoFs whose rows are
  /// assembled: ids [0, n_assembled_)) and `n_system_` (unknowns solved: ids [0, n_system_)
  /// when there are no constraints).
  virtual void NumberDofs() = 0;
  /// Whether the numbering depends on fixity that changed since NumberDofs.
  virtual bool NumberingIsStale() const { return false; }
  /// Imposes fixed (and slave) DoFs on A_ / b_system_ after assembly and reduction.
  virtual void ApplyDirichletConditions(bool lhs, bool rhs) {}

  bool IsSlave(const Dof& dof) const { return slave_of_.count(&dof) > 0; }
  /// Fixity of each equation when NumberDofs ran.
  std::vector<char> fixed_at_numbering_;
  std::vector<Dof*> dofs_;
  std::size_t n_assembled_ = 0;
  std::size_t n_system_ = 0;
  SparseMatrix A_;
  Vector b_system_;
  int echo_level_ = 0;

 private:
  enum class Mode { kBoth, kLhs, kRhs };
  void PrepareBuild();
  void BuildPattern(ModelPart& model_part);
  void BuildConstraintMatrix();
  void Assemble(Scheme& scheme, ModelPart& model_part, Mode mode);
  bool ElementMatrixIsConstant(const Scheme& scheme, const ModelPart& model_part) const;
  void AddElementMatrixProduct(const SparseMatrix& target, double sign, Vector& out);
  void FinishResidual();
  void ReduceSystem(Mode mode);
  /// C_ from combination_ at the current numbering; a new structure makes the solver analyse again.
  void BuildCombinationMatrix();
  void CheckEmptyColumns() const;
  bool TouchesOwnRows(const Entity& entity, const ProcessInfo& info) const;
  void SumResidualOverRanks();
  /// The owners of the nodes: the stored partition of a cut model, else node_partition_.
  const NodePartition& Owners() const noexcept { return piece_owners_ ? *piece_owners_ : node_partition_; }
  /// A cut model (piece_owners_): numbers the piece's DoFs by DistributedDofNumbering, sets each
  /// equation_id to its local position and partition_ with the columns' system rows.
  void NumberPiece();
  /// A cut model: the ghost entries of `v` (indexed by equation id) from their owners.
  void UpdateGhosts(Vector& v) const;
  [[noreturn]] void ThrowSingular(const std::vector<const Dof*>& dofs, const std::string& detail) const;

  std::shared_ptr<LinearSolver> linear_solver_;
  const AssemblyCommunicator* communicator_ = nullptr;  ///< owned by linear_solver_
  RowPartition partition_;
  NodePartition node_partition_;
  const NodePartition* piece_owners_ = nullptr;         ///< the cut model's partition
  std::unique_ptr<DistributedDofNumbering> numbering_;  ///< a cut model, after SetUpSystem
  std::vector<Dof*> owned_dofs_;                        ///< a cut model: ordered_dofs_' head, this rank's
  std::vector<Dof*> ordered_dofs_;                      ///< distributed: dofs_ grouped by owning rank
  std::vector<char> owned_;                             ///< distributed: by equation id, whether this rank owns the row
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> added_constraints_;  ///< by AddConstraint
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> constraints_;        ///< added + model part's
  std::unordered_map<const Dof*, const MasterSlaveConstraint*> slave_of_;
  std::vector<Dof*> dofs_by_equation_;
  bool numbered_ = false;
  bool constraints_changed_ = false;
  bool pattern_valid_ = false;
  int pattern_builds_ = 0;
  long pattern_version_ = 0;
  long solver_pattern_version_ = -1;

  SparseMatrix K_;                         ///< assembled matrix when constraints are reduced into A_
  SparseMatrix T_;                         ///< n_assembled x n_system constraint map
  std::vector<ResidualTerm> combination_;  ///< SetResidualCombination
  SparseMatrix C_;                         ///< n_assembled x n_assembled, from combination_
  std::vector<ResidualTerm> combination_stiffness_;
  SparseMatrix S_;                                ///< n_assembled x n_assembled, from combination_stiffness_
  std::vector<std::pair<int, int>> C_structure_;  ///< (row, column) of C_'s then S_'s entries
  long combination_version_ = 0;                  ///< changes with C_structure_
  long solver_combination_version_ = -1;
  Vector g_;              ///< constraint violations (n_assembled)
  Vector rhs_raw_;        ///< f_ext - f_int for every DoF
  Vector rhs_effective_;  ///< rhs_raw_ with slave entries moved to the masters
  Vector residual_;
  Vector x_system_;
  Vector dx_;
  Timings timings_;
  std::vector<double> element_matrix_;  ///< element part of the assembled matrix values
  long element_matrix_pattern_ = -1;    ///< pattern_version_ it was assembled on
  bool element_matrix_valid_ = false;
  Vector element_force_;  ///< f of the element residual f - K u (affine: K constant)
  bool element_force_valid_ = false;
  Vector values_;  ///< DoF values by equation id (scratch)
  int element_matrix_reuses_ = 0;
};

}  // namespace mc
