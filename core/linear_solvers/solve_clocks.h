// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ctime>

namespace mc {

/// CPU seconds of the parts of the linear-solve phase, summed over the process: where a run's
/// solve time goes beyond the factorizations (benchmarks/hertz/linear_phase.py). Thread CPU time,
/// so a loaded machine does not inflate it; the solves run on the calling thread (with
/// OMP_NUM_THREADS=1 the parts are all of the work). One process-wide record because the parts
/// sit in solvers wrapped by others (scaling, MixedULM, fallback) that do not forward timings.
struct SolveClocks {
  double phase = 0.0;                ///< the builder's SolveSystem, everything included
  double analysis = 0.0;             ///< symbolic analyses of the direct solvers (orderings)
  double pattern_check = 0.0;        ///< compressing A and comparing its pattern with the analysed one
  double factorization = 0.0;        ///< numeric factorizations
  double direct_substitution = 0.0;  ///< substitutions right after a factorization
  double krylov_substitution = 0.0;  ///< substitutions with kept factors inside GMRES
  double krylov_other = 0.0;         ///< GMRES besides them: products with A, orthogonalization, checks
  double comparison = 0.0;           ///< changed rows against the factorized matrix, its copy and row norms

  static SolveClocks& Process();

  /// Adds the thread CPU time of its scope to an accumulator.
  class Scope {
   public:
    explicit Scope(double& seconds) : seconds_(seconds), start_(Now()) {}
    ~Scope() { seconds_ += Now() - start_; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    static double Now() {
      timespec t{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }
    double& seconds_;
    double start_;
  };
};

}  // namespace mc
