#include "fault_episode.h"

#include <algorithm>

#include <fmt/format.h>

#include "graph_processes.h"
#include "topay/drive_status_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"

namespace topay::tools {
namespace {

constexpr double kMovingRecentlyS = 0.3;  // moving = an ACTUATOR_COMMAND above threshold this recently
constexpr double kResetPeriodS = 0.5;
constexpr double kBrakingConfirmS = 0.05;  // a braking run this long is the drives stopping
constexpr const char* kAtZeroEvidence = "every drive commanded to 0";
constexpr const char* kBrakingEvidence = "every drive braking";
// The injector's goal ids: 900000001 on (the mission's are microsecond stamps, about 1.8e15).
constexpr std::int64_t kToolGoalIds = 900000000, kToolGoalIdsEnd = 1000000000;
bool IsToolGoal(std::int64_t goal_id) { return goal_id >= kToolGoalIds && goal_id < kToolGoalIdsEnd; }
constexpr double kDriveStatusFreshS = 0.5;         // DRIVE_STATUS comes at 10 Hz: older means no bridge

// The bridge's state, if its last DRIVE_STATUS is recent (a dead bridge's last word is not news).
int FreshDriveState(const GraphView& view) {
  return view.last_drive_status_s >= 0.0 && view.now_s - view.last_drive_status_s < kDriveStatusFreshS
             ? view.drive_state
             : -1;
}

bool HeartbeatFrom(const GraphView& view, pid_t pid) {
  for (const auto& [name, beat_pid] : view.heartbeat_pid) {
    if (beat_pid == pid) return true;
  }
  return false;
}

std::string DriveStateName(int state) {
  switch (state) {
    case drive_status_t::STARTING: return "STARTING";
    case drive_status_t::ENABLING: return "ENABLING";
    case drive_status_t::RUNNING: return "RUNNING";
    case drive_status_t::STOPPED: return "STOPPED";
    case drive_status_t::FAULT: return "FAULT";
    case drive_status_t::RECOVERING: return "RECOVERING";
    case drive_status_t::REPLAY: return "REPLAY";
  }
  return "none";
}

bool MissionOver(int state) {
  return state == mission_status_t::SUCCEEDED || state == mission_status_t::FAILED ||
         state == mission_status_t::ABORTED;
}

}  // namespace

FaultEpisode::FaultEpisode(const FaultSpec& fault, std::uint64_t seed, FaultInjector* injector, pid_t graph_ancestor,
                           const FaultEpisodeOptions& options)
    : fault_(fault), injector_(injector), ancestor_(graph_ancestor), options_(options) {
  result_.fault = fault.name;
  result_.seed = seed;
}

// Moving now: a robot that has just come to rest (every drive at 0 since before the injection)
// would never show the stop the fault should cause (the safe state is a stop that begins after
// the injection), and would say nothing about it either.
bool FaultEpisode::Ready(const GraphView& view) const {
  return !view.actuator_zero && view.last_moving_s >= 0.0 && view.now_s - view.last_moving_s < kMovingRecentlyS &&
         FreshDriveState(view) == drive_status_t::RUNNING && view.mission_state == mission_status_t::RUNNING;
}

bool FaultEpisode::Tick(const GraphView& view) {
  if (start_s_ < 0.0) start_s_ = view.now_s;
  switch (phase_) {
    case Phase::kWaitReady:
      if (Ready(view)) {
        Inject(view);
      } else if (view.now_s - start_s_ > options_.ready_timeout_s || MissionOver(view.mission_state)) {
        result_.notes = MissionOver(view.mission_state) ? "the mission ended before the robot moved again"
                                                        : "the robot did not move under a running bridge";
        phase_ = Phase::kDone;
      }
      break;
    case Phase::kFault:
      injector_->Tick();
      WatchPlannerGoal(view);
      WatchSafeState(view, -1.0);
      OperatorReset(view);
      if (view.now_s - inject_s_ >= fault_.hold_s) {
        injector_->End();
        clear_s_ = view.now_s;
        phase_ = Phase::kRecover;
      }
      break;
    case Phase::kRecover:
      WatchSafeState(view, -1.0);
      OperatorReset(view);
      if (Recovered(view)) {
        result_.recovered = true;
        result_.recover_s = view.now_s - inject_s_;
        recovered_at_s_ = view.now_s;
        phase_ = Phase::kSettle;
      } else if (view.mission_state == mission_status_t::FAILED || view.mission_state == mission_status_t::ABORTED) {
        Finish(view, "mission " + std::string(view.mission_state == mission_status_t::FAILED ? "FAILED" : "ABORTED") +
                         ": " + view.mission_detail);
      } else if (view.now_s - clear_s_ > options_.recover_timeout_s) {
        Finish(view, fmt::format("not recovered {:.0f} s after the fault was cleared (bridge {}, mission step {}; "
                                 "waiting for {})",
                                 options_.recover_timeout_s, DriveStateName(FreshDriveState(view)), view.mission_step,
                                 awaiting_));
      }
      break;
    case Phase::kSettle:
      if (view.now_s - recovered_at_s_ >= options_.settle_s || MissionOver(view.mission_state)) Finish(view, "");
      break;
    case Phase::kDone:
      break;
  }
  return phase_ == Phase::kDone;
}

void FaultEpisode::Inject(const GraphView& view) {
  pids_at_start_ = GraphProcesses(ancestor_);
  contacts_at_start_ = view.contacts;
  mission_step_at_start_ = view.mission_step;
  inject_s_ = view.now_s;
  result_.injected = injector_->Begin(fault_);
  result_.notes = injector_->Notes();
  if (!result_.injected) {
    result_.refused = true;
    phase_ = Phase::kDone;
    return;
  }
  phase_ = Phase::kFault;
}

// The safe state, then, apart, when every drive's output reached 0 (the end of the devices' stop
// ramps), from the same reference (a restarted tracker's new commands must not move it).
void FaultEpisode::WatchSafeState(const GraphView& view, double graph_end_s) {
  if (result_.safe_ms < 0.0) FindSafeState(view, graph_end_s);
  if (result_.zero_ms < 0.0 && result_.safe_ms >= 0.0 && view.actuator_zero && view.actuator_zero_since_s >= inject_s_) {
    result_.zero_ms = 1000.0 * (view.actuator_zero_since_s - safe_reference_s_);
  }
}

// The safe state: the bridge STOPPED or FAULT, every drive braking (or at 0) for good, or the
// graph gone; whichever is seen first after the injection.
void FaultEpisode::FindSafeState(const GraphView& view, double graph_end_s) {
  double safe_s = -1.0;
  std::string evidence;
  for (const DriveStateChange& change : view.drive_changes) {
    if (change.time_s >= inject_s_ &&
        (change.state == drive_status_t::STOPPED || change.state == drive_status_t::FAULT)) {
      safe_s = change.time_s;
      evidence = "bridge " + DriveStateName(change.state) + ": " + change.stop_reason;
      break;
    }
  }
  // A run of braking outputs counts once it reached 0 or lasted kBrakingConfirmS (not one
  // message of a tracked deceleration); it is timed from its start.
  const double braking_s = view.actuator_braking_since_s;
  if (braking_s >= inject_s_ && (view.actuator_zero || view.last_actuator_s - braking_s >= kBrakingConfirmS) &&
      (safe_s < 0.0 || braking_s < safe_s)) {
    safe_s = braking_s;
    evidence = view.actuator_zero && view.actuator_zero_since_s <= braking_s ? kAtZeroEvidence : kBrakingEvidence;
  }
  // Zeros after a braking run that began before the fault (a tracked deceleration through it).
  if (view.actuator_zero && view.actuator_zero_since_s >= inject_s_ && safe_s < 0.0) {
    safe_s = view.actuator_zero_since_s;
    evidence = kAtZeroEvidence;
  }
  if (graph_end_s >= 0.0 && safe_s < 0.0) safe_s = graph_end_s, evidence = "graph stopped";
  if (safe_s < 0.0) return;
  safe_reference_s_ =
      fault_.from_last_command && view.last_control_command_s >= 0.0 ? view.last_control_command_s : inject_s_;
  result_.safe_ms = 1000.0 * (safe_s - safe_reference_s_);
  result_.safe_evidence = evidence;
}

void FaultEpisode::OperatorReset(const GraphView& view) {
  if (!fault_.operator_reset || view.drive_state != drive_status_t::FAULT) {
    fault_seen_s_ = -1.0;
    return;
  }
  if (fault_seen_s_ < 0.0) fault_seen_s_ = view.now_s;
  if (view.now_s - fault_seen_s_ >= options_.reset_after_s &&
      (last_reset_s_ < 0.0 || view.now_s - last_reset_s_ >= kResetPeriodS)) {
    injector_->SendFaultReset();
    last_reset_s_ = view.now_s;
    ++resets_sent_;
  }
}

void FaultEpisode::WatchPlannerGoal(const GraphView& view) {
  for (const PlannerStatusChange& c : view.planner_changes) {
    if (c.time_s < inject_s_ || !IsToolGoal(c.goal_id)) continue;
    tool_goal_taken_ = true;
    if (!planner_failure_noted_ && c.state == planner_status_t::FAILED) {
      AddReaction("planner: " + c.failure_reason);
      planner_failure_noted_ = true;
    }
  }
}

bool FaultEpisode::Awaiting(std::string what) {
  awaiting_ = std::move(what);
  return false;
}

bool FaultEpisode::Recovered(const GraphView& view) {
  WatchPlannerGoal(view);
  if (fault_.refusal_expected && !planner_failure_noted_) {
    // The planner took the goal (its target not in the map: a box it has not seen) and the
    // mission's own goal replaced it before any refusal: none can come now; recovery as for any
    // fault. Otherwise the refusal has not come yet.
    const std::int64_t current = view.planner_goal_id();
    const bool superseded = tool_goal_taken_ && current != 0 && !IsToolGoal(current);
    if (!superseded) return Awaiting("the planner's refusal of the injected goal");
    if (!superseded_noted_) AddReaction("planner: planned for it (the target not in its map), superseded by the mission's goal");
    superseded_noted_ = true;
  }
  if (view.mission_state == mission_status_t::SUCCEEDED) return true;
  if (fault_.stop_expected && result_.safe_ms < 0.0) return Awaiting("the stop");  // no recovery before it
  // Moving again after the fault was cleared and after the stop it caused, if it caused one.
  const double stopped_s = result_.safe_ms >= 0.0 ? inject_s_ + std::max(0.0, result_.safe_ms * 1e-3) : 0.0;
  // Not on a stop ramp now: the ramp's own outputs are above the moving threshold for a while.
  const bool moving_again = view.last_moving_s > std::max(clear_s_, stopped_s) && view.actuator_braking_since_s < 0.0;
  const bool step_done = view.mission_step > mission_step_at_start_;
  if (FreshDriveState(view) != drive_status_t::RUNNING) return Awaiting("the drives RUNNING");
  if (!(moving_again || step_done)) return Awaiting("the robot moving again or the mission's next step");
  const auto now = GraphProcesses(ancestor_);  // only now: a scan of /proc
  for (const auto& [name, pid] : pids_at_start_) {
    if (!now.count(name)) return Awaiting(name + " running again");
  }
  if (fault_.family == FaultFamily::kKill) {
    const auto it = now.find(CommandNameOf(fault_.target));
    if (it == now.end() || it->second == injector_->KilledPid()) return Awaiting("the restarted " + fault_.target);
    // Back at work: its first heartbeat (the logger sends none).
    if (fault_.target != "logger" && !HeartbeatFrom(view, it->second)) {
      return Awaiting(fmt::format("a heartbeat from the restarted {} (pid {})", fault_.target, it->second));
    }
  }
  return true;
}

void FaultEpisode::GraphEnded(const GraphView& view, int exit_code) {
  if (phase_ == Phase::kDone) return;
  if (phase_ == Phase::kWaitReady) {
    result_.notes = "the graph ended before the robot moved again";
    phase_ = Phase::kDone;
    return;
  }
  injector_->End();
  WatchSafeState(view, view.now_s);
  const bool success = view.mission_state == mission_status_t::SUCCEEDED && exit_code == 0;
  if (success && !result_.recovered) result_.recovered = true, result_.recover_s = view.now_s - inject_s_;
  Finish(view, fmt::format("graph ended (launcher exit code {}{})", exit_code,
                           view.mission_state >= 0 && !view.mission_detail.empty() && !success
                               ? ", mission: " + view.mission_detail
                               : ""));
}

void FaultEpisode::Finish(const GraphView& view, const std::string& outcome) {
  injector_->End();
  result_.notes = injector_->Notes();
  result_.contacts = view.contacts - contacts_at_start_;
  const auto now = GraphProcesses(ancestor_);
  const std::string target = fault_.family == FaultFamily::kKill ? CommandNameOf(fault_.target) : "";
  std::string restarted;
  for (const auto& [name, pid] : pids_at_start_) {
    const auto it = now.find(name);
    if (name != target && it != now.end() && it->second != pid) {
      ++result_.other_restarts;
      restarted += (restarted.empty() ? "" : ", ") + name;
    }
  }
  std::string head = result_.safe_ms >= 0.0 ? fmt::format("{} after {:.0f} ms", result_.safe_evidence, result_.safe_ms)
                                            : "no stop";
  if (result_.zero_ms >= 0.0 && result_.safe_evidence == kBrakingEvidence) {
    head += fmt::format(", at 0 after {:.0f} ms", result_.zero_ms);
  }
  if (resets_sent_ > 0) head += fmt::format("; {} FAULT_RESET sent", resets_sent_);
  const auto held = std::find_if(view.tracker_held_starts_s.begin(), view.tracker_held_starts_s.end(),
                                 [&](double s) { return s >= inject_s_; });
  if (held != view.tracker_held_starts_s.end()) {
    head += fmt::format("; tracker HELD after {:.0f} ms", 1000.0 * (*held - inject_s_));
  }
  result_.reaction = head + (result_.reaction.empty() ? "" : "; " + result_.reaction);
  if (!target.empty()) {
    const auto it = now.find(target);
    const bool back = it != now.end() && it->second != injector_->KilledPid();
    AddReaction(back ? fmt::format("restarted as pid {}", it->second) : std::string("NOT restarted"));
  }
  if (!restarted.empty()) AddReaction("also restarted: " + restarted);
  if (!outcome.empty()) AddReaction(outcome);
  phase_ = Phase::kDone;
}

void FaultEpisode::AddReaction(const std::string& text) {
  result_.reaction += (result_.reaction.empty() ? "" : "; ") + text;
}

}  // namespace topay::tools
