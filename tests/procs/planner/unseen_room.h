#pragma once
// Shared by the planner's graph tests: the room the simulator runs and the planner has never
// seen, written out so that the test knows it exactly too (goals, box places).

#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/planning/base_reachability.h"
#include "core/robot/kinematics.h"
#include "tests/common/arm_state.h"
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

/// A goal configuration (arm bent, random yaw) r_min-r_max m from `from`, exactly clear of
/// `scene` by 0.3 m and whose base the base at `from` can be proven to reach (nullopt if none
/// in 20 000 draws).
inline std::optional<WholeBodyState> ReachableGoal(const Scene& scene, const Kinematics& kinematics,
                                                   const Eigen::Vector2d& from, double r_min, double r_max,
                                                   Rng* rng) {
  const ProvenBaseRegion region(scene, kinematics, from);
  const SceneClearanceChecker checker(kinematics, scene);
  for (int k = 0; k < 20000; ++k) {
    const double r = rng->Uniform(r_min, r_max), a = rng->Uniform(-M_PI, M_PI);
    const WholeBodyState s = BentArmState(from.x() + r * std::cos(a), from.y() + r * std::sin(a), rng->Uniform(-M_PI, M_PI));
    if (!region.Reaches({s.x_m, s.y_m})) continue;
    if (checker.Compute(s).obstacle_m() > 0.3) return s;
  }
  return std::nullopt;
}

}  // namespace topay::test
