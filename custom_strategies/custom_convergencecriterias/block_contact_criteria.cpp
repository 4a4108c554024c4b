// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

using Measure = BlockContactCriteria::Measure;

/// How one family is measured by a criterion and its tolerance keys: `relative` and `absolute`
/// in the criterion's own settings; read from contact_settings the absolute one is
/// `contact_absolute` (only Kratos' mixed frictional criterion names them differently).
struct BlockKeys {
  Measure measure;
  const char* relative;
  const char* absolute;
  const char* contact_absolute = nullptr;
  double relative_default = 1e-4;
  double absolute_default = 1e-9;
  const char* ContactAbsolute() const { return contact_absolute ? contact_absolute : absolute; }
};

/// One criterion: Kratos' name and its blocks, indexed by DofFamily (none: not measured).
/// Frictional rows split the vector multipliers into normal / stick / slip blocks.
struct CriterionRow {
  const char* name;
  std::array<std::optional<BlockKeys>, kDofFamilies> blocks;
  bool frictional = false;
};

constexpr BlockKeys kDisplacementIncrement{Measure::kIncrement, "displacement_relative_tolerance",
                                           "displacement_absolute_tolerance"};
constexpr BlockKeys kDisplacementResidual{Measure::kResidual, "residual_relative_tolerance",
                                          "residual_absolute_tolerance"};
constexpr BlockKeys kRotationIncrement{Measure::kIncrement, "rotation_relative_tolerance",
                                       "rotation_absolute_tolerance"};
constexpr BlockKeys kRotationResidual{Measure::kResidual, "rotation_residual_relative_tolerance",
                                      "rotation_residual_absolute_tolerance"};
constexpr BlockKeys kMultiplierIncrement{Measure::kIncrement, "contact_displacement_relative_tolerance",
                                         "contact_displacement_absolute_tolerance"};
constexpr BlockKeys kMultiplierResidual{Measure::kResidual, "contact_residual_relative_tolerance",
                                        "contact_residual_absolute_tolerance"};
constexpr BlockKeys kStickIncrement{Measure::kIncrement, "frictional_stick_contact_displacement_relative_tolerance",
                                    "frictional_stick_contact_displacement_absolute_tolerance"};
constexpr BlockKeys kStickResidual{Measure::kResidual, "frictional_stick_contact_residual_relative_tolerance",
                                   "frictional_stick_contact_residual_absolute_tolerance"};
constexpr BlockKeys kSlipIncrement{Measure::kIncrement, "frictional_slip_contact_displacement_relative_tolerance",
                                   "frictional_slip_contact_displacement_absolute_tolerance"};
constexpr BlockKeys kSlipResidual{Measure::kResidual, "frictional_slip_contact_residual_relative_tolerance",
                                  "frictional_slip_contact_residual_absolute_tolerance"};
// Kratos' mixed frictional criterion: the absolute tolerance of a tangential increment block is
// its key "..._residual_relative_tolerance" (default 1e-9), fed from "..._residual_absolute_tolerance".
constexpr BlockKeys kStickIncrementMixed{
    Measure::kIncrement, "frictional_stick_contact_displacement_relative_tolerance",
    "frictional_stick_contact_residual_relative_tolerance", "frictional_stick_contact_residual_absolute_tolerance"};
constexpr BlockKeys kSlipIncrementMixed{Measure::kIncrement, "frictional_slip_contact_displacement_relative_tolerance",
                                        "frictional_slip_contact_residual_relative_tolerance",
                                        "frictional_slip_contact_residual_absolute_tolerance"};

