// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Keeps freed heap memory in the process instead of handing it back to the kernel after every
/// factorization. A Newton loop frees and re-allocates the same sparse-LU workspace at every
/// iteration; with glibc's defaults each round trip returns the pages and the next
/// factorization faults them in again, zero-filled. Measured on hertz2d_8k (7k equations,
/// 14 factorizations): page faults 58.7k -> 22.1k, CPU time 1053 -> 828 ms (one perf stat run).
///
/// Sets, on glibc only: blocks up to 32 MB (glibc's largest mmap threshold) come from the heap,
/// which is trimmed only beyond 128 MB of free top, and grows with 16 MB of padding. Blocks above
/// 32 MB are still mapped and unmapped by the kernel; for SuiteSparse's factors
/// SuiteSparseMemory keeps them instead (hertz2d_30k: 18 % of UMFPACK's numeric time was the
/// zero-fill of a 40 MB block). (A 1 GB trim threshold kept 100 MB more at the
/// peak of hertz3d_50k for no gain.) The setting is process-wide; the Python module
/// applies it on import unless MORTARCONTACT_HEAP_TUNING=0. Returns whether it was applied.
bool TuneHeapForRepeatedFactorizations();

}  // namespace mc
