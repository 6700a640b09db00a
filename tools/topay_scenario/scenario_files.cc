#include "tools/topay_scenario/scenario_files.h"

#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "sim/scenarios/pick_place_mission.h"
#include "sim/scenes/scene_json.h"

namespace topay::scenario {
namespace {

nlohmann::json GoalJson(const char* name, const TableTopGoal& goal) {
  const Eigen::Vector3d p_WE = goal.X_WE.translation();
  const Eigen::Quaterniond q_WE(goal.X_WE.rotation());
  const WholeBodyState& s = goal.state;
  return {{"name", name},
          {"table_top", goal.table_top},
          {"clearance_m", goal.clearance_m},
          {"state", {{"x_m", s.x_m}, {"y_m", s.y_m}, {"yaw_rad", s.yaw_rad},
                     {"q_rad", std::vector<double>(s.q_rad.data(), s.q_rad.data() + s.q_rad.size())}}},
          {"p_WE_m", {p_WE.x(), p_WE.y(), p_WE.z()}},
          {"quat_wxyz", {q_WE.w(), q_WE.x(), q_WE.y(), q_WE.z()}}};
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw ConfigError(path, "", "cannot be written");
}

}  // namespace

std::string ScenarioJson(const PickPlaceScenario& scenario) {
  const nlohmann::json json = {
      {"seed", scenario.seed},
      {"room", "room.json"},
      {"mission", "mission.yaml"},
      {"start", {{"x_m", scenario.p_W_start_m.x()}, {"y_m", scenario.p_W_start_m.y()}}},
      {"goals", {GoalJson("pickup", scenario.pickup), GoalJson("dropoff", scenario.dropoff)}}};
  return json.dump(2) + "\n";
}

std::string GoalLine(const char* name, const PickPlaceScenario& scenario, const TableTopGoal& goal,
                     const Eigen::Vector2d& p_W_from_m, const char* from_name) {
  const OrientedBox& top = scenario.room.scene.boxes.at(goal.table_top);
  const Eigen::Vector3d p_WE = goal.X_WE.translation();
  const Eigen::Vector2d p_WB(goal.state.x_m, goal.state.y_m);
  return fmt::format(
      "{}: table top {} (upper face {:.2f} m), p_WE ({:.3f}, {:.3f}, {:.3f}) m, base ({:.3f}, {:.3f}) m yaw {:.3f} rad, "
      "{:.2f} m from the {}, clearance {:.3f} m",
      name, goal.table_top, top.center_W_m.z() + 0.5 * top.size_m.z(), p_WE.x(), p_WE.y(), p_WE.z(), p_WB.x(),
      p_WB.y(), goal.state.yaw_rad, (p_WB - p_W_from_m).norm(), from_name, goal.clearance_m);
}

void WriteScenarioFiles(const std::string& dir, const PickPlaceScenario& scenario,
                        const PickPlaceScenarioOptions& options) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw ConfigError(dir, "", "cannot create the folder: " + error.message());
  WriteSceneJson(dir + "/room.json", scenario.room.scene, &scenario.room.roles);
  WriteText(dir + "/mission.yaml", PickPlaceMissionYaml(scenario, options));
  WriteText(dir + "/scenario.json", ScenarioJson(scenario));
}

}  // namespace topay::scenario
