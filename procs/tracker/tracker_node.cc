#include "procs/tracker/tracker_node.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/angles.h"
#include "core/common/sample_statistics.h"
#include "core/control/arc_yaw_reference.h"
#include "procs/msgs/convert_trajectory.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::tracker {
namespace {

bool Every(std::int64_t n) { return n <= 10 || n % 1000 == 0; }  // log the first 10, then every 1000th

bool AtRest(const ControlCommand& c, double tolerance) {
  return std::abs(c.v_mps) < tolerance && std::abs(c.omega_radps) < tolerance &&
         (c.qd_radps.size() == 0 || c.qd_radps.cwiseAbs().maxCoeff() < tolerance);
}

}  // namespace

TrackerNode::TrackerNode(const TrackerOptions& options, const TrackerLimits& limits)
    : options_(options),
      num_joints_(limits.num_joints()),
      base_limits_(limits.base),
      tracker_(options.nmpc, limits),
      state_intake_(num_joints_),
      planner_watch_(options.planner_watch) {
  solve_ms_.reserve(1 << 16);
  cycle_.command.num_joints = num_joints_;
  cycle_.command.qdot_radps.assign(num_joints_, 0.0);
}

TrackerNode::TrackerNode(const TrackerOptions& options, const RobotModel& model)
    : TrackerNode(options, MakeTrackerLimits(model)) {
  if (!options.protective_field.enabled) return;
  field_.emplace(options.protective_field, model.base_cylinder, model.base_limits);
  field_intake_ = std::make_unique<FieldScanIntake>(model, options.protective_field.self_margin_m);
}

double TrackerNode::Seconds(std::int64_t utime) {
  if (!origin_utime_) origin_utime_ = utime;
  return static_cast<double>(utime - *origin_utime_) * 1e-6;
}

void TrackerNode::OnTrajectory(const poly_trajectory_t& msg, std::int64_t now_utime) {
  ++counts_.trajectories;
  const auto reject = [&](const std::string& why) {
    ++counts_.trajectories_rejected;
    if (Every(counts_.trajectories_rejected)) {
      spdlog::warn("rejected TRAJECTORY {} (#{}): {}", msg.trajectory_id, counts_.trajectories_rejected, why);
    }
  };
  if (held()) {
    ++counts_.trajectories_dropped_held;
    if (Every(counts_.trajectories_dropped_held)) {
      spdlog::warn("dropped TRAJECTORY {} (#{}): {}", msg.trajectory_id, counts_.trajectories_dropped_held,
                   held_         ? "the drives are not running (" + hold_reason_ + ")"
                   : stale_held_ ? std::string("the robot state is stale")
                                 : lost_reason_);
    }
    return;
  }
  const std::int64_t newest = !pending_.empty() ? pending_.back().id : active_ ? active_->id : 0;
  if (msg.trajectory_id <= newest) {
    ++counts_.trajectories_ignored;
    if (Every(counts_.trajectories_ignored)) {
      spdlog::info("ignored TRAJECTORY {} (#{}): not newer than {} {}", msg.trajectory_id,
                   counts_.trajectories_ignored, !pending_.empty() ? "pending" : "active", newest);
    }
    return;
  }
  std::string error;
  const std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(msg, &error);
  if (!poly) return reject(error);
  if (poly->num_joints() != num_joints_) {
    return reject(fmt::format("{} joints, the robot has {}", poly->num_joints(), num_joints_));
  }
  std::optional<ArcYawTrajectory> trajectory = msgs::ToArcYaw(*poly, options_.rebuild, &error);
  if (!trajectory) return reject(error);

  Loaded loaded;
  loaded.id = msg.trajectory_id;
  loaded.goal_id = msg.goal_id;
  loaded.start_utime = msg.start_utime;
  auto shared = std::make_shared<const ArcYawTrajectory>(std::move(*trajectory));
  loaded.trajectory = shared;
  loaded.reference = MakeArcYawReference(shared, msg.trajectory_id, Seconds(msg.start_utime));
  spdlog::info("TRAJECTORY {} (goal {}) accepted: {:.2f} s, starts in {:.3f} s", loaded.id, loaded.goal_id,
               loaded.reference.duration_s, static_cast<double>(msg.start_utime - now_utime) * 1e-6);
  // It takes over at its start: a pending one starting then or later would never run; one
  // starting earlier runs until then (the planner planned this one from where that one leads).
  while (!pending_.empty() && pending_.back().start_utime >= msg.start_utime) {
    ++counts_.pending_superseded;
    pending_.pop_back();
  }
  if (msg.start_utime <= now_utime) {
    Activate(std::move(loaded));
  } else {
    pending_.push_back(std::move(loaded));
  }
}

