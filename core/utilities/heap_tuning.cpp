// SPDX-License-Identifier: BSD-3-Clause
#include "core/utilities/heap_tuning.h"

#include <cstdlib>  // defines __GLIBC__ on glibc systems

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mc {

bool TuneHeapForRepeatedFactorizations() {
#if defined(__GLIBC__)
  constexpr int kMB = 1 << 20;
  // mallopt returns 1 on success; every call runs so that a refused value leaves the others set.
  const bool mmap = mallopt(M_MMAP_THRESHOLD, 32 * kMB) == 1;
  const bool trim = mallopt(M_TRIM_THRESHOLD, 128 * kMB) == 1;
  const bool pad = mallopt(M_TOP_PAD, 16 * kMB) == 1;
  return mmap && trim && pad;
#else
  return false;
#endif
}

}  // namespace mc
