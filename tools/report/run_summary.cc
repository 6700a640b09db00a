#include "tools/report/run_summary.h"

#include <cmath>

namespace topay::report {
namespace {

CollisionSummary SummarizeCollisions(const RunLog& log) {
  CollisionSummary c;
  c.contact_messages = static_cast<std::int64_t>(log.sim_contacts.size());
  if (log.sim_statuses.empty()) return c;
  const sim_status_t& last = log.sim_statuses.back();
  c.has_sim_status = true;
  c.contact_events = last.contact_events;
  c.contact_steps = last.contact_steps;
  c.max_depth_m = last.max_depth_m;
  return c;
}

double DistanceDriven(const std::vector<msgs::RobotStateEstimate>& states) {
  double distance_m = 0.0;
  for (std::size_t k = 1; k < states.size(); ++k) {
    const WholeBodyState& a = states[k - 1].state;
    const WholeBodyState& b = states[k].state;
    distance_m += std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  }
  return distance_m;
}

std::vector<AppearedBox> AppearedBoxes(const std::vector<sim_event_t>& events) {
  std::vector<AppearedBox> boxes;
  for (const sim_event_t& e : events) {
    if (e.action != sim_event_t::APPEAR) continue;
    boxes.push_back({e.box_id, e.name, e.has_box != 0, Eigen::Vector3d(e.center_m[0], e.center_m[1], e.center_m[2]),
                     Eigen::Vector3d(e.size_m[0], e.size_m[1], e.size_m[2]), e.yaw_rad});
  }
  return boxes;
}

}  // namespace

RunSummary Summarize(const RunLog& log) {
  RunSummary s;
  s.log_path = log.path;
  s.log_span_s = static_cast<double>(log.last_utime - log.first_utime) * 1e-6;
  s.mission = SummarizeMission(log.mission_statuses);
  s.planner = SummarizePlanner(log.planner_statuses);
  s.trajectory_messages = log.trajectory_messages;
  s.trajectories_rebuilt = static_cast<std::int64_t>(log.trajectories.size());
  s.collisions = SummarizeCollisions(log);
  s.tracking = SummarizeTracking(log.tracker_statuses);
  s.estimation = SummarizeEstimation(log.robot_states, log.plant_states);
  s.distance_driven_m = DistanceDriven(log.robot_states);
  s.appeared_boxes = AppearedBoxes(log.sim_events);
  s.channels = log.channels;
  for (const auto& [channel, count] : log.channels) s.decode_failures += count.decode_failures;
  return s;
}

RunSummary Summarize(const std::string& log_path) { return Summarize(ReadRunLog(log_path)); }

}  // namespace topay::report
