// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/properties.h"

#include <cmath>

#include "core/model/constitutive_law.h"
#include "core/utilities/error.h"

namespace mc {

const Table& Properties::GetTable(const std::string& input, const std::string& output) const {
  const auto it = tables_.find({input, output});
  if (it == tables_.end())
    throw InputError(Concat("properties ", id_, " have no table of ", output, " against ", input));
  return it->second;
}

double Properties::GetPositive(const Variable<double>& var) const {
  if (!Has(var)) throw InputError(Concat("properties ", id_, ": ", var.Name(), " is missing"));
  const double value = GetValue(var);
  if (!std::isfinite(value) || value <= 0.0)
    throw InputError(Concat("properties ", id_, ": ", var.Name(), " must be positive and finite, got ", value));
  return value;
}

}  // namespace mc
