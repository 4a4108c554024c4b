// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Registers the heat conduction elements by name (LaplacianElement2D3N, 2D4N, 3D4N, 3D8N);
/// idempotent.
void RegisterThermal();

}  // namespace mc
