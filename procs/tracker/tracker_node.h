#pragma once
// topay-tracker's logic (docs/tracker.md): TRAJECTORY, ROBOT_STATE, GRIPPER_COMMAND, DRIVE_STATUS
// and the planner's HEARTBEAT in; every cycle (50 Hz) NmpcTracker::Step and a CONTROL_COMMAND and TRACKER_STATUS out. No LCM in the
// class itself (ConnectTrackerNode wires it to a ProcessLoop), so tests call its handlers with
// the times they choose.
//
// Trajectories: a TRAJECTORY is rebuilt into the core trajectory (msgs::ToArcYaw, exact MINCO
// check); one whose start_utime is in the future waits (pending) and becomes active at its
// start, the current one being followed until then. A new one replaces the pending ones that
// start at or after its own start (they would never run) and keeps those that start before it:
// they run from their start until its own, as the planner assumes (it plans a replan from the
// trajectory the robot will be on at the replan's start; dropping such a one left the robot
// stopped where the next trajectory expected it moving, 0.3 m behind). An id older than or
// equal to the active's (or the newest pending one's) is ignored. Bad ones are counted and
// logged, never followed. Safe behaviour (no trajectory, an ended one, a robot state older than
// nmpc.stale_state_s or none) is NmpcTracker's: decelerate to a stop within the limits.
//
// Drives not running: a DRIVE_STATUS whose state is not RUNNING (the CAN bridge stopped or
// faulted the robot, or is starting or recovering) holds the tracker: it drops its trajectories,
// commands exact zeros (the bridge's condition for running again) and drops every TRAJECTORY
// that comes meanwhile; its status is HELD. When the bridge is RUNNING again the tracker is IDLE
// at rest, and the planner, which saw HELD, plans anew from where the robot stopped. Without a
// bridge (no DRIVE_STATUS, e.g. the kinematic simulator) the drives never hold it.
//
// Stopped on a stale state: once the stop on a state gone stale has brought the command to
// rest, the trajectory is dropped and the tracker is HELD the same way until a fresh state
// comes; it is then IDLE at rest and the planner plans anew from there. Resuming the old
// trajectory instead chased a reference that had run on (by the length of the gap) from a state
// that may have jumped meanwhile (localisation back after 8 s lost: 1.7 m), through whatever was
// in between (fault campaign 2026-12-05: the base 0.16 m into a box). docs/tracker.md.
//
// Tracking lost: a base position error above options.lost_position_m while tracking drops the
// trajectory; the robot brakes within the limits (status HELD, trajectories dropped) and is
// released at rest, where the planner plans anew.
//
// Unguarded trajectories (PlannerWatch, finding 24): the planner that published the trajectories
// restarted (its HEARTBEAT from a new process) or fell silent (options.planner_watch.silence_s):
// nobody checks them against the map any more, so they are dropped and the robot brakes the same
// way (HELD until at rest); the planner, restarted, plans anew from rest where it stopped.
//
// Protective field (finding 30; core/control/protective_field.h): with a robot model, POINT_CLOUD
// scans (the robot's own body removed, FieldScanIntake) are kept, and every tracking cycle the
// base cylinder along the reference ahead, as far as the robot needs to stop, is checked against
// them; enough points inside drop the trajectory and brake the same way (HELD until at rest; the
// planner plans anew from rest). It needs no map: the planner cannot avoid what its map lacks.

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/control/nmpc_tracker.h"
#include "core/control/protective_field.h"
#include "core/control/tracker_limits.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/robot_state_intake.h"
#include "procs/tracker/field_scan_intake.h"
#include "procs/tracker/planner_watch.h"
#include "procs/tracker/tracker_options.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::procs {
class ProcessLoop;
}