void TrackerNode::Activate(Loaded loaded) {
  ++counts_.switches;
  active_ = std::move(loaded);
}

void TrackerNode::OnRobotState(const robot_state_t& msg) {
  std::string error;
  std::optional<msgs::RobotStateEstimate> estimate = state_intake_.Take(msg, &error);
  if (!estimate) {
    ++counts_.states_rejected;
    if (state_intake_.LogRefusal()) spdlog::warn("rejected ROBOT_STATE (#{}): {}", counts_.states_rejected, error);
    return;
  }
  ++counts_.states;
  if (state_intake_.last_verdict() == ContinuityVerdict::kReanchored) {
    spdlog::warn("ROBOT_STATE: {}", state_intake_.gate_reason());
  }
  if (std::isfinite(estimate->gripper)) measured_gripper_ = estimate->gripper;
  if (field_intake_) field_intake_->AddState(estimate->utime, estimate->state);
  CheckJump(*estimate);
  state_ = std::move(estimate);
}

void TrackerNode::CheckJump(const msgs::RobotStateEstimate& next) {
  if (!state_ || held() || !MayMove()) return;
  const double dt = 1e-6 * static_cast<double>(next.utime - state_->utime);
  const double moved_m = std::hypot(next.state.x_m - state_->state.x_m, next.state.y_m - state_->state.y_m);
  const double turned_rad = std::abs(WrapAngle(next.state.yaw_rad - state_->state.yaw_rad));
  const double excess_m = moved_m - base_limits_.v_max_mps * dt;
  const double excess_rad = turned_rad - base_limits_.omega_max_radps * dt;
  const bool jumped = (options_.jump_position_m > 0.0 && excess_m > options_.jump_position_m) ||
                      (options_.jump_yaw_rad > 0.0 && excess_rad > options_.jump_yaw_rad);
  if (!jumped) return;
  BrakeOff(&counts_.jumps, "the robot state jumped, braking",
           fmt::format("the robot state jumped: {:.3f} m and {:.3f} rad in {:.3f} s, {:.3f} m and {:.3f} rad beyond the "
                       "robot's limits (at most {:.3f} m, {:.3f} rad): the reference is no longer where the robot "
                       "is; braking to a stop",
                       moved_m, turned_rad, dt, excess_m, excess_rad, options_.jump_position_m, options_.jump_yaw_rad));
}

void TrackerNode::OnGripper(const gripper_command_t& msg) {
  if (!std::isfinite(msg.position) || msg.position < 0.0 || msg.position > 1.0) {
    ++counts_.grippers_rejected;
    if (Every(counts_.grippers_rejected)) {
      spdlog::warn("rejected GRIPPER_COMMAND (#{}): position {} not in [0, 1]", counts_.grippers_rejected, msg.position);
    }
    return;
  }
  ++counts_.grippers;
  gripper_ = msg.position;
}

void TrackerNode::OnPointCloud(const point_cloud_t& msg) {
  if (!field_) return;
  if (const std::optional<std::string> error = field_intake_->Take(msg, &field_points_)) {
    ++counts_.scans_rejected;
    if (Every(counts_.scans_rejected)) {
      spdlog::warn("POINT_CLOUD not used by the protective field (#{}): {}", counts_.scans_rejected, *error);
    }
    return;
  }
  ++counts_.scans;
  const Eigen::Vector2d p_WB = state_ ? Eigen::Vector2d(state_->state.x_m, state_->state.y_m)
                                      : Eigen::Vector2d(msg.p_WS[0], msg.p_WS[1]);
  field_->SetScan(field_points_, Seconds(msg.utime), p_WB);
}

