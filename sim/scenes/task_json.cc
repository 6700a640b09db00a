#include "sim/scenes/task_json.h"

#include <cmath>
#include <fstream>
#include <limits>

#include "core/common/error.h"
#include "sim/scenes/json_fields.h"

namespace topay {
namespace {

using Json = nlohmann::ordered_json;

Json StateJson(const WholeBodyState& state) {
  Json json;
  json["x_m"] = state.x_m;
  json["y_m"] = state.y_m;
  json["yaw_rad"] = state.yaw_rad;
  json["q_rad"] = Json::array();
  for (int i = 0; i < state.num_joints(); ++i) json["q_rad"].push_back(state.q_rad(i));
  return json;
}

Json PoseJson(const Eigen::Isometry3d& X_WE) {
  const Eigen::Vector3d p = X_WE.translation();
  const Eigen::Quaterniond quaternion(X_WE.rotation());
  Json json;
  json["position_m"] = Json::array({p.x(), p.y(), p.z()});
  json["quaternion_wxyz"] =
      Json::array({quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z()});
  return json;
}

Json TightEndJson(const TightEnd& end) {
  Json json;
  json["clearance_m"] = end.clearance_m;
  json["box"] = end.box;
  json["body"] = std::string(TightBodyName(end.body));
  return json;
}

}  // namespace

nlohmann::ordered_json TightInfoToJson(const TightTaskInfo& info) {
  Json json;
  json["start"] = TightEndJson(info.start);
  json["goal"] = TightEndJson(info.goal);
  json["goal_kind"] = std::string(TightGoalKindName(info.goal_kind));
  json["goal_table_top"] = info.goal_table_top >= 0 ? Json(info.goal_table_top) : Json(nullptr);
  return json;
}

namespace {

// A box index: a non-negative integer below 2^31.
int ReadBoxIndex(const JsonFieldReader& reader, const nlohmann::json& value,
                 const std::string& path) {
  const std::uint64_t index = reader.Unsigned(value, path);
  if (index > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    reader.Fail(path, "box index too large");
  }
  return static_cast<int>(index);
}

TightEnd ReadTightEnd(const JsonFieldReader& reader, const nlohmann::json& tight,
                      const std::string& key) {
  const std::string path = "tight." + key;
  const nlohmann::json& value = reader.Member(tight, "tight", key);
  reader.RequireKnownKeys(value, path, {"clearance_m", "box", "body"});
  TightEnd end;
  end.clearance_m =
      reader.Number(reader.Member(value, path, "clearance_m"), path + ".clearance_m");
  end.box = ReadBoxIndex(reader, reader.Member(value, path, "box"), path + ".box");
  const std::string body = reader.String(reader.Member(value, path, "body"), path + ".body");
  const std::optional<TightBody> parsed = ParseTightBody(body);
  if (!parsed) reader.Fail(path + ".body", "unknown body \"" + body + "\" (base, arm)");
  end.body = *parsed;
  return end;
}

TightTaskInfo ReadTight(const JsonFieldReader& reader, const nlohmann::json& value) {
  reader.RequireObject(value, "tight");
  reader.RequireKnownKeys(value, "tight", {"start", "goal", "goal_kind", "goal_table_top"});
  TightTaskInfo info;
  info.start = ReadTightEnd(reader, value, "start");
  info.goal = ReadTightEnd(reader, value, "goal");
  const std::string kind =
      reader.String(reader.Member(value, "tight", "goal_kind"), "tight.goal_kind");
  const std::optional<TightGoalKind> parsed = ParseTightGoalKind(kind);
  if (!parsed) {
    reader.Fail("tight.goal_kind",
                "unknown goal kind \"" + kind + "\" (near_box, on_table, under_table)");
  }
  info.goal_kind = *parsed;
  const nlohmann::json& top = reader.Member(value, "tight", "goal_table_top");
  if (!top.is_null()) info.goal_table_top = ReadBoxIndex(reader, top, "tight.goal_table_top");
  if ((info.goal_kind == TightGoalKind::kNearBox) != (info.goal_table_top < 0)) {
    reader.Fail("tight.goal_table_top",
                "must be null exactly when goal_kind is near_box (goal_kind \"" + kind + "\")");
  }
  return info;
}

WholeBodyState ReadState(const JsonFieldReader& reader, const nlohmann::json& document,
                         const std::string& key) {
  const nlohmann::json& value = reader.Member(document, "", key);
  reader.RequireKnownKeys(value, key, {"x_m", "y_m", "yaw_rad", "q_rad"});
  auto field = [&](const char* name) -> const nlohmann::json& {
    return reader.Member(value, key, name);
  };
  WholeBodyState state;
  state.x_m = reader.Number(field("x_m"), key + ".x_m");
  state.y_m = reader.Number(field("y_m"), key + ".y_m");
  state.yaw_rad = reader.Number(field("yaw_rad"), key + ".yaw_rad");
  state.q_rad = reader.NumberArray(field("q_rad"), key + ".q_rad", -1);
  return state;
}

Eigen::Isometry3d ReadPose(const JsonFieldReader& reader, const nlohmann::json& document) {
  const std::string key = "goal_end_effector";
  const nlohmann::json& value = reader.Member(document, "", key);
  reader.RequireKnownKeys(value, key, {"position_m", "quaternion_wxyz"});
  const Eigen::Vector3d p =
      reader.Vector3(reader.Member(value, key, "position_m"), key + ".position_m");
  const std::string q_path = key + ".quaternion_wxyz";
  const Eigen::VectorXd q = reader.NumberArray(reader.Member(value, key, "quaternion_wxyz"),
                                               q_path, 4);
  if (std::abs(q.norm() - 1.0) > 1e-6) {
    reader.Fail(q_path, "not a unit quaternion (norm " + JsonNumberText(q.norm()) + ")");
  }
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.linear() = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
  X_WE.translation() = p;
  return X_WE;
}

void CheckJointCounts(const JsonFieldReader& reader, const PlanningTask& task,
                      int expected_num_joints) {
  if (task.goal.num_joints() != task.start.num_joints()) {
    reader.Fail("goal.q_rad", "has " + std::to_string(task.goal.num_joints()) +
                                  " joints, start.q_rad has " +
                                  std::to_string(task.start.num_joints()));
  }
  if (expected_num_joints >= 0 && task.start.num_joints() != expected_num_joints) {
    reader.Fail("start.q_rad", "has " + std::to_string(task.start.num_joints()) +
                                   " joints, the robot has " +
                                   std::to_string(expected_num_joints));
  }
}

PlanningTask TaskFromDocument(const JsonFieldReader& reader, const nlohmann::json& document,
                              int expected_num_joints) {
  reader.RequireKnownKeys(document, "", {"range", "seed", "scene_seed", "base_distance_m",
                                         "start", "goal", "goal_end_effector", "tight"});
  PlanningTask task;
  const std::string range = reader.String(reader.Member(document, "", "range"), "range");
  const std::optional<DistanceRange> parsed = ParseDistanceRange(range);
  if (!parsed) reader.Fail("range", "unknown range \"" + range + "\" (small, medium, large)");
  task.range = *parsed;
  task.seed = reader.Unsigned(reader.Member(document, "", "seed"), "seed");
  task.scene_seed = reader.Unsigned(reader.Member(document, "", "scene_seed"), "scene_seed");
  task.base_distance_m =
      reader.Number(reader.Member(document, "", "base_distance_m"), "base_distance_m");
  task.start = ReadState(reader, document, "start");
  task.goal = ReadState(reader, document, "goal");
  CheckJointCounts(reader, task, expected_num_joints);
  const double distance = std::hypot(task.goal.x_m - task.start.x_m,
                                     task.goal.y_m - task.start.y_m);
  if (std::abs(distance - task.base_distance_m) > 1e-6) {
    reader.Fail("base_distance_m", "disagrees with start and goal (" +
                                       JsonNumberText(distance) + " m)");
  }
  task.X_WE_goal = ReadPose(reader, document);
  if (const nlohmann::json* tight = reader.OptionalMember(document, "tight")) {
    task.tight = ReadTight(reader, *tight);
  }
  return task;
}

}  // namespace

std::string TaskToJson(const PlanningTask& task) {
  Json json;
  json["range"] = std::string(DistanceRangeName(task.range));
  json["seed"] = task.seed;
  json["scene_seed"] = task.scene_seed;
  json["base_distance_m"] = task.base_distance_m;
  json["start"] = StateJson(task.start);
  json["goal"] = StateJson(task.goal);
  json["goal_end_effector"] = PoseJson(task.X_WE_goal);
  if (task.tight) json["tight"] = TightInfoToJson(*task.tight);
  return json.dump(2) + "\n";
}

void WriteTaskJson(const std::string& path, const PlanningTask& task) {
  const std::string text = TaskToJson(task);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw ConfigError(path, "", "cannot write the task file");
}

PlanningTask ReadTaskJson(const std::string& path, int expected_num_joints) {
  const JsonFieldReader reader(path);
  return TaskFromDocument(reader, reader.ParseFile(kMaxTaskJsonBytes, "task JSON"),
                          expected_num_joints);
}

PlanningTask TaskFromJson(const std::string& text, const std::string& file_name,
                          int expected_num_joints) {
  const JsonFieldReader reader(file_name);
  return TaskFromDocument(reader, reader.ParseText(text), expected_num_joints);
}

}  // namespace topay
