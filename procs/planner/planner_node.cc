#include "procs/planner/planner_node.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/collision/scene_clearance.h"
#include "core/common/angles.h"
#include "core/common/stamp_difference.h"
#include "core/common/stopwatch.h"
#include "core/trajectory/offset_trajectory.h"
#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/planner_status_text.h"
#include "procs/planner/paths_message.h"
#include "topay/heartbeat_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::planner {
namespace {

// After the tracker's release a plan waits this long at most for the robot to come to rest (it
// brakes from at most 1 m/s within about 1 s); then a robot still moving is planned from a
// moving start as before.
constexpr double kRestAfterHoldWaitS = 3.0;

std::int64_t Micros(double seconds) { return static_cast<std::int64_t>(std::llround(seconds * 1e6)); }

bool AtRest(const TrajectorySample& s, double rest_speed) {
  return std::abs(s.v_mps) < rest_speed && std::abs(s.omega_radps) < rest_speed &&
         (s.qd_radps.size() == 0 || s.qd_radps.cwiseAbs().maxCoeff() < rest_speed);
}

// A measured robot state as a plan's start: the pose and joints, with the measured rates and
// zero accelerations.
TrajectorySample StartFromEstimate(const msgs::RobotStateEstimate& robot) {
  TrajectorySample s = MakeTrajectorySample(robot.state.num_joints());
  s.state = robot.state;
  s.v_mps = robot.v_mps;
  s.omega_radps = robot.omega_radps;
  if (robot.qdot_radps.size() == robot.state.q_rad.size()) s.qd_radps = robot.qdot_radps;
  return s;
}

// A plan from rest is validated without the robot's own voxels at its start (PlanWorker).
std::optional<StandingRobot> StandingOf(const PlanJob& job) {
  if (!job.from_rest) return std::nullopt;
  return job.Standing();
}

// A plan from rest that failed on its start because an arm sphere stands in the map's blocked
// voxels, as the core words it: "start state: the arm sphere 11 (...) penetrates box ..."
// (DiagnoseStartState, core/collision/start_target_diagnosis.h) or "start state: arm collision
// (...)" (core/planner/plan_in_scene.cc). PlannerProcess.AnArmStoppedDeepInVoxelsIsPlannedOutOfThem
// holds the wording.
bool StartArmInCollision(const PlanJob& job, const WholeBodyPlanResult& r) {
  const std::string& why = r.failure_reason;
  return job.from_rest && (why.find("start state: the arm sphere") != std::string::npos ||
                           why.find("start state: arm collision") != std::string::npos);
}

// The goal's content (all but its utime) as bytes: a goal id is issued once.
std::vector<std::uint8_t> GoalContent(goal_t msg) {
  msg.utime = 0;
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace

const char* ToString(PlanTrigger trigger) {
  switch (trigger) {
    case PlanTrigger::kGoal: return "goal";
    case PlanTrigger::kMapCollision: return "map_collision";
    case PlanTrigger::kDrift: return "drift";
    case PlanTrigger::kDriftCollision: return "drift_collision";
    case PlanTrigger::kRetry: return "retry";
    case PlanTrigger::kResume: return "resume";
  }
  return "?";
}

PlannerNode::PlannerNode(procs::ProcessLoop* loop, PlanWorker* worker, const Kinematics& kinematics,
                         const StopPlanner& stop_planner, const PlannerProcessOptions& options,
                         TrackedRobotPredictor* tracked_start)
    : loop_(loop),
      worker_(worker),
      kinematics_(kinematics),
      stop_planner_(stop_planner),
      options_(options),
      tracked_start_(tracked_start),
      plan_limits_(MakeTrackerLimits(kinematics.model())),
      clock_(options.deterministic.enabled ? ClockSource::kMessages : ClockSource::kWall),
      reach_(ComputeReachHeights(kinematics)),
      map_(options.map.unknown),
      robot_intake_(kinematics.num_joints()),
      delivery_(options.delivery) {
  const std::string goal(channels::GOAL), state(channels::ROBOT_STATE), map(channels::MAP_UPDATE),
      tracker(channels::TRACKER_STATUS);
  const std::vector<lcm::Subscription*> subscriptions = {
      loop->Subscribe<goal_t>(goal, [this](const goal_t& m) { Receive(m); }),
      loop->Subscribe<robot_state_t>(state, [this](const robot_state_t& m) { Receive(m); }),
      loop->Subscribe<map_update_t>(map, [this](const map_update_t& m) { Receive(m); }),
      loop->Subscribe<tracker_status_t>(tracker, [this](const tracker_status_t& m) { Receive(m); })};
  if (clock_.message_time()) {
    // Every input counts: LCM's default queue (30 messages not yet handled) would drop some
    // while the loop works through a backlog.
    for (lcm::Subscription* s : subscriptions) {
      if (s != nullptr) s->setQueueCapacity(0);  // 0: no limit
    }
  }
  loop->AddTimer(0.01, [this] { Tick(); });
  status_.state = planner_status_t::IDLE;
  loop->SetHealth(heartbeat_t::OK, "waiting for a goal");
}

void PlannerNode::Receive(PlannerInput msg) {
  if (!clock_.message_time()) {
    Dispatch(msg);
    return;
  }
  inbox_.push_back(std::move(msg));
  counts_.inbox_max = std::max<std::int64_t>(counts_.inbox_max, static_cast<std::int64_t>(inbox_.size()));
  HandleInbox();
}

void PlannerNode::Dispatch(const PlannerInput& msg) {
  if (const auto* m = std::get_if<goal_t>(&msg)) OnGoal(*m);
  if (const auto* m = std::get_if<robot_state_t>(&msg)) OnRobotState(*m);
  if (const auto* m = std::get_if<map_update_t>(&msg)) OnMap(*m);
  if (const auto* m = std::get_if<tracker_status_t>(&msg)) OnTrackerStatus(*m);
}

void PlannerNode::HandleInbox() {
  // A long backlog is worked through in slices (the rest in the next Tick), so that the loop
  // keeps reading the bus and heartbeating; only when a message is handled depends on the
  // wall clock, never what is decided.
  constexpr double kSliceMs = 50.0;
  const Stopwatch slice;
  while (!awaiting_plan_ && !inbox_.empty() && slice.ElapsedMs() < kSliceMs) {
    const PlannerInput msg = std::move(inbox_.front());
    inbox_.pop_front();
    ++counts_.inbox_handled;
    ++counts_.inbox_handled_by_channel[msg.index()];
    clock_.OnMessage(std::visit([](const auto& m) { return m.utime; }, msg));
    Dispatch(msg);
    if (!awaiting_plan_) DecideAt(clock_.Now());  // else after its result (Tick)
  }
  UpdateHealth();  // the heartbeat says how far it is (a replay waits for "0 waiting")
}

void PlannerNode::OnGoal(const goal_t& msg) {
  ++counts_.goals;
  const IssuedGoals::Verdict verdict = issued_goals_.Take(msg.goal_id, GoalContent(msg));
  if (verdict != IssuedGoals::Verdict::kNew) {
    // A repeat changes nothing; another goal under an id taken before (a corrupted or foreign
    // sender) must neither take the robot elsewhere in its name nor fail that goal: both ignored.
    const bool same = verdict == IssuedGoals::Verdict::kRepeat;
    ++(same ? counts_.goals_repeated : counts_.goals_refused);
    if (!same || counts_.goals_repeated <= 3) {
      const bool in_hand = goal_ && goal_->goal.goal_id == msg.goal_id;
      spdlog::warn("GOAL {} ignored: {}", msg.goal_id,
                   !same     ? "its id was issued before with a different target"
                   : in_hand ? "a repeat of the goal in hand"
                             : "a repeat of an earlier goal");
    }
    return;
  }
  std::string error;
  const std::optional<msgs::PlanGoal> goal = msgs::FromMessage(msg, &error);
  const std::string reason = goal ? ScreenGoal(*goal, map_, reach_, options_.goals) : "bad goal: " + error;
  if (!reason.empty()) {
    RefuseGoal(msg.goal_id, reason);
    return;
  }
  if (goal_ && !goal_->done) {
    // Superseded: said also when no plan is running (its trajectory under way, a retry due),
    // so whoever sent it knows at once (a mission waited for a forged goal's end, finding 36).
    if (worker_->busy()) worker_->Cancel();
    ++counts_.goals_cancelled;
    PublishStatus(planner_status_t::CANCELLED, "", fmt::format("goal {} superseded by goal {}",
                                                               goal_->goal.goal_id, msg.goal_id));
  }
  goal_ = GoalRecord{*goal};
  collision_points_.clear();
  pending_.reset();
  retry_at_utime_ = 0;
  RequestPlan(PlanTrigger::kGoal, fmt::format("new goal {}", goal->goal_id));
}

void PlannerNode::RefuseGoal(std::int64_t goal_id, const std::string& reason) {
  ++counts_.goals_refused;
  spdlog::warn("goal {} refused: {}", goal_id, reason);
  if (!goal_ || goal_->done) {
    goal_.reset();
    status_.goal_id = goal_id;
    PublishStatus(planner_status_t::FAILED, reason, "goal refused before planning");
    return;
  }
  // A goal in hand goes on: only a goal the planner takes supersedes it (a malformed or
  // impossible goal from any sender must not end the mission's; fault table, session 27). The
  // refusal is said under its own id, apart from the status of the goal in hand.
  planner_status_t refusal{};  // no trajectory, timings or replans: it was never planned
  refusal.utime = clock_.Now();
  refusal.state = planner_status_t::FAILED;
  refusal.goal_id = goal_id;
  refusal.failure_reason = reason;
  refusal.detail = fmt::format("goal refused before planning; goal {} in hand goes on", goal_->goal.goal_id);
  loop_->lcm().publish(std::string(channels::PLANNER_STATUS), &refusal);
}

void PlannerNode::OnRobotState(const robot_state_t& msg) {
  std::string error;
  std::optional<msgs::RobotStateEstimate> robot = robot_intake_.Take(msg, &error);
  if (!robot) {
    if (robot_intake_.LogRefusal()) spdlog::warn("ROBOT_STATE ignored (#{}): {}", robot_intake_.refused(), error);
    return;
  }
  if (robot_intake_.last_verdict() == ContinuityVerdict::kReanchored) {
    spdlog::warn("ROBOT_STATE: {}", robot_intake_.gate_reason());
  }
  robot_ = std::move(robot);
  if (!active_ || active_->stopping || active_->EndedBy(robot_->utime) || !goal_ || goal_->done) return;
  if (robot_->state.num_joints() != active_->trajectory->num_joints()) return;
  const ActiveTrajectory* on_ptr = OnAt(robot_->utime);
  if (on_ptr == nullptr || on_ptr->stopping ||
      on_ptr->trajectory->num_joints() != robot_->state.num_joints()) {
    return;
  }
  const ActiveTrajectory& on = *on_ptr;
  const Drift d = MeasureDrift(on, *robot_);
  const ReplanTriggerOptions& t = options_.triggers;
  if (d.position_m > t.drift_position_m || d.yaw_rad > t.drift_yaw_rad || d.joint_rad > t.drift_joint_rad) {
    RequestPlan(PlanTrigger::kDrift,
                fmt::format("drift from trajectory {}: {:.3f} m, {:.3f} rad yaw, {:.3f} rad joint",
                            on.trajectory_id, d.position_m, d.yaw_rad, d.joint_rad));
  }
  if (DriftWorthChecking(d, t.drift_check) && clock_.Now() - last_drift_check_utime_ >= Micros(t.drift_check.period_s)) {
    CheckActiveAgainstMap(clock_.Now());  // the drifted robot too
  }
}

void PlannerNode::OnMap(const map_update_t& msg) {
  msgs::MapAcceptResult result;
  std::optional<MapWork> work = map_.Accept(msg, &result);
  if (result.outcome == msgs::MapUpdateOutcome::kRejected) {
    ++counts_.maps_rejected;
    spdlog::warn("MAP_UPDATE rejected: {}", result.reason);
    return;
  }
  const bool applied = result.outcome == msgs::MapUpdateOutcome::kSnapshotApplied ||
                       result.outcome == msgs::MapUpdateOutcome::kDeltaApplied;
  if (!work && applied && clock_.message_time()) {
    // A snapshot with nothing new still advances the map's sequence number: the fields must
    // reach it for a plan that waits for every map update (PlanJob::flush_all_map).
    work = MapWork{};
    work->geometry = map_.receiver().geometry();
    work->map_seq = map_.receiver().map_seq();
    work->map_utime = map_.receiver().utime();
  }
  if (work) worker_->SubmitMap(std::move(*work));
  if (applied && !FailGoalTheMapRefuses(clock_.Now())) CheckActiveAgainstMap(clock_.Now());
}

bool PlannerNode::FailGoalTheMapRefuses(std::int64_t now) {
  if (!goal_ || goal_->done) return false;
  const std::string reason = ScreenTargetInMap(goal_->goal.X_WE.translation(), map_, options_.goals);
  if (reason.empty()) return false;
  ++counts_.goals_failed_on_map;
  spdlog::warn("goal {} fails: {} (seen since the goal was taken)", goal_->goal.goal_id, reason);
  goal_->done = true;
  AbandonPlans();
  std::string detail = "the map changed since the goal was taken";
  if (active_ && !active_->stopping && !active_->EndedBy(now)) {
    const std::int64_t begin = now + Micros(options_.stop.latency_s);
    std::string why;
    if (std::optional<ArcYawTrajectory> stop = MakeStop(begin, &why)) {
      PublishStop(std::move(*stop), begin, "the goal's target is inside an obstacle: stopping");
      detail += "; the robot is stopping";
    } else {
      spdlog::error("goal {}: no stopping trajectory: {}", goal_->goal.goal_id, why);
    }
  }
  PublishStatus(planner_status_t::FAILED, reason, detail);
  return true;
}

void PlannerNode::OnTrackerStatus(const tracker_status_t& msg) {
  delivery_.OnTrackerStatus(msg);
  const std::optional<tracker_status_t> before = tracker_;
  tracker_ = msg;
  const bool held = msg.state == tracker_status_t::HELD;
  if (held == held_) return;
  held_ = held;
  if (held) {
    // Its trajectory ended on the planner's clock, but the robot, still closing on the end, was
    // stopped short of it (a bus-off 35 ms after the end left the end effector 3 cm off, and the
    // mission waited 120 s for a FINISHED that never came): the goal is open again, planned from
    // rest once released (or reached at rest where the robot stopped).
    if (goal_ && goal_->ended && (!before || before->state != tracker_status_t::FINISHED)) {
      spdlog::warn("goal {}: held before the tracker finished its trajectory: planned again once released",
                   goal_->goal.goal_id);
      goal_->done = goal_->ended = false;
    }
    return Hold(msg);
  }
  spdlog::info("tracker released: the robot may move again");
  rest_after_hold_until_utime_ = clock_.Now() + Micros(kRestAfterHoldWaitS);
  RequestPlan(PlanTrigger::kResume, "the tracker released the robot");
}

void PlannerNode::AbandonPlans() {
  if (worker_->busy()) worker_->Cancel();
  latest_job_ = 0;  // no result of a plan asked for before is used
  pending_.reset();
  retry_at_utime_ = 0;
}

void PlannerNode::Hold(const tracker_status_t& msg) {
  spdlog::warn("tracker HELD at {:.3f} s: the robot is held at rest (drives stopped, or a stale robot state) and "
               "every trajectory was dropped{}",
               1e-6 * static_cast<double>(msg.utime), active_ ? fmt::format(" (was on {})", active_->trajectory_id) : "");
  AbandonPlans();
  delivery_.Forget();
  active_.reset();
  replaced_.clear();
  ClearPredictedCollision();
  if (goal_ && !goal_->done) {
    PublishStatus(planner_status_t::PLANNING, "", "waiting: the robot is held at rest (tracker HELD)");
  }
}

Scene PlannerNode::BoxesNear(const Eigen::AlignedBox3d& region, const std::optional<StandingRobot>& standing) const {
  Scene scene;
  scene.boxes = standing ? map_.BlockedBoxesNear(region, kinematics_, *standing) : map_.BlockedBoxesNear(region);
  return scene;
}

std::optional<PredictedCollision> PlannerNode::CheckAhead(const ArcYawTrajectory& trajectory, double t_from_s,
                                                           const std::optional<StandingRobot>& standing) const {
  const double height_m = GridBounds(map_.receiver().geometry()).max().z();
  const Scene scene = BoxesNear(
      SweptRegion(trajectory, t_from_s, trajectory.duration_s(), options_.triggers.check_reach_m, height_m), standing);
  if (scene.boxes.empty()) return std::nullopt;
  const SceneClearanceChecker checker(kinematics_, scene);
  return FirstPredictedCollision(trajectory, t_from_s, trajectory.duration_s(), checker,
                                 options_.triggers.check);
}

std::optional<PlannerNode::DriftedCollision> PlannerNode::CheckDriftedAhead(std::int64_t now) {
  if (!robot_ || active_->stopping || OnAt(robot_->utime) != &*active_ ||
      robot_->state.num_joints() != active_->trajectory->num_joints() ||
      !(std::abs(1e-6 * StampDifferenceUs(now, robot_->utime)) <= options_.timing.max_state_age_s)) {
    return std::nullopt;
  }
  const ReplanTriggerOptions& t = options_.triggers;
  const Drift drift = MeasureDrift(*active_, *robot_);
  if (!DriftWorthChecking(drift, t.drift_check)) return std::nullopt;
  last_drift_check_utime_ = now;
  ++counts_.drift_checks;
  const DriftedRobot drifted(*active_, *robot_);
  const double t_from_s = drifted.state_time_s();
  const double height_m = GridBounds(map_.receiver().geometry()).max().z();
  // The region of the trajectory, wider by the drift (the offset turns with the trajectory).
  const Scene scene = BoxesNear(SweptRegion(*active_->trajectory, t_from_s, t_from_s + t.drift_check.horizon_s,
                                            t.check_reach_m + drift.position_m, height_m),
                                active_->standing);
  if (scene.boxes.empty()) return std::nullopt;
  const SceneClearanceChecker checker(kinematics_, scene);
  const std::optional<PredictedCollision> hit = FirstDriftedCollision(drifted, t.drift_check.horizon_s, checker, t.check);
  if (!hit) return std::nullopt;
  ++counts_.drift_collisions;
  return DriftedCollision{*hit, drift};
}

void PlannerNode::CheckActiveAgainstMap(std::int64_t now) {
  if (!active_ || active_->EndedBy(now) || !map_.has_map()) return;
  const Stopwatch watch;
  std::optional<PredictedCollision> hit =
      CheckAhead(*active_->trajectory, active_->TimeAt(now), active_->standing);
  const std::optional<DriftedCollision> drifted = CheckDriftedAhead(now);
  const double ms = watch.ElapsedMs();
  ++counts_.map_checks;
  counts_.map_check_ms_sum += ms;
  counts_.map_check_ms_max = std::max(counts_.map_check_ms_max, ms);
  const bool by_drift = drifted && (!hit || drifted->hit.t_s < hit->t_s);
  if (by_drift) hit = drifted->hit;
  if (!hit) {
    ClearPredictedCollision();
    return;
  }
  const std::int64_t at = active_->start_utime + Micros(hit->t_s);
  // A collision not predicted before (or a new one, sooner): a plan in progress was asked for
  // without it and is replaced at once rather than awaited.
  constexpr double kSooner_s = 0.25;
  const bool first = !collision_utime_;
  const bool sooner = collision_utime_ && at < *collision_utime_ - Micros(kSooner_s);
  collision_utime_ = at;
  collision_by_drift_ = by_drift;
  if (first || sooner) collision_seen_utime_ = now;  // the grace of the safe stop counts from here
  RememberCollision(*active_->trajectory, hit->t_s);
  if (active_->stopping) return;  // braking already; the replans go on (retry)
  const std::string reason =
      by_drift ? fmt::format("the robot, {:.3f} m, {:.3f} rad yaw, {:.3f} rad joint off trajectory {}, collides "
                             "{:.2f} s ahead as it drifts (clearance {:.3f} m, map seq {})",
                             drifted->drift.position_m, drifted->drift.yaw_rad, drifted->drift.joint_rad,
                             active_->trajectory_id, 1e-6 * (at - now), hit->clearance.obstacle_m(),
                             map_.receiver().map_seq())
               : fmt::format("map seq {}: trajectory {} collides {:.2f} s ahead (clearance {:.3f} m)",
                             map_.receiver().map_seq(), active_->trajectory_id, 1e-6 * (at - now),
                             hit->clearance.obstacle_m());
  if (first || sooner) spdlog::info("{}", reason);
  RequestPlan(by_drift ? PlanTrigger::kDriftCollision : PlanTrigger::kMapCollision, reason,
              /*preempt=*/first || sooner);
}

TrajectorySample PlannerNode::DriftedStart(const ActiveTrajectory& on, std::int64_t t0, double* spent_s) {
  *spent_s = 0.0;
  const TrajectorySample carried = PredictDriftedStart(on, *robot_, t0);
  if (tracked_start_ == nullptr) return carried;
  const Stopwatch watch;
  TrackedRobotPredictionSummary summary;
  TrajectorySample tracked;
  try {
    tracked = PredictTrackedStart(tracked_start_, on, *robot_, t0, plan_limits_, &summary);
  } catch (const std::exception& e) {  // the intake checked the state: not expected
    spdlog::error("drift replan from trajectory {}: no tracked start ({}); starting with the error carried along",
                  on.trajectory_id, e.what());
    return carried;
  }
  const double ms = watch.ElapsedMs();
  if (!clock_.message_time()) *spent_s = 1e-3 * ms;
  const double shift_m = std::hypot(tracked.state.x_m - carried.state.x_m, tracked.state.y_m - carried.state.y_m);
  ++counts_.tracked_starts;
  counts_.tracked_start_ms_max = std::max(counts_.tracked_start_ms_max, ms);
  counts_.tracked_start_shift_m_max = std::max(counts_.tracked_start_shift_m_max, shift_m);
  spdlog::info("drift replan from trajectory {}: starts where the tracker will have brought the robot, {:.3f} m "
               "and {:.3f} rad from the start carried with its error ({:.3f} m off the trajectory then; {} cycles, "
               "{:.1f} ms)", on.trajectory_id, shift_m, std::abs(WrapAngle(tracked.state.yaw_rad - carried.state.yaw_rad)),
               summary.final_position_error_m, summary.cycles, ms);
  return tracked;
}

bool PlannerNode::FillStart(PlanTrigger trigger, std::int64_t now, PlanJob* job, std::string* error) {
  const PlanTimingOptions& t = options_.timing;
  const std::int64_t t0 = now + Micros(t.replan_budget_s);
  // A trajectory still running now: the robot will be where it says at t0 (at its end, at
  // rest, if it ends before t0). Not the measured state extrapolated with its rates: a robot
  // braking on a stopping trajectory that ended within the budget was extrapolated 1 s at its
  // yaw rate, the new trajectory began 0.47 rad off, and drift replans compounded it into a box.
  // The trajectory it will be on at t0 (OnAt: the newest one started by then).
  const ActiveTrajectory* on = active_ ? OnAt(t0) : nullptr;
  const bool running = on != nullptr && !active_->EndedBy(now);
  // A drift replan while the robot follows the trajectory it drifted from until t0: where that
  // trajectory will be, with the robot's error carried along (a newer one starting before t0:
  // planned on that one, as any replan; the drift check looks again once it runs).
  const bool drift = trigger == PlanTrigger::kDrift || trigger == PlanTrigger::kDriftCollision;
  const ActiveTrajectory* drifted_from = drift && robot_ ? OnAt(robot_->utime) : nullptr;
  if (running && drifted_from == on) {
    double predicted_s = 0.0;
    job->start = DriftedStart(*on, t0, &predicted_s);
    job->from_rest = false;
    job->on_trajectory_id = on->trajectory_id;
    job->t0_utime = t0;
    // The prediction (tens of ms, more under load) came out of the budget: a plan finishing
    // after t0 is dropped as late. At least kMinDriftPlan_s is left to it.
    constexpr double kMinDriftPlan_s = 0.1;
    job->time_limit_s = std::max(kMinDriftPlan_s, t.replan_budget_s - t.publish_margin_s - predicted_s);
    return true;
  }
  if (running) {
    job->start = on->SampleAt(t0);  // where the robot will be at t0 on the trajectory
    if (!AtRest(job->start, t.rest_speed) || on->TimeAt(t0) > 0.0) {
      job->from_rest = false;
      job->on_trajectory_id = on->trajectory_id;
      job->t0_utime = t0;
      job->time_limit_s = t.replan_budget_s - t.publish_margin_s;
      return true;
    }
  }
  if (!robot_) {
    *error = "no ROBOT_STATE received yet";
    return false;
  }
  job->start = StartFromEstimate(*robot_);
  if (!AtRest(job->start, t.rest_speed) && now < rest_after_hold_until_utime_) {
    // Released after a hold: the tracker commands zero and the robot is still braking. A moving
    // start extrapolated at its measured rates ran 0.35 m ahead of where it stopped, and the
    // drift replans that followed took the base into a box (fault campaign 2026-12-05): wait
    // (retried every timing.retry_period_s) and plan from rest.
    *error = "the robot is coming to rest after the tracker's hold";
    return false;
  }
  if (!AtRest(job->start, t.rest_speed)) {
    // Moving off any trajectory of ours (a restart, one that ended): start at the measured
    // state extrapolated to t0 with its measured rates.
    const double age_s = 1e-6 * StampDifferenceUs(now, robot_->utime);
    if (!(std::abs(age_s) <= t.max_state_age_s)) {
      *error = fmt::format("the robot is moving and its state is {:.2f} s old (more than timing.max_state_age_s, "
                           "{:.2f} s): not extrapolated", age_s, t.max_state_age_s);
      return false;
    }
    const double dt = 1e-6 * StampDifferenceUs(t0, robot_->utime);
    job->from_rest = false;
    job->t0_utime = t0;
    job->time_limit_s = t.replan_budget_s - t.publish_margin_s;
    job->start.state.x_m += dt * job->start.v_mps * std::cos(job->start.state.yaw_rad);
    job->start.state.y_m += dt * job->start.v_mps * std::sin(job->start.state.yaw_rad);
    job->start.state.yaw_rad += dt * job->start.omega_radps;
    job->start.state.q_rad += dt * job->start.qd_radps;
    return true;
  }
  job->start = MakeTrajectorySample(robot_->state.num_joints());  // at rest: rates zero
  job->start.state = robot_->state;
  job->from_rest = true;
  // On the wall clock it starts when it is published; in message time the plan's own time
  // does not exist, so it starts a replanning budget after it was asked for, like a replan.
  job->t0_utime = clock_.message_time() ? t0 : 0;
  job->time_limit_s = t.from_rest_time_limit_s;
  return true;
}

void PlannerNode::RequestPlan(PlanTrigger trigger, const std::string& reason, bool preempt) {
  if (!goal_ || goal_->done) return;
  if (trigger != PlanTrigger::kGoal && !preempt && worker_->busy()) {
    pending_ = {trigger, reason};  // after the plan in progress
    return;
  }
  PlanJob job;
  std::string error;
  const std::int64_t now = clock_.Now();
  if (held_ || map_stale_) {  // planned when the tracker is released / the map is fresh (kResume)
    PublishStatus(planner_status_t::PLANNING, "",
                  held_ ? "waiting: the robot is held at rest (tracker HELD)" : "waiting: the map is stale");
    return;
  }
  if (!map_.has_map()) error = "no map yet (no MAP_UPDATE snapshot received)";  // e.g. a goal at start-up
  if (!error.empty() || !FillStart(trigger, now, &job, &error)) {
    spdlog::warn("goal {}: cannot plan yet: {}", goal_->goal.goal_id, error);
    retry_at_utime_ = now + Micros(options_.timing.retry_period_s);
    PublishStatus(planner_status_t::PLANNING, "", "waiting: " + error);
    return;
  }
  if (job.from_rest && ReachedAtRest(job.start.state)) return;
  job.job_id = latest_job_ = ++job_seq_;
  job.goal_id = goal_->goal.goal_id;
  job.trigger = fmt::format("{}: {}", ToString(trigger), reason);
  job.X_WE_goal = goal_->goal.X_WE;
  job.hint = goal_->goal.hint;
  job.certify_reachability = !goal_->planned_once && options_.goals.certify_reachability;
  job.map_seq = map_.receiver().map_seq();
  job.fresh_regions_xy_W_m = FreshRegions(job.start);
  // From rest there is time (the robot waits): the fields take every map update first.
  job.flush_all_map = job.from_rest && options_.map.flush_all_from_rest;
  job.clear_arm_overlap_m = goal_->escape ? options_.map.start_arm_escape_overlap_m : options_.map.start_arm_overlap_m;
  if (clock_.message_time()) {
    job.flush_all_map = true;  // fields from every map update handled before it
    job.time_limit_s = options_.deterministic.time_limit_s;
  }
  ++counts_.triggers[trigger];
  if (trigger != PlanTrigger::kGoal && trigger != PlanTrigger::kRetry) ++goal_->replans;
  retry_at_utime_ = 0;
  spdlog::info("goal {}: plan {} ({}; {}, limit {:.2f} s)", job.goal_id, job.job_id, job.trigger,
               job.from_rest ? "from rest" : "moving start", job.time_limit_s);
  PublishStatus(planner_status_t::PLANNING, "", job.trigger);
  worker_->SubmitPlan(std::move(job));
  awaiting_plan_ = clock_.message_time();
}

void PlannerNode::Tick() {
  if (clock_.message_time()) {
    if (!awaiting_plan_) {
      if (!inbox_.empty()) HandleInbox();  // the rest of a backlog
    } else if (std::optional<PlanJobOutcome> outcome = worker_->TakeResult()) {
      HandleAwaitedOutcome(std::move(*outcome));
    }
    return;
  }
  while (std::optional<PlanJobOutcome> outcome = worker_->TakeResult()) HandleOutcome(std::move(*outcome));
  DecideAt(clock_.Now());
  ResendUnconfirmed(clock_.Now());
}

void PlannerNode::ResendUnconfirmed(std::int64_t now) {
  const std::int64_t given_up = delivery_.counts().given_up;
  const poly_trajectory_t* copy = delivery_.Due(now);
  if (delivery_.counts().given_up > given_up) {
    spdlog::warn("the tracker never reported the last trajectory within {:.1f} s of its start: no more copies",
                 options_.delivery.give_up_s);
  }
  if (copy == nullptr) return;
  loop_->lcm().publish(std::string(channels::TRAJECTORY), copy);
  const std::int64_t n = delivery_.counts().resent;
  if (n <= 10 || n % 100 == 0) {
    spdlog::info("TRAJECTORY {} not reported by the tracker yet: sent again (#{})", copy->trajectory_id, n);
  }
}

void PlannerNode::HandleAwaitedOutcome(PlanJobOutcome outcome) {
  awaiting_plan_ = false;
  HandleOutcome(std::move(outcome));
  if (!awaiting_plan_) DecideAt(clock_.Now());  // what the message that asked for it left
  HandleInbox();
}

std::size_t PlannerNode::FinishInbox() {
  HandleInbox();
  while (awaiting_plan_ || !inbox_.empty()) {
    if (!awaiting_plan_) {
      HandleInbox();
      continue;
    }
    std::optional<PlanJobOutcome> outcome = worker_->WaitForResult(options_.deterministic.time_limit_s + 5.0);
    if (!outcome) {
      spdlog::error("deterministic mode: no plan result at the end: {} messages left unhandled", inbox_.size());
      break;
    }
    HandleAwaitedOutcome(std::move(*outcome));
  }
  return inbox_.size();
}

void PlannerNode::DecideAt(std::int64_t now) {
  CheckMapFreshness(now);
  MaybeSafeStop(now);
  MaybeFinishGoal(now);
  if (pending_ && !worker_->busy()) {
    const auto [trigger, reason] = *pending_;
    pending_.reset();
    RequestPlan(trigger, reason);
  }
  if (retry_at_utime_ != 0 && now >= retry_at_utime_ && !worker_->busy()) {
    RequestPlan(PlanTrigger::kRetry, "after a failed plan");
  }
  if (now - last_status_utime_ >= Micros(options_.status_period_s)) {
    PublishStatus(status_.state, status_.failure_reason, status_.detail);
  }
}

void PlannerNode::HandleOutcome(PlanJobOutcome outcome) {
  if (outcome.job.job_id != latest_job_ || !goal_ || goal_->done ||
      outcome.job.goal_id != goal_->goal.goal_id) {
    return;  // superseded (a newer job or goal); its cancel was reported
  }
  const std::int64_t now = clock_.Now();
  if (!outcome.result.success()) {
    HandleFailure(outcome);
    return;
  }
  // In message time a moving start is never late: it takes effect at its t0 by definition.
  if (!clock_.message_time() && !outcome.job.from_rest && now > outcome.job.t0_utime) {
    ++counts_.results_dropped_late;
    spdlog::warn("goal {}: plan {} came {:.0f} ms after its start time: dropped", outcome.job.goal_id,
                 outcome.job.job_id, 1e-3 * (now - outcome.job.t0_utime));
    RequestPlan(PlanTrigger::kRetry, "the last plan came too late");
    return;
  }
  // A stopping trajectory went out meanwhile: the robot is no longer where the plan starts.
  const ActiveTrajectory* on = OnAt(outcome.job.t0_utime);
  if (outcome.job.on_trajectory_id != 0 && (on == nullptr || on->trajectory_id != outcome.job.on_trajectory_id)) {
    ++counts_.results_dropped_late;
    spdlog::warn("goal {}: plan {} starts on trajectory {}, replaced meanwhile: dropped", outcome.job.goal_id,
                 outcome.job.job_id, outcome.job.on_trajectory_id);
    RequestPlan(PlanTrigger::kRetry, "the last plan started on a replaced trajectory");
    return;
  }
  // The fields it planned on may lag the map away from its start, and the map may have
  // changed while it planned: check it against the newest.
  // A plan from rest was validated without the robot's own voxels at its start: so is it here.
  const std::optional<PredictedCollision> hit = CheckAhead(*outcome.result.trajectory, 0.0, StandingOf(outcome.job));
  if (!hit) {
    PublishTrajectory(outcome, now);
    return;
  }
  ++counts_.results_colliding;
  const std::string reason =
      fmt::format("plan {} collides with the newer map at {:.2f} s", outcome.job.job_id, hit->t_s);
  if (clock_.message_time()) {
    // Its fields held every map update and no message came while it planned: the same map
    // would give the same plan.
    ScheduleRetry(now, reason, &outcome.result);
    return;
  }
  RememberCollision(*outcome.result.trajectory, hit->t_s);
  const std::int64_t start = outcome.job.from_rest ? now : outcome.job.t0_utime;
  const std::int64_t at = start + Micros(hit->t_s);
  if (1e-6 * (at - now) > options_.timing.publish_collision_horizon_s) {
    // Far enough ahead to replan before a stop could be due: out it goes, replanned at once.
    PublishTrajectory(outcome, now);
    collision_utime_ = at;
    collision_seen_utime_ = now;
  }
  RequestPlan(PlanTrigger::kMapCollision, reason);
}

void PlannerNode::RememberCollision(const ArcYawTrajectory& trajectory, double t_s) {
  TrajectorySample p = trajectory.MakePoint();
  trajectory.Evaluate(std::clamp(t_s, 0.0, trajectory.duration_s()), &p);
  collision_points_.push_back({p.state.x_m, p.state.y_m});
  constexpr std::size_t kKeep = 6;  // the newest collisions: where the map keeps changing
  if (collision_points_.size() > kKeep) collision_points_.erase(collision_points_.begin());
}

std::vector<Eigen::AlignedBox2d> PlannerNode::FreshRegions(const TrajectorySample& start) const {
  const auto square = [](const Eigen::Vector2d& c, double half) {
    return Eigen::AlignedBox2d(c - Eigen::Vector2d::Constant(half), c + Eigen::Vector2d::Constant(half));
  };
  std::vector<Eigen::AlignedBox2d> regions{square({start.state.x_m, start.state.y_m}, options_.map.fresh_radius_m)};
  for (const Eigen::Vector2d& p : collision_points_) regions.push_back(square(p, options_.map.fresh_collision_radius_m));
  if (goal_) {  // where the goal's base poses are searched
    regions.push_back(square(goal_->goal.X_WE.translation().head<2>(), options_.map.fresh_radius_m));
    if (goal_->goal.hint) regions.push_back(square({goal_->goal.hint->x_m, goal_->goal.hint->y_m}, options_.map.fresh_radius_m));
  }
  return regions;
}

void PlannerNode::HandleFailure(const PlanJobOutcome& outcome) {
  const WholeBodyPlanResult& r = outcome.result;
  if (r.status == PlanStatus::kCancelled) return;
  ++counts_.plans_failed;
  PublishPaths(r, outcome.job.goal_id, 0);
  spdlog::warn("goal {}: plan {} failed ({}): {}", outcome.job.goal_id, outcome.job.job_id,
               ToString(r.status), r.failure_reason);
  if (!goal_->escape && StartArmInCollision(outcome.job, r) &&
      options_.map.start_arm_escape_overlap_m > outcome.job.clear_arm_overlap_m) {
    // The arm stopped in voxels deeper than a plan from rest leaves out (a stop near a table's
    // edge): plan it out of them, leaving out those it reaches into by at most the escape's depth.
    goal_->escape = true;
    ++counts_.escapes;
    spdlog::warn("goal {}: the arm stands in the map's voxels deeper than {:.3f} m: planning from rest again without "
                 "those it reaches into by at most {:.3f} m (an escape)",
                 outcome.job.goal_id, options_.map.start_arm_overlap_m, options_.map.start_arm_escape_overlap_m);
    return RequestPlan(PlanTrigger::kRetry, "escape: the arm stands in the map's voxels");
  }
  const bool definite = outcome.certified_unreachable || r.status == PlanStatus::kInvalidInput;
  if (!goal_->planned_once && (definite || ++goal_->failed_attempts >= options_.timing.first_plan_attempts)) {
    goal_->done = true;  // no trajectory for it after its attempts: FAILED (the mission may resend it)
    PublishStatus(planner_status_t::FAILED, r.failure_reason, outcome.job.trigger, &r);
    return;
  }
  if (outcome.job.from_rest && ++goal_->failed_from_rest >= options_.timing.max_failed_plans_from_rest) {
    goal_->done = true;  // stopped with no way on: the mission decides (resend, give up)
    PublishStatus(planner_status_t::FAILED,
                  fmt::format("stuck: {} plans from rest failed in a row; the last: {}", goal_->failed_from_rest,
                              r.failure_reason),
                  outcome.job.trigger, &r);
    return;
  }
  // A replan while moving: keep trying; the safe stop guards the trajectory under way.
  ScheduleRetry(clock_.Now(), "replan failed, retrying: " + r.failure_reason, &r);
}

void PlannerNode::ScheduleRetry(std::int64_t now, const std::string& detail, const WholeBodyPlanResult* result) {
  retry_at_utime_ = now + Micros(options_.timing.retry_period_s);
  PublishStatus(collision_utime_ ? planner_status_t::STOPPING : planner_status_t::PLANNING, "", detail, result);
}

void PlannerNode::PublishTrajectory(const PlanJobOutcome& outcome, std::int64_t now) {
  ActiveTrajectory active;
  active.trajectory_id = NextTrajectoryId();
  active.goal_id = outcome.job.goal_id;
  active.start_utime = outcome.job.t0_utime != 0 ? outcome.job.t0_utime : now;  // 0: from rest, now
  active.trajectory = std::make_shared<const ArcYawTrajectory>(*outcome.result.trajectory);
  active.standing = StandingOf(outcome.job);
  MakeActive(std::move(active));
  goal_->planned_once = true;
  goal_->failed_from_rest = 0;
  goal_->escape = false;
  ++counts_.trajectories;
  PublishActive("plan");
  PublishPaths(outcome.result, outcome.job.goal_id, active_->trajectory_id);
  PublishStatus(planner_status_t::SUCCEEDED, "", outcome.job.trigger, &outcome.result);
}

void PlannerNode::PublishPaths(const WholeBodyPlanResult& result, std::int64_t goal_id, std::int64_t trajectory_id) {
  if (result.front_end.base_paths.empty()) return;
  const planner_paths_t msg = ToPathsMessage(result, clock_.Now(), goal_id, trajectory_id);
  loop_->lcm().publish(std::string(channels::PLANNER_PATHS), &msg);
}

void PlannerNode::PublishActive(const char* what) {
  const ArcYawTrajectory& t = *active_->trajectory;
  TrajectorySample start = t.MakePoint();
  t.Evaluate(0.0, &start);
  msgs::PolyTrajectory poly = msgs::FromArcYaw(t, {start.state.x_m, start.state.y_m});
  poly.utime = clock_.Now();
  poly.trajectory_id = active_->trajectory_id;
  poly.goal_id = active_->goal_id;
  poly.start_utime = active_->start_utime;
  const poly_trajectory_t msg = msgs::ToMessage(poly);
  loop_->lcm().publish(std::string(channels::TRAJECTORY), &msg);
  if (!clock_.message_time()) delivery_.Sent(msg, poly.utime);  // a replay's outputs are its messages' alone
  spdlog::info("goal {}: {} trajectory {} out, {:.2f} s, starts in {:.0f} ms", active_->goal_id, what,
               active_->trajectory_id, t.duration_s(), 1e-3 * (active_->start_utime - poly.utime));
}

void PlannerNode::ClearPredictedCollision() {
  collision_utime_.reset();
  collision_by_drift_ = false;
  collision_seen_utime_.reset();
  last_stop_duration_s_.reset();
  stop_error_logged_ = false;
}

void PlannerNode::MakeActive(ActiveTrajectory trajectory) {
  // A new plan was checked against the newest map; a stopping trajectory keeps the collision
  // it stops for (the status says STOPPING while replans fail).
  if (!trajectory.stopping) ClearPredictedCollision();
  if (active_) replaced_.push_back(std::move(*active_));
  // Only the newest that started by the new one's start can still be under way then.
  while (replaced_.size() > 1 && replaced_[1].start_utime <= trajectory.start_utime) replaced_.pop_front();
  while (replaced_.size() > 4) replaced_.pop_front();
  active_ = std::move(trajectory);
}

std::int64_t PlannerNode::NextTrajectoryId() {
  trajectory_seq_ = std::max(trajectory_seq_ + 1, clock_.Now());
  return trajectory_seq_;
}

const ActiveTrajectory* PlannerNode::OnAt(std::int64_t utime) const {
  return TrajectoryOnAt(active_ ? &*active_ : nullptr, replaced_, utime);
}

double PlannerNode::CollisionDistance(std::int64_t now) const {
  const TrajectorySample at = active_->SampleAt(*collision_utime_);
  const TrajectorySample robot = active_->SampleAt(now);
  return std::hypot(at.state.x_m - robot.state.x_m, at.state.y_m - robot.state.y_m);
}

std::optional<ArcYawTrajectory> PlannerNode::MakeStop(std::int64_t begin, std::string* why, bool blind) const {
  // Brake from the trajectory the robot is on when the stop begins: the newest one may not have
  // started yet (a replan waits for its t0), and braking from its start put the stop 0.7 s of
  // travel away from the robot (0.7 m of drift in the demo).
  const ActiveTrajectory& on = OnAt(begin) != nullptr ? *OnAt(begin) : *active_;
  std::optional<ArcYawTrajectory> stop = stop_planner_.Make(
      *on.trajectory, on.TimeAt(begin), why, blind ? std::optional(options_.stop.blind_duration_per_rate_ratio) : std::nullopt);
  if (stop && collision_by_drift_ && !blind) return StopWhereTheRobotIs(on, begin, std::move(*stop));
  return stop;
}

ArcYawTrajectory PlannerNode::StopWhereTheRobotIs(const ActiveTrajectory& on, std::int64_t begin,
                                                  ArcYawTrajectory stop) const {
  if (!robot_ || robot_->state.num_joints() != on.trajectory->num_joints()) return stop;
  TrajectorySample robot = on.trajectory->MakePoint();
  DriftedRobot(on, *robot_).Evaluate(on.TimeAt(begin), &robot);
  const TrajectorySample reference = on.SampleAt(begin);
  return OffsetTrajectory(stop, {robot.state.x_m, robot.state.y_m}, robot.state.yaw_rad - reference.state.yaw_rad,
                          robot.state.q_rad - reference.state.q_rad);
}

void PlannerNode::PublishStop(ArcYawTrajectory stop, std::int64_t begin, const std::string& detail) {
  ActiveTrajectory s;
  s.trajectory_id = NextTrajectoryId();
  s.goal_id = active_->goal_id;
  s.start_utime = begin;
  s.stopping = true;
  s.trajectory = std::make_shared<const ArcYawTrajectory>(std::move(stop));
  const ActiveTrajectory* on = OnAt(begin);  // the one it brakes from (MakeStop)
  s.standing = (on != nullptr ? on : &*active_)->standing;
  MakeActive(std::move(s));
  ++counts_.stops;
  PublishActive("stopping");
  PublishStatus(planner_status_t::STOPPING, "", detail);
}

double PlannerNode::StaleLimitS(std::int64_t now) const {
  const PlannerMapOptions& map = options_.map;
  const double limit_s = map.stale_stop_s;
  if (map.stale_blind_distance_m <= 0.0) return limit_s;
  double speed_mps = robot_ ? std::abs(robot_->v_mps) : 0.0;
  if (const ActiveTrajectory* on = OnAt(now); on != nullptr && !on->stopping) {
    speed_mps = std::max(speed_mps, std::abs(on->SampleAt(now).v_mps));
  }
  if (!(speed_mps > 0.0)) return limit_s;
  return std::clamp(map.stale_blind_distance_m / speed_mps, std::min(map.stale_min_s, limit_s), limit_s);
}

void PlannerNode::CheckMapFreshness(std::int64_t now) {
  const PlannerMapOptions& map = options_.map;
  if (map.stale_stop_s <= 0.0 || !map_.has_map()) return;
  const double age_s = 1e-6 * static_cast<double>(now - map_.receiver().utime());
  // Younger than any limit StaleLimitS gives, and not stale: nothing to decide (this runs every
  // tick; the limit evaluates the trajectory the robot is on).
  if (!map_stale_ && age_s <= std::min(map.stale_min_s, map.stale_stop_s)) return;
  const double limit_s = StaleLimitS(now);
  if (age_s <= limit_s) {
    if (!map_stale_) return;
    map_stale_ = false;
    spdlog::info("map fresh again: newest scan {:.2f} s old", age_s);
    RequestPlan(PlanTrigger::kResume, "the map is fresh again");
    return;
  }
  if (map_stale_) return;
  map_stale_ = true;
  const std::string detail = fmt::format("the map is stale: newest scan {:.2f} s old (limit {:.2f} s)", age_s, limit_s);
  spdlog::warn("{}: stopping, no plan until it is fresh", detail);
  AbandonPlans();
  if (active_ && !active_->stopping && !active_->EndedBy(now)) {
    const std::int64_t begin = now + Micros(options_.stop.latency_s);
    std::string why;
    if (std::optional<ArcYawTrajectory> stop = MakeStop(begin, &why, /*blind=*/true)) {
      ++counts_.stale_map_stops;
      PublishStop(std::move(*stop), begin, detail + ": stopping");
      return;
    }
    spdlog::error("goal {}: {} and no stopping trajectory: {}", active_->goal_id, detail, why);
  }
  if (goal_ && !goal_->done) PublishStatus(planner_status_t::PLANNING, "", "waiting: " + detail);
}

void PlannerNode::MaybeSafeStop(std::int64_t now) {
  if (!collision_utime_ || !active_ || active_->stopping || active_->EndedBy(now)) return;
  const double until_collision_s = 1e-6 * (*collision_utime_ - now);
  const double lead_s = options_.stop.latency_s + options_.stop.margin_s;
  // Far from the collision a stopping trajectory made less than 0.1 s ago says no stop is due
  // yet (with a quarter second to spare for a robot speeding up meanwhile): not worth making
  // one every tick. An older one is made again: a robot that sped up needs a longer stop.
  constexpr double kSlack_s = 0.25;
  constexpr double kStopRecheck_s = 0.1;
  // A near collision that waited its grace for a new trajectory: stop now, plan on meanwhile.
  const bool grace_over = collision_seen_utime_ &&
                          now - *collision_seen_utime_ >= Micros(options_.stop.replan_grace_s) &&
                          (until_collision_s <= options_.timing.publish_collision_horizon_s ||
                           CollisionDistance(now) <= options_.stop.grace_reach_m);
  if (!grace_over && last_stop_duration_s_ && now - last_stop_made_utime_ < Micros(kStopRecheck_s) &&
      until_collision_s > *last_stop_duration_s_ + lead_s + kSlack_s) {
    return;
  }
  const std::int64_t begin = now + Micros(options_.stop.latency_s);
  std::string why;
  std::optional<ArcYawTrajectory> stop = MakeStop(begin, &why);
  last_stop_duration_s_ = stop ? stop->duration_s() : 0.0;
  last_stop_made_utime_ = now;
  if (!grace_over && until_collision_s > *last_stop_duration_s_ + lead_s) return;
  if (!stop) {
    if (!stop_error_logged_) {
      spdlog::error("goal {}: collision {:.2f} s ahead and no stopping trajectory: {}", active_->goal_id,
                    until_collision_s, why);
    }
    stop_error_logged_ = true;
    return;
  }
  PublishStop(std::move(*stop), begin,
              fmt::format("collision {:.2f} s ahead, no new trajectory yet: stopping", until_collision_s));
  // A plan in progress started on the trajectory the stop replaces: it would not join.
  RequestPlan(PlanTrigger::kRetry, "replanning from the safe stop", /*preempt=*/true);
}

bool PlannerNode::ReachedAtRest(const WholeBodyState& state) {
  const GoalCheckOptions& o = options_.goals;
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(state);
  const Eigen::Isometry3d& X_WT = goal_->goal.X_WE;
  const double position_m = (X_WE.translation() - X_WT.translation()).norm();
  const double angle_rad = Eigen::AngleAxisd(X_WT.linear().transpose() * X_WE.linear()).angle();
  if (position_m > o.reached_position_m || angle_rad > o.reached_orientation_rad) return false;
  goal_->done = true;
  const std::string detail = msgs::ReachedAtRestDetail(position_m, angle_rad);
  spdlog::info("goal {}: {}", goal_->goal.goal_id, detail);
  PublishStatus(planner_status_t::SUCCEEDED, "", detail);
  return true;
}

void PlannerNode::MaybeFinishGoal(std::int64_t now) {
  if (!goal_ || goal_->done || !active_ || active_->stopping || !active_->EndedBy(now)) return;
  if (active_->goal_id != goal_->goal.goal_id || worker_->busy() || pending_) return;
  goal_->done = goal_->ended = true;  // its trajectory ran to the end: nothing more to replan
  PublishStatus(planner_status_t::SUCCEEDED, "", msgs::TrajectoryEndedDetail(active_->trajectory_id));
}

void PlannerNode::PublishStatus(std::int8_t state, const std::string& reason, const std::string& detail,
                                const WholeBodyPlanResult* result) {
  status_.utime = clock_.Now();
  status_.state = state;
  status_.goal_id = goal_ ? goal_->goal.goal_id : status_.goal_id;
  status_.trajectory_id = active_ ? active_->trajectory_id : 0;
  status_.failure_reason = reason;
  status_.detail = detail;
  status_.replans = goal_ ? goal_->replans : 0;
  if (result != nullptr) {
    status_.front_end_ms = result->timings.search_ms;
    status_.sampling_ms = result->timings.sampling_ms;
    status_.optimization_ms = result->timings.optimization_ms;
    status_.total_ms = result->timings.total_ms;
  }
  loop_->lcm().publish(std::string(channels::PLANNER_STATUS), &status_);
  last_status_utime_ = status_.utime;
  UpdateHealth();
}

void PlannerNode::UpdateHealth() {
  static constexpr const char* kStates[] = {"IDLE", "PLANNING", "SUCCEEDED", "FAILED", "CANCELLED", "STOPPING"};
  const int s = std::clamp<int>(status_.state, 0, 5);
  const PlanWorkerCounts w = worker_->counts();
  const std::string tracker =
      tracker_ ? fmt::format("; tracker on {}", tracker_->trajectory_id) : std::string("; no TRACKER_STATUS");
  const std::string inbox =
      clock_.message_time() ? fmt::format("; inputs {} handled, {} waiting{}", counts_.inbox_handled, inbox_.size(),
                                          awaiting_plan_ ? ", a plan running" : "")
                            : std::string();
  loop_->SetHealth(status_.state == planner_status_t::STOPPING ? heartbeat_t::WARN : heartbeat_t::OK,
                   fmt::format("goal {} {}; trajectory {}; replans {}; map seq {}; field slice {:.0f} ms, {} changes "
                               "pending{}{}", status_.goal_id, kStates[s], status_.trajectory_id, status_.replans,
                               map_.receiver().map_seq(), w.last_flush_ms, w.pending_changes, tracker, inbox));
}

std::string PlannerNode::Report() const {
  const PlanWorkerCounts w = worker_->counts();
  std::string out = fmt::format(
      "topay-planner: {} goals ({} refused, {} failed as the map came to refuse them, {} repeats ignored, {} "
      "cancelled), {} trajectories, {} stops ({} on a stale map), {} plans ({} failed, {} cancelled, {} late, {} "
      "colliding with a newer map), {} arm escapes\n",
      counts_.goals, counts_.goals_refused, counts_.goals_failed_on_map, counts_.goals_repeated, counts_.goals_cancelled,
      counts_.trajectories,
      counts_.stops, counts_.stale_map_stops, w.plans, counts_.plans_failed, w.cancelled, counts_.results_dropped_late,
      counts_.results_colliding, counts_.escapes);
  const TrajectoryDeliveryCounts& d = delivery_.counts();
  out += fmt::format("  delivery: {} trajectories reported by the tracker, {} copies sent again, {} never reported\n",
                     d.confirmed, d.resent, d.given_up);
  out += "  triggers:";
  for (const auto& [trigger, n] : counts_.triggers) out += fmt::format(" {} {}", ToString(trigger), n);
  out += fmt::format("\n  drift starts: {} where the tracker will have brought the robot (max {:.1f} ms, at most "
                     "{:.3f} m from the start carried with its error)",
                     counts_.tracked_starts, counts_.tracked_start_ms_max, counts_.tracked_start_shift_m_max);
  out += fmt::format("\n  map: {} checks of the trajectory ahead (mean {:.2f} ms, max {:.2f} ms; {} of the drifted robot, "
                     "{} colliding), {} rejected; "
                     "{} background field updates (last {:.0f} ms, max {:.0f} ms), before a plan max {:.0f} ms\n",
                     counts_.map_checks,
                     counts_.map_checks > 0 ? counts_.map_check_ms_sum / counts_.map_checks : 0.0,
                     counts_.map_check_ms_max, counts_.drift_checks, counts_.drift_collisions,
                     counts_.maps_rejected, w.flushes, w.last_flush_ms,
                     w.max_flush_ms, w.max_fresh_ms);
  if (clock_.message_time()) {
    const auto& n = counts_.inbox_handled_by_channel;
    out += fmt::format("  deterministic: {} messages handled in message time (GOAL {}, ROBOT_STATE {}, MAP_UPDATE {}, "
                       "TRACKER_STATUS {}), at most {} waiting for a plan\n",
                       counts_.inbox_handled, n[0], n[1], n[2], n[3], counts_.inbox_max);
  }
  return out;
}

}  // namespace topay::planner
