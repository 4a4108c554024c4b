// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Registers the contact formulations of the application (ContactFormulation), the implemented
/// ones and those still to come under their Kratos names, and the name of the condensing linear
/// solver (RegisterLinearSolver). Idempotent.
void RegisterContactFormulations();

}  // namespace mc
