// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mpi.h>

#include "core/linear_solvers/assembly_communicator.h"

namespace mc {

/// The MPI processes of a distributed PETSc solve (PETSC_COMM_WORLD under mpirun), as the
/// builder-and-solver sees them.
class PetscCommunicator : public AssemblyCommunicator {
 public:
  explicit PetscCommunicator(MPI_Comm comm);
  int Rank() const override { return rank_; }
  int Size() const override { return size_; }
  /// Reduced on rank 0, then broadcast: MPI_Allreduce does not promise the same bits on every
  /// rank, and the replicated models must not part ways by a rounding.
  void SumToAll(double* values, std::size_t count) const override;
  std::int64_t ExclusiveScan(std::int64_t value) const override;
  /// The counts by MPI_Alltoall, then the lists by MPI_Alltoallv.
  std::vector<std::vector<std::int64_t>> Exchange(
      const std::vector<std::vector<std::int64_t>>& outgoing) const override;
  MPI_Comm Comm() const noexcept { return comm_; }

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace mc
