#pragma once
// The planner node's "now" (docs/planner.md#replay). On the robot it is the wall clock. In
// deterministic mode it is message time: the newest utime of the messages handled so far, so
// that the same message sequence gives the same decisions whatever the machine's speed or
// the replay speed.

#include <algorithm>
#include <cstdint>

#include "procs/runtime/process_loop.h"

namespace topay::planner {

/// Where the node's time comes from.
enum class ClockSource {
  kWall,     ///< procs::NowUtime(): the robot
  kMessages  ///< the newest utime of the messages handled (never going back): replay, tests
};

/// The node's clock: the wall clock, or message time advanced by every message handled.
class PlannerClock {
 public:
  explicit PlannerClock(ClockSource source) : source_(source) {}

  /// A message stamped `utime` is being handled: in message time, now becomes the largest
  /// utime seen so far (a MAP_UPDATE is stamped with its scan's time, older than the robot
  /// states handled before it: time does not go back for it). Nothing on the wall clock.
  void OnMessage(std::int64_t utime) { newest_utime_ = std::max(newest_utime_, utime); }

  /// Now, us since the Unix epoch (message time: 0 before the first message).
  std::int64_t Now() const { return source_ == ClockSource::kWall ? procs::NowUtime() : newest_utime_; }

  bool message_time() const { return source_ == ClockSource::kMessages; }

 private:
  ClockSource source_;
  std::int64_t newest_utime_ = 0;
};

}  // namespace topay::planner
