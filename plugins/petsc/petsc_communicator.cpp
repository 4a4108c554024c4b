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

std::int64_t PetscCommunicator::ExclusiveScan(std::int64_t value) const {
  std::int64_t below = 0;
  CheckMpi(MPI_Exscan(&value, &below, 1, MPI_INT64_T, MPI_SUM, comm_), "MPI_Exscan");
  return rank_ == 0 ? 0 : below;  // MPI leaves rank 0's result undefined
}

std::vector<std::vector<std::int64_t>> PetscCommunicator::Exchange(
    const std::vector<std::vector<std::int64_t>>& outgoing) const {
  if (outgoing.size() != static_cast<std::size_t>(size_))
    throw Error(Concat("MPI exchange: ", outgoing.size(), " outgoing lists for ", size_, " ranks"));
  const auto ranks = static_cast<std::size_t>(size_);
  std::vector<int> send_count(ranks), send_start(ranks), receive_count(ranks), receive_start(ranks);
  std::vector<std::int64_t> sent;
  for (std::size_t r = 0; r < ranks; ++r) {
    if (outgoing[r].size() > static_cast<std::size_t>(INT_MAX) - sent.size())
      throw Error(Concat("MPI exchange: more than ", INT_MAX, " values sent by rank ", rank_));
    send_start[r] = static_cast<int>(sent.size());
    send_count[r] = static_cast<int>(outgoing[r].size());
    sent.insert(sent.end(), outgoing[r].begin(), outgoing[r].end());
  }
  CheckMpi(MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, comm_), "MPI_Alltoall");
  std::size_t total = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    receive_start[r] = static_cast<int>(total);
    total += static_cast<std::size_t>(receive_count[r]);
  }
  std::vector<std::int64_t> received(total);
  CheckMpi(MPI_Alltoallv(sent.data(), send_count.data(), send_start.data(), MPI_INT64_T, received.data(),
                         receive_count.data(), receive_start.data(), MPI_INT64_T, comm_),
           "MPI_Alltoallv");
  std::vector<std::vector<std::int64_t>> incoming(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
    incoming[r].assign(received.begin() + receive_start[r], received.begin() + receive_start[r] + receive_count[r]);
  return incoming;
}

}  // namespace mc