/// The table, indexed by BlockCriterion.
constexpr std::array<CriterionRow, 8> kCriteria = {{
    {"displacement_contact_criteria", {kDisplacementIncrement, kRotationIncrement}},
    {"displacement_residual_contact_criteria", {kDisplacementResidual, kRotationResidual}},
    {"displacement_lagrangemultiplier_contact_criteria",
     {kDisplacementIncrement, kRotationIncrement, kMultiplierIncrement}},
    {"displacement_lagrangemultiplier_residual_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierResidual}},
    {"displacement_lagrange_multiplier_mixed_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierIncrement}},
    {"displacement_lagrangemultiplier_frictional_contact_criteria",
     {kDisplacementIncrement, kRotationIncrement, kMultiplierIncrement, kStickIncrement, kSlipIncrement},
     true},
    {"displacement_lagrangemultiplier_ressidual_frictional_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierResidual, kStickResidual, kSlipResidual},
     true},
    {"displacement_lagrangemultiplier_mixed_frictional_contact_criteria",
     {kDisplacementResidual, kRotationResidual, kMultiplierIncrement, kStickIncrementMixed, kSlipIncrementMixed},
     true},
}};

// The correct spelling of Kratos' "ressidual" frictional criterion, accepted by Create.
constexpr const char* kResidualFrictionalSpelledRight =
    "displacement_lagrangemultiplier_residual_frictional_contact_criteria";
constexpr double kRatioNormalTangentDefault = 1e-4;

const CriterionRow& RowOf(BlockCriterion criterion) { return kCriteria[static_cast<std::size_t>(criterion)]; }

bool IsTangential(std::size_t family) {
  return family == static_cast<std::size_t>(DofFamily::kStickMultiplier) ||
         family == static_cast<std::size_t>(DofFamily::kSlipMultiplier);
}

/// The tolerances of `criterion`: the displacement family's from `displacement_source`, the
/// others from `other_source` (`contact`: a contact_settings block, with its key names).
BlockContactCriteria::Blocks ReadBlocks(BlockCriterion criterion, const Parameters& displacement_source,
                                        const Parameters& other_source, bool contact) {
  const CriterionRow& row = RowOf(criterion);
  BlockContactCriteria::Blocks blocks;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!row.blocks[f]) continue;
    const BlockKeys& keys = *row.blocks[f];
    const bool displacement = f == static_cast<std::size_t>(DofFamily::kDisplacement);
    const Parameters& source = displacement ? displacement_source : other_source;
    const std::string relative = keys.relative;
    const std::string absolute = contact && !displacement ? keys.ContactAbsolute() : keys.absolute;
    BlockContactCriteria::Block block{keys.measure, source[relative].GetDouble(), source[absolute].GetDouble()};
    if (!(block.relative_tolerance >= 0.0) || !(block.absolute_tolerance >= 0.0))
      throw InputError(Concat(source.Where(), ": ", relative, " = ", block.relative_tolerance, " and ", absolute, " = ",
                              block.absolute_tolerance, " must not be negative"));
    blocks[f] = block;
  }
  return blocks;
}

/// Residual measures need the residual at the updated state.
bool MeasuresResidual(const BlockContactCriteria::Blocks& blocks) {
  return std::any_of(blocks.begin(), blocks.end(),
                     [](const auto& block) { return block && block->measure == Measure::kResidual; });
}

double ReadRatioNormalTangent(BlockCriterion criterion, const Parameters& settings) {
  if (!RowOf(criterion).frictional) return 0.0;
  const double ratio = settings["ratio_normal_tangent_threshold"].GetDouble();
  if (!(ratio >= 0.0))
    throw InputError(Concat(settings.Where(), ".ratio_normal_tangent_threshold: ", ratio, " must not be negative"));
  return ratio;
}

/// `settings`, validated in place against the defaults of `criterion`.
const Parameters& Validated(BlockCriterion criterion, Parameters& settings) {
  settings.ValidateAndAssignDefaults(BlockContactCriteria::GetDefaultParameters(criterion));
  return settings;
}

constexpr double kTiny = std::numeric_limits<double>::epsilon();
// Relative size of an increment that no longer changes the unknowns (a few hundred ulps).
constexpr double kRoundOffIncrement = 256.0 * std::numeric_limits<double>::epsilon();

// The symbol of the unknown of each family, in the column names ("|du|/|u|", "|r_lm|^2/n"); the
// frictional rows call the normal multiplier "lm_n".
constexpr std::array<const char*, kDofFamilies> kSymbol = {"u", "w", "lm", "lm_st", "lm_sl"};

}  // namespace

