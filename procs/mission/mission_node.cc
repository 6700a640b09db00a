#include "procs/mission/mission_node.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "procs/msgs/convert_goal.h"
#include "procs/msgs/planner_status_text.h"

namespace topay::mission {
namespace {

const char* StateName(std::int8_t state) {
  switch (state) {
    case mission_status_t::IDLE: return "IDLE";
    case mission_status_t::RUNNING: return "RUNNING";
    case mission_status_t::SUCCEEDED: return "SUCCEEDED";
    case mission_status_t::FAILED: return "FAILED";
    case mission_status_t::ABORTED: return "ABORTED";
  }
  return "?";
}

const char* PlannerStateName(std::int8_t state) {
  switch (state) {
    case planner_status_t::IDLE: return "IDLE";
    case planner_status_t::PLANNING: return "PLANNING";
    case planner_status_t::SUCCEEDED: return "SUCCEEDED";
    case planner_status_t::FAILED: return "FAILED";
    case planner_status_t::CANCELLED: return "CANCELLED";
    case planner_status_t::STOPPING: return "STOPPING";
  }
  return "?";
}

std::int64_t Micros(double seconds) { return static_cast<std::int64_t>(std::llround(seconds * 1e6)); }

}  // namespace

MissionNode::MissionNode(Mission mission, const Kinematics& kinematics, const MissionOptions& options,
                         MissionOutputs outputs, std::int64_t first_goal_id)
    : mission_(std::move(mission)),
      kinematics_(kinematics),
      options_(options),
      outputs_(std::move(outputs)),
      next_goal_id_(first_goal_id),
      robot_intake_(kinematics.num_joints()) {
  status_.mission = mission_.name;
  status_.state = mission_status_t::IDLE;
  status_.num_steps = static_cast<std::int32_t>(mission_.steps.size());
  status_.step = mission_.steps.empty() ? "" : mission_.steps[0].Describe();
  for (const MissionStep& s : mission_.steps) records_.push_back({s.Describe(), 0.0, 0, false});
}

bool MissionNode::finished() const {
  return status_.state == mission_status_t::SUCCEEDED || status_.state == mission_status_t::FAILED ||
         status_.state == mission_status_t::ABORTED;
}

bool MissionNode::MovingStep() const {
  return status_.state == mission_status_t::RUNNING &&
         (step().type == StepType::kGoto || step().type == StepType::kHome);
}

bool MissionNode::TrackerFinished() const {
  // "goal reached at rest" naming no trajectory (a hold had dropped them all): the tracker at
  // rest with nothing to track is done. Before, the mission waited for a FINISHED that never
  // came until its step timed out (the fault campaign's can-heartbeat-loss, docs/reliability.md).
  // The same with the tracker FINISHED on a trajectory of another goal (a restarted planner's
  // earlier one: at rest at its end, finding 23).
  // Also when the status names a trajectory (the planner's last one, of an earlier goal: the
  // goal flood of finding 28 left the tracker FINISHED on it and the mission waited 120 s): the
  // planner saw the robot at rest at the target, and a tracker IDLE or FINISHED moves it no more.
  const bool tracker_at_rest = tracker_state_ == tracker_status_t::IDLE || tracker_state_ == tracker_status_t::FINISHED;
  if (reached_at_rest_ && tracker_at_rest) return true;
  return tracker_finished_id_ != 0 && (ended_trajectory_id_ == 0 || tracker_finished_id_ == ended_trajectory_id_);
}

ArrivalTolerance MissionNode::Tolerance() const { return step().tolerance.value_or(options_.tolerance); }

double MissionNode::StepTimeout() const { return step().timeout_s.value_or(options_.step_timeout_s); }

void MissionNode::OnRobotState(const robot_state_t& msg, std::int64_t now) {
  std::string error;
  std::optional<msgs::RobotStateEstimate> estimate = robot_intake_.Take(msg, &error);
  if (!estimate) {
    if (robot_intake_.LogRefusal()) spdlog::warn("ROBOT_STATE ignored (#{}): {}", robot_intake_.refused(), error);
    return;
  }
  robot_ = std::move(estimate);
  if (status_.state == mission_status_t::IDLE) MaybeStart(now);
  CheckArrival(now);
}

void MissionNode::OnPlannerStatus(const planner_status_t& msg, std::int64_t now) {
  planner_seen_ = true;
  if (status_.state == mission_status_t::IDLE) MaybeStart(now);
  if (!MovingStep() || msg.goal_id != goal_id_) return;
  if (msg.state != last_planner_state_ || msg.detail != last_planner_detail_) {  // a change, not a repeat
    last_planner_state_ = msg.state;
    last_planner_detail_ = msg.detail;
    spdlog::info("  planner: goal {} {}{}{}", goal_id_, PlannerStateName(msg.state),
                 msg.detail.empty() ? "" : " (" + msg.detail + ")",
                 msg.failure_reason.empty() ? "" : ": " + msg.failure_reason);
  }
  attempt_replans_ = std::max(attempt_replans_, static_cast<int>(msg.replans));
  // Its last trajectory ran to its end ("trajectory N ended"), or the robot stood at the
  // target when a plan from rest was due ("goal reached at rest ...").
  if (msgs::ReportsGoalReached(msg)) {
    planner_ended_ = true;
    ended_trajectory_id_ = msg.trajectory_id;
    reached_at_rest_ = msgs::ReportsReachedAtRest(msg);
  } else if (msg.state == planner_status_t::CANCELLED && retry_utime_ == 0) {
    GoalPreempted(msg.detail, now);
    return;
  } else if (msg.state == planner_status_t::FAILED && retry_utime_ == 0) {
    AttemptFailed(msg.failure_reason.empty() ? std::string("plan failed") : msg.failure_reason, "no plan", now);
    return;
  }
  CheckArrival(now);
}

void MissionNode::OnTrackerStatus(const tracker_status_t& msg, std::int64_t now) {
  tracker_seen_ = true;
  tracker_state_ = msg.state;
  if (!MovingStep()) return;
  if (msg.goal_id == goal_id_) tracker_finished_id_ = msg.state == tracker_status_t::FINISHED ? msg.trajectory_id : 0;
  CheckArrival(now);
}

void MissionNode::Tick(std::int64_t now) {
  if (first_tick_utime_ == 0) first_tick_utime_ = now;
  if (finished()) return;
  if (status_.state == mission_status_t::IDLE) {
    MaybeStart(now);
    if (status_.state == mission_status_t::IDLE && Seconds(first_tick_utime_, now) > options_.start_timeout_s) {
      Finish(mission_status_t::FAILED,
             fmt::format("not started within {:.1f} s: {}", options_.start_timeout_s,
                         !robot_ ? "no ROBOT_STATE" : "no PLANNER_STATUS (is the planner running?)"),
             now);
      return;
    }
  }
  if (status_.state == mission_status_t::RUNNING) {
    if (MovingStep()) {
      if (retry_utime_ != 0 && now >= retry_utime_) SendGoal(now);
      if (finished()) return;
      RepeatGoal(now);
      if (Seconds(step_start_utime_, now) > StepTimeout()) {
        std::string why = planner_ended_ ? "the trajectory ended" : "the planner has not reported the goal reached";
        if (const auto error = EndEffectorError()) {
          why += fmt::format(", end effector {:.3f} m / {:.3f} rad from the target", error->first, error->second);
        }
        if (planner_ended_ && tracker_seen_ && !TrackerFinished()) why += ", tracker not FINISHED";
        Finish(mission_status_t::FAILED,
               fmt::format("step {} ({}) timed out after {:.1f} s: {}", step_index_ + 1, step().Describe(),
                           StepTimeout(), why),
               now);
        return;
      }
      CheckArrival(now);
    } else if (now >= step_due_utime_) {
      CompleteStep(now);
    }
  }
  if (!finished() && now - last_publish_utime_ >= Micros(options_.status_period_s)) Publish(now, status_.detail);
}

void MissionNode::Abort(const std::string& reason, std::int64_t now) {
  if (finished()) return;
  Finish(mission_status_t::ABORTED, reason, now);
}

void MissionNode::MaybeStart(std::int64_t now) {
  if (status_.state != mission_status_t::IDLE || !robot_) return;
  if (options_.wait_for_planner && !planner_seen_) return;
  start_state_ = robot_->state;
  start_utime_ = now;
  status_.state = mission_status_t::RUNNING;
  const Eigen::Vector3d p = kinematics_.EndEffectorPose(*start_state_).translation();
  spdlog::info("mission '{}': {} steps, start: base ({:.2f}, {:.2f}, yaw {:.2f}), end effector ({:.2f}, {:.2f}, {:.2f})",
               mission_.name, mission_.steps.size(), start_state_->x_m, start_state_->y_m, start_state_->yaw_rad,
               p.x(), p.y(), p.z());
  BeginStep(0, now);
}

void MissionNode::BeginStep(std::size_t index, std::int64_t now) {
  step_index_ = index;
  step_start_utime_ = now;
  attempts_ = 0;
  preemptions_ = 0;
  resend_after_preemption_ = false;
  step_replans_ = 0;
  attempt_replans_ = 0;
  goal_id_ = 0;
  retry_utime_ = 0;
  last_failure_.clear();
  const MissionStep& s = step();
  status_.step_index = static_cast<std::int32_t>(index);
  status_.step = s.Describe();
  spdlog::info("step {}/{}: {}", index + 1, mission_.steps.size(), s.Describe());
  switch (s.type) {
    case StepType::kGoto:
      target_X_WE_ = s.X_WE;
      target_hint_ = s.hint;
      SendGoal(now);
      return;
    case StepType::kHome:
      target_X_WE_ = kinematics_.EndEffectorPose(*start_state_);
      target_hint_ = *start_state_;
      SendGoal(now);
      return;
    case StepType::kGripper: {
      gripper_command_t command{};
      command.utime = now;
      command.position = s.gripper_position;
      command.source = "mission";
      if (outputs_.gripper) outputs_.gripper(command);
      step_due_utime_ = now + Micros(s.settle_s.value_or(options_.gripper_settle_s));
      Publish(now, fmt::format("gripper to {:.2f}", s.gripper_position));
      return;
    }
    case StepType::kWait:
      step_due_utime_ = now + Micros(s.duration_s);
      Publish(now, fmt::format("waiting {:.1f} s", s.duration_s));
      return;
  }
}

void MissionNode::SendGoal(std::int64_t now) {
  if (!resend_after_preemption_) ++attempts_;
  resend_after_preemption_ = false;
  goal_id_ = next_goal_id_++;
  retry_utime_ = 0;
  step_replans_ += attempt_replans_;
  attempt_replans_ = 0;
  planner_ended_ = false;
  ended_trajectory_id_ = 0;
  reached_at_rest_ = false;
  outside_since_utime_ = 0;
  tracker_finished_id_ = 0;
  last_planner_state_ = -1;
  last_planner_detail_.clear();
  msgs::PlanGoal goal;
  goal.utime = now;
  goal.goal_id = goal_id_;
  goal.X_WE = target_X_WE_;
  goal.hint = target_hint_;
  goal_msg_ = msgs::ToMessage(goal);
  goal_sent_utime_ = now;
  if (outputs_.goal) outputs_.goal(goal_msg_);
  status_.goal_id = goal_id_;
  status_.attempts = attempts_;
  const Eigen::Vector3d p = target_X_WE_.translation();
  Publish(now, fmt::format("goal {} sent (attempt {}/{}): end effector to ({:.2f}, {:.2f}, {:.2f}){}", goal_id_,
                           attempts_, options_.max_attempts, p.x(), p.y(), p.z(), target_hint_ ? " with hint" : ""));
}

void MissionNode::RepeatGoal(std::int64_t now) {
  if (goal_id_ == 0 || retry_utime_ != 0 || options_.goal_repeat_period_s <= 0.0) return;
  if (now - goal_sent_utime_ < Micros(options_.goal_repeat_period_s)) return;
  goal_sent_utime_ = now;
  if (outputs_.goal) outputs_.goal(goal_msg_);
}

std::optional<std::pair<double, double>> MissionNode::EndEffectorError() const {
  if (!robot_) return std::nullopt;
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(robot_->state);
  const double position_m = (X_WE.translation() - target_X_WE_.translation()).norm();
  const Eigen::Matrix3d R_TE = target_X_WE_.linear().transpose() * X_WE.linear();
  const double angle_rad = Eigen::AngleAxisd(R_TE).angle();
  return std::make_pair(position_m, std::abs(angle_rad));
}

void MissionNode::AttemptFailed(const std::string& reason, const char* outcome, std::int64_t now) {
  last_failure_ = reason;
  if (attempts_ >= options_.max_attempts) {
    Finish(mission_status_t::FAILED,
           fmt::format("step {} ({}): {} after {} attempt{}: {}", step_index_ + 1, step().Describe(), outcome,
                       attempts_, attempts_ == 1 ? "" : "s", last_failure_),
           now);
    return;
  }
  retry_utime_ = now + Micros(options_.retry_delay_s);
  Publish(now, fmt::format("attempt {} failed ({}), retrying", attempts_, last_failure_));
}

// Another sender's goal superseded ours (the planner takes the newest goal): not a failed plan,
// so it is sent again without using an attempt, up to max_preemptions times per step (hostile
// payloads of the twenty-seventh session: two forged copies and an injected goal used up a
// step's three attempts in 4 s).
void MissionNode::GoalPreempted(const std::string& detail, std::int64_t now) {
  ++preemptions_;
  last_failure_ = detail.empty() ? std::string("goal cancelled") : "goal cancelled: " + detail;
  if (preemptions_ > options_.max_preemptions) {
    Finish(mission_status_t::FAILED,
           fmt::format("step {} ({}): goal superseded {} times by other goals (max_preemptions {}): {}",
                       step_index_ + 1, step().Describe(), preemptions_, options_.max_preemptions, last_failure_),
           now);
    return;
  }
  resend_after_preemption_ = true;
  retry_utime_ = now + Micros(options_.retry_delay_s);
  Publish(now, fmt::format("{} ({} of {} allowed this step), sending it again", last_failure_, preemptions_,
                           options_.max_preemptions));
}

void MissionNode::CheckArrival(std::int64_t now) {
  if (!MovingStep() || !planner_ended_ || retry_utime_ != 0) return;
  if (tracker_seen_ && !TrackerFinished()) return;
  const std::optional<std::pair<double, double>> error = EndEffectorError();
  if (!error) return;
  const ArrivalTolerance tolerance = Tolerance();
  if (error->first > tolerance.position_m || error->second > tolerance.orientation_rad) {
    if (outside_since_utime_ == 0) outside_since_utime_ = now;
    if (now - outside_since_utime_ >= Micros(options_.arrival_settle_s)) {
      AttemptFailed(fmt::format("ended with the end effector {:.3f} m / {:.3f} rad from the target", error->first,
                                error->second),
                    "not arrived", now);
    }
    return;
  }
  status_.detail = fmt::format("arrived: end effector {:.3f} m / {:.3f} rad from the target", error->first, error->second);
  CompleteStep(now);
}

void MissionNode::CompleteStep(std::int64_t now) {
  StepRecord& record = records_[step_index_];
  record.duration_s = Seconds(step_start_utime_, now);
  record.attempts = attempts_;
  record.replans = step_replans_ + attempt_replans_;
  record.done = true;
  spdlog::info("step {}/{} done in {:.1f} s: {}{}", step_index_ + 1, mission_.steps.size(), record.duration_s,
               record.description, MovingStep() ? fmt::format(" ({}; {} attempt{})", status_.detail, attempts_,
                                                              attempts_ == 1 ? "" : "s")
                                                : "");
  goal_id_ = 0;
  if (step_index_ + 1 < mission_.steps.size()) {
    BeginStep(step_index_ + 1, now);
  } else {
    Finish(mission_status_t::SUCCEEDED, "every step done", now);
  }
}

void MissionNode::Finish(std::int8_t state, const std::string& detail, std::int64_t now) {
  if (status_.state == mission_status_t::RUNNING && !records_[step_index_].done) {
    records_[step_index_].duration_s = Seconds(step_start_utime_, now);
    records_[step_index_].attempts = attempts_;
    records_[step_index_].replans = step_replans_ + attempt_replans_;
  }
  status_.state = state;
  end_utime_ = now;
  if (state == mission_status_t::SUCCEEDED) {
    spdlog::info("mission '{}' SUCCEEDED", mission_.name);
  } else {
    spdlog::error("mission '{}' {}: {}", mission_.name, StateName(state), detail);
  }
  Publish(now, detail);
}

void MissionNode::Publish(std::int64_t now, const std::string& detail) {
  if (detail != status_.detail && status_.state == mission_status_t::RUNNING && !detail.empty()) {
    spdlog::info("  {}", detail);
  }
  status_.detail = detail;
  status_.utime = now;
  status_.elapsed_s = start_utime_ == 0 ? 0.0 : Seconds(start_utime_, finished() ? end_utime_ : now);
  last_publish_utime_ = now;
  if (outputs_.status) outputs_.status(status_);
}

std::string MissionNode::StatusLine() const {
  if (status_.state == mission_status_t::IDLE) {
    return !robot_ ? "waiting for ROBOT_STATE" : "waiting for the planner";
  }
  return fmt::format("{} step {}/{} {}", StateName(status_.state), status_.step_index + 1, status_.num_steps,
                     status_.step);
}

std::string MissionNode::Summary() const {
  std::string text = fmt::format("mission '{}' {}", mission_.name, StateName(status_.state));
  if (start_utime_ != 0) text += fmt::format(" in {:.1f} s", Seconds(start_utime_, end_utime_ ? end_utime_ : start_utime_));
  if (status_.state != mission_status_t::SUCCEEDED && !status_.detail.empty()) text += ": " + status_.detail;
  text += "\n";
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const StepRecord& r = records_[i];
    const bool started = start_utime_ != 0 && i <= step_index_;
    text += fmt::format("  {:2d}. {:<28} {}", i + 1, r.description,
                        r.done ? fmt::format("{:7.1f} s", r.duration_s)
                               : started ? fmt::format("{:7.1f} s (not done)", r.duration_s) : "  not run");
    if (r.attempts > 0) text += fmt::format(", {} attempt{}", r.attempts, r.attempts == 1 ? "" : "s");
    if (r.replans > 0) text += fmt::format(", {} replan{}", r.replans, r.replans == 1 ? "" : "s");
    text += "\n";
  }
  return text;
}

}  // namespace topay::mission
