// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

using Measure = BlockContactCriteria::Measure;

/// How one family is measured by a criterion, and the prefix of its tolerance keys
/// (`<prefix>_relative_tolerance`, `<prefix>_absolute_tolerance`).
struct BlockKeys {
  Measure measure;
  const char* prefix;
  double relative_default = 1e-4;
  double absolute_default = 1e-9;
};

/// One criterion: Kratos' name and its blocks, indexed by DofFamily (none: not measured).
struct CriterionRow {
  const char* name;
  std::array<std::optional<BlockKeys>, kDofFamilies> blocks;
};

constexpr BlockKeys kDisplacementIncrement{Measure::kIncrement, "displacement"};
constexpr BlockKeys kDisplacementResidual{Measure::kResidual, "residual"};
constexpr BlockKeys kRotationIncrement{Measure::kIncrement, "rotation"};
constexpr BlockKeys kRotationResidual{Measure::kResidual, "rotation_residual"};
constexpr BlockKeys kMultiplierIncrement{Measure::kIncrement, "contact_displacement"};
constexpr BlockKeys kMultiplierResidual{Measure::kResidual, "contact_residual"};

/// The table, indexed by BlockCriterion.
constexpr std::array<CriterionRow, 5> kCriteria = {{
    {"displacement_contact_criteria", {kDisplacementIncrement, kRotationIncrement, std::nullopt}},
    {"displacement_residual_contact_criteria", {kDisplacementResidual, kRotationResidual, std::nullopt}},
    {"displacement_lagrangemultiplier_contact_criteria",
     {kDisplacementIncrement, kRotationIncrement, kMultiplierIncrement}},
    {"displacement_lagrangemultiplier_residual_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierResidual}},
    {"displacement_lagrange_multiplier_mixed_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierIncrement}},
}};

const CriterionRow& RowOf(BlockCriterion criterion) { return kCriteria[static_cast<std::size_t>(criterion)]; }

std::string RelativeKey(const BlockKeys& keys) { return Concat(keys.prefix, "_relative_tolerance"); }
std::string AbsoluteKey(const BlockKeys& keys) { return Concat(keys.prefix, "_absolute_tolerance"); }

/// The tolerances of `criterion`: the displacement family's from `displacement_source`, the
/// others from `other_source`.
BlockContactCriteria::Blocks ReadBlocks(BlockCriterion criterion, const Parameters& displacement_source,
                                        const Parameters& other_source) {
  const CriterionRow& row = RowOf(criterion);
  BlockContactCriteria::Blocks blocks;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!row.blocks[f]) continue;
    const BlockKeys& keys = *row.blocks[f];
    const Parameters& source =
        f == static_cast<std::size_t>(DofFamily::kDisplacement) ? displacement_source : other_source;
    const std::string relative = RelativeKey(keys);
    const std::string absolute = AbsoluteKey(keys);
    BlockContactCriteria::Block block{keys.measure, source[relative].GetDouble(), source[absolute].GetDouble()};
    if (!(block.relative_tolerance >= 0.0) || !(block.absolute_tolerance >= 0.0))
      throw InputError(Concat(source.Where(), ": ", relative, " = ", block.relative_tolerance, " and ", absolute, " = ",
                              block.absolute_tolerance, " must not be negative"));
    blocks[f] = block;
  }
  return blocks;
}

/// `settings`, validated in place against the defaults of `criterion`.
const Parameters& Validated(BlockCriterion criterion, Parameters& settings) {
  settings.ValidateAndAssignDefaults(BlockContactCriteria::GetDefaultParameters(criterion));
  return settings;
}

constexpr double kTiny = std::numeric_limits<double>::epsilon();
// Relative size of an increment that no longer changes the unknowns (a few hundred ulps).
constexpr double kRoundOffIncrement = 256.0 * std::numeric_limits<double>::epsilon();

// The symbol of the unknown of each family, in the column names ("|du|/|u|", "|r_lm|^2/n").
constexpr std::array<const char*, kDofFamilies> kSymbol = {"u", "w", "lm"};

}  // namespace

Parameters BlockContactCriteria::GetDefaultParameters(BlockCriterion criterion) {
  const CriterionRow& row = RowOf(criterion);
  Parameters defaults;
  defaults.AddString("name", row.name);
  defaults.AddBool("ensure_contact", false);
  defaults.AddBool("print_convergence_criterion", false);
  for (const auto& keys : row.blocks) {
    if (!keys) continue;
    defaults.AddDouble(RelativeKey(*keys), keys->relative_default);
    defaults.AddDouble(AbsoluteKey(*keys), keys->absolute_default);
  }
  return defaults;
}

Parameters BlockContactCriteria::GetContactSettingsDefaults() {
  // The rows' keys but the displacement tolerances (solver_settings keys) and
  // print_convergence_criterion (declared in contact_settings by the active-set criteria).
  Parameters defaults;
  defaults.AddValue("ensure_contact", GetDefaultParameters(BlockCriterion::kDisplacement)["ensure_contact"]);
  for (const CriterionRow& row : kCriteria)
    for (std::size_t f = 0; f < kDofFamilies; ++f) {
      if (!row.blocks[f] || f == static_cast<std::size_t>(DofFamily::kDisplacement)) continue;
      const BlockKeys& keys = *row.blocks[f];
      if (defaults.Has(RelativeKey(keys))) continue;
      defaults.AddDouble(RelativeKey(keys), keys.relative_default);
      defaults.AddDouble(AbsoluteKey(keys), keys.absolute_default);
    }
  return defaults;
}

BlockContactCriteria::BlockContactCriteria(BlockCriterion criterion, Parameters settings)
    : BlockContactCriteria(criterion, Validated(criterion, settings), settings) {}

BlockContactCriteria::BlockContactCriteria(BlockCriterion criterion, const Parameters& solver_settings,
                                           const Parameters& contact_settings)
    : criterion_(criterion),
      blocks_(ReadBlocks(criterion, solver_settings, contact_settings)),
      ensure_contact_(contact_settings["ensure_contact"].GetBool()),
      print_(contact_settings["print_convergence_criterion"].GetBool()) {
  assert(blocks_[static_cast<std::size_t>(DofFamily::kDisplacement)].has_value());
  for (std::size_t f = 0; f < kDofFamilies; ++f)
    if (blocks_[f] && blocks_[f]->measure == Measure::kResidual) SetActualizeRHSFlag(true);
}

std::string BlockContactCriteria::Name() const { return RowOf(criterion_).name; }

void BlockContactCriteria::InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                  const Vector& dx, const Vector& b) {
  initial_residual_set_ = false;
  std::array<bool, kDofFamilies> has{};
  for (const Dof* dof : dofs)
    if (!dof->fixed) has[static_cast<std::size_t>(FamilyOf(*dof->variable))] = true;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    results_[f] = BlockResult{};
    // Displacements and multipliers always have their columns; rotations only when solved for.
    const bool shown = f != static_cast<std::size_t>(DofFamily::kRotation) || has[f];
    results_[f].present = blocks_[f].has_value() && shown;
  }
}

bool BlockContactCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                        const Vector& dx, const Vector& b) {
  const FamilySumsArray sums = SumByFamily(dofs, dx, b);
  const ProcessInfo& info = model_part.GetProcessInfo();
  bool converged = true;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!blocks_[f]) continue;
    const Block& block = *blocks_[f];
    const FamilySums& s = sums[f];
    BlockResult& r = results_[f];
    r.present = r.present || s.count > 0;
    if (!r.present) continue;
    const bool multiplier = f == static_cast<std::size_t>(DofFamily::kMultiplier);
    const double value_norm = std::sqrt(s.value);
    if (multiplier && value_norm < kTiny) {
      if (ensure_contact_)
        throw SolutionError(Concat(Name(),
                                   ": ensure_contact is true but every Lagrange multiplier is zero at "
                                   "iteration ",
                                   info.GetValue(NL_ITERATION_NUMBER), " of step ", info.GetValue(STEP), " (time ",
                                   info.GetValue(TIME),
                                   "): no slave node is in contact. Check the contact pairs (search radius, "
                                   "active_check_factor) or set ensure_contact to false"));
      // No contact: nothing to converge in this family.
      r.ratio = 0.0;
      r.absolute = s.count > 0 ? (block.measure == Measure::kIncrement ? std::sqrt(s.increment) : s.residual) /
                                     static_cast<double>(s.count)
                               : 0.0;
      r.converged = true;
      continue;
    }
    double norm;
    double reference;
    if (block.measure == Measure::kIncrement) {
      norm = std::sqrt(s.increment);
      reference = value_norm;
    } else {
      // The residual tolerances of the contact criteria are defined on squared norms (Kratos
      // compares sum r^2 / sum r0^2 and sum r^2 / n): a Kratos file's residual tolerances keep
      // their meaning, and its cases stop at the same iteration.
      norm = s.residual;
      if (!initial_residual_set_) initial_residual_[f] = norm;
      reference = initial_residual_[f];
    }
    r.ratio = norm / (reference < kTiny ? 1.0 : reference);
    r.absolute = s.count > 0 ? norm / static_cast<double>(s.count) : 0.0;
    r.converged = r.ratio <= block.relative_tolerance || r.absolute <= block.absolute_tolerance;
    // A residual can only be reduced to the round-off of the terms that form it (k times the
    // weighted gap is ~1e9 x 1e-16 for stiff contact). When the Newton increment of this block no
    // longer changes its unknowns, the state already solved the equations: accept it. Kratos has
    // no such rule and then loops to max_iteration when a step starts at equilibrium.
    if (block.measure == Measure::kResidual && !r.converged)
      r.converged = std::sqrt(s.increment) <= kRoundOffIncrement * value_norm;
    converged = converged && r.converged;
  }
  initial_residual_set_ = true;
  if (echo_level_ >= 1 && print_)
    Logger::Info(Concat(Name(), FormatLine(info.GetValue(NL_ITERATION_NUMBER), LastValues(), converged)));
  return converged;
}

std::vector<CriterionValue> BlockContactCriteria::LastValues() const {
  std::vector<CriterionValue> values;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!blocks_[f] || !results_[f].present) continue;
    const Block& block = *blocks_[f];
    const char* x = kSymbol[f];
    const bool increment = block.measure == Measure::kIncrement;
    values.push_back({increment ? Concat("|d", x, "|/|", x, "|") : Concat("|r_", x, "|^2/|r_", x, "0|^2"),
                      results_[f].ratio, block.relative_tolerance});
    values.push_back({increment ? Concat("|d", x, "|/n") : Concat("|r_", x, "|^2/n"), results_[f].absolute,
                      block.absolute_tolerance});
  }
  return values;
}

}  // namespace mc
