// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// Static condensation of dual Lagrange multipliers (thesis eqs. 4.37-4.40) around an inner
/// solver, for the components formulations (VECTOR_LAGRANGE_MULTIPLIER).
///
/// The rows of the assembled system are split by their DoF (ProvideAdditionalData):
///   N other | M master | S_A, S_I active / inactive slave displacements |
///   LM_A, LM_I active / inactive multipliers (nodal ACTIVE flag).
/// Each S_A row s is paired with the LM_A unknown l of the same node and component. With dual
/// multipliers D is diagonal, so K_{S_A,LM_A} couples the slave rows of a node to the multipliers
/// of that node only: block diagonal with one small block B_j per node (d x d, d the number of
/// its pairs). B_j = k D_jj I for frictionless components and sticking nodes; for a slipping
/// node the Coulomb traction makes it full (its normal and the slip direction enter). The slave
/// rows of node j give
///   dlambda_j = B_j^-1 (b_S - sum_{c not in LM_A} K_Sc dx_c)                  (eq. 4.40b)
/// and eliminating dlambda_j from every other row leaves a square system in displacements whose
/// S_A rows are the former LM_A rows (eqs. 4.38-4.39: P for the master rows, C for the
/// multiplier rows). The LM_I rows are diagonal (k^2/eps I): dlambda_I is solved first and its
/// columns move to the right-hand side. The inner solver then solves
///   A' = A_RC - A_RL K_SL^-1 A_SC,   R = rows \ (S_A, LM_I),  C = columns \ (LM_A, LM_I).
///
/// Fixed DoFs (identity rows of the block builder, absent rows of the elimination builder) are
/// "other": a fixed multiplier leaves its slave row unpaired and vice versa; unpaired rows and
/// unknowns stay in the condensed system, which is exact for them too. With master-slave
/// constraints a master's row also holds its slaves' rows; where that couples a slave row to
/// another node's multipliers the block check below fails and the system is solved in full.
///
/// The result equals the monolithic solution. When K_{S_A,LM_A} is not block diagonal by node
/// (an entry at another node's multiplier |K_sl'| > kDiagonalTolerance * row max), a block is
/// singular, or an LM_I row is not diagonal, the full system is solved by the inner solver and
/// the reason is logged once.
///
/// Why K_{S_A,LM_A} can be off the block diagonal (issue 18): K_{S,LM} = dR_S/dlambda = k D^T
/// (times DYNAMIC_FACTOR), nothing else in the residual of a slave row depends on the multipliers,
/// and each pair's D is diagonal by construction of its dual basis (to round-off). The exception
/// is a sliver pair, whose overlap is too thin for a regular dual basis and which takes the
/// standard one (DualLagrangeMultiplier): its D = M couples the two or more nodes of its slave
/// face by about the sliver's area. The components patches (hyper-simple, slope, triangle) have
/// no sliver and condense at every solve; the dynamic Taylor patch (components) meets one and
/// solves that system in full (the entry was 1.3e-7 against its row's largest;
/// tests/python/test_contact_cases.py::test_mixed_ulm_condenses_the_components_patches). Dropping it would make the
/// condensed solution differ from the monolithic one; grouping the coupled nodes into one block would re-analyse the
/// condensed pattern whenever a sliver appears; a full solve, logged, is exact and rare.
///
/// Work per solve with an unchanged pattern and active set: one pass over precomputed index
/// lists (no search, no allocation); the inner solver is initialized again only when the
/// condensed pattern changes.
class MixedULMLinearSolver : public LinearSolver {
 public:
  enum class BlockType : std::uint8_t { kOther, kMaster, kSlaveInactive, kSlaveActive, kLmInactive, kLmActive };

  /// Relative size of an entry of K_{S_A,LM_A} off the node's block (or of an LM_I row off the
  /// diagonal), against the largest entry of its row, below which it counts as zero.
  static constexpr double kDiagonalTolerance = 1e-10;

  explicit MixedULMLinearSolver(std::unique_ptr<LinearSolver> inner);
  MixedULMLinearSolver(const MixedULMLinearSolver&) = delete;
  MixedULMLinearSolver& operator=(const MixedULMLinearSolver&) = delete;
  ~MixedULMLinearSolver() override;

