#pragma once
// topay-estimator's logic (docs/estimator.md): BASE_POSE, BASE_VELOCITY, JOINT_STATE and
// GRIPPER_STATE in; every cycle (100 Hz) a ROBOT_STATE out while the estimate is valid. No LCM
// in the class itself (ConnectEstimatorNode wires it to a ProcessLoop), so tests call its
// handlers with the times they choose.
//
// ROBOT_STATE: utime = the cycle's time; pose = the filter's estimate predicted to that time
// with the latest odometry (Se2Estimator::EstimateAt); velocity = the latest BASE_VELOCITY (its
// own utime); joints = the latest JOINT_STATE (its own utime); gripper = the latest
// GRIPPER_STATE position, NaN ("none", robot_state_t) when none came or it is older than
// gripper_timeout_s (the tracker then keeps its last known gripper value).
// Valid (published) only with a pose taken (no older than pose_timeout_s), a BASE_VELOCITY no
// older than odometry_timeout_s and a JOINT_STATE no older than joints_timeout_s (ages from the
// stamps against the cycle's time). Otherwise nothing is published and the tracker stops the
// robot on its stale-state rule. Bad inputs are counted per kind and logged once per kind; a
// JOINT_STATE whose positions jump beyond the joint rate limit is one (StateContinuityGate on q;
// a consistent new stream is taken after a few).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/estimation/se2_estimator.h"
#include "core/estimation/state_continuity_gate.h"
#include "procs/estimator/estimator_config.h"
#include "procs/estimator/input_checks.h"
#include "topay/robot_state_t.hpp"

namespace topay::procs {
class ProcessLoop;
}

namespace topay::estimator {

/// Why ROBOT_STATE is (not) published.
enum class Validity : std::int8_t { kValid, kNoPose, kPoseStale, kNoOdometry, kOdometryStale, kNoJoints, kJointsStale };
const char* ValidityName(Validity validity);

struct EstimatorCounts {
  std::int64_t cycles = 0;
  std::int64_t published = 0;
  std::int64_t held = 0;            ///< cycles without a valid estimate (nothing published)
  std::int64_t invalidations = 0;   ///< valid -> not valid transitions
  std::int64_t poses = 0, velocities = 0, joints = 0, grippers = 0;  ///< messages handled
  FaultCounts faults{};             ///< bad inputs by kind
  std::int64_t total_faults() const;
};

class EstimatorNode {
 public:
  /// Throws std::invalid_argument for bad options.
  explicit EstimatorNode(const EstimatorProcessOptions& options);

  void OnPose(const base_pose_t& msg, std::int64_t now_utime);
  void OnVelocity(const base_velocity_t& msg, std::int64_t now_utime);
  void OnJoints(const joint_state_t& msg, std::int64_t now_utime);
  void OnGripper(const joint_state_t& msg, std::int64_t now_utime);
  /// One cycle at now_utime: the ROBOT_STATE to publish, or nullptr while not valid.
  const robot_state_t* Step(std::int64_t now_utime);

  Validity validity() const { return validity_; }
  const EstimatorCounts& counts() const { return counts_; }
  const Se2Estimator& filter() const { return filter_; }
  /// heartbeat_t::OK while publishing, WARN while not; the heartbeat's status line (state,
  /// inputs' ages, pose outcomes, bad inputs).
  std::int8_t Health() const;
  std::string StatusLine(std::int64_t now_utime) const;
  /// The final report: cycles, published, held, the filter's summary, bad inputs by kind.
  std::string Report() const;

 private:
  Validity Evaluate(std::int64_t now_utime) const;
  bool Future(std::int64_t utime, std::int64_t now_utime) const;
  void Fault(InputFault fault);
  void Fill(std::int64_t now_utime);

  EstimatorProcessOptions options_;
  Se2Estimator filter_;
  std::optional<std::int64_t> pose_utime_;  // the newest pose taken into the filter
  std::optional<base_velocity_t> velocity_;
  std::optional<joint_state_t> joints_;
  StateContinuityGate joints_gate_;  // JOINT_STATE positions within the joint rate limit
  std::optional<std::int64_t> gripper_utime_;
  double gripper_ = 0.0;
  Validity validity_ = Validity::kNoPose;
  robot_state_t out_{};
  EstimatorCounts counts_;
};

/// Subscribes `node` to BASE_POSE, BASE_VELOCITY, JOINT_STATE and GRIPPER_STATE on *loop
/// (times from the wall clock, procs::NowUtime) and adds the cycle timer (1 / publish_rate_hz)
/// that publishes ROBOT_STATE when valid and sets the heartbeat's health. Call before Run.
void ConnectEstimatorNode(procs::ProcessLoop* loop, EstimatorNode* node, double period_s);

}  // namespace topay::estimator
