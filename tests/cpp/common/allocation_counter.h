// SPDX-License-Identifier: BSD-3-Clause
// Heap allocation counter for the allocation tests. Linking allocation_counter.cpp into a test
// executable replaces malloc, calloc, realloc, memalign, aligned_alloc, posix_memalign, free and
// every global operator new/delete of the whole process (the executable and every library it
// loads) with forwarders to glibc's allocator that count the allocations made while counting is
// on. Link it only into the executables that count allocations.
//
// Allocations made by the OpenMP runtime (libgomp, recognized by the return address of the
// allocation call) are counted apart: libgomp allocates a team for every parallel region run by
// a single thread, and a work share now and then, which no caller can avoid.
#pragma once

namespace mc::test {

/// Zeroes both counts.
void Reset();
/// Counts the allocations from now on (without resetting the counts).
void StartCounting();
/// Stops counting; the counts are kept.
void StopCounting();
bool IsCounting();
/// Allocations counted, other than the OpenMP runtime's.
long Allocations();
/// Allocations counted that the OpenMP runtime made.
long OpenMpAllocations();
/// Whether the executable code of the OpenMP runtime was found (looked up on first use).
bool OpenMpRuntimeFound();

}  // namespace mc::test