namespace topay::tracker {

/// What the node counted since its start (heartbeat and exit report).
struct TrackerCounts {
  std::int64_t trajectories = 0;          ///< TRAJECTORY messages handled
  std::int64_t trajectories_rejected = 0; ///< malformed, wrong joint count or not MINCO
  std::int64_t trajectories_ignored = 0;  ///< id not newer than the active or the newest pending one
  std::int64_t pending_superseded = 0;    ///< pending ones dropped: a newer one starts first
  std::int64_t switches = 0;              ///< trajectories that became active
  std::int64_t states = 0, states_rejected = 0;  ///< rejected: malformed or refused by the continuity gate
  std::int64_t grippers = 0, grippers_rejected = 0;
  std::int64_t cycles = 0, solves = 0;
  std::int64_t stops_stale = 0;  ///< cycles that entered the stale-state stop
  std::int64_t stops_ended = 0;  ///< trajectories whose end was reached (stop after the settle)
  std::int64_t holds = 0;        ///< times a DRIVE_STATUS not RUNNING held the tracker
  std::int64_t trajectories_dropped_held = 0;  ///< active, pending or arriving ones dropped while held
  std::int64_t stale_holds = 0;  ///< times the robot came to rest on a stale state (trajectory dropped, held)
  std::int64_t losses = 0;       ///< times tracking was lost (options.lost_position_m): dropped, braked, held
  /// times the planner restarted or fell silent while the robot could move: dropped, braked, held
  std::int64_t unguarded = 0;
  /// times the robot state jumped (options.jump_*) while the robot could move: dropped, braked, held
  std::int64_t jumps = 0;
  std::int64_t scans = 0, scans_rejected = 0;  ///< POINT_CLOUDs taken by the protective field / refused
  /// times the protective field was entered while tracking: dropped, braked, held
  std::int64_t protective_stops = 0;
  /// cycles whose arm reference waited for a lagging base (NmpcOptions::arm_pacing), and the
  /// times such a wait began
  std::int64_t arm_paced_cycles = 0, arm_pacings = 0;
};

/// One cycle's messages.
struct TrackerCycle {
  control_command_t command{};
  tracker_status_t status{};
};

class TrackerNode {
 public:
  /// Throws std::invalid_argument for bad NMPC options or limits. Without a robot model: no
  /// protective field (POINT_CLOUD ignored).
  TrackerNode(const TrackerOptions& options, const TrackerLimits& limits);
  /// The limits from `model` (MakeTrackerLimits) and, if options.protective_field.enabled, the
  /// protective field on its base. Throws std::invalid_argument for bad options.
  TrackerNode(const TrackerOptions& options, const RobotModel& model);

  void OnTrajectory(const poly_trajectory_t& msg, std::int64_t now_utime);
  void OnRobotState(const robot_state_t& msg);
  void OnGripper(const gripper_command_t& msg);
  /// A LiDAR scan for the protective field (ignored without one).
  void OnPointCloud(const point_cloud_t& msg);
  /// The CAN bridge's state: not RUNNING (REPLAY aside) holds the tracker, RUNNING releases it.
  void OnDriveStatus(const drive_status_t& msg);
  /// Every process's HEARTBEAT, received at now_utime: the planner's restart brakes the robot
  /// off the trajectories it no longer guards (PlannerWatch).
  void OnHeartbeat(const heartbeat_t& msg, std::int64_t now_utime);
  /// One control cycle at now_utime: activates a pending trajectory whose start has come,
  /// steps the NMPC and returns the command and the status to publish.
  const TrackerCycle& Step(std::int64_t now_utime);

  const TrackerCounts& counts() const { return counts_; }
  const NmpcTracker& tracker() const { return tracker_; }
  const PlannerWatch& planner_watch() const { return planner_watch_; }
  /// The protective field (nullptr: none).
  const ProtectiveField* protective_field() const { return field_ ? &*field_ : nullptr; }
  /// The active trajectory's id (0: none) and the next pending one's (0: none).
  std::int64_t active_id() const { return active_ ? active_->id : 0; }
  std::int64_t pending_id() const { return pending_.empty() ? 0 : pending_.front().id; }
  /// True while the drives are not running (the last DRIVE_STATUS was not RUNNING), the
  /// robot, stopped on a stale state, waits for a fresh one, or it brakes after tracking was
  /// lost or its trajectories were left unguarded.
  bool held() const { return held_ || stale_held_ || lost_; }
  /// heartbeat_t::WARN while held or stopping on a stale or missing robot state with a
  /// trajectory, else OK; and the heartbeat's status line (mode, ids, solves, fallbacks, rejected messages).
  std::int8_t Health() const;
  std::string StatusLine() const;
  /// The final report: cycles, solves, median / p99 solve ms, fallbacks, stops, counts.
  std::string Report() const;

