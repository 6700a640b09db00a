#pragma once
// Real-time pacing of the plant: step k is due at start + k * step_s / rate (wall clock,
// steady). At each wake-up the caller runs the steps that are due (at most max_catch_up; if
// more are due the schedule is moved so the sim lags instead of bursting, and the reset is
// counted). rate 0: as fast as possible (a fixed batch per wake-up). Records how late each step
// ran (its lateness: wall time of the step minus its due time) for the jitter figures.

#include <chrono>
#include <cstdint>
#include <vector>

namespace topay::simproc {

class RealTimePacer {
 public:
  using Clock = std::chrono::steady_clock;

  /// rate > 0: real-time factor; rate == 0: as fast as possible (batch_steps per call).
  RealTimePacer(double step_s, double rate, int max_catch_up, int batch_steps = 100);

  void Start(Clock::time_point now);
  /// The number of steps to run now, given that steps_done have run since Start.
  int StepsDue(Clock::time_point now, std::int64_t steps_done);
  /// Records the lateness of step number `step` (1-based since Start) run at `now`.
  void RecordStep(Clock::time_point now, std::int64_t step);
  /// When the next step is due (for a sleep), Clock::time_point::min() with rate 0.
  Clock::time_point NextDue(std::int64_t steps_done) const;

  /// Steps that ran more than one step period late, since Start.
  std::int64_t late_steps() const { return late_steps_; }
  /// Times the schedule was moved because more than max_catch_up steps were due.
  std::int64_t schedule_resets() const { return resets_; }
  /// The steps the schedule was moved by in those resets, in all (steps the world did not run:
  /// it paused while the process stalled).
  std::int64_t slipped_steps() const { return -offset_steps_; }
  /// Lateness of the steps recorded since the last call, microseconds: p50, p99, max; clears.
  struct Lateness {
    double p50_us = 0.0, p99_us = 0.0, max_us = 0.0;
    std::int64_t count = 0;
  };
  Lateness TakeLateness();
  /// The same over every step recorded since Start (the first 10 million), not cleared.
  Lateness RunLateness() const;
  double rate() const { return rate_; }

 private:
  Clock::time_point DueTime(std::int64_t step) const;

  double step_s_;
  double rate_;
  int max_catch_up_;
  int batch_steps_;
  Clock::time_point start_;
  std::int64_t offset_steps_ = 0;  // steps of schedule moved by resets
  std::int64_t late_steps_ = 0;
  std::int64_t resets_ = 0;
  std::vector<double> lateness_us_;
  std::vector<float> run_lateness_us_;
};

}  // namespace topay::simproc