Parameters BlockContactCriteria::GetDefaultParameters(BlockCriterion criterion) {
  const CriterionRow& row = RowOf(criterion);
  Parameters defaults;
  defaults.AddString("name", row.name);
  defaults.AddBool("ensure_contact", false);
  defaults.AddBool("print_convergence_criterion", false);
  if (row.frictional) defaults.AddBool("pure_slip", false);
  for (const auto& keys : row.blocks) {
    if (!keys) continue;
    defaults.AddDouble(keys->relative, keys->relative_default);
    defaults.AddDouble(keys->absolute, keys->absolute_default);
  }
  if (row.frictional) defaults.AddDouble("ratio_normal_tangent_threshold", kRatioNormalTangentDefault);
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
      if (!defaults.Has(keys.relative)) defaults.AddDouble(keys.relative, keys.relative_default);
      if (!defaults.Has(keys.ContactAbsolute())) defaults.AddDouble(keys.ContactAbsolute(), keys.absolute_default);
    }
  defaults.AddDouble("ratio_normal_tangent_threshold", kRatioNormalTangentDefault);
  return defaults;
}

std::shared_ptr<BlockContactCriteria> BlockContactCriteria::Create(Parameters settings) {
  std::vector<std::string> names;
  for (const CriterionRow& row : kCriteria) names.emplace_back(row.name);
  names.emplace_back(kResidualFrictionalSpelledRight);
  if (!settings.Has("name"))
    throw InputError(Concat(settings.Where(), ": \"name\" is missing: it selects the block contact criterion"));
  std::string name = settings["name"].GetString();
  if (name == kResidualFrictionalSpelledRight) {
    name = RowOf(BlockCriterion::kDisplacementLagrangeMultiplierResidualFrictional).name;
    settings["name"].SetString(name);
  }
  for (std::size_t i = 0; i < kCriteria.size(); ++i)
    if (name == kCriteria[i].name)
      return std::make_shared<BlockContactCriteria>(static_cast<BlockCriterion>(i), std::move(settings));
  throw InputError(
      Concat(settings["name"].Where(), ": unknown block contact criterion \"", name, "\"", DidYouMean(name, names)));
}

BlockContactCriteria::BlockContactCriteria(BlockCriterion criterion, Parameters settings)
    : criterion_(criterion),
      blocks_(ReadBlocks(criterion, Validated(criterion, settings), settings, false)),
      ensure_contact_(settings["ensure_contact"].GetBool()),
      print_(settings["print_convergence_criterion"].GetBool()),
      pure_slip_(RowOf(criterion).frictional && settings["pure_slip"].GetBool()),
      ratio_normal_tangent_threshold_(ReadRatioNormalTangent(criterion, settings)) {
  if (MeasuresResidual(blocks_)) SetActualizeRHSFlag(true);
}

BlockContactCriteria::BlockContactCriteria(BlockCriterion criterion, const Parameters& solver_settings,
                                           const Parameters& contact_settings, bool pure_slip)
    : criterion_(criterion),
      blocks_(ReadBlocks(criterion, solver_settings, contact_settings, true)),
      ensure_contact_(contact_settings["ensure_contact"].GetBool()),
      print_(contact_settings["print_convergence_criterion"].GetBool()),
      pure_slip_(RowOf(criterion).frictional && pure_slip),
      ratio_normal_tangent_threshold_(ReadRatioNormalTangent(criterion, contact_settings)) {
  if (MeasuresResidual(blocks_)) SetActualizeRHSFlag(true);
}

std::string BlockContactCriteria::Name() const { return RowOf(criterion_).name; }

void BlockContactCriteria::InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                  const Vector& dx, const Vector& b) {
  initial_residual_known_.fill(false);
  std::array<bool, kDofFamilies> has{};
  std::array<double, kDofFamilies> counts{};
  for (const Dof* dof : dofs)
    if (!dof->fixed) counts[static_cast<std::size_t>(FamilyOf(*dof->variable))] = 1.0;
  SumOverRanks(counts.data(), counts.size());
  for (std::size_t f = 0; f < kDofFamilies; ++f) has[f] = counts[f] > 0.0;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    results_[f] = BlockResult{};
    // Displacements and multipliers always have their columns; rotations only when solved for;
    // the stick block not in pure slip, where every node slips.
    const bool shown = f == static_cast<std::size_t>(DofFamily::kRotation)          ? has[f]
                       : f == static_cast<std::size_t>(DofFamily::kStickMultiplier) ? !pure_slip_
                                                                                    : true;
    results_[f].present = blocks_[f].has_value() && shown;
  }
}