void TrackerNode::OnDriveStatus(const drive_status_t& msg) {
  if (msg.state == drive_status_t::REPLAY) return;  // a log being decoded: drives nothing
  if (msg.state == drive_status_t::RUNNING) {
    if (held_) spdlog::info("drives running again: tracker released (at rest, waiting for a trajectory)");
    held_ = false;
    return;
  }
  static constexpr std::array<const char*, 6> kStates = {"STARTING", "ENABLING", "RUNNING",
                                                         "STOPPED",  "FAULT",    "RECOVERING"};
  const bool known = msg.state >= 0 && msg.state < static_cast<int>(kStates.size());
  hold_reason_ = fmt::format("bridge {}{}{}", known ? kStates[msg.state] : "state " + std::to_string(msg.state),
                             msg.stop_reason.empty() ? "" : ": ", msg.stop_reason);
  if (held_) return;
  held_ = true;
  ++counts_.holds;
  DropTrajectories(fmt::format("drives not running ({}): holding the robot at zero", hold_reason_));
}

void TrackerNode::OnHeartbeat(const heartbeat_t& msg, std::int64_t now_utime) {
  const double silence_s = planner_watch_.SilenceS(now_utime);
  switch (planner_watch_.OnHeartbeat(msg, now_utime)) {
    case PlannerWatch::Event::kFirstHeard:
      spdlog::info("planner '{}' heard (pid {}): a restart or {:.1f} s of silence stops its trajectories",
                   msg.process_name, msg.pid, options_.planner_watch.silence_s);
      return;
    case PlannerWatch::Event::kRestarted:
      if (!held() && MayMove()) {
        BrakeOff(&counts_.unguarded, "the planner restarted, braking",
                 fmt::format("the planner restarted (pid {} -> {}, {:.2f} s after the last heartbeat): nobody guards "
                             "its trajectories any more; braking to a stop",
                             planner_watch_.previous_pid(), msg.pid, silence_s));
      } else {
        spdlog::info("the planner restarted (pid {} -> {}): no trajectory under way", planner_watch_.previous_pid(),
                     msg.pid);
      }
      return;
    case PlannerWatch::Event::kIgnored:
      if (Every(planner_watch_.ignored())) {
        spdlog::warn("HEARTBEAT of '{}' (pid {}, seq {}) ignored (#{}): not the live planner's", msg.process_name,
                     msg.pid, msg.seq, planner_watch_.ignored());
      }
      return;
    case PlannerWatch::Event::kNone: return;
  }
}

bool TrackerNode::MayMove() const {
  return !pending_.empty() || (active_ && cycle_.status.state != tracker_status_t::FINISHED);
}

void TrackerNode::BrakeOff(std::int64_t* count, std::string reason, std::string_view why) {
  ++*count;
  lost_ = true;
  lost_reason_ = std::move(reason);
  DropTrajectories(why);
}

void TrackerNode::DropTrajectories(std::string_view why) {
  const std::int64_t dropped = (active_ ? 1 : 0) + static_cast<std::int64_t>(pending_.size());
  counts_.trajectories_dropped_held += dropped;
  spdlog::warn("{}, {} trajectories dropped (active {})", why, dropped, active_id());
  active_.reset();
  pending_.clear();
}

bool TrackerNode::StateFresh(std::int64_t now_utime) const {
  return state_ && static_cast<double>(now_utime - state_->utime) * 1e-6 <= options_.nmpc.stale_state_s;
}

