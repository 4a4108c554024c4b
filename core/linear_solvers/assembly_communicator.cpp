// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/assembly_communicator.h"

#include <cstdlib>
#include <string>

namespace mc {

namespace {

// Open MPI's mpirun, then the PMI launchers (MPICH's hydra, Slurm's srun).
int FromEnvironment(const char* open_mpi, const char* pmi, int otherwise) {
  for (const char* name : {open_mpi, pmi}) {
    if (const char* value = std::getenv(name)) {
      try {
        return std::stoi(value);
      } catch (const std::exception&) {
        return otherwise;
      }
    }
  }
  return otherwise;
}

}  // namespace

int AssemblyCommunicator::LaunchedSize() { return FromEnvironment("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", 1); }

int AssemblyCommunicator::LaunchedRank() { return FromEnvironment("OMPI_COMM_WORLD_RANK", "PMI_RANK", 0); }

}  // namespace mc
