#pragma once
// topay-planner on the bus: GOAL, ROBOT_STATE, MAP_UPDATE and TRACKER_STATUS in, TRAJECTORY,
// PLANNER_STATUS and PLANNER_PATHS out (docs/planner.md). The LCM thread only decides; the plans
// run on the planning thread (PlanWorker). It replans when
//  (a) a map update shows the rest of the current trajectory colliding (checked at once
//      against the map's blocked voxels, exactly),
//  (b) the robot has drifted from the trajectory beyond the tolerances,
//  (c) the goal changed (a new goal cancels the plan in progress; a GOAL with the id of the
//      last one is not a new goal: a repeat is ignored, a different target under it refused),
//  (e) the map is fresh again after it went stale (its newest scan older than
//      map.stale_stop_s: the robot was stopped and no plan went out meanwhile),
//  (d) the tracker is released after it was HELD (the CAN bridge stopped or faulted the robot,
//      or it came to rest on a stale robot state, and the tracker dropped every trajectory):
//      while held it forgets its trajectories, cancels the plan in progress and waits; then it plans from rest where the robot stopped,
// and, while the robot moves, a replan starts on the current trajectory at t0 = now + the
// replanning budget and joins it there C2-continuously. If the trajectory ahead collides and
// no new one comes before the robot must start braking, it publishes a stopping trajectory
// along the current path and keeps trying.
// In deterministic mode (options.deterministic) its clock is message time and its plans are
// synchronous: messages wait in an inbox while a plan runs (docs/planner.md#replay).

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Geometry>

#include "core/control/tracked_robot_prediction.h"
#include "core/control/tracker_limits.h"
#include "core/optimization/trajectory_problem.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/convert_goal.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/robot_state_intake.h"
#include "procs/planner/active_trajectory.h"
#include "procs/planner/goal_screen.h"
#include "procs/planner/issued_goals.h"
#include "procs/planner/map_intake.h"
#include "procs/planner/plan_worker.h"
#include "procs/planner/planner_clock.h"
#include "procs/planner/planner_process_options.h"
#include "procs/planner/stop_planner.h"
#include "procs/planner/trajectory_delivery.h"
#include "procs/runtime/process_loop.h"
#include "topay/goal_t.hpp"
#include "topay/map_update_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::planner {

/// Why a plan was asked for.
/// kDriftCollision: the robot, off the trajectory, collides as it drifts (drifted_collision.h).
enum class PlanTrigger { kGoal, kMapCollision, kDrift, kDriftCollision, kRetry, kResume };
const char* ToString(PlanTrigger trigger);

/// What the node counted since its start (the heartbeat and the exit report).
struct PlannerNodeCounts {
  std::map<PlanTrigger, std::int64_t> triggers;
  std::int64_t goals = 0, goals_refused = 0, goals_cancelled = 0;
  std::int64_t goals_failed_on_map = 0;  ///< goals in hand the map came to refuse (FailGoalTheMapRefuses)
  std::int64_t goals_repeated = 0;  ///< repeats of the last goal (same id and content): ignored
  std::int64_t stale_map_stops = 0;  ///< stopping trajectories for a stale map (map.stale_stop_s)
  std::int64_t trajectories = 0, stops = 0;
  std::int64_t plans_failed = 0, results_dropped_late = 0, results_colliding = 0;
  std::int64_t escapes = 0;  ///< plans from rest planned again with the arm's escape allowance (finding 18)
  std::int64_t maps_rejected = 0, map_checks = 0;
  /// Checks of the drifted robot (triggers.drift_check), and how many found a collision.
  std::int64_t drift_checks = 0, drift_collisions = 0;
  /// Drift replans started where the tracker will have brought the robot (triggers.drift_start
  /// tracked), the largest prediction's time (ms) and the largest distance (m) between that
  /// start and the one carried with the robot's error (PredictDriftedStart).
  std::int64_t tracked_starts = 0;
  double tracked_start_ms_max = 0.0, tracked_start_shift_m_max = 0.0;
  double map_check_ms_max = 0.0, map_check_ms_sum = 0.0;
  /// Deterministic mode: messages handled from the inbox (all, and by PlannerInput's
  /// alternative: GOAL, ROBOT_STATE, MAP_UPDATE, TRACKER_STATUS), and the most that waited.
  std::int64_t inbox_handled = 0, inbox_max = 0;
  std::array<std::int64_t, 4> inbox_handled_by_channel{};
};

