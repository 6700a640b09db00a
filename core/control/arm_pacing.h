#pragma once
// The arm's reference paced by the base's progress (docs/control.md "Arm pacing";
// docs/reliability.md, finding 34).
//
// A whole-body trajectory is validated as pairs: the arm's configuration q(t) on the base at
// X_WB(t), the same t. When the base falls behind its reference (wheels that slip, drives that
// lag, a simulator that steps late), tracking both on the clock puts q(t) on a base still near
// X_WB(t - lag): a pair nobody checked. Under overload the arm touched a table top that way (the
// base 0.18 m off its reference, the joints within 0.005 rad of theirs). So the arm's
// reference time is the latest time, no earlier than `window_s` before the clock, whose base pose
// is within `slack_m` of the pose nearest the measured base: on the clock while the base keeps up
// (within the slack), waiting for it while it lags. The base's own reference stays on the clock
// (paced the same way, the NMPC drifted off a bend after a stall: docs/control.md).

#include "core/robot/whole_body_state.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// Options of ArmPacedTime (NmpcOptions::arm_pacing; config/tracker/tracker.yaml nmpc.arm_pacing).
struct ArmPacingOptions {
  double window_s = 1.0;       ///< How far the arm's time may fall behind the clock (s); 0: off.
  double slack_m = 0.05;       ///< Base lag (pose distance, m) the arm does not wait for.
  double yaw_m_per_rad = 0.3;  ///< Pose distance = |p - p_ref| + yaw_m_per_rad |wrap(yaw - yaw_ref)|.
  double resolution_s = 0.02;  ///< Step of the search over the window (s).

  /// Throws std::invalid_argument naming the first field out of range (the window may hold at
  /// most kMaxSamples - 1 steps).
  void Check() const;
  static constexpr int kMaxSamples = 257;
};

/// The base pose distance of ArmPacingOptions (m): |p_WB - p_ref| + yaw_m_per_rad |yaw error|.
double BasePoseDistance(const WholeBodyState& a, const WholeBodyState& b, double yaw_m_per_rad);

/// The arm's reference time on a trajectory (duration_s, sampled by `sampler`) whose clock is at
/// clock_t_s, for a base measured at `base` (its x, y, yaw): the latest tau in
/// [clock_t - window, clock_t] (within [0, duration]) with
///   d(X_WB(tau), base) <= min over the window of d + slack_m.
/// Returns clock_t_s itself when that tau is the window's latest time (the arm on the clock;
/// past the end: clock_t_s, so the end is held as before) or when pacing is off. Never later
/// than the clock. *scratch is a sample sized for the trajectory's joints. Allocation-free apart from
/// what the sampler does.
double ArmPacedTime(const TrajectorySampler& sampler, double duration_s, double clock_t_s,
                    const WholeBodyState& base, const ArmPacingOptions& options,
                    TrajectorySample* scratch);

}  // namespace topay
