#include "procs/viz/viz_channels.h"
#include "procs/viz/json_text.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <utility>

namespace topay::viz {
namespace {

using nlohmann::json;

json Type(const char* type, const char* description = nullptr) {
  json j = {{"type", type}};
  if (description != nullptr) j["description"] = description;
  return j;
}
json Number(const char* description = nullptr) { return Type("number", description); }
json Integer(const char* description = nullptr) { return Type("integer", description); }
json String(const char* description = nullptr) { return Type("string", description); }
json Boolean() { return Type("boolean"); }
json NullableNumber() { return json{{"type", json::array({"number", "null"})}}; }
json Array(json items) { return {{"type", "array"}, {"items", std::move(items)}}; }
json Vector(int size, const char* description) {
  json j = Array(Number());
  j["minItems"] = size;
  j["maxItems"] = size;
  j["description"] = description;
  return j;
}
json Base64(const char* description) {
  json j = String(description);
  j["contentEncoding"] = "base64";
  return j;
}
json Object(std::initializer_list<std::pair<const char*, json>> properties) {
  json props = json::object();
  for (const auto& [name, schema] : properties) props[name] = schema;
  return {{"type", "object"}, {"properties", std::move(props)}};
}

json RobotDescription() {
  json visual = Object({{"shape", String("box, cylinder (axis z of the visual) or sphere")},
                        {"size_m", Vector(3, "box edges; cylinder 2r, 2r, length; sphere 2r")},
                        {"p_LV_m", Vector(3, "visual origin in the link frame L, m")},
                        {"quat_LV", Vector(4, "visual orientation in L, w x y z")},
                        {"rgba", Vector(4, "colour 0..1")}});
  return Object({{"name", String()},
                 {"joint_names", Array(String())},
                 {"base", Object({{"radius_m", Number()}, {"height_m", Number()}})},
                 {"links", Array(Object({{"name", String()}, {"visuals", Array(visual)}}))}});
}

json RobotState() {
  return Object({{"t", Number("time of the estimate, s since the Unix epoch")},
                 {"x_m", Number()}, {"y_m", Number()}, {"yaw_rad", Number()},
                 {"v_mps", Number()}, {"omega_radps", Number()},
                 {"q_rad", Array(Number())}, {"gripper", NullableNumber()},
                 {"links", Array(Object({{"p_WL_m", Vector(3, "link origin in W, m")},
                                         {"quat_WL", Vector(4, "link orientation in W, w x y z")}}))},
                 {"p_WE_m", Vector(3, "end effector in W, m")}});
}

json MapBlocks() {
  json block = Object({{"key", Array(Integer())},
                       {"occupied", Base64("uint16 LE local indices li + 16 (lj + 16 lk)")}});
  return Object({{"map_seq", Integer()}, {"t", Number()}, {"resolution_m", Number()},
                 {"origin_W_m", Vector(3, "minimum corner of voxel (0, 0, 0) in W, m")},
                 {"dims", Array(Integer())}, {"block_edge", Integer()}, {"reset", Boolean()},
                 {"blocks", Array(block)}, {"occupied_total", Integer()}});
}

json Scan() {
  return Object({{"t", Number()}, {"p_WS_m", Vector(3, "sensor origin in W, m")},
                 {"count", Integer("points sent")}, {"points_total", Integer("points in the scan")},
                 {"points_cm", Base64("int16 LE x y z per point: p_W - p_WS, cm")}});
}

json Trajectory() {
  json samples = Object({{"t_s", Array(Number())}, {"v_mps", Array(Number())},
                         {"omega_radps", Array(Number())}, {"a_mps2", Array(Number())},
                         {"beta_radps2", Array(Number())}, {"q_rad", Array(Array(Number()))}});
  return Object({{"trajectory_id", Integer()}, {"goal_id", Integer()}, {"start_t", Number()},
                 {"duration_s", Number()}, {"base_path_m", Array(Array(Number()))},
                 {"ee_path_m", Array(Array(Number()))}, {"samples", samples}});
}

json CandidatePaths() {
  json path = Object({{"points_m", Array(Array(Number()))}, {"length_m", Number()},
                      {"chosen", Boolean()}, {"source", String()}});
  return Object({{"t", Number()}, {"goal_id", Integer()}, {"trajectory_id", Integer()},
                 {"paths", Array(path)}});
}

json Goal() {
  return Object({{"t", Number()}, {"goal_id", Integer()}, {"p_WE_m", Vector(3, "m")},
                 {"quat_WE", Vector(4, "w x y z")}});
}

json Contacts() {
  json contact = Object({{"t", Number()}, {"body", String()}, {"box_id", Integer()},
                         {"depth_m", Number()}, {"p_W_m", Vector(3, "where the body was, m")},
                         {"radius_m", Number()}});
  return Object({{"count", Integer("contacts so far")}, {"contacts", Array(contact)}});
}

json PlotSample() {
  return Object({{"t", Number()}, {"trajectory_id", Integer()}, {"v_mps", Number()},
                 {"omega_radps", Number()}, {"q_rad", Array(Number())},
                 {"v_plan_mps", NullableNumber()}, {"omega_plan_radps", NullableNumber()},
                 {"a_plan_mps2", NullableNumber()}, {"beta_plan_radps2", NullableNumber()},
                 {"q_plan_rad", {{"type", json::array({"array", "null"})}, {"items", Number()}}}});
}

/// A status message: its LCM fields by name (lcmtypes/<type>.lcm), t and state_name.
json StatusMessage(const char* lcm_type) {
  json j = Object({{"t", Number()}, {"state_name", String()}});
  j["description"] = std::string("the fields of topay.") + lcm_type + " (lcmtypes/), utime as t (s)";
  j["additionalProperties"] = true;
  return j;
}

json GraphStatus() {
  json process = Object({{"name", String()}, {"state", Integer()}, {"state_name", String()},
                         {"pid", Integer()}, {"restarts", Integer()}, {"cpu_percent", Number()},
                         {"rss_kB", Integer()}, {"heartbeat_age_s", Number()}, {"health", Integer()}});
  return Object({{"t", Number()}, {"graph_name", String()}, {"processes", Array(process)}});
}

json VizStats() {
  return Object({{"t", Number()}, {"clients", Integer()}, {"lcm_messages", Integer()},
                 {"lcm_malformed", Integer()}, {"frames_sent", Integer()}, {"frames_dropped", Integer()},
                 {"bytes_sent", Integer()}, {"bytes_per_s", Number()}});
}

json Playback() {
  return Object({{"mode", String("live or replay")}, {"t", Number()}, {"start_t", Number()},
                 {"end_t", Number()}, {"playing", Boolean()}, {"speed", Number()},
                 {"seeks", Integer("seeks so far: a change means drop what was drawn")}});
}

VizChannel Make(Topic topic, const char* name, const char* schema_name, const json& schema, bool latched) {
  return VizChannel{topic, name, std::string("topay.viz.") + schema_name, schema.dump(-1, ' ', false, kReplaceInvalidUtf8), latched};
}

}  // namespace

std::array<VizChannel, kNumTopics> VizChannels() {
  return {
      Make(Topic::kRobotDescription, "/robot/description", "RobotDescription", RobotDescription(), true),
      Make(Topic::kRobotState, "/robot/state", "RobotState", RobotState(), true),
      Make(Topic::kMapBlocks, "/map/blocks", "MapBlocks", MapBlocks(), true),
      Make(Topic::kScan, "/lidar/scan", "Scan", Scan(), true),
      Make(Topic::kTrajectory, "/planner/trajectory", "Trajectory", Trajectory(), true),
      Make(Topic::kCandidatePaths, "/planner/paths", "CandidatePaths", CandidatePaths(), true),
      Make(Topic::kPlannerStatus, "/planner/status", "PlannerStatus", StatusMessage("planner_status_t"), true),
      Make(Topic::kGoal, "/goal", "Goal", Goal(), true),
      Make(Topic::kContacts, "/sim/contacts", "Contacts", Contacts(), true),
      Make(Topic::kPlotSample, "/plot/state", "PlotSample", PlotSample(), false),
      Make(Topic::kTrackerStatus, "/tracker/status", "TrackerStatus", StatusMessage("tracker_status_t"), true),
      Make(Topic::kMissionStatus, "/mission/status", "MissionStatus", StatusMessage("mission_status_t"), true),
      Make(Topic::kGraphStatus, "/graph/status", "GraphStatus", GraphStatus(), true),
      Make(Topic::kDriveStatus, "/can/drives", "DriveStatus", StatusMessage("drive_status_t"), true),
      Make(Topic::kSimStatus, "/sim/status", "SimStatus", StatusMessage("sim_status_t"), true),
      Make(Topic::kVizStats, "/viz/stats", "VizStats", VizStats(), true),
      Make(Topic::kPlayback, "/viz/playback", "Playback", Playback(), true),
  };
}

}  // namespace topay::viz
