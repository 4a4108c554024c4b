// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/SparseCore>

#include "core/variables/value_types.h"

namespace mc {

/// The global system matrix: compressed sparse columns with 32-bit indices, the layout
/// UMFPACK, CHOLMOD and KLU take without a copy. FE matrices have a symmetric pattern, so
/// assembling by columns costs the same as by rows.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace mc
