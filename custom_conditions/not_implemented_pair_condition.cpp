// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/not_implemented_pair_condition.h"

#include "core/utilities/error.h"

namespace mc {

std::unique_ptr<Condition> NotImplementedPairCondition::Create(IndexType, Geometry::NodesArray, Properties*) const {
  Fail();
}

std::unique_ptr<PairedCondition> NotImplementedPairCondition::CreatePaired(IndexType, Condition&, Condition&,
                                                                           Properties*) const {
  Fail();
}

void NotImplementedPairCondition::Fail() const {
  throw NotImplementedError(Concat("pair condition '", name_, "' is not implemented: ", reason_));
}

}  // namespace mc
