// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/parameters/parameters.h"
#include "core/solving/convergence_criteria.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"

namespace mc {

/// The block criteria of Kratos' contact application. Each is a row of the table in
/// block_contact_criteria.cpp: its Kratos name and, per DoF family, the measure and its tolerance
/// keys. Kratos' names and key prefixes (`<prefix>_relative_tolerance`, `_absolute_tolerance`):
///
///   criterion                                              displacement  rotation           multiplier (normal)
///   displacement_contact_criteria                          displacement  rotation           -
///   displacement_residual_contact_criteria                 residual      rotation_residual  -
///   displacement_lagrangemultiplier_contact_criteria       displacement  rotation           contact_displacement
///   displacement_lagrangemultiplier_residual_contact_criteria
///                                                          residual      rotation_residual  contact_residual
///   displacement_lagrange_multiplier_mixed_contact_criteria
///                                                          residual      rotation_residual  contact_displacement
///
/// and the frictional rows, whose vector multipliers are split into normal, stick-tangent and
/// slip-tangent blocks (SumByFamily):
///
///   displacement_lagrangemultiplier_frictional_contact_criteria: increments, the tangential
///     blocks frictional_{stick,slip}_contact_displacement
///   displacement_lagrangemultiplier_ressidual_frictional_contact_criteria (Kratos' spelling; the
///     correct "residual" is accepted by Create): residuals, frictional_{stick,slip}_contact_residual
///   displacement_lagrangemultiplier_mixed_frictional_contact_criteria: displacement residual,
///     multiplier increments. As in Kratos, its own settings name the absolute tolerance of a
///     tangential block frictional_{stick,slip}_contact_residual_relative_tolerance (default
///     1e-9); read from contact_settings it is frictional_{stick,slip}_contact_residual_absolute_tolerance.
///
/// (`displacement`, `contact_displacement`: increments; `residual`, `contact_residual`:
/// residuals). The mixed criterion is usually the most robust for ALM: the multiplier residual
/// (the weak gap) is a poor indicator while the active set still changes.
enum class BlockCriterion {
  kDisplacement,
  kDisplacementResidual,
  kDisplacementLagrangeMultiplier,
  kDisplacementLagrangeMultiplierResidual,
  kDisplacementLagrangeMultiplierMixed,
  kDisplacementLagrangeMultiplierFrictional,
  kDisplacementLagrangeMultiplierResidualFrictional,
  kDisplacementLagrangeMultiplierMixedFrictional,
};

/// The engine of the block criteria: the free DoFs are split into families (displacement,
/// rotation, Lagrange multiplier, see FamilyOf) and each family that the criterion's row names
/// and that is present is measured on its own, by increment or by residual:
///
///   increment:  ratio = |dx| / |x|        absolute = |dx| / n
///   residual:   ratio = |r|^2 / |r_0|^2   absolute = |r|^2 / n
/// (x after the update, |x| taken as 1 when it is 0; r_0 the residual at the first check of the
/// step; n the number of free DoFs of the family). Residuals are squared as in Kratos, whose
/// tolerance values the input files carry.
///
/// A family converges when ratio <= relative tolerance or absolute <= absolute tolerance; the
/// criterion converges when every family does. A multiplier family whose values are all zero
/// (no node in contact) counts as converged, or is an error with `ensure_contact`. In the
/// frictional rows a tangential block that misses its tolerances is still accepted when its
/// absolute value is at most `ratio_normal_tangent_threshold` times the normal block's: the
/// tangential multipliers are orders smaller than the normal ones and would stall the iterations.
/// A tangential block without values (no node sticks, or none slips) is converged.
///
/// Settings (Kratos' names and defaults): `ensure_contact` (false), `print_convergence_criterion`
/// (false), per family of the row its relative (1e-4) and absolute (1e-9) tolerance, and in the
/// frictional rows `pure_slip` (false: own settings only; for a contact solver it comes from
/// the mortar criterion of the formulation) and `ratio_normal_tangent_threshold` (1e-4).
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

