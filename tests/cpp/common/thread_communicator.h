// SPDX-License-Identifier: BSD-3-Clause
// Ranks of a distributed run simulated by threads of one process (no MPI): the collectives of
// AssemblyCommunicator through shared slots and a barrier, with the bits the MPI implementation
// promises (sums added in rank order, so every rank gets the same).
#pragma once

#include <barrier>
#include <cstdint>
#include <vector>

#include "core/linear_solvers/assembly_communicator.h"

namespace mc::test {

struct ThreadRanks {
  explicit ThreadRanks(int size)
      : sync(size), slots(static_cast<std::size_t>(size)), lists(static_cast<std::size_t>(size)) {}
  std::barrier<> sync;
  std::vector<std::vector<double>> slots;
  std::vector<std::vector<std::vector<std::int64_t>>> lists;  ///< [from][to]
};

class ThreadCommunicator : public AssemblyCommunicator {
 public:
  ThreadCommunicator(ThreadRanks& ranks, int rank) : ranks_(ranks), rank_(rank) {}
  int Rank() const override { return rank_; }
  int Size() const override { return static_cast<int>(ranks_.slots.size()); }
  void SumToAll(double* values, std::size_t count) const override {
    ranks_.slots[static_cast<std::size_t>(rank_)].assign(values, values + count);
    ranks_.sync.arrive_and_wait();
    for (std::size_t i = 0; i < count; ++i) {
      double sum = 0.0;
      for (const auto& slot : ranks_.slots) sum += slot[i];
      values[i] = sum;
    }
    ranks_.sync.arrive_and_wait();  // no rank refills its slot before all have read
  }
  std::int64_t ExclusiveScan(std::int64_t value) const override {
    std::vector<std::vector<std::int64_t>> outgoing(ranks_.slots.size(), std::vector<std::int64_t>{value});
    const auto incoming = Exchange(outgoing);
    std::int64_t below = 0;
    for (int r = 0; r < rank_; ++r) below += incoming[static_cast<std::size_t>(r)].front();
    return below;
  }
  std::vector<std::vector<std::int64_t>> Exchange(
      const std::vector<std::vector<std::int64_t>>& outgoing) const override {
    ranks_.lists[static_cast<std::size_t>(rank_)] = outgoing;
    ranks_.sync.arrive_and_wait();
    std::vector<std::vector<std::int64_t>> incoming;
    for (const auto& sent : ranks_.lists) incoming.push_back(sent[static_cast<std::size_t>(rank_)]);
    ranks_.sync.arrive_and_wait();
    return incoming;
  }

 private:
  ThreadRanks& ranks_;
  int rank_;
};

}  // namespace mc::test
