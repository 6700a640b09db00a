#include "sim/scenarios/pick_place_mission.h"

#include <string>

#include <Eigen/Geometry>
#include <fmt/format.h>

namespace topay {
namespace {

std::string List(const double* values, int n) {
  std::string text = "[";
  for (int i = 0; i < n; ++i) text += fmt::format("{}{}", i == 0 ? "" : ", ", values[i]);
  return text + "]";
}

std::string GotoStep(const char* name, const TableTopGoal& goal) {
  const Eigen::Vector3d p_WE = goal.X_WE.translation();
  const Eigen::Quaterniond q_WE(goal.X_WE.rotation());
  const double wxyz[4] = {q_WE.w(), q_WE.x(), q_WE.y(), q_WE.z()};
  const WholeBodyState& s = goal.state;
  return fmt::format(
      "  - type: goto\n"
      "    name: {}\n"
      "    position_m: {}\n"
      "    quat_wxyz: {}\n"
      "    hint: {{x_m: {}, y_m: {}, yaw_rad: {}, q_rad: {}}}\n",
      name, List(p_WE.data(), 3), List(wxyz, 4), s.x_m, s.y_m, s.yaw_rad, List(s.q_rad.data(), s.num_joints()));
}

}  // namespace

std::string PickPlaceMissionYaml(const PickPlaceScenario& scenario, const PickPlaceScenarioOptions& options) {
  return fmt::format(
      "# The pick-and-place scenario of seed {} (topay-scenario): pickup above table top {}, drop-off\n"
      "# above table top {}, back home.\n"
      "name: pick_and_place\n"
      "steps:\n"
      "{}"
      "  - type: gripper\n"
      "    action: close\n"
      "{}"
      "  - type: gripper\n"
      "    action: open\n"
      "  - type: wait\n"
      "    duration_s: {}\n"
      "  - type: home\n",
      scenario.seed, scenario.pickup.table_top, scenario.dropoff.table_top, GotoStep("pickup", scenario.pickup),
      GotoStep("dropoff", scenario.dropoff), options.wait_s);
}

}  // namespace topay
