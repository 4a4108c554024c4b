// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mc {

/// The processes that share one distributed linear system (PETSc under `mpirun -n N`), seen by
/// the builder-and-solver without MPI: the core links no MPI, the PETSc plugin implements this.
/// Every rank runs the same control flow (today on the whole model; ModelPartPartitioner cuts it
/// to a piece per rank), so every collective call here is made by all ranks in the same order.
class AssemblyCommunicator {
 public:
  virtual ~AssemblyCommunicator() = default;
  virtual int Rank() const = 0;
  virtual int Size() const = 0;
  /// values[i] = the sum over the ranks of values[i], the same bits on every rank: the replicated
  /// model must update identically everywhere, or the ranks' Newton loops part ways.
  virtual void SumToAll(double* values, std::size_t count) const = 0;
  /// The sum of `value` over the ranks below this one (0 on rank 0): where this rank's block of a
  /// numbering by ranks starts.
  virtual std::int64_t ExclusiveScan(std::int64_t value) const = 0;
  /// Sends outgoing[r] to rank r (outgoing has Size() lists) and returns incoming, incoming[r] the
  /// list rank r sent here: the neighbour exchange of a distributed numbering and of ghost values.
  virtual std::vector<std::vector<std::int64_t>> Exchange(
      const std::vector<std::vector<std::int64_t>>& outgoing) const = 0;
  /// Every rank's `bytes`, in rank order, on every rank (one Exchange): how the outputs of a model
  /// cut across the ranks reach rank 0, and how a check on each rank's piece reaches every rank.
  std::vector<std::string> AllGather(const std::string& bytes) const;

  /// How many processes the launcher (mpirun, mpiexec, srun) started this one among, and its
  /// rank, read from the launcher's environment (OMPI_COMM_WORLD_SIZE, PMI_SIZE, ...) before any
  /// MPI is loaded; 1 and 0 for a process started on its own.
  static int LaunchedSize();
  static int LaunchedRank();
};

}  // namespace mc
