#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stop_token>
#include <thread>

namespace topay {

/// Requests stop on a std::stop_source at a deadline that can be moved earlier while it runs
/// (the front end's "first success + improvement window" and its hard budget). A small
/// watcher thread sleeps on a condition variable until the deadline; destroying the object
/// ends the watcher without requesting stop if the deadline has not passed.
class StopDeadline {
 public:
  using Clock = std::chrono::steady_clock;

  /// `source` must outlive this object. Clock::time_point::max(): no deadline yet.
  StopDeadline(std::stop_source* source, Clock::time_point deadline);
  ~StopDeadline();
  StopDeadline(const StopDeadline&) = delete;
  StopDeadline& operator=(const StopDeadline&) = delete;

  /// Moves the deadline to min(current, deadline). Thread-safe.
  void Tighten(Clock::time_point deadline);

 private:
  void Watch();

  std::stop_source* source_;
  std::mutex mutex_;
  std::condition_variable wake_;
  Clock::time_point deadline_;
  bool quit_ = false;
  std::thread watcher_;  // last: starts after the members it reads are initialised
};

}  // namespace topay
