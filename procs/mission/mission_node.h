#pragma once
// The mission sequencer's logic (topay-mission, docs/mission.md), free of the bus: main.cc
// feeds it messages and the time, and it answers through MissionOutputs. Steps run in order:
//  - goto / home: a GOAL with a fresh goal id; arrived when the planner reports SUCCEEDED
//    "trajectory N ended" for that id AND the end effector (ROBOT_STATE + kinematics) is
//    within the tolerance of the target AND, once any TRACKER_STATUS has come (a tracker
//    runs), the tracker reports FINISHED for that goal's ended trajectory. A FAILED (or CANCELLED) plan is sent
//    again with a new id up to max_attempts; a step that does not arrive within its timeout
//    fails the mission. home goes to the end-effector pose of the start state (the first
//    ROBOT_STATE), with that state as the hint.
//    While it waits, the goal is re-sent unchanged every goal_repeat_period_s (a restarted
//    planner lost it; the planner ignores repeats).
//  - gripper: a GRIPPER_COMMAND, then the settle time.
//  - wait: its duration.
// MISSION_STATUS goes out on every change and every status_period_s.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/robot/kinematics.h"
#include "procs/mission/mission_options.h"
#include "procs/mission/mission_spec.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/robot_state_intake.h"
#include "topay/goal_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::mission {

/// Where the node's messages go (LCM publishers in main, recorders in tests). Each may be empty.
struct MissionOutputs {
  std::function<void(const goal_t&)> goal;
  std::function<void(const gripper_command_t&)> gripper;
  std::function<void(const mission_status_t&)> status;
};

/// What one step took (the summary).
struct StepRecord {
  std::string description;
  double duration_s = 0.0;
  int attempts = 0;   ///< plans sent (goto / home)
  int replans = 0;    ///< the planner's replans for them (PLANNER_STATUS.replans, summed over attempts)
  bool done = false;
};

class MissionNode {
 public:
  /// Goal ids count up from first_goal_id (e.g. the wall clock in us at start: unique across
  /// runs). `kinematics` outlives the node.
  MissionNode(Mission mission, const Kinematics& kinematics, const MissionOptions& options, MissionOutputs outputs,
              std::int64_t first_goal_id);

  // Inputs; `now_utime` is the time of handling (us since the Unix epoch).
  void OnRobotState(const robot_state_t& msg, std::int64_t now_utime);
  void OnPlannerStatus(const planner_status_t& msg, std::int64_t now_utime);
  void OnTrackerStatus(const tracker_status_t& msg, std::int64_t now_utime);
  /// The time-driven part: the start, waits, retries, timeouts, the periodic status. Call it
  /// often (every 50 ms in the process).
  void Tick(std::int64_t now_utime);
  /// Ends a mission not yet over as ABORTED (SIGINT), with `reason`.
  void Abort(const std::string& reason, std::int64_t now_utime);

  bool finished() const;
  /// mission_status_t::IDLE / RUNNING / SUCCEEDED / FAILED / ABORTED.
  std::int8_t state() const { return status_.state; }
  const mission_status_t& status() const { return status_; }
  const std::vector<StepRecord>& steps() const { return records_; }
  /// The start state (the home step's target), once the mission has started.
  const std::optional<WholeBodyState>& start_state() const { return start_state_; }
  /// A one-line status for the heartbeat.
  std::string StatusLine() const;
  /// The end-of-mission summary: result, time, per-step times and attempts.
  std::string Summary() const;