  /// Validates `settings` against the defaults of `criterion` (unknown keys rejected with the
  /// nearest valid one) and reads its tolerances.
  BlockContactCriteria(BlockCriterion criterion, Parameters settings);
  /// The criterion of a contact solver: the displacement tolerances are the mechanical solver's
  /// keys of `solver_settings`, the other keys are read from `contact_settings` (both already
  /// validated by their owners; see GetContactSettingsDefaults). `pure_slip`: frictional rows.
  BlockContactCriteria(BlockCriterion criterion, const Parameters& solver_settings, const Parameters& contact_settings,
                       bool pure_slip = false);
  /// Kratos' defaults of `criterion`, keys in Kratos' order.
  static Parameters GetDefaultParameters(BlockCriterion criterion);
  /// The keys of `contact_settings` that the block criteria read, over every row: `ensure_contact`,
  /// the rotation and multiplier tolerances and `ratio_normal_tangent_threshold` (their one
  /// declaration).
  static Parameters GetContactSettingsDefaults();
  /// The criterion named by `settings["name"]` (Kratos' names; for the residual frictional one
  /// both spellings), built from `settings` as the first constructor does. An unknown name is an
  /// InputError naming the nearest ones.
  static std::shared_ptr<BlockContactCriteria> Create(Parameters settings);

  std::string Name() const override;
  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                              const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  /// Ratio and absolute value of each present family, in the order displacement, rotation,
  /// multiplier (normal), stick, slip: the columns of the convergence table.
  std::vector<CriterionValue> LastValues() const override;

  const BlockResult& Result(DofFamily family) const noexcept { return results_[static_cast<std::size_t>(family)]; }
  const std::optional<Block>& Configuration(DofFamily family) const noexcept {
    return blocks_[static_cast<std::size_t>(family)];
  }
  bool EnsureContact() const noexcept { return ensure_contact_; }
  bool PrintConvergenceCriterion() const noexcept { return print_; }
  /// Frictional rows: the tangential multipliers are all counted as slip.
  bool PureSlip() const noexcept { return pure_slip_; }
  /// Frictional rows: the accepted ratio of a tangential block to the normal one (0 otherwise).
  double RatioNormalTangentThreshold() const noexcept { return ratio_normal_tangent_threshold_; }

 private:
  BlockCriterion criterion_;
  Blocks blocks_;
  bool ensure_contact_;
  bool print_;
  bool pure_slip_;
  double ratio_normal_tangent_threshold_;
  std::array<BlockResult, kDofFamilies> results_{};
  std::array<double, kDofFamilies> initial_residual_{};
  std::array<bool, kDofFamilies> initial_residual_known_{};
};

/// One row of the table as a type of its own, so that each criterion keeps its Kratos class name
/// (in Python too) and a constructor taking only the settings.
template <BlockCriterion kCriterion>
class NamedBlockContactCriteria final : public BlockContactCriteria {
 public:
  explicit NamedBlockContactCriteria(Parameters settings = Parameters())
      : BlockContactCriteria(kCriterion, std::move(settings)) {}
  NamedBlockContactCriteria(const Parameters& solver_settings, const Parameters& contact_settings,
                            bool pure_slip = false)
      : BlockContactCriteria(kCriterion, solver_settings, contact_settings, pure_slip) {}
  static Parameters GetDefaultParameters() { return BlockContactCriteria::GetDefaultParameters(kCriterion); }
};

using DisplacementContactCriteria = NamedBlockContactCriteria<BlockCriterion::kDisplacement>;
using DisplacementResidualContactCriteria = NamedBlockContactCriteria<BlockCriterion::kDisplacementResidual>;
using DisplacementLagrangeMultiplierContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplier>;
using DisplacementLagrangeMultiplierResidualContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplierResidual>;
using DisplacementLagrangeMultiplierMixedContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplierMixed>;
using DisplacementLagrangeMultiplierFrictionalContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplierFrictional>;
using DisplacementLagrangeMultiplierResidualFrictionalContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplierResidualFrictional>;
using DisplacementLagrangeMultiplierMixedFrictionalContactCriteria =
    NamedBlockContactCriteria<BlockCriterion::kDisplacementLagrangeMultiplierMixedFrictional>;

}  // namespace mc
