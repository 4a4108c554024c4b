// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

namespace mc {

/// The allocator of SuiteSparse (UMFPACK, KLU, CHOLMOD): malloc and free, except that the largest
/// block freed is kept mapped and handed out again for the next request of about its size.
///
/// Why: every numeric factorization allocates one block for its LU factors (UMFPACK: tens of MB
/// for the 2D contact benchmarks) and frees the previous one. glibc serves blocks that large with
/// a fresh mmap and returns them with munmap, so each factorization faulted in and zeroed every
/// page of its factors again: 18 % of UMFPACK's numeric time on hertz2d_30k (perf). The kept
/// block costs no memory at the peak: it is the previous factors' block, reused by the next ones.
class SuiteSparseMemory {
 public:
  /// Blocks from this size on are kept when freed; smaller ones are glibc's as usual.
  static constexpr std::size_t kKeptMinBytes = std::size_t{4} << 20;

  /// Installs the allocator in SuiteSparse_config (once per process; later calls do nothing).
  static void Install();

  /// Bytes of the block kept for reuse (0 when none), and blocks handed out again so far.
  static std::size_t KeptBytes();
  static long Reuses();
};

}  // namespace mc
