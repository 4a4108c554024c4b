// SPDX-License-Identifier: BSD-3-Clause
#include "tests/cpp/common/allocation_counter.h"

#include <link.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>

// glibc's own allocator, called by the interposed C allocation functions below.
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {

std::atomic<long> g_allocations{0};
std::atomic<long> g_openmp_allocations{0};
std::atomic<bool> g_counting{false};
// Executable code of the OpenMP runtime, whose allocations are counted apart.
std::uintptr_t g_openmp_begin = 0;
std::uintptr_t g_openmp_end = 0;

int FindOpenMpRuntime(dl_phdr_info* info, std::size_t, void*) {
  if (info->dlpi_name == nullptr || std::strstr(info->dlpi_name, "libgomp") == nullptr) return 0;
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_LOAD || !(segment.p_flags & PF_X)) continue;
    g_openmp_begin = info->dlpi_addr + segment.p_vaddr;
    g_openmp_end = g_openmp_begin + segment.p_memsz;
  }
  return 1;
}

void LocateOpenMpRuntime() {
  if (g_openmp_end == 0) dl_iterate_phdr(FindOpenMpRuntime, nullptr);
}

// Not inlined, so that a debugger can break on it to see where a counted allocation comes from.
[[gnu::noinline]] void CountAllocation(const void* caller) {
  const auto address = reinterpret_cast<std::uintptr_t>(caller);
  if (address >= g_openmp_begin && address < g_openmp_end)
    g_openmp_allocations.fetch_add(1, std::memory_order_relaxed);
  else
    g_allocations.fetch_add(1, std::memory_order_relaxed);
}

inline void Count(const void* caller) {
  if (g_counting.load(std::memory_order_relaxed)) CountAllocation(caller);
}

void* NewOrThrow(std::size_t size, std::size_t alignment) {
  void* p = alignment > alignof(std::max_align_t) ? __libc_memalign(alignment, size ? size : 1)
                                                  : __libc_malloc(size ? size : 1);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

namespace mc::test {

void Reset() {
  g_allocations = 0;
  g_openmp_allocations = 0;
}

void StartCounting() {
  LocateOpenMpRuntime();
  g_counting = true;
}

void StopCounting() { g_counting = false; }

bool IsCounting() { return g_counting.load(); }

long Allocations() { return g_allocations.load(); }

long OpenMpAllocations() { return g_openmp_allocations.load(); }

bool OpenMpRuntimeFound() {
  LocateOpenMpRuntime();
  return g_openmp_end > g_openmp_begin;
}

}  // namespace mc::test

// Eigen allocates with malloc, the standard containers with operator new: count both, in the
// executable and in every library it loads. The caller is the return address of the allocation
// function, evaluated in the function itself.
#define MC_CALLER __builtin_return_address(0)
extern "C" {
void* malloc(std::size_t size) {
  Count(MC_CALLER);
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  Count(MC_CALLER);
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  Count(MC_CALLER);
  return __libc_realloc(p, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  Count(MC_CALLER);
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  Count(MC_CALLER);
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** p, std::size_t alignment, std::size_t size) {
  Count(MC_CALLER);
  *p = __libc_memalign(alignment, size);
  return *p ? 0 : ENOMEM;
}
void free(void* p) { __libc_free(p); }
}

void* operator new(std::size_t size) {
  Count(MC_CALLER);
  return NewOrThrow(size, 0);
}
void* operator new[](std::size_t size) {
  Count(MC_CALLER);
  return NewOrThrow(size, 0);
}
void* operator new(std::size_t size, std::align_val_t a) {
  Count(MC_CALLER);
  return NewOrThrow(size, std::size_t(a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  Count(MC_CALLER);
  return NewOrThrow(size, std::size_t(a));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  Count(MC_CALLER);
  return __libc_malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  Count(MC_CALLER);
  return __libc_malloc(size ? size : 1);
}
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  Count(MC_CALLER);
  return __libc_memalign(std::size_t(a), size ? size : 1);
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  Count(MC_CALLER);
  return __libc_memalign(std::size_t(a), size ? size : 1);
}
void operator delete(void* p) noexcept { __libc_free(p); }
void operator delete[](void* p) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
#undef MC_CALLER