  /// "mixed_ulm_linear_solver(<inner name>)".
  std::string Name() const override;
  bool IsDirect() const override { return inner_->IsDirect(); }
  /// Records the new pattern of A; the inner solver is initialized at the next Solve, for the
  /// condensed or the full system as needed.
  void Initialize(const SparseMatrix& A) override;
  /// Without a preceding ProvideAdditionalData for this pattern, solves the full system.
  /// SingularMatrixError of the inner solver names the row of A, not of the condensed system.
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return inner_->IterationsNumber(); }
  void SetForcingTerm(double eta) override { inner_->SetForcingTerm(eta); }
  double LastTolerance() const override { return inner_->LastTolerance(); }
  WorkCounters Counters() const override { return (*inner_).Counters(); }

  bool AdditionalPhysicalDataIsNeeded() const override { return true; }
  /// Classifies every row from its DoF (ACTIVE, SLAVE, MASTER flags of the node, fixity).
  void ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) override;

  const LinearSolver& Inner() const noexcept { return *inner_; }
  /// Block of each row of the last ProvideAdditionalData (fixed DoFs are kOther).
  const std::vector<BlockType>& BlockTypes() const noexcept { return types_; }
  /// Whether the last Solve went through the condensed system.
  bool LastSolveWasCondensed() const noexcept { return last_condensed_; }
  /// Why the last Solve solved the full system (empty when it was condensed).
  const std::string& FallbackReason() const noexcept { return fallback_reason_; }
  /// Size of the last condensed system and number of (S_A, LM_A) pairs eliminated.
  long CondensedSize() const noexcept { return static_cast<long>(cond_to_column_.size()); }
  long NumberOfPairs() const noexcept { return static_cast<long>(pair_slave_.size()); }
  /// Times the inner solver was initialized (for the condensed or the full system).
  int InnerInitializations() const noexcept { return inner_initializations_; }

 private:
  enum class InnerState { kNone, kFull, kCondensed };
  /// One term K_rl (B^-1)_ls K_sc of a condensed entry: positions in A's values and the index
  /// of (B^-1)_ls in inv_block_.
  struct Correction {
    int rl;
    int sc;
    int inverse;
  };

  void BuildStructure(const SparseMatrix& A);
  void BuildRowLists(const SparseMatrix& A);
  /// Empty when K_{S_A,LM_A} is block diagonal by node with invertible blocks (stored inverted
  /// in inv_block_) and the LM_I rows are diagonal; else the reason, naming the DoFs.
  std::string CheckDiagonalBlocks(const SparseMatrix& A);
  /// values (one per pair, grouped by node) := B^-1 values, block by block.
  void ApplyInverseBlocks(Vector& values) const;
  /// Solves A x = b with the inner solver; `warn` logs the reason (once per solver).
  void SolveFull(const SparseMatrix& A, Vector& x, const Vector& b, std::string reason, bool warn);
  void SolveCondensed(const SparseMatrix& A, Vector& x, const Vector& b);
  std::string DofName(int row) const;

  std::unique_ptr<LinearSolver> inner_;
  InnerState inner_state_ = InnerState::kNone;
  int inner_initializations_ = 0;

  // Classification (ProvideAdditionalData).
  std::vector<BlockType> types_;
  std::vector<BlockType> new_types_;
  std::vector<Dof*> dofs_;
  bool data_valid_ = false;       ///< types_ and dofs_ describe the rows of the current pattern
  bool structure_valid_ = false;  ///< the index lists below match types_ and the pattern of A

  // Structure (BuildStructure), rebuilt when the pattern or the classification changes.
  std::vector<int> pair_slave_;        ///< row s of each pair
  std::vector<int> pair_lm_;           ///< column l of each pair
  std::vector<int> pair_group_;        ///< node group of each pair
  std::vector<int> group_start_;       ///< first pair of each group (+ end)
  std::vector<int> inv_offset_;        ///< start of each group's m x m block in inv_block_ (+ end)
  std::vector<int> block_positions_;   ///< position of K(s_a, l_b) in A's values, -1 if absent
  std::vector<int> lm_inactive_;       ///< LM_I rows
  std::vector<int> lm_inactive_diag_;  ///< position of their diagonal (-1 if absent)
  std::vector<int> row_to_cond_;       ///< condensed row of each row of A, -1 if eliminated
  std::vector<int> column_to_cond_;    ///< condensed column of each column of A, -1 if eliminated
  std::vector<int> cond_to_column_;
  std::vector<int> eliminated_pair_;  ///< pair of each eliminated LM_A column, -1 otherwise
  /// Entries of the S_A and LM_I rows: (position in A's values, column), CSR-like.
  std::vector<int> tracked_row_;  ///< index into row_offsets_ of each row, -1 if untracked
  std::vector<int> row_offsets_;
  std::vector<int> row_positions_;
  std::vector<int> row_columns_;
  SparseMatrix condensed_;
  std::vector<int> cond_source_;   ///< position in A's values of each condensed entry, -1 if none
  std::vector<int> cond_offsets_;  ///< corrections of each condensed entry
  std::vector<Correction> corrections_;

  // Work vectors.
  Vector inv_block_;   ///< B^-1 of each group, row-major: (B^-1)(b, a) at inv_offset_ + b m + a
  Vector group_work_;  ///< one value per pair
  Vector b_work_;
  Vector b_condensed_;
  Vector x_condensed_;

  bool last_condensed_ = false;
  std::string fallback_reason_;
  bool warned_ = false;
};

}  // namespace mc