 private:
  struct Loaded {
    std::int64_t id = 0;
    std::int64_t goal_id = 0;
    std::int64_t start_utime = 0;
    std::shared_ptr<const ArcYawTrajectory> trajectory;
    TrackerReference reference;
  };
  double Seconds(std::int64_t utime);
  void Activate(Loaded loaded);
  void Fill(const TrackerOutput& out, std::int64_t now_utime);
  void FillHeld(std::int64_t now_utime);
  void DropTrajectories(std::string_view why);  // logs why, counts and drops active and pending ones
  bool StateFresh(std::int64_t now_utime) const;
  // Tracking lost: the NMPC's stop (no reference) within the limits, status HELD, released at rest.
  const TrackerCycle& StepLost(std::int64_t now_utime);
  // Drops the trajectories and brakes like a loss of tracking, for `reason` (the status line's
  // words) logged with `why`; counts it in *count.
  void BrakeOff(std::int64_t* count, std::string reason, std::string_view why);
  // A taken state farther from the last one than the robot's limits allow (options.jump_*):
  // brakes off the trajectories.
  void CheckJump(const msgs::RobotStateEstimate& next);
  // A trajectory the robot may still be moving on: active and not FINISHED, or pending.
  bool MayMove() const;
  // Counts the cycles whose arm waited for the base (report).
  void NoteArmPacing(const TrackerOutput& out);
  TrackerInput StateInput(std::int64_t now_utime);
  // The protective field on the active reference ahead: true if it was entered (braking begun).
  bool FieldEntered(std::int64_t now_utime);

  TrackerOptions options_;
  int num_joints_;
  BaseLimits base_limits_;  // the robot's (the jump check)
  NmpcTracker tracker_;
  std::optional<std::int64_t> origin_utime_;  // utime of the core's t = 0 s (first one seen)
  std::optional<Loaded> active_;
  std::deque<Loaded> pending_;  // by start time, all in the future
  msgs::RobotStateIntake state_intake_;  // decode, joint count, continuity gate
  std::optional<msgs::RobotStateEstimate> state_;
  std::optional<double> gripper_;       // the latest GRIPPER_COMMAND target
  double measured_gripper_ = 0.0;       // the robot's, until a GRIPPER_COMMAND comes
  TrackerMode last_mode_ = TrackerMode::kStopNoReference;
  bool held_ = false;
  std::string hold_reason_;  // the bridge's state and stop reason while held
  bool stale_held_ = false;  // at rest after a stale-state stop, until a fresh state
  bool lost_ = false;        // braking after tracking was lost (or unguarded), until at rest
  std::string lost_reason_;  // ... why, in the status line's words
  PlannerWatch planner_watch_;
  std::optional<ProtectiveField> field_;
  std::unique_ptr<FieldScanIntake> field_intake_;
  std::vector<Eigen::Vector3f> field_points_;  // the last scan's obstacle points (W)
  std::vector<Eigen::Vector2d> field_path_;    // base positions ahead (W)
  TrajectorySample field_sample_;
  std::vector<double> solve_ms_;
  double arm_lag_s_ = 0.0, arm_lag_max_s_ = 0.0;  ///< the arm's lag: the last cycle's, the largest
  TrackerCycle cycle_;
  TrackerCounts counts_;
};

/// Subscribes `node` to TRAJECTORY, ROBOT_STATE, GRIPPER_COMMAND, DRIVE_STATUS, HEARTBEAT and
/// (with a protective field) POINT_CLOUD on *loop (times from the
/// wall clock, procs::NowUtime) and adds the cycle timer (nmpc.control_period_s) that publishes
/// CONTROL_COMMAND and TRACKER_STATUS and sets the heartbeat's health. Call before Run.
void ConnectTrackerNode(procs::ProcessLoop* loop, TrackerNode* node, double period_s);

}  // namespace topay::tracker
