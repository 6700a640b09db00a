#include "procs/sim/real_time_pacer.h"

#include <algorithm>
#include <cmath>

namespace topay::simproc {

RealTimePacer::RealTimePacer(double step_s, double rate, int max_catch_up, int batch_steps)
    : step_s_(step_s), rate_(rate), max_catch_up_(std::max(1, max_catch_up)), batch_steps_(batch_steps) {}

void RealTimePacer::Start(Clock::time_point now) {
  start_ = now;
  offset_steps_ = 0;
}

RealTimePacer::Clock::time_point RealTimePacer::DueTime(std::int64_t step) const {
  const double seconds = static_cast<double>(step - offset_steps_) * step_s_ / rate_;
  return start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

RealTimePacer::Clock::time_point RealTimePacer::NextDue(std::int64_t steps_done) const {
  if (rate_ <= 0.0) return Clock::time_point::min();
  return DueTime(steps_done + 1);
}

int RealTimePacer::StepsDue(Clock::time_point now, std::int64_t steps_done) {
  if (rate_ <= 0.0) return batch_steps_;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  const std::int64_t due_total = static_cast<std::int64_t>(std::floor(elapsed_s * rate_ / step_s_ + 1e-9)) + offset_steps_;
  std::int64_t due = due_total - steps_done;
  if (due > max_catch_up_) {
    // Too far behind: run max_catch_up now and let the schedule slip by the rest.
    offset_steps_ -= due - max_catch_up_;
    ++resets_;
    due = max_catch_up_;
  }
  return static_cast<int>(std::max<std::int64_t>(0, due));
}

void RealTimePacer::RecordStep(Clock::time_point now, std::int64_t step) {
  if (rate_ <= 0.0) return;
  const double late_us = std::chrono::duration<double, std::micro>(now - DueTime(step)).count();
  if (late_us > step_s_ / rate_ * 1e6) ++late_steps_;
  lateness_us_.push_back(std::max(0.0, late_us));
  if (run_lateness_us_.size() < 10'000'000) run_lateness_us_.push_back(static_cast<float>(std::max(0.0, late_us)));
}

RealTimePacer::Lateness RealTimePacer::RunLateness() const {
  Lateness l;
  l.count = static_cast<std::int64_t>(run_lateness_us_.size());
  if (run_lateness_us_.empty()) return l;
  std::vector<float> sorted = run_lateness_us_;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) { return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(q * (sorted.size() - 1) + 0.5))]; };
  l.p50_us = at(0.5);
  l.p99_us = at(0.99);
  l.max_us = sorted.back();
  return l;
}

RealTimePacer::Lateness RealTimePacer::TakeLateness() {
  Lateness l;
  l.count = static_cast<std::int64_t>(lateness_us_.size());
  if (lateness_us_.empty()) return l;
  std::sort(lateness_us_.begin(), lateness_us_.end());
  const auto at = [&](double q) {
    return lateness_us_[std::min(lateness_us_.size() - 1, static_cast<std::size_t>(q * (lateness_us_.size() - 1) + 0.5))];
  };
  l.p50_us = at(0.5);
  l.p99_us = at(0.99);
  l.max_us = lateness_us_.back();
  lateness_us_.clear();
  return l;
}

}  // namespace topay::simproc
