// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Registers the structural constitutive laws, solid elements and load / skin conditions by
/// their Kratos names in Registry<ConstitutiveLaw>, Registry<Element> and Registry<Condition>.
/// Idempotent and thread-safe.
void RegisterStructuralMechanics();

}  // namespace mc
