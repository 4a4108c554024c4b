// SPDX-License-Identifier: BSD-3-Clause
#include "core/variables/variables_list.h"

#include "core/utilities/error.h"

namespace mc {

void VariablesList::Add(const VariableData& var) {
  const VariableData& source = var.IsComponent() ? *var.Source() : var;
  if (Has(source)) return;
  if (source.Type() != ValueType::Double && source.Type() != ValueType::Array3)
    throw Error(Concat("variable ", source.Name(), " (", ValueTypeName(source.Type()),
                       ") cannot be a historical nodal variable: only doubles and arrays of 3 can"));
  if (locked_)
    throw Error(Concat("cannot add historical variable ", source.Name(),
                       " after nodes were created; add it before reading the mesh"));
  if (offsets_.size() <= source.Key()) offsets_.resize(source.Key() + 1, -1);
  offsets_[source.Key()] = static_cast<int>(stride_);
  stride_ += source.HistoricalSize();
  variables_.push_back(&source);
}

}  // namespace mc
