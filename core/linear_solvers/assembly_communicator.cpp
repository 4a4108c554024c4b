// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/assembly_communicator.h"

#include <cstdlib>
#include <cstring>
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

std::vector<std::string> AssemblyCommunicator::AllGather(const std::string& bytes) const {
  // The length, then the bytes packed into whole 64-bit words (the last one zero-padded).
  std::vector<std::int64_t> words(1 + (bytes.size() + sizeof(std::int64_t) - 1) / sizeof(std::int64_t), 0);
  words[0] = static_cast<std::int64_t>(bytes.size());
  if (!bytes.empty()) std::memcpy(words.data() + 1, bytes.data(), bytes.size());
  const auto incoming = Exchange(std::vector<std::vector<std::int64_t>>(static_cast<std::size_t>(Size()), words));
  std::vector<std::string> gathered;
  gathered.reserve(incoming.size());
  for (const auto& sent : incoming) {
    std::string& text = gathered.emplace_back(static_cast<std::size_t>(sent.at(0)), '\0');
    if (!text.empty()) std::memcpy(text.data(), sent.data() + 1, text.size());
  }
  return gathered;
}

int AssemblyCommunicator::LaunchedSize() { return FromEnvironment("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", 1); }

int AssemblyCommunicator::LaunchedRank() { return FromEnvironment("OMPI_COMM_WORLD_RANK", "PMI_RANK", 0); }

}  // namespace mc