const TrackerCycle& TrackerNode::Step(std::int64_t now_utime) {
  ++counts_.cycles;
  if (stale_held_ && StateFresh(now_utime)) {
    stale_held_ = false;
    spdlog::info("robot state fresh again: tracker released (at rest, waiting for a trajectory)");
  }
  if (!held() && MayMove() && planner_watch_.Silent(now_utime)) {
    BrakeOff(&counts_.unguarded, "the planner is silent, braking",
             fmt::format("the planner is silent ({:.1f} s without a heartbeat, limit {:.1f} s): nobody guards the "
                         "trajectories; braking to a stop",
                         planner_watch_.SilenceS(now_utime), options_.planner_watch.silence_s));
  }
  if (lost_ && !held_ && !stale_held_) return StepLost(now_utime);
  if (held()) {
    FillHeld(now_utime);
    tracker_.Halt();  // the drives are at rest: no command to ramp down from on release
    return cycle_;
  }
  // Pending ones start in order; of those whose start has come the last is the one to follow.
  while (!pending_.empty() && pending_.front().start_utime <= now_utime) {
    Activate(std::move(pending_.front()));
    pending_.pop_front();
  }
  if (FieldEntered(now_utime)) return StepLost(now_utime);
  TrackerInput input = StateInput(now_utime);
  if (active_) input.reference = &active_->reference;
  const TrackerOutput& out = tracker_.Step(input);
  if (out.mode == TrackerMode::kTrack) {
    ++counts_.solves;
    solve_ms_.push_back(out.solve_ms);
  }
  NoteArmPacing(out);
  const std::int8_t previous = cycle_.status.state;
  Fill(out, now_utime);
  if (out.mode != last_mode_ && out.mode == TrackerMode::kStopStaleState && active_) {
    ++counts_.stops_stale;
    spdlog::warn("robot state {}: stopping", state_ ? "stale" : "missing");
  }
  if (out.mode == TrackerMode::kStopStaleState && active_ && state_ && AtRest(out.command, options_.rest_command)) {
    ++counts_.stale_holds;
    stale_held_ = true;
    DropTrajectories("at rest on a stale robot state: holding the robot at zero");
  }
  if (last_mode_ == TrackerMode::kStopStaleState && out.mode == TrackerMode::kTrack) {
    spdlog::info("robot state fresh again: tracking trajectory {}", out.trajectory_id);
  }
  if (out.mode != last_mode_ && out.mode == TrackerMode::kStopReferenceEnded) {
    ++counts_.stops_ended;
    spdlog::info("trajectory {} ended: stopping", out.trajectory_id);
  }
  if (previous != cycle_.status.state && cycle_.status.state == tracker_status_t::FINISHED) {
    spdlog::info("trajectory {} finished", cycle_.status.trajectory_id);
  }
  last_mode_ = out.mode;
  if (out.mode == TrackerMode::kTrack && active_ && options_.lost_position_m > 0.0 &&
      out.position_error_m > options_.lost_position_m) {
    BrakeOff(&counts_.losses, "tracking lost, braking",
             fmt::format("tracking lost: the base {:.2f} m from the reference (limit {:.2f} m): braking to a stop",
                         out.position_error_m, options_.lost_position_m));
  }
  return cycle_;
}

void TrackerNode::NoteArmPacing(const TrackerOutput& out) {
  if (out.arm_lag_s > 0.0) {
    ++counts_.arm_paced_cycles;
    if (arm_lag_s_ == 0.0) {
      ++counts_.arm_pacings;
      spdlog::debug("trajectory {}: the base lags its reference by {:.2f} m: the arm waits for it",
                    out.trajectory_id, out.position_error_m);
    }
  }
  arm_lag_s_ = out.arm_lag_s;
  arm_lag_max_s_ = std::max(arm_lag_max_s_, out.arm_lag_s);
}

TrackerInput TrackerNode::StateInput(std::int64_t now_utime) {
  TrackerInput input;
  input.now_s = Seconds(now_utime);
  if (state_) {
    input.state = &state_->state;
    input.state_time_s = Seconds(state_->utime);
  }
  return input;
}

bool TrackerNode::FieldEntered(std::int64_t now_utime) {
  if (!field_ || !active_ || !StateFresh(now_utime) || last_mode_ != TrackerMode::kTrack) return false;
  // The speed the robot brakes from: the measured one or the last command, the larger.
  const double speed_mps = std::max(std::abs(state_->v_mps), std::abs(cycle_.command.v_mps));
  const double v_max = base_limits_.v_max_mps;
  const ProtectiveFieldOptions& o = field_->options();
  const double now_s = Seconds(now_utime);
  const double length_m = field_->LengthM(speed_mps);
  // Positions at most step_m apart at v_max; for at most the longest stop plus a second (a
  // reference that turns in place covers no length).
  BasePathAhead(active_->reference, now_s, length_m, o.step_m / v_max,
                o.reaction_s + v_max / base_limits_.a_max_mps2 + 1.0, &field_path_, &field_sample_);
  const ProtectiveFieldCheck check = field_->Check(field_path_, now_s);
  if (!check.entered) return false;
  BrakeOff(&counts_.protective_stops, "obstacle in the protective field, braking",
           fmt::format("protective field entered: {} LiDAR points inside the base's path {:.2f} m ahead (field "
                       "{:.2f} m at {:.2f} m/s), the first at ({:.2f}, {:.2f}, {:.2f}) {:.2f} m along it: braking to a stop",
                       check.num_inside, check.path_length_m, length_m, speed_mps,
                       check.p_W_first.x(), check.p_W_first.y(), check.p_W_first.z(), check.distance_ahead_m));
  return true;
}

