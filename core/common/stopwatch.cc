#include "core/common/stopwatch.h"

#include <ctime>

namespace topay {

Stopwatch::Clock::time_point DeadlineAfter(Stopwatch::Clock::time_point from, double seconds) {
  using Clock = Stopwatch::Clock;
  const double limit_s = std::chrono::duration<double>(Clock::time_point::max() - from).count();
  if (!(seconds < limit_s)) return Clock::time_point::max();
  const double back_s = std::chrono::duration<double>(from - Clock::time_point::min()).count();
  if (!(seconds > -back_s)) return Clock::time_point::min();
  return from + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

double CpuStopwatch::NowS() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace topay
