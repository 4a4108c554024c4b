// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <optional>
#include <string>

#include "core/parameters/parameters.h"
#include "core/solving/convergence_criteria.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"

namespace mc {

/// The engine of the displacement / residual / mixed contact criteria: the free DoFs are split
/// into families (displacement, rotation, Lagrange multiplier, see FamilyOf) and each family
/// that is configured and present is measured on its own, by increment or by residual:
///
///   increment:  ratio = |dx| / |x|        absolute = |dx| / n
///   residual:   ratio = |r|^2 / |r_0|^2   absolute = |r|^2 / n
/// (x after the update, |x| taken as 1 when it is 0; r_0 the residual at the first check of the
/// step; n the number of free DoFs of the family). Residuals are squared as in Kratos, whose
/// tolerance values the input files carry.
///
/// A family converges when ratio <= relative tolerance or absolute <= absolute tolerance; the
/// criterion converges when every family does. A multiplier family whose values are all zero
/// (no node in contact) counts as converged, or is an error with `ensure_contact`.
class BlockContactCriteria : public ConvergenceCriteria {
 public:
  enum class Measure { kIncrement, kResidual };
  struct Block {
    Measure measure = Measure::kIncrement;
    double relative_tolerance = 1e-4;
    double absolute_tolerance = 1e-9;
  };
  /// Which families are measured, and how (indexed by DofFamily).
  using Blocks = std::array<std::optional<Block>, kDofFamilies>;
  /// The measure of one family at the last check.
  struct BlockResult {
    bool present = false;  ///< configured and with free DoFs in the current DoF set
    double ratio = 0.0;
    double absolute = 0.0;
    bool converged = true;
  };

  BlockContactCriteria(const Blocks& blocks, bool ensure_contact, bool print_convergence_criterion);

  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                              const Vector& dx, const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  /// Ratio and absolute value of each present family, in the order displacement, rotation,
  /// multiplier: the columns of the convergence table.
  std::vector<CriterionValue> LastValues() const override;

  const BlockResult& Result(DofFamily family) const noexcept { return results_[static_cast<std::size_t>(family)]; }
  const std::optional<Block>& Configuration(DofFamily family) const noexcept {
    return blocks_[static_cast<std::size_t>(family)];
  }
  bool EnsureContact() const noexcept { return ensure_contact_; }
  bool PrintConvergenceCriterion() const noexcept { return print_; }

 protected:
  /// Tolerance keys of one family in the settings of a named criterion.
  struct BlockKeys {
    Measure measure;
    const char* relative;
    const char* absolute;
  };
  /// Validates `settings` against `defaults` (unknown keys rejected with the nearest valid
  /// one) and reads the families' tolerances.
  static Blocks ReadBlocks(Parameters& settings, const std::string& defaults_json,
                           const std::array<std::optional<BlockKeys>, kDofFamilies>& keys);

 private:
  Blocks blocks_;
  bool ensure_contact_;
  bool print_;
  std::array<BlockResult, kDofFamilies> results_{};
  std::array<double, kDofFamilies> initial_residual_{};
  bool initial_residual_set_ = false;
};

}  // namespace mc