bool BlockContactCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                        const Vector& dx, const Vector& b) {
  const bool frictional = RowOf(criterion_).frictional;
  const MultiplierSplit split = !frictional  ? MultiplierSplit::kNone
                                : pure_slip_ ? MultiplierSplit::kFrictionalPureSlip
                                             : MultiplierSplit::kFrictional;
  FamilySumsArray sums = SumByFamily(dofs, dx, b, split);
  std::array<double, 4 * kDofFamilies> flat{};  // each rank's sums of a cut model, summed over the ranks
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    flat[4 * f] = sums[f].increment;
    flat[4 * f + 1] = sums[f].value;
    flat[4 * f + 2] = sums[f].residual;
    flat[4 * f + 3] = static_cast<double>(sums[f].count);
  }
  SumOverRanks(flat.data(), flat.size());
  for (std::size_t f = 0; f < kDofFamilies; ++f)
    sums[f] = {flat[4 * f], flat[4 * f + 1], flat[4 * f + 2], static_cast<long>(flat[4 * f + 3])};
  // Tangential absolute values are per multiplier DoF, as the normal one (Kratos' choice), so the
  // two compare in the ratio test.
  const auto multiplier_count = static_cast<double>(sums[static_cast<std::size_t>(DofFamily::kMultiplier)].count);
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
    const bool tangential = IsTangential(f);
    const double value_norm = std::sqrt(s.value);
    if (tangential && value_norm < kTiny) {
      // No node in this state, or no tangential traction: nothing to converge.
      r.ratio = 0.0;
      r.absolute = 0.0;
      r.converged = true;
      continue;
    }
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
      // The first check of the step is the reference; a tangential block's is its first check
      // with nodes in its state (the stick and slip sets change within a step).
      if (!initial_residual_known_[f]) {
        initial_residual_[f] = norm;
        initial_residual_known_[f] = true;
      }
      reference = initial_residual_[f];
    }
    r.ratio = norm / (reference < kTiny ? 1.0 : reference);
    const double count = tangential ? multiplier_count : static_cast<double>(s.count);
    r.absolute = count > 0 ? norm / count : 0.0;
    r.converged = r.ratio <= block.relative_tolerance || r.absolute <= block.absolute_tolerance;
    // A tangential block far below the normal one is accepted (ratio_normal_tangent_threshold).
    const BlockResult& normal = results_[static_cast<std::size_t>(DofFamily::kMultiplier)];
    if (tangential && !r.converged && normal.absolute > 0.0)
      r.converged = r.absolute <= ratio_normal_tangent_threshold_ * normal.absolute;
    // A residual can only be reduced to the round-off of the terms that form it (k times the
    // weighted gap is ~1e9 x 1e-16 for stiff contact). When the Newton increment of this block no
    // longer changes its unknowns, the state already solved the equations: accept it. Kratos has
    // no such rule and then loops to max_iteration when a step starts at equilibrium.
    if (block.measure == Measure::kResidual && !r.converged)
      r.converged = std::sqrt(s.increment) <= kRoundOffIncrement * value_norm;
    converged = converged && r.converged;
  }
  // Displacement, rotation and normal blocks keep the first check's reference even if they had
  // nothing to measure then (no contact yet: the reference is 1).
  for (std::size_t f = 0; f < kDofFamilies; ++f)
    if (!IsTangential(f)) initial_residual_known_[f] = true;
  if (echo_level_ >= 1 && print_)
    Logger::Info(Concat(Name(), FormatLine(info.GetValue(NL_ITERATION_NUMBER), LastValues(), converged)));
  return converged;
}

std::vector<CriterionValue> BlockContactCriteria::LastValues() const {
  std::vector<CriterionValue> values;
  for (std::size_t f = 0; f < kDofFamilies; ++f) {
    if (!blocks_[f] || !results_[f].present) continue;
    const Block& block = *blocks_[f];
    const char* x =
        f == static_cast<std::size_t>(DofFamily::kMultiplier) && RowOf(criterion_).frictional ? "lm_n" : kSymbol[f];
    const bool increment = block.measure == Measure::kIncrement;
    values.push_back({increment ? Concat("|d", x, "|/|", x, "|") : Concat("|r_", x, "|^2/|r_", x, "0|^2"),
                      results_[f].ratio, block.relative_tolerance});
    values.push_back({increment ? Concat("|d", x, "|/n") : Concat("|r_", x, "|^2/n"), results_[f].absolute,
                      block.absolute_tolerance});
  }
  return values;
}

}  // namespace mc
