#include "procs/viz/status_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace topay::viz {
namespace {

using nlohmann::json;

// The name of state constant `state` in `names`, or "unknown(<n>)".
template <std::size_t N>
std::string StateName(int state, const std::array<const char*, N>& names) {
  if (state >= 0 && state < static_cast<int>(N)) return names[state];
  return "unknown(" + std::to_string(state) + ")";
}

// NaN and infinities are not JSON numbers: null.
json Finite(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

constexpr std::array<const char*, 6> kPlannerStates = {"IDLE", "PLANNING", "SUCCEEDED", "FAILED", "CANCELLED",
                                                       "STOPPING"};
constexpr std::array<const char*, 5> kTrackerStates = {"IDLE", "TRACKING", "FINISHED", "STOPPING", "HELD"};
constexpr std::array<const char*, 5> kMissionStates = {"IDLE", "RUNNING", "SUCCEEDED", "FAILED", "ABORTED"};
constexpr std::array<const char*, 7> kDriveStates = {"STARTING", "ENABLING", "RUNNING",   "STOPPED",
                                                     "FAULT",    "RECOVERING", "REPLAY"};
constexpr std::array<const char*, 6> kProcessStates = {"WAITING", "STARTING", "RUNNING", "BACKOFF", "EXITED",
                                                       "STOPPING"};

}  // namespace

json PlannerStatusJson(const planner_status_t& m) {
  return {{"t", m.utime * 1e-6},         {"state", m.state},
          {"state_name", StateName(m.state, kPlannerStates)},
          {"goal_id", m.goal_id},        {"trajectory_id", m.trajectory_id},
          {"failure_reason", m.failure_reason},
          {"front_end_ms", Finite(m.front_end_ms)}, {"sampling_ms", Finite(m.sampling_ms)},
          {"optimization_ms", Finite(m.optimization_ms)}, {"total_ms", Finite(m.total_ms)},
          {"replans", m.replans},        {"detail", m.detail}};
}

json TrackerStatusJson(const tracker_status_t& m) {
  return {{"t", m.utime * 1e-6},   {"state", m.state},
          {"state_name", StateName(m.state, kTrackerStates)},
          {"trajectory_id", m.trajectory_id}, {"goal_id", m.goal_id},
          {"t_along_s", Finite(m.t_along_s)}, {"position_error_m", Finite(m.position_error_m)},
          {"yaw_error_rad", Finite(m.yaw_error_rad)}, {"joint_error_rad", Finite(m.joint_error_rad)},
          {"solve_ms", Finite(m.solve_ms)}};
}

json MissionStatusJson(const mission_status_t& m) {
  return {{"t", m.utime * 1e-6},      {"mission", m.mission},
          {"state", m.state},         {"state_name", StateName(m.state, kMissionStates)},
          {"step_index", m.step_index}, {"num_steps", m.num_steps},
          {"step", m.step},           {"goal_id", m.goal_id},
          {"attempts", m.attempts},   {"elapsed_s", Finite(m.elapsed_s)},
          {"detail", m.detail}};
}

json SimStatusJson(const sim_status_t& m) {
  return {{"t", m.utime * 1e-6},
          {"state_name", m.in_contact ? "IN_CONTACT" : "OK"},
          {"sim_time_s", Finite(m.sim_time_s)},
          {"real_time_factor", Finite(m.real_time_factor)},
          {"target_rate", Finite(m.target_rate)},
          {"plant_steps", m.plant_steps},
          {"late_steps", m.late_steps},
          {"step_lateness_p99_us", Finite(m.step_lateness_p99_us)},
          {"commands_accepted", m.commands_accepted},
          {"commands_rejected", m.commands_rejected},
          {"command_timeouts", m.command_timeouts},
          {"contact_events", m.contact_events},
          {"contact_steps", m.contact_steps},
          {"max_depth_m", Finite(m.max_depth_m)},
          {"in_contact", m.in_contact},
          {"scans", m.scans},
          {"events_applied", m.events_applied},
          {"boxes_present", m.boxes_present}};
}

json DriveStatusJson(const drive_status_t& m) {
  json drives = json::array();
  for (int i = 0; i < m.num_drives; ++i) {
    drives.push_back({{"node_id", m.node_id[i]},
                      {"joint_name", m.joint_name[i]},
                      {"drive_state", m.drive_state[i]},
                      {"nmt_state", m.nmt_state[i]},
                      {"statusword", m.statusword[i]},
                      {"last_emcy_code", m.last_emcy_code[i]},
                      {"heartbeat_age_s", Finite(m.heartbeat_age_s[i])}});
  }
  return {{"t", m.utime * 1e-6},
          {"state", m.state},
          {"state_name", StateName(m.state, kDriveStates)},
          {"stop_reason", m.stop_reason},
          {"can_url", m.can_url},
          {"bus_state", m.bus_state},
          {"frames_sent", m.frames_sent},
          {"frames_received", m.frames_received},
          {"error_frames", m.error_frames},
          {"bus_off_count", m.bus_off_count},
          {"tx_refused", m.tx_refused},
          {"frames_malformed", m.frames_malformed},
          {"frames_unknown", m.frames_unknown},
          {"bus_load_percent", Finite(m.bus_load_percent)},
          {"command_age_s", Finite(m.command_age_s)},
          {"commands_received", m.commands_received},
          {"commands_rejected", m.commands_rejected},
          {"clamp_count", m.clamp_count},
          {"command_latency_p99_ms", Finite(m.command_latency_p99_ms)},
          {"cycle_jitter_p99_ms", Finite(m.cycle_jitter_p99_ms)},
          {"base_mode", m.base_mode},
          {"base_fault_bits", m.base_fault_bits},
          {"base_faults", m.base_faults},
          {"base_status_age_s", Finite(m.base_status_age_s)},
          {"base_battery_v", Finite(m.base_battery_v)},
          {"drives", std::move(drives)}};
}

json GraphStatusJson(const graph_status_t& m) {
  json processes = json::array();
  for (int i = 0; i < m.num_processes; ++i) {
    processes.push_back({{"name", m.names[i]},
                         {"state", m.states[i]},
                         {"state_name", StateName(m.states[i], kProcessStates)},
                         {"pid", m.pids[i]},
                         {"restarts", m.restarts[i]},
                         {"cpu_percent", Finite(m.cpu_percent[i])},
                         {"rss_kB", m.rss_kB[i]},
                         {"heartbeat_age_s", Finite(m.heartbeat_age_s[i])},
                         {"health", m.health[i]}});
  }
  return {{"t", m.utime * 1e-6}, {"graph_name", m.graph_name}, {"run_dir", m.run_dir},
          {"processes", std::move(processes)}};
}

json GoalJson(const goal_t& m) {
  return {{"t", m.utime * 1e-6},
          {"goal_id", m.goal_id},
          {"p_WE_m", {Finite(m.p_WE[0]), Finite(m.p_WE[1]), Finite(m.p_WE[2])}},
          {"quat_WE", {Finite(m.quat_WE[0]), Finite(m.quat_WE[1]), Finite(m.quat_WE[2]), Finite(m.quat_WE[3])}}};
}

json CandidatePathsJson(const planner_paths_t& m) {
  json paths = json::array();
  int first = 0;
  for (int i = 0; i < m.num_paths; ++i) {
    json points = json::array();
    const int count = std::clamp(m.path_points[i], 0, m.num_points - first);  // a short message: what is there
    for (int k = first; k < first + count; ++k) points.push_back({Finite(m.x_m[k]), Finite(m.y_m[k])});
    first += count;
    paths.push_back({{"points_m", std::move(points)}, {"length_m", Finite(m.length_m[i])},
                     {"chosen", i == m.chosen}, {"source", m.source[i]}});
  }
  return {{"t", m.utime * 1e-6}, {"goal_id", m.goal_id}, {"trajectory_id", m.trajectory_id},
          {"paths", std::move(paths)}};
}

}  // namespace topay::viz
