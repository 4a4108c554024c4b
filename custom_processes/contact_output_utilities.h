// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/model_part.h"

namespace mc {

/// Zeroes the augmented tractions (AUGMENTED_NORMAL_CONTACT_PRESSURE and
/// AUGMENTED_TANGENT_CONTACT_PRESSURE) of the slave nodes of `part` that are not ACTIVE, so
/// that output shows no pressure where there is no contact (clear_inactive_for_post).
/// Returns the number of nodes cleared.
std::size_t ClearInactiveForPost(ModelPart& part);

}  // namespace mc