/// A message of the planner's inputs, as it waits in the deterministic mode's inbox.
using PlannerInput = std::variant<goal_t, robot_state_t, map_update_t, tracker_status_t>;

class PlannerNode {
 public:
  /// Subscribes and adds its timer to *loop (before Run). Everything passed outlives it.
  /// tracked_start: where drift replans start (triggers.drift_start tracked; null: carried,
  /// PredictDriftedStart).
  PlannerNode(procs::ProcessLoop* loop, PlanWorker* worker, const Kinematics& kinematics,
              const StopPlanner& stop_planner, const PlannerProcessOptions& options,
              TrackedRobotPredictor* tracked_start = nullptr);

  void OnGoal(const goal_t& msg);
  /// A goal that fails its screen: FAILED under its id; a goal in hand is kept.
  void RefuseGoal(std::int64_t goal_id, const std::string& reason);
  void OnRobotState(const robot_state_t& msg);
  void OnMap(const map_update_t& msg);
  void OnTrackerStatus(const tracker_status_t& msg);
  /// Every 10 ms: plan results, the safe stop, retries, the periodic status. In deterministic
  /// mode only the result of the plan the inbox waits for: the rest is decided per message.
  void Tick();
  /// A message from the bus: handled at once on the wall clock; in deterministic mode queued
  /// and handled in order, at its message time, as soon as no plan is running (HandleInbox).
  void Receive(PlannerInput msg);
  /// Deterministic mode, once the loop has stopped: handles what is left in the inbox, waiting
  /// for each plan (up to deterministic.time_limit_s + 5 s), so that every message received has
  /// its outputs whenever the process is stopped. Returns the messages still left (0 unless a
  /// plan never came back).
  std::size_t FinishInbox();

  const PlannerNodeCounts& counts() const { return counts_; }
  std::string Report() const;

 private:
  struct GoalRecord {
    msgs::PlanGoal goal;
    bool planned_once = false;  // a trajectory went out for it
    bool done = false;          // failed, or its trajectory ended
    bool ended = false;         // done because its trajectory ended (MaybeFinishGoal)
    int replans = 0;
    int failed_attempts = 0;    // plans that failed before its first trajectory went out
    int failed_from_rest = 0;   // plans from rest that failed in a row after it
    // The standing arm was found in the map's voxels deeper than map.start_arm_overlap_m: its
    // plans from rest leave out map.start_arm_escape_overlap_m until one goes out (finding 18).
    bool escape = false;
  };

