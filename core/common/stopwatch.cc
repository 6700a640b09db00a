#include "core/common/stopwatch.h"

#include <ctime>

namespace topay {

Stopwatch::Clock::time_point DeadlineAfter(Stopwatch::Clock::time_point from, double seconds) {
  using Clock = Stopwatch::Clock;
  using Seconds = std::chrono::duration<double>;
  // In double, so that neither difference can overflow the clock's integer ticks.
  const double from_s = Seconds(from.time_since_epoch()).count();
  const double limit_s = Seconds(Clock::time_point::max().time_since_epoch()).count() - from_s;
  if (!(seconds < limit_s)) return Clock::time_point::max();
  const double back_s = from_s - Seconds(Clock::time_point::min().time_since_epoch()).count();
  if (!(seconds > -back_s)) return Clock::time_point::min();
  return from + std::chrono::duration_cast<Clock::duration>(Seconds(seconds));
}

double CpuStopwatch::NowS() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace topay
