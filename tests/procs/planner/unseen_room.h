#pragma once
// Shared by the planner's graph tests: the room the simulator runs and the planner has never
// seen, written out so that the test knows it exactly too (goals, box places).

#include <string>

#include <Eigen/Core>

#include "core/geometry/scene.h"
#include "sim/scenes/scene_json.h"
#include "sim/world/scene_source.h"

namespace topay::test {

/// The Tables room of seed 3 with nothing within 1.2 m of the start (the origin, where the
/// simulator puts the robot), written to `path` as scene JSON (topay-sim --scene path).
inline Scene WriteUnseenTablesRoom(const std::string& path) {
  KeepOutRegions keep_out;
  VerticalCylinder start;
  start.axis_W_m = Eigen::Vector2d::Zero();
  start.radius_m = 1.2;
  start.bottom_z_m = 0.0;
  start.height_m = 3.0;
  keep_out.cylinders.push_back(start);
  Scene room = sim::LoadScene(*sim::ParseSceneArgument("tables", 3), keep_out);
  WriteSceneJson(path, room, nullptr);
  return room;
}

}  // namespace topay::test
