#pragma once
// The replay's clock: log time (us, the log's timestamps) as a function of wall time (us), with
// play, pause, speed and seek; it stops at the log's end.

#include <cstdint>

namespace topay::viz {

class ReplayClock {
 public:
  /// A clock over [start, end] of the log, paused at start (play with Play()).
  ReplayClock(std::int64_t start_utime, std::int64_t end_utime);

  /// The log time at wall time `wall_utime`; reaching the end pauses the clock there.
  std::int64_t Now(std::int64_t wall_utime);

  void Play(std::int64_t wall_utime);
  void Pause(std::int64_t wall_utime);
  /// Moves to log time t (clamped to the log); keeps playing or paused.
  void Seek(std::int64_t log_utime, std::int64_t wall_utime);
  /// speed: log seconds per wall second, clamped to [0.01, 100].
  void SetSpeed(double speed, std::int64_t wall_utime);

  bool playing() const { return playing_; }
  double speed() const { return speed_; }
  std::int64_t start() const { return start_; }
  std::int64_t end() const { return end_; }

 private:
  void Anchor(std::int64_t wall_utime);  // re-anchors at the current log time

  std::int64_t start_, end_;
  std::int64_t anchor_log_, anchor_wall_ = 0;
  bool playing_ = false;
  double speed_ = 1.0;
};

}  // namespace topay::viz