  void Dispatch(const PlannerInput& msg);
  // Deterministic mode: the queued messages in order, each followed by the decisions at its
  // time (DecideAt), until one starts a plan (the others wait for its result: Tick).
  void HandleInbox();
  // Deterministic mode: the result of the plan the inbox waited for, then what its message
  // left to decide.
  void HandleAwaitedOutcome(PlanJobOutcome outcome);
  // The decisions that depend on time alone: the safe stop, the goal's end, a pending or
  // retried plan, the periodic status.
  void DecideAt(std::int64_t now);
  // A failed or unusable plan: tried again after timing.retry_period_s while the goal stands.
  void ScheduleRetry(std::int64_t now, const std::string& detail, const WholeBodyPlanResult* result);
  // Starts a plan now (a goal, or `preempt`: cancelling the one in progress) or after the plan
  // in progress.
  void RequestPlan(PlanTrigger trigger, const std::string& reason, bool preempt = false);
  bool FillStart(PlanTrigger trigger, std::int64_t now, PlanJob* job, std::string* error);
  // Where a drift replan from `on` starts at t0 (tracked_start_, or carried along); *spent_s:
  // the wall-clock time the prediction took (0 in message time), which the plan does not have.
  TrajectorySample DriftedStart(const ActiveTrajectory& on, std::int64_t t0, double* spent_s);
  void HandleOutcome(PlanJobOutcome outcome);
  void HandleFailure(const PlanJobOutcome& outcome);
  void PublishTrajectory(const PlanJobOutcome& outcome, std::int64_t now);
  void PublishActive(const char* what);
  // PLANNER_PATHS: the plan's candidate base paths (trajectory_id 0: the plan failed).
  void PublishPaths(const WholeBodyPlanResult& result, std::int64_t goal_id, std::int64_t trajectory_id);
  // The first collision of `trajectory` from t_from_s on the newest map (without the voxels
  // of `standing`: a plan from rest).
  std::optional<PredictedCollision> CheckAhead(const ArcYawTrajectory& trajectory, double t_from_s,
                                               const std::optional<StandingRobot>& standing) const;
  // The map's blocked voxels in `region` as boxes (without those of `standing`).
  Scene BoxesNear(const Eigen::AlignedBox3d& region, const std::optional<StandingRobot>& standing) const;
  // The first collision ahead of the trajectory and, while the robot is off it by more than
  // triggers.drift_check's tolerances, of the drifted robot (CheckDriftedAhead); the earlier
  // one replans (and is stopped for by MaybeSafeStop), none clears the prediction.
  void CheckActiveAgainstMap(std::int64_t now);
  struct DriftedCollision {
    PredictedCollision hit;  // t_s along active_
    Drift drift;
  };
  // The drifted robot's first collision within triggers.drift_check.horizon_s (nullopt: none,
  // or not checked: no fresh state, drift within the tolerances, not on active_).
  std::optional<DriftedCollision> CheckDriftedAhead(std::int64_t now);
  // Keeps the base position at t_s on `trajectory` (a predicted collision) for FreshRegions.
  void RememberCollision(const ArcYawTrajectory& trajectory, double t_s);
  // Where a plan from `start` needs the newest map in its fields: around its start and the
  // recent collisions.
  std::vector<Eigen::AlignedBox2d> FreshRegions(const TrajectorySample& start) const;
  void MaybeSafeStop(std::int64_t now);
  // map.stale_stop_s: stops the robot and holds the plans while the map's newest scan is too
  // old; plans the goal again once it is fresh.
  void CheckMapFreshness(std::int64_t now);
  // A goal in hand whose target the map now refuses (ScreenTargetInMap: e.g. a box seen from
  // around, its inside holding the target): FAILED, its plans dropped, a moving robot stopped.
  // True if it failed.
  bool FailGoalTheMapRefuses(std::int64_t now);
  // A stopping trajectory from the one the robot is on at now + stop.latency_s (nullopt with
  // *why when none can be made), and its publication (STOPPING with `detail`).
  // `blind`: the stale map's stop, shorter (stop.blind_duration_per_rate_ratio).
  std::optional<ArcYawTrajectory> MakeStop(std::int64_t begin, std::string* why, bool blind = false) const;
  // A stop for a robot that collides as it drifts off `on` (collision_by_drift_): `stop` (made
  // from `on` at `begin`) moved to where the robot will be then (DriftedRobot). Braking along
  // the trajectory, the tracker would first close the robot's error, driving it through what
  // the drift check found (finding 34); from where it is, it only brakes.
  ArcYawTrajectory StopWhereTheRobotIs(const ActiveTrajectory& on, std::int64_t begin, ArcYawTrajectory stop) const;
  void PublishStop(ArcYawTrajectory stop, std::int64_t begin, const std::string& detail);
  // A new trajectory id: the clock's microseconds, or one more than the last id when that is
  // later. Unique and increasing across restarts of the planner: the tracker takes only a
  // trajectory newer than the one it has, and a restarted planner counting from 1 again had
  // every trajectory ignored while the tracker kept the dead planner's last one (finding 13).
  std::int64_t NextTrajectoryId();
  /// Straight-line distance (m) from the robot's place on active_ now to the predicted collision.
  double CollisionDistance(std::int64_t now) const;
  void MaybeFinishGoal(std::int64_t now);
  // At rest with the end effector within goals.reached_* of the target: the goal is reached
  // (SUCCEEDED "goal reached at rest ..."), no plan. True if so.
  bool ReachedAtRest(const WholeBodyState& state);
  void PublishStatus(std::int8_t state, const std::string& reason, const std::string& detail,
                     const WholeBodyPlanResult* result = nullptr);
  void UpdateHealth();
  // Sends the newest TRAJECTORY again while the tracker does not report it (TrajectoryDelivery).
  void ResendUnconfirmed(std::int64_t now);
  // The tracker is HELD (drives not running): the robot is at rest off every trajectory.
  void Hold(const tracker_status_t& msg);
  // Cancels the plan in progress and forgets the pending and retried ones (a hold, a stale map).
  void AbandonPlans();
  void MakeActive(ActiveTrajectory trajectory);
  void ClearPredictedCollision();
  // The trajectory the robot is on at `utime`: the newest one started by then (null: none).
  const ActiveTrajectory* OnAt(std::int64_t utime) const;
  // The map's age (s) beyond which it is stale at now (map.stale_stop_s, shorter while moving:
  // map.stale_blind_distance_m).
  double StaleLimitS(std::int64_t now) const;

