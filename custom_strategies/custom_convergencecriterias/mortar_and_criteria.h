// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/solving/and_criteria.h"
#include "custom_strategies/custom_convergencecriterias/condition_number_utility.h"
#include "custom_utilities/mortar_updater.h"

namespace mc {

/// "mortar_and_criteria": the mechanical criterion (first) AND the mortar active-set criterion
/// (second), with the residual refreshed after each update, and the convergence table of the
/// contact solvers printed through mc::Logger (echo level >= 1):
///
///   ITER | COND.NUM. | <ratio and absolute of each block of the mechanical criterion> |
///   CONVERGENCE | ACTIVE SET CONV [| SLIP/STICK CONV]
///
/// The block columns are the names of the mechanical criterion's LastValues ("|du|/|u|", ...),
/// with a second header line giving their tolerances; CONVERGENCE is the mechanical answer and
/// ACTIVE SET CONV the mortar one ("no (3)": three nodes changed); SLIP/STICK CONV, for a
/// frictional mortar criterion, the nodes that switched between stick and slip. COND.NUM. (only with a
/// ConditionNumberUtility, `condn_convergence_criterion`) is the condition number of the
/// system matrix, a slow diagnostic. `print_convergence_criterion` also lists the slave nodes
/// whose state changed.
class MortarAndConvergenceCriteria : public AndCriteria {
 public:
  /// `print_table` is `fancy_convergence_criterion`; without it each criterion logs its own line.
  MortarAndConvergenceCriteria(std::shared_ptr<ConvergenceCriteria> mechanical,
                               std::shared_ptr<ConvergenceCriteria> mortar, bool print_convergence_criterion = false,
                               std::optional<ConditionNumberUtility> condition_number = std::nullopt,
                               bool print_table = true);

  std::string Name() const override { return "mortar_and_criteria"; }
  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                              const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  /// The mechanical values, then {"COND.NUM.", value, 0} when computed.
  std::vector<CriterionValue> LastValues() const override;

  /// Forwards the updater to the mortar criterion (when it is a BaseMortarConvergenceCriteria).
  void SetMortarUpdater(std::shared_ptr<MortarUpdater> updater);
  ConvergenceCriteria& Mechanical() const noexcept { return *mechanical_; }
  ConvergenceCriteria& Mortar() const noexcept { return *mortar_; }
  bool MechanicalConverged() const noexcept { return mechanical_converged_; }
  bool ActiveSetConverged() const noexcept { return active_set_converged_; }
  double LastConditionNumber() const noexcept { return condition_number_value_; }

  /// Column titles of the table (for the current DoF set) and the cells of the last row.
  std::vector<std::string> TableHeader() const;
  const std::vector<std::string>& LastTableRow() const noexcept { return last_row_; }

 private:
  std::string FormatRow(const std::vector<std::string>& cells) const;

  std::shared_ptr<ConvergenceCriteria> mechanical_;
  std::shared_ptr<ConvergenceCriteria> mortar_;
  bool print_;
  std::optional<ConditionNumberUtility> condition_number_;
  bool print_table_;
  bool mechanical_converged_ = false;
  bool active_set_converged_ = false;
  double condition_number_value_ = 0.0;
  std::vector<std::string> last_row_;
};

}  // namespace mc
