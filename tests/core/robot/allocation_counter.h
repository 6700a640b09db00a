#pragma once

// Counts heap allocations, to check that kernels documented as allocation-free are. Replaces
// the global operator new/delete of the test binary that includes it: include it from exactly
// one source file of a test executable.

#include <atomic>
#include <cstdlib>
#include <new>

namespace topay::testing {

inline std::atomic<bool> g_count_allocations{false};
inline std::atomic<int> g_allocation_count{0};

/// Counts the allocations made during its lifetime.
class AllocationCounter {
 public:
  AllocationCounter() {
    g_allocation_count = 0;
    g_count_allocations = true;
  }
  ~AllocationCounter() { g_count_allocations = false; }
  int count() const { return g_allocation_count.load(); }
};

}  // namespace topay::testing

// Every form that allocates with malloc is replaced together with its deallocation (the
// plain, nothrow and array forms), so no block is allocated by one allocator and freed by
// another (ASan reports that as alloc-dealloc-mismatch: std::stable_sort's buffer comes from
// the nothrow form). The align_val_t forms stay the library's, paired among themselves.
// noinline: keeps GCC from pairing a new-expression with free() after inlining
// (-Wmismatched-new-delete); the replacement pairs are consistent.
__attribute__((noinline)) void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (topay::testing::g_count_allocations) ++topay::testing::g_allocation_count;
  return std::malloc(size == 0 ? 1 : size);
}
__attribute__((noinline)) void* operator new(std::size_t size) {
  if (void* p = ::operator new(size, std::nothrow)) return p;
  throw std::bad_alloc();
}
__attribute__((noinline)) void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return ::operator new(size, std::nothrow);
}
__attribute__((noinline)) void* operator new[](std::size_t size) { return ::operator new(size); }
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
__attribute__((noinline)) void operator delete[](void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