  procs::ProcessLoop* loop_;
  PlanWorker* worker_;
  const Kinematics& kinematics_;
  const StopPlanner& stop_planner_;
  PlannerProcessOptions options_;
  TrackedRobotPredictor* tracked_start_;
  TrackerLimits plan_limits_;  // the plans' rate limits (a share of the robot's accelerations)
  PlannerClock clock_;
  std::deque<PlannerInput> inbox_;  // deterministic mode: messages waiting for the running plan
  bool awaiting_plan_ = false;      // deterministic mode: a plan runs, the inbox waits for it
  ReachHeights reach_;
  MapIntake map_;
  msgs::RobotStateIntake robot_intake_;  // decode, joint count, continuity gate
  std::optional<msgs::RobotStateEstimate> robot_;
  std::optional<tracker_status_t> tracker_;  // the last TRACKER_STATUS (heartbeat status line)
  bool held_ = false;                        // the last TRACKER_STATUS was HELD
  // Until then, after the tracker's release, a plan waits for the robot at rest (see FillStart).
  std::int64_t rest_after_hold_until_utime_ = 0;
  bool map_stale_ = false;                   // the map's newest scan is older than map.stale_stop_s
  // The GOALs' ids and contents (GoalContent): ids are issued once; a repeat is ignored and a
  // different goal under an id taken before refused, also after newer goals (finding 36).
  IssuedGoals issued_goals_;
  std::optional<GoalRecord> goal_;
  std::optional<ActiveTrajectory> active_;
  // The trajectories active_ replaced that may still be under way (the newest last): until a
  // new trajectory's start_utime the robot follows the one before it.
  std::deque<ActiveTrajectory> replaced_;
  std::optional<std::int64_t> collision_utime_;  // predicted collision on active_, if any
  std::optional<std::int64_t> collision_seen_utime_;  // ... when it was first predicted
  std::int64_t last_drift_check_utime_ = 0;  // the drifted robot's last check (drift_check.period_s)
  bool collision_by_drift_ = false;  // collision_utime_ is the drifted robot's (CheckDriftedAhead)
  std::vector<Eigen::Vector2d> collision_points_;  // base xy at the newest predicted collisions
  std::optional<double> last_stop_duration_s_;   // of the last stopping trajectory made for it
  std::int64_t last_stop_made_utime_ = 0;         // ... and when
  bool stop_error_logged_ = false;
  std::optional<std::pair<PlanTrigger, std::string>> pending_;  // asked for while busy
  std::int64_t retry_at_utime_ = 0;               // 0: no retry scheduled
  std::int64_t job_seq_ = 0, latest_job_ = 0;
  std::int64_t trajectory_seq_ = 0;  // the last trajectory id issued (NextTrajectoryId)
  TrajectoryDelivery delivery_;  // the newest TRAJECTORY until the tracker reports it (wall clock only)
  planner_status_t status_{};
  std::int64_t last_status_utime_ = 0;
  PlannerNodeCounts counts_;
};

}  // namespace topay::planner
