// SPDX-License-Identifier: BSD-3-Clause
#pragma once

/// Calls `X(D, S, M)` for each (dimension, slave nodes, master nodes) case of a mortar pair: 2D2N,
/// 3D3N, 3D4N and the mixed 3D3N4N and 3D4N3N. The explicit instantiations of the pair templates
/// (kinematics, conditions) are written with it, so they list the same cases.
#define MC_FOR_EACH_MORTAR_CASE(X) X(2, 2, 2) X(3, 3, 3) X(3, 4, 4) X(3, 3, 4) X(3, 4, 3)
