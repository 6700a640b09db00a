#pragma once

// Test helper: how long a cancellable call runs on after a stop request from another thread.
// Two measures: wall-clock latency (includes the OS scheduler: on a loaded machine a thread
// can wait several ms for a core) and the calling thread's CPU time spent after the request
// (the work the code under test does once stopped, independent of scheduling). The calling
// thread's CPU time is only complete when all the work runs on it (e.g. in a 1-thread TBB
// arena); the process's CPU time covers every worker thread too. Unit tests bound CPU time,
// which a loaded machine does not inflate; wall-clock latency is a printed figure.

#include <pthread.h>
#include <time.h>

#include <chrono>
#include <stop_token>
#include <thread>

namespace topay::testing {

struct StopLatency {
  double wall_ms = 0.0;  ///< Return time - request time.
  double cpu_ms = 0.0;   ///< Calling thread's CPU time from the request to the return.
  double process_cpu_ms = 0.0;  ///< All threads' CPU time from the request to the return.
};

inline double ThreadCpuMs(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

/// Calls run(stop_token) on this thread and requests stop from another thread after
/// `delay_ms`.
template <typename Run>
StopLatency MeasureStopLatency(int delay_ms, Run&& run) {
  using Clock = std::chrono::steady_clock;
  clockid_t cpu_clock{};
  pthread_getcpuclockid(pthread_self(), &cpu_clock);
  std::stop_source source;
  Clock::time_point requested;
  double requested_cpu_ms = 0.0;
  double requested_process_cpu_ms = 0.0;
  std::jthread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    requested_cpu_ms = ThreadCpuMs(cpu_clock);
    requested_process_cpu_ms = ThreadCpuMs(CLOCK_PROCESS_CPUTIME_ID);
    requested = Clock::now();
    source.request_stop();
  });
  run(source.get_token());
  const Clock::time_point returned = Clock::now();
  const double returned_cpu_ms = ThreadCpuMs(cpu_clock);
  const double returned_process_cpu_ms = ThreadCpuMs(CLOCK_PROCESS_CPUTIME_ID);
  stopper.join();
  StopLatency latency;
  latency.wall_ms = std::chrono::duration<double, std::milli>(returned - requested).count();
  latency.cpu_ms = returned_cpu_ms - requested_cpu_ms;
  latency.process_cpu_ms = returned_process_cpu_ms - requested_process_cpu_ms;
  return latency;
}

}  // namespace topay::testing
