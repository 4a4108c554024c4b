// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/convergence_criteria.h"

#include <cstdio>

#include "core/linear_solvers/assembly_communicator.h"

namespace mc {

std::string ConvergenceCriteria::FormatLine(int iteration, const std::vector<CriterionValue>& values, bool converged) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "  it %d", iteration);
  std::string line = buffer;
  for (const auto& v : values) {
    std::snprintf(buffer, sizeof buffer, "  %s = %.1e (tol %.0e)", v.name.c_str(), v.value, v.tolerance);
    line += buffer;
  }
  line += converged ? "  converged" : "  not converged";
  return line;
}

void ConvergenceCriteria::SumOverRanks(double* values, std::size_t count) const {
  if (communicator_) communicator_->SumToAll(values, count);
}

}  // namespace mc
