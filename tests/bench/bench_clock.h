#pragma once
// Clocks shared by the Google Benchmark programs: the calling thread's CPU time and the
// monotonic wall clock, in seconds.

#include <time.h>

namespace topay::bench_clock {

inline double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

inline double WallSeconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

}  // namespace topay::bench_clock
