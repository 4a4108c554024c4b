// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// The relative tolerance of each Krylov solve of a Newton loop (inexact Newton). The first solves
/// of a load step carry the load increment and cost most of the Krylov iterations: they stop at
/// `loose`. The later ones stop at the solver's own tolerance (0 here), since the contact criteria
/// need accurate late increments. A solver never stops before its own tolerance
/// (LinearSolver::SetForcingTerm).
///
/// On hertz3d_50k (field split, own tolerance 1e-8) the first two solves at 1e-6 take 426 FGMRES
/// iterations instead of 521, in the same Newton iterations (6, 5, 4, 5), and the reactions move
/// by 1e-12; three loose solves changed the iterations (6, 5, 4, 4) and the multipliers by 8e-6.
/// Eisenstat and Walker's adaptive term (choice 2, eta_k = 0.9 (|r_k| / |r_{k-1}|)^2 under a
/// ceiling) does not suit a semi-smooth contact Newton: its residual jumps up when the active set
/// is updated (9.5e-3 at iteration 2, 3.3e3 at iteration 3), so the ratio keeps the late solves
/// loose; with a ceiling of 1e-6 the Newton iterations became 6, 4, 4, 7, as with a fixed 1e-6
/// (benchmarks/hertz/results_3d_multigrid.md).
class ForcingTerm {
 public:
  explicit ForcingTerm(int loose_solves = kLooseSolves, double loose = kLoose)
      : loose_solves_(loose_solves), loose_(loose) {}

  /// For the solve of Newton iteration `iteration` (from 1) of a load step.
  double ForIteration(int iteration) const noexcept;

  static constexpr int kLooseSolves = 2;
  static constexpr double kLoose = 1.0e-6;

 private:
  int loose_solves_;
  double loose_;
};

}  // namespace mc