 private:
  void MaybeStart(std::int64_t now);
  void BeginStep(std::size_t index, std::int64_t now);
  void SendGoal(std::int64_t now);
  // The goal in hand again, unchanged, every goal_repeat_period_s (none while a retry waits).
  void RepeatGoal(std::int64_t now);
  void CheckArrival(std::int64_t now);
  // An attempt of a goto / home step failed (`reason`): the goal is sent again after
  // retry_delay_s, or after max_attempts the mission FAILS ("<outcome> after N attempts: ...").
  void AttemptFailed(const std::string& reason, const char* outcome, std::int64_t now);
  // The planner reported the goal CANCELLED (another sender's goal superseded it, `detail`):
  // sent again after retry_delay_s without using an attempt, or after max_preemptions the
  // mission FAILS ("goal superseded N times by other goals").
  void GoalPreempted(const std::string& detail, std::int64_t now);
  void CompleteStep(std::int64_t now);
  void Finish(std::int8_t state, const std::string& detail, std::int64_t now);
  // Publishes MISSION_STATUS with `detail` (logged as a progress line if it changed).
  void Publish(std::int64_t now, const std::string& detail);
  bool MovingStep() const;
  const MissionStep& step() const { return mission_.steps[step_index_]; }
  ArrivalTolerance Tolerance() const;
  // The tracker FINISHED the goal's trajectory that the planner reported ended (or, before
  // that report, any of the goal's).
  bool TrackerFinished() const;
  double StepTimeout() const;
  // End-effector errors (m, rad) against the target from the last robot state (nullopt: none).
  std::optional<std::pair<double, double>> EndEffectorError() const;
  double Seconds(std::int64_t from, std::int64_t to) const { return 1e-6 * static_cast<double>(to - from); }

  Mission mission_;
  const Kinematics& kinematics_;
  MissionOptions options_;
  MissionOutputs outputs_;
  std::int64_t next_goal_id_;
  mission_status_t status_{};
  std::vector<StepRecord> records_;

  msgs::RobotStateIntake robot_intake_;  // decode, joint count, continuity gate
  std::optional<msgs::RobotStateEstimate> robot_;
  std::optional<WholeBodyState> start_state_;
  bool planner_seen_ = false;
  bool tracker_seen_ = false;
  std::int64_t first_tick_utime_ = 0;  // when the node began waiting to start
  std::int64_t start_utime_ = 0;       // when the mission started
  std::int64_t end_utime_ = 0;
  std::int64_t last_publish_utime_ = 0;

  // The step under way.
  std::size_t step_index_ = 0;
  std::int64_t step_start_utime_ = 0;
  std::int64_t step_due_utime_ = 0;    // gripper / wait: when it is done
  Eigen::Isometry3d target_X_WE_ = Eigen::Isometry3d::Identity();
  std::optional<WholeBodyState> target_hint_;
  std::int64_t goal_id_ = 0;           // the goal of the current attempt
  goal_t goal_msg_{};                  // ... as sent (repeated unchanged)
  std::int64_t goal_sent_utime_ = 0;   // ... last sent or repeated
  int attempts_ = 0;
  int preemptions_ = 0;                   ///< this step's goals superseded by other senders' goals
  bool resend_after_preemption_ = false;  ///< the next SendGoal uses no attempt
  std::int64_t retry_utime_ = 0;       // 0: none scheduled
  bool planner_ended_ = false;         // SUCCEEDED "ended" for goal_id_
  std::int64_t ended_trajectory_id_ = 0;     // the trajectory the planner reported ended
  bool reached_at_rest_ = false;       // ... or "goal reached at rest" (no trajectory to finish)
  std::int64_t outside_since_utime_ = 0;     // ended, but the end effector outside the tolerance since
  std::int64_t tracker_finished_id_ = 0;     // the trajectory of goal_id_ the tracker FINISHED (0: none)
  std::int8_t tracker_state_ = -1;           // the tracker's last state, whatever its goal (-1: none yet)
  std::int8_t last_planner_state_ = -1;  // for goal_id_, to log its changes
  std::string last_planner_detail_;
  std::string last_failure_;
  int attempt_replans_ = 0;            // PLANNER_STATUS.replans for goal_id_
  int step_replans_ = 0;               // ... of the step's earlier attempts
};

}  // namespace topay::mission
