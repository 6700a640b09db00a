#pragma once

#include <cstddef>

namespace topay {

/// Process-wide allocator setting for a process that plans repeatedly (planner process,
/// benchmark tools): call once at the top of main, never from library code.
///
/// glibc serves allocations above its mmap threshold (128 KiB at start, raised as large
/// blocks are freed) with fresh mmap()s and gives freed heap tops back to the kernel, so the
/// planner's per-call grids (JPS's 1 M-cell arrays, PRM and RRT* buffers) are page-faulted in
/// again on every call: about 10 ms of a 50 ms front end on Tables large tasks
/// (docs/benchmarks.md). This keeps blocks up to `max_block_bytes` on the heap and trims
/// only when more than 4 x that is free, so later calls reuse the memory. Returns false
/// (and changes nothing) where the C library has no such setting.
bool RetainFreedHeapMemory(std::size_t max_block_bytes = std::size_t{32} << 20);

}  // namespace topay
