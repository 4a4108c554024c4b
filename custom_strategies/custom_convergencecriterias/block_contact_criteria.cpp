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

constexpr double kTiny = std::numeric_limits<double>::epsilon();
// Relative size of an increment that no longer changes the unknowns (a few hundred ulps).
constexpr double kRoundOffIncrement = 256.0 * std::numeric_limits<double>::epsilon();

// Column names: the symbol of the unknown of each family, and of its residual.
constexpr std::array<const char*, kDofFamilies> kIncrementRatio = {"|du|/|u|", "|dw|/|w|", "|dlm|/|lm|"};
constexpr std::array<const char*, kDofFamilies> kIncrementAbsolute = {"|du|/n", "|dw|/n", "|dlm|/n"};
constexpr std::array<const char*, kDofFamilies> kResidualRatio = {"|r_u|^2/|r_u0|^2", "|r_w|^2/|r_w0|^2",
                                                                   "|r_lm|^2/|r_lm0|^2"};
constexpr std::array<const char*, kDofFamilies> kResidualAbsolute = {"|r_u|^2/n", "|r_w|^2/n", "|r_lm|^2/n"};

}  // namespace

BlockContactCriteria::BlockContactCriteria(const Blocks& blocks, bool ensure_contact, bool print_convergence_criterion)
    : blocks_(blocks), ensure_contact_(ensure_contact), print_(print_convergence_criterion) {
  assert(blocks_[static_cast<std::size_t>(DofFamily::kDisplacement)].has_value());
  for (std::size_t f = 0; f < kDofFamilies; ++f)
    if (blocks_[f] && blocks_[f]->measure == Measure::kResidual) SetActualizeRHSFlag(true);
}

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
        throw SolutionError(Concat(Name(), ": ensure_contact is true but every Lagrange multiplier is zero at "
                                   "iteration ",
                                   info.GetValue(NL_ITERATION_NUMBER), " of step ", info.GetValue(STEP),
                                   " (time ", info.GetValue(TIME),
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
    const bool increment = block.measure == Measure::kIncrement;
    values.push_back({increment ? kIncrementRatio[f] : kResidualRatio[f], results_[f].ratio, block.relative_tolerance});
    values.push_back(
        {increment ? kIncrementAbsolute[f] : kResidualAbsolute[f], results_[f].absolute, block.absolute_tolerance});
  }
  return values;
}

BlockContactCriteria::Blocks BlockContactCriteria::ReadBlocks(
    Parameters& settings, const std::string& defaults_json, const std::array<std::optional<BlockKeys>, kDofFamilies>& keys) {
  settings.ValidateAndAssignDefaults(Parameters(defaults_json));
  Blocks blocks;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!keys[f]) continue;
    Block block{keys[f]->measure, settings[keys[f]->relative].GetDouble(), settings[keys[f]->absolute].GetDouble()};
    if (!(block.relative_tolerance >= 0.0) || !(block.absolute_tolerance >= 0.0))
      throw InputError(Concat(settings.Where(), ": ", keys[f]->relative, " = ", block.relative_tolerance, " and ",
                              keys[f]->absolute, " = ", block.absolute_tolerance, " must not be negative"));
    blocks[f] = block;
  }
  return blocks;
}

}  // namespace mc
