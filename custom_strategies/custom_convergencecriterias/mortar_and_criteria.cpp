// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"

#include <cstdio>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"

namespace mc {

namespace {

constexpr int kColumnWidth = 14;

std::string Scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", value);
  return buffer;
}

std::string YesNo(bool converged, std::size_t changes) {
  if (converged) return "yes";
  return changes > 0 ? Concat("no (", changes, ")") : "no";
}

}  // namespace

MortarAndConvergenceCriteria::MortarAndConvergenceCriteria(std::shared_ptr<ConvergenceCriteria> mechanical,
                                                           std::shared_ptr<ConvergenceCriteria> mortar,
                                                           bool print_convergence_criterion,
                                                           std::optional<ConditionNumberUtility> condition_number,
                                                           bool print_table)
    : AndCriteria(mechanical, mortar),
      mechanical_(std::move(mechanical)),
      mortar_(std::move(mortar)),
      print_(print_convergence_criterion),
      condition_number_(condition_number),
      print_table_(print_table) {
  // The residual criteria and the active set need the state after the update.
  SetActualizeRHSFlag(true);
}

void MortarAndConvergenceCriteria::SetMortarUpdater(std::shared_ptr<MortarUpdater> updater) {
  if (auto* mortar = dynamic_cast<BaseMortarConvergenceCriteria*>(mortar_.get()))
    mortar->SetMortarUpdater(std::move(updater));
}

std::vector<std::string> MortarAndConvergenceCriteria::TableHeader() const {
  std::vector<std::string> header{"ITER"};
  if (condition_number_) header.emplace_back("COND.NUM.");
  for (const auto& v : mechanical_->LastValues()) header.push_back(v.name);
  header.emplace_back("CONVERGENCE");
  header.emplace_back("ACTIVE SET CONV");
  if (const auto* base_mortar = dynamic_cast<const BaseMortarConvergenceCriteria*>(mortar_.get());
      base_mortar && base_mortar->HasSlipSet())
    header.emplace_back("SLIP/STICK CONV");
  return header;
}

std::string MortarAndConvergenceCriteria::FormatRow(const std::vector<std::string>& cells) const {
  std::string line;
  for (const auto& cell : cells) {
    char buffer[64];
    // Two spaces between columns keep headers as wide as the column apart.
    std::snprintf(buffer, sizeof buffer, "  %*s", kColumnWidth, cell.c_str());
    line += buffer;
  }
  return line;
}

void MortarAndConvergenceCriteria::InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs,
                                                          const SparseMatrix& A, const Vector& dx, const Vector& b) {
  AndCriteria::InitializeSolutionStep(model_part, dofs, A, dx, b);
  last_row_.clear();
  if (echo_level_ < 1 || !print_table_) return;
  Logger::Info(FormatRow(TableHeader()));
  std::vector<std::string> tolerances{""};
  if (condition_number_) tolerances.emplace_back("");
  for (const auto& v : mechanical_->LastValues()) tolerances.push_back(Concat("< ", Scientific(v.tolerance)));
  Logger::Info(FormatRow(tolerances));
}

bool MortarAndConvergenceCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                const Vector& dx, const Vector& b) {
  mechanical_converged_ = mechanical_->PostCriteria(model_part, dofs, A, dx, b);
  active_set_converged_ = mortar_->PostCriteria(model_part, dofs, A, dx, b);
  const bool converged = mechanical_converged_ && active_set_converged_;
  if (condition_number_) condition_number_value_ = condition_number_->Estimate(A);

  const int iteration = model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER);
  const auto* base_mortar = dynamic_cast<const BaseMortarConvergenceCriteria*>(mortar_.get());
  const std::size_t changes = base_mortar ? base_mortar->LastChangeCount() : 0;
  last_row_ = {std::to_string(iteration)};
  if (condition_number_) last_row_.push_back(Scientific(condition_number_value_));
  for (const auto& v : mechanical_->LastValues()) last_row_.push_back(Scientific(v.value));
  last_row_.push_back(YesNo(mechanical_converged_, 0));
  const bool slip_set = base_mortar && base_mortar->HasSlipSet();
  const std::size_t slip_changes = slip_set ? base_mortar->LastSlipChangeCount() : 0;
  // Frictional: the active set alone (the mortar answer also needs the stick/slip set).
  const std::string active_set_cell = YesNo(base_mortar ? changes == 0 : active_set_converged_, changes);
  last_row_.push_back(active_set_cell);
  if (slip_set) last_row_.push_back(YesNo(slip_changes == 0, slip_changes));

  if (echo_level_ >= 1) {
    if (print_table_) {
      Logger::Info(FormatRow(last_row_));
      if (converged) Logger::Info(Concat("  converged at iteration ", iteration));
    } else {
      Logger::Info(Concat(FormatLine(iteration, LastValues(), mechanical_converged_), ", active set ", active_set_cell,
                          slip_set ? Concat(", stick/slip set ", YesNo(slip_changes == 0, slip_changes)) : ""));
    }
    if (print_ && base_mortar && !base_mortar->LastChangedNodes().empty()) {
      std::string ids;
      for (IndexType id : base_mortar->LastChangedNodes()) ids += Concat(ids.empty() ? "" : ", ", id);
      Logger::Detail(Concat("  slave nodes that changed state: ", ids));
    }
  }
  return converged;
}

std::vector<CriterionValue> MortarAndConvergenceCriteria::LastValues() const {
  auto values = AndCriteria::LastValues();
  if (condition_number_) values.push_back({"COND.NUM.", condition_number_value_, 0.0});
  return values;
}

}  // namespace mc
