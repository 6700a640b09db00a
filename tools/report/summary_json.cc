#include "tools/report/summary_json.h"

#include <fstream>
#include <stdexcept>

namespace topay::report {
namespace {

using nlohmann::json;

json TimingJson(const TimingStats& t) {
  return {{"count", t.count}, {"median", t.median}, {"p95", t.p95}, {"p99", t.p99}, {"max", t.max}};
}

json ErrorJson(const ErrorStats& e) { return {{"count", e.count}, {"rms", e.rms}, {"max", e.max}}; }

json MissionJson(const MissionSummary& m) {
  json steps = json::array();
  for (const MissionStepSummary& s : m.steps) {
    steps.push_back({{"index", s.index}, {"description", s.description}, {"start_s", s.start_s},
                     {"time_s", s.time_s}, {"moving", s.moving}, {"attempts", s.attempts}});
  }
  return {{"name", m.name},           {"result", ToString(m.result)}, {"detail", m.detail},
          {"elapsed_s", m.elapsed_s}, {"num_steps", m.num_steps},     {"steps", steps}};
}

json PlannerJson(const RunSummary& s) {
  const PlannerSummary& p = s.planner;
  return {{"replans", p.replans},
          {"goals", p.goals},
          {"trajectory_messages", s.trajectory_messages},
          {"trajectories_rebuilt", s.trajectories_rebuilt},
          {"stopping", p.stopping},
          {"reached_at_rest", p.reached_at_rest},
          {"planning_total_ms", TimingJson(p.planning_ms)},
          {"failures", p.failures},
          {"failure_reasons", p.failure_reasons}};
}

json CollisionJson(const CollisionSummary& c) {
  return {{"has_sim_status", c.has_sim_status}, {"contact_events", c.contact_events},
          {"contact_steps", c.contact_steps},   {"max_depth_m", c.max_depth_m},
          {"contact_messages", c.contact_messages}};
}

json TrackingJson(const TrackingSummary& t) {
  return {{"position_m", ErrorJson(t.position_m)},
          {"yaw_rad", ErrorJson(t.yaw_rad)},
          {"joint_rad", ErrorJson(t.joint_rad)},
          {"solve_ms", TimingJson(t.solve_ms)}};
}

json EstimationJson(const EstimationSummary& e) {
  return {{"pairs", e.pairs},
          {"position_m", ErrorJson(e.position_m)},
          {"yaw_rad", ErrorJson(e.yaw_rad)},
          {"joint_rad", ErrorJson(e.joint_rad)}};
}

json BoxesJson(const std::vector<AppearedBox>& boxes) {
  json out = json::array();
  for (const AppearedBox& b : boxes) {
    json box = {{"box_id", b.box_id}, {"name", b.name}, {"has_box", b.has_box}};
    if (b.has_box) {
      box["center_m"] = {b.center_W_m.x(), b.center_W_m.y(), b.center_W_m.z()};
      box["size_m"] = {b.size_m.x(), b.size_m.y(), b.size_m.z()};
      box["yaw_rad"] = b.yaw_rad;
    }
    out.push_back(box);
  }
  return out;
}

json ChannelsJson(const std::map<std::string, ChannelCount>& channels) {
  json out = json::object();
  for (const auto& [name, c] : channels) {
    out[name] = {{"messages", c.messages}, {"decode_failures", c.decode_failures}};
  }
  return out;
}

}  // namespace

json SummaryToJson(const RunSummary& s) {
  return {{"log", {{"path", s.log_path}, {"span_s", s.log_span_s}}},
          {"success", s.succeeded()},
          {"mission", MissionJson(s.mission)},
          {"planner", PlannerJson(s)},
          {"collisions", CollisionJson(s.collisions)},
          {"tracking", TrackingJson(s.tracking)},
          {"estimation", EstimationJson(s.estimation)},
          {"distance_driven_m", s.distance_driven_m},
          {"appeared_boxes", BoxesJson(s.appeared_boxes)},
          {"channels", ChannelsJson(s.channels)},
          {"decode_failures", s.decode_failures},
          {"files",
           {{"summary_json", s.files.summary_json},
            {"path_png", s.files.path_png},
            {"time_plots_png", s.files.time_plots_png}}}};
}

void WriteSummaryJson(const RunSummary& summary, const std::string& path) {
  std::ofstream file(path);
  file << SummaryToJson(summary).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";  // texts from the log
  if (!file.good()) throw std::runtime_error(path + ": cannot write the summary");
}

}  // namespace topay::report
