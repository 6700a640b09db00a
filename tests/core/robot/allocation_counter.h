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

// noinline: keeps GCC from pairing a new-expression with free() after inlining
// (-Wmismatched-new-delete); the replacement pair is consistent.
__attribute__((noinline)) void* operator new(std::size_t size) {
  if (topay::testing::g_count_allocations) ++topay::testing::g_allocation_count;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }
