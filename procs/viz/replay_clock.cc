#include "procs/viz/replay_clock.h"

#include <algorithm>
#include <cmath>

namespace topay::viz {

ReplayClock::ReplayClock(std::int64_t start_utime, std::int64_t end_utime)
    : start_(start_utime), end_(std::max(start_utime, end_utime)), anchor_log_(start_utime) {}

std::int64_t ReplayClock::Now(std::int64_t wall_utime) {
  if (!playing_) return anchor_log_;
  const double elapsed = static_cast<double>(wall_utime - anchor_wall_) * speed_;
  const std::int64_t now = anchor_log_ + static_cast<std::int64_t>(std::llround(std::max(0.0, elapsed)));
  if (now >= end_) {
    anchor_log_ = end_;
    anchor_wall_ = wall_utime;
    playing_ = false;
    return end_;
  }
  return now;
}

void ReplayClock::Anchor(std::int64_t wall_utime) {
  anchor_log_ = Now(wall_utime);
  anchor_wall_ = wall_utime;
}

void ReplayClock::Play(std::int64_t wall_utime) {
  Anchor(wall_utime);
  if (anchor_log_ >= end_) anchor_log_ = start_;  // play at the end starts again
  playing_ = true;
}

void ReplayClock::Pause(std::int64_t wall_utime) {
  Anchor(wall_utime);
  playing_ = false;
}

void ReplayClock::Seek(std::int64_t log_utime, std::int64_t wall_utime) {
  anchor_log_ = std::clamp(log_utime, start_, end_);
  anchor_wall_ = wall_utime;
}

void ReplayClock::SetSpeed(double speed, std::int64_t wall_utime) {
  Anchor(wall_utime);
  speed_ = std::isfinite(speed) ? std::clamp(speed, 0.01, 100.0) : 1.0;
}

}  // namespace topay::viz