const TrackerCycle& TrackerNode::StepLost(std::int64_t now_utime) {
  const TrackerOutput& out = tracker_.Step(StateInput(now_utime));  // no reference: stop within the limits
  Fill(out, now_utime);
  cycle_.status.state = tracker_status_t::HELD;
  last_mode_ = out.mode;
  if (AtRest(out.command, options_.rest_command)) {
    lost_ = false;
    spdlog::info("at rest ({}): tracker released (waiting for a trajectory)", lost_reason_);
  }
  return cycle_;
}

void TrackerNode::Fill(const TrackerOutput& out, std::int64_t now_utime) {
  control_command_t& c = cycle_.command;
  c.utime = now_utime;
  c.trajectory_id = out.trajectory_id;
  c.v_mps = out.command.v_mps;
  c.omega_radps = out.command.omega_radps;
  c.num_joints = num_joints_;
  for (int j = 0; j < num_joints_; ++j) c.qdot_radps[j] = out.command.qd_radps[j];
  c.gripper = gripper_.value_or(measured_gripper_);

  tracker_status_t& s = cycle_.status;
  s.utime = now_utime;
  switch (active_ ? out.mode : TrackerMode::kStopNoReference) {  // no trajectory: IDLE
    case TrackerMode::kTrack: s.state = tracker_status_t::TRACKING; break;
    case TrackerMode::kStopNoReference: s.state = tracker_status_t::IDLE; break;
    case TrackerMode::kStopStaleState: s.state = tracker_status_t::STOPPING; break;
    case TrackerMode::kStopReferenceEnded:
      s.state = AtRest(out.command, options_.rest_command) ? tracker_status_t::FINISHED : tracker_status_t::STOPPING;
      break;
  }
  s.trajectory_id = active_ ? active_->id : 0;
  s.goal_id = active_ ? active_->goal_id : 0;
  s.t_along_s = active_ ? static_cast<double>(now_utime - active_->start_utime) * 1e-6 : 0.0;
  const bool measured = active_ && state_;
  s.position_error_m = measured ? out.position_error_m : 0.0;
  s.yaw_error_rad = measured ? out.yaw_error_rad : 0.0;
  s.joint_error_rad = measured ? out.joint_error_rad : 0.0;
  s.solve_ms = out.solve_ms;
}

void TrackerNode::FillHeld(std::int64_t now_utime) {
  control_command_t& c = cycle_.command;
  c.utime = now_utime;
  c.trajectory_id = 0;
  c.v_mps = 0.0;
  c.omega_radps = 0.0;
  c.num_joints = num_joints_;
  std::fill(c.qdot_radps.begin(), c.qdot_radps.end(), 0.0);
  c.gripper = gripper_.value_or(measured_gripper_);
  cycle_.status = tracker_status_t{};
  cycle_.status.utime = now_utime;
  cycle_.status.state = tracker_status_t::HELD;
  last_mode_ = TrackerMode::kStopNoReference;
}

std::int8_t TrackerNode::Health() const {
  return held() || (last_mode_ == TrackerMode::kStopStaleState && active_) ? heartbeat_t::WARN : heartbeat_t::OK;
}

