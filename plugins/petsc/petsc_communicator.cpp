// SPDX-License-Identifier: BSD-3-Clause
#include "petsc/petsc_communicator.h"

#include <algorithm>
#include <climits>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {

void CheckMpi(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw SolutionError(Concat("MPI: ", call, " failed: ", std::string(text, static_cast<std::size_t>(length))));
}

}  // namespace

PetscCommunicator::PetscCommunicator(MPI_Comm comm) : comm_(comm) {
  CheckMpi(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  CheckMpi(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

void PetscCommunicator::SumToAll(double* values, std::size_t count) const {
  constexpr std::size_t kChunk = INT_MAX / 2;  // MPI counts are ints
  for (std::size_t first = 0; first < count; first += kChunk) {
    const int n = static_cast<int>(std::min(kChunk, count - first));
    double* chunk = values + first;
    if (rank_ == 0)
      CheckMpi(MPI_Reduce(MPI_IN_PLACE, chunk, n, MPI_DOUBLE, MPI_SUM, 0, comm_), "MPI_Reduce");
    else
      CheckMpi(MPI_Reduce(chunk, nullptr, n, MPI_DOUBLE, MPI_SUM, 0, comm_), "MPI_Reduce");
    CheckMpi(MPI_Bcast(chunk, n, MPI_DOUBLE, 0, comm_), "MPI_Bcast");
  }
}

}  // namespace mc
