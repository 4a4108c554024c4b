// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/suitesparse_memory.h"

#include <suitesparse/SuiteSparse_config.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace mc {

namespace {

/// Blocks of at least kKeptMinBytes handed out by this allocator (address -> capacity), and the
/// one kept for reuse. A mutex: two solvers may factorize on different threads.
struct State {
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> capacity;
  void* kept = nullptr;
  std::size_t kept_bytes = 0;
  long reuses = 0;
};

State& Memory() {
  static State* state = new State();  // never destroyed: SuiteSparse may free after static destructors
  return *state;
}

/// The kept block serves a request of at least a quarter of its size: a small work array must
/// not pin the factors' block.
void* Allocate(std::size_t bytes) {
  if (bytes < SuiteSparseMemory::kKeptMinBytes) return std::malloc(bytes);
  State& s = Memory();
  std::lock_guard lock(s.mutex);
  if (s.kept != nullptr && bytes <= s.kept_bytes && 4 * bytes >= s.kept_bytes) {
    void* block = s.kept;
    s.kept = nullptr;
    s.kept_bytes = 0;
    ++s.reuses;
    return block;
  }
  if (s.kept != nullptr && bytes > s.kept_bytes) {  // outgrown: not held beside the larger block
    s.capacity.erase(s.kept);
    std::free(s.kept);
    s.kept = nullptr;
    s.kept_bytes = 0;
  }
  void* block = std::malloc(bytes);
  if (block != nullptr) s.capacity[block] = bytes;
  return block;
}

void Free(void* block) {
  if (block == nullptr) return;
  State& s = Memory();
  std::unique_lock lock(s.mutex);
  const auto found = s.capacity.find(block);
  if (found == s.capacity.end()) {
    lock.unlock();
    std::free(block);
    return;
  }
  void* released = block;
  if (found->second > s.kept_bytes) {  // keep the largest: the next factors are about its size
    released = s.kept;
    s.kept = block;
    s.kept_bytes = found->second;
  }
  if (released != nullptr) {
    s.capacity.erase(released);
    std::free(released);
  }
}

void* AllocateZeroed(std::size_t count, std::size_t size) {
  if (size != 0 && count > static_cast<std::size_t>(-1) / size) return nullptr;
  const std::size_t bytes = count * size;
  if (bytes < SuiteSparseMemory::kKeptMinBytes) return std::calloc(count, size);
  void* block = Allocate(bytes);
  if (block != nullptr) std::memset(block, 0, bytes);
  return block;
}

/// A tracked block keeps its capacity when shrunk (UMFPACK trims its factors' block after a
/// factorization), so that it can serve the next factorization whole.
void* Reallocate(void* block, std::size_t bytes) {
  if (block == nullptr) return Allocate(bytes);
  std::size_t capacity = 0;
  {
    State& s = Memory();
    std::lock_guard lock(s.mutex);
    const auto found = s.capacity.find(block);
    if (found == s.capacity.end()) return std::realloc(block, bytes);
    capacity = found->second;
  }
  if (bytes <= capacity) return block;
  void* grown = Allocate(bytes);
  if (grown == nullptr) return nullptr;  // the old block stays valid, as with realloc
  std::memcpy(grown, block, capacity);
  Free(block);
  return grown;
}

}  // namespace

void SuiteSparseMemory::Install() {
  static std::once_flag once;
  std::call_once(once, [] {
    SuiteSparse_config.malloc_func = Allocate;
    SuiteSparse_config.calloc_func = AllocateZeroed;
    SuiteSparse_config.realloc_func = Reallocate;
    SuiteSparse_config.free_func = Free;
  });
}

std::size_t SuiteSparseMemory::KeptBytes() {
  State& s = Memory();
  std::lock_guard lock(s.mutex);
  return s.kept_bytes;
}

long SuiteSparseMemory::Reuses() {
  State& s = Memory();
  std::lock_guard lock(s.mutex);
  return s.reuses;
}

}  // namespace mc