std::string TrackerNode::StatusLine() const {
  if (held()) {
    return fmt::format("held: {}, {} trajectories dropped",
                       held_ ? hold_reason_ : stale_held_ ? "robot state stale" : lost_reason_,
                       counts_.trajectories_dropped_held);
  }
  return fmt::format("{} trajectory {} (pending {}), {} solves, {} fallbacks, {} rejected", TrackerModeName(last_mode_),
                     active_id(), pending_id(), counts_.solves,
                     tracker_.solver().summary().num_over_budget + tracker_.solver().summary().num_failed,
                     counts_.trajectories_rejected + counts_.states_rejected + counts_.grippers_rejected);
}

std::string TrackerNode::Report() const {
  const NmpcSummary& summary = tracker_.solver().summary();
  const TrackerCounts& c = counts_;
  return fmt::format(
      "topay-tracker: {} cycles, {} solves (median {:.3f} ms, p99 {:.3f} ms, max {:.3f} ms), fallbacks {} "
      "({} over budget, {} failed)\n"
      "  stops: {} stale state, {} trajectory ended, {} tracking lost, {} state jumps, {} unguarded (planner restarted "
      "or silent); "
      "held {} times (drives not running), {} times "
      "(at rest on a stale state), {} trajectories dropped held\n"
      "  trajectories: {} received, {} became active, {} rejected, {} ignored (not newer), {} pending superseded\n"
      "  robot states: {} ({} rejected: {}); gripper commands: {} ({} rejected)\n"
      "  protective field: {}, {} scans ({} not used), {} stops\n"
      "  arm pacing: {}, {} cycles waiting for the base in {} waits, at most {:.2f} s behind the clock\n",
      c.cycles, c.solves, solve_ms_.empty() ? 0.0 : Median(solve_ms_),
      solve_ms_.empty() ? 0.0 : NearestRankQuantile(solve_ms_, 0.99),
      solve_ms_.empty() ? 0.0 : *std::max_element(solve_ms_.begin(), solve_ms_.end()),
      summary.num_over_budget + summary.num_failed, summary.num_over_budget, summary.num_failed, c.stops_stale,
      c.stops_ended, c.losses, c.jumps, c.unguarded, c.holds, c.stale_holds, c.trajectories_dropped_held, c.trajectories, c.switches, c.trajectories_rejected, c.trajectories_ignored, c.pending_superseded,
      c.states, c.states_rejected, state_intake_.Report(), c.grippers, c.grippers_rejected,
      field_ ? "on" : "off", c.scans, c.scans_rejected, c.protective_stops,
      options_.nmpc.arm_pacing.window_s > 0.0 ? "on" : "off", c.arm_paced_cycles, c.arm_pacings, arm_lag_max_s_);
}

void ConnectTrackerNode(procs::ProcessLoop* loop, TrackerNode* node, double period_s) {
  loop->Subscribe<poly_trajectory_t>(std::string(channels::TRAJECTORY), [node](const poly_trajectory_t& msg) {
    node->OnTrajectory(msg, procs::NowUtime());
  });
  loop->Subscribe<robot_state_t>(std::string(channels::ROBOT_STATE),
                                 [node](const robot_state_t& msg) { node->OnRobotState(msg); });
  loop->Subscribe<gripper_command_t>(std::string(channels::GRIPPER_COMMAND),
                                     [node](const gripper_command_t& msg) { node->OnGripper(msg); });
  loop->Subscribe<drive_status_t>(std::string(channels::DRIVE_STATUS),
                                  [node](const drive_status_t& msg) { node->OnDriveStatus(msg); });
  loop->Subscribe<heartbeat_t>(std::string(channels::HEARTBEAT), [node](const heartbeat_t& msg) {
    node->OnHeartbeat(msg, procs::NowUtime());
  });
  if (node->protective_field()) {
    loop->Subscribe<point_cloud_t>(std::string(channels::POINT_CLOUD),
                                   [node](const point_cloud_t& msg) { node->OnPointCloud(msg); });
  }
  loop->AddTimer(period_s, [loop, node] {
    const TrackerCycle& cycle = node->Step(procs::NowUtime());
    loop->lcm().publish(std::string(channels::CONTROL_COMMAND), &cycle.command);
    loop->lcm().publish(std::string(channels::TRACKER_STATUS), &cycle.status);
    loop->SetHealth(node->Health(), node->StatusLine());
  });
}

}  // namespace topay::tracker
