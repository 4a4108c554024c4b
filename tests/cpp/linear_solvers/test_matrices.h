// SPDX-License-Identifier: BSD-3-Clause
// Test systems shared by the linear-solver tests.
#pragma once

#include "core/linear_solvers/sparse_types.h"

namespace mc::testing {

/// 5-point Laplacian (scaled by h^2: 4 on the diagonal, -1 to the neighbours) on an n x n grid
/// of interior points with Dirichlet boundaries: symmetric positive definite, n^2 unknowns.
SparseMatrix Poisson2D(int n);

/// Central-difference convection-diffusion -Δu + β·∇u on the same grid (times h^2), with
/// β h / 2 = (0.3, -0.2): non-symmetric, diagonally dominant.
SparseMatrix ConvectionDiffusion2D(int n);

/// A smooth, non-trivial manufactured solution x_i = 1 + sin(0.37 i) + i / size.
Vector ManufacturedSolution(long size);

/// |x - y| / |y|.
double RelativeError(const Vector& x, const Vector& y);

/// |b - A x| / |b|.
double RelativeResidual(const SparseMatrix& A, const Vector& x, const Vector& b);

/// Zeroes row and column k, keeping the entries in the pattern (explicit zeros).
void ZeroRowAndColumn(SparseMatrix& A, int k);

}  // namespace mc::testing
