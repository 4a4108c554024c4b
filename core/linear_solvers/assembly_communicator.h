// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

namespace mc {

/// The processes that share one distributed linear system (PETSc under `mpirun -n N`), seen by
/// the builder-and-solver without MPI: the core links no MPI, the PETSc plugin implements this.
/// Every rank holds the whole model and runs the same control flow, so every collective call
/// here is made by all ranks in the same order.
class AssemblyCommunicator {
 public:
  virtual ~AssemblyCommunicator() = default;
  virtual int Rank() const = 0;
  virtual int Size() const = 0;
  /// values[i] = the sum over the ranks of values[i], the same bits on every rank: the replicated
  /// model must update identically everywhere, or the ranks' Newton loops part ways.
  virtual void SumToAll(double* values, std::size_t count) const = 0;

  /// How many processes the launcher (mpirun, mpiexec, srun) started this one among, and its
  /// rank, read from the launcher's environment (OMPI_COMM_WORLD_SIZE, PMI_SIZE, ...) before any
  /// MPI is loaded; 1 and 0 for a process started on its own.
  static int LaunchedSize();
  static int LaunchedRank();
};

}  // namespace mc
