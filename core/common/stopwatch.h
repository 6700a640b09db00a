#pragma once

#include <chrono>

namespace topay {

/// Wall-clock (steady clock) time since a start point: the one timing helper of the stack
/// (stage times in summaries, deadlines). Cheap to copy; not thread-safe to Restart while
/// another thread reads it.
class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;

  /// Starts now.
  Stopwatch() : start_(Clock::now()) {}
  /// Starts at `start` (e.g. a time point taken earlier).
  explicit Stopwatch(Clock::time_point start) : start_(start) {}

  /// Starts again now.
  void Restart() { start_ = Clock::now(); }
  Clock::time_point start() const { return start_; }

  /// Time since the start (s, ms).
  double ElapsedS() const { return SecondsBetween(start_, Clock::now()); }
  double ElapsedMs() const { return MillisecondsBetween(start_, Clock::now()); }
  /// Time from the start to `t` (negative if t is earlier).
  double ElapsedSAt(Clock::time_point t) const { return SecondsBetween(start_, t); }
  double ElapsedMsAt(Clock::time_point t) const { return MillisecondsBetween(start_, t); }

  static double SecondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
  }
  static double MillisecondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
  }

 private:
  Clock::time_point start_;
};

/// `from` + `seconds`, saturating at Clock::time_point::max() (no deadline) for +infinity,
/// NaN or a sum past the clock's range. Negative seconds give a time before `from`
/// (saturating at Clock::time_point::min()).
Stopwatch::Clock::time_point DeadlineAfter(Stopwatch::Clock::time_point from, double seconds);

/// CPU time of the whole process (every thread; CLOCK_PROCESS_CPUTIME_ID) since a start
/// point. For bounds on work done rather than on wall-clock time (tests on a shared machine:
/// a cancelled search must stop burning CPU, whatever the scheduler does).
class CpuStopwatch {
 public:
  CpuStopwatch() : start_s_(NowS()) {}
  void Restart() { start_s_ = NowS(); }
  double ElapsedS() const { return NowS() - start_s_; }
  double ElapsedMs() const { return 1e3 * ElapsedS(); }
  /// The process's CPU time (s) since an unspecified origin.
  static double NowS();

 private:
  double start_s_;
};

}  // namespace topay
