#pragma once
// The robot's recent states (from ROBOT_STATE), so that a scan is filtered with the robot's
// configuration at the scan's capture time, not at the time the scan arrives.

#include <cstdint>
#include <deque>
#include <optional>

#include "core/robot/whole_body_state.h"

namespace topay {

struct RobotStateHistoryOptions {
  /// States older than this behind the newest are dropped, s. 2 s holds 200 ROBOT_STATEs at
  /// 100 Hz, more than a scan's delivery delay (a scan is published when captured, 10 Hz).
  double horizon_s = 2.0;
  /// A scan time farther than this from every state has no state (the self filter is then
  /// skipped and counted), s: 0.1 s is 10 ROBOT_STATE periods; the arm moves < 0.1 rad in it.
  double max_gap_s = 0.1;
};

/// A time-ordered buffer of whole-body states. At(t) interpolates linearly between the two
/// states around t (yaw along the shorter arc), or returns the nearest state when t lies
/// outside the buffer but within max_gap_s of its end.
class RobotStateHistory {
 public:
  explicit RobotStateHistory(const RobotStateHistoryOptions& options = {});

  /// Adds a state at utime (us). A state older than the newest is inserted in order; one with
  /// a non-finite value or a joint count different from the buffer's is ignored (false).
  bool Add(std::int64_t utime, const WholeBodyState& state);

  /// The state at utime, or nullopt if the buffer is empty or no state lies within max_gap_s.
  std::optional<WholeBodyState> At(std::int64_t utime) const;

  const RobotStateHistoryOptions& options() const { return options_; }
  std::size_t size() const { return states_.size(); }
  std::int64_t rejected() const { return rejected_; }

 private:
  struct Stamped {
    std::int64_t utime;
    WholeBodyState state;
  };
  RobotStateHistoryOptions options_;
  std::deque<Stamped> states_;
  std::int64_t rejected_ = 0;
};

}  // namespace topay
