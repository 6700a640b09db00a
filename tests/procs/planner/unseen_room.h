#pragma once
// Shared by the planner's graph tests: the room the simulator runs and the planner has never
// seen, written out so that the test knows it exactly too (goals, box places).

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "graph_test_support.h"
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

/// Starts the planner's graph before the tracker exists, in `dir` (logs mapper.txt,
/// planner.txt, sim.txt): topay-mapper, topay-planner (config/planner/topay.yaml, 10 s for a
/// plan from rest) and topay-sim --follow (the ideal follower) in the room `dir`/room.json.
inline std::vector<pid_t> SpawnFollowGraph(const std::string& dir, const std::string& lcm_url) {
  const auto config = [](const std::string& rel) { return std::string(TOPAY_SOURCE_DIR) + "/config/" + rel; };
  WriteText(dir + "/planner.yaml",
            "planner_config: " + config("planner/topay.yaml") + "\ntiming: {from_rest_time_limit_s: 10.0}\n");
  return {Spawn({BinDir() + "/topay-mapper", "--config", config("mapper/mapper.yaml"), "--name", "mapper",
                 "--lcm-url", lcm_url}, dir + "/mapper.txt"),
          Spawn({BinDir() + "/topay-planner", "--config", dir + "/planner.yaml", "--name", "planner", "--lcm-url",
                 lcm_url}, dir + "/planner.txt"),
          Spawn({BinDir() + "/topay-sim", "--config", config("sim/sim.yaml"), "--scene", dir + "/room.json",
                 "--follow", "--name", "sim", "--lcm-url", lcm_url}, dir + "/sim.txt")};
}

/// The clearance (m) each passage on the way to a goal keeps beyond the robot's footprint
/// (ProvenBaseRegion's openness) in the graph tests. The sensed map's voxels stand out of the
/// surfaces they hold by up to ~0.10 m (voxel centres up to 8 cm off with the LiDAR's 2 cm range
/// noise, plus half a voxel), and the planner's base search keeps the validator's margin and
/// 5 % of the base radius more: a gap narrower than the robot + 2 x ~0.12 m is closed on the
/// map although the exact room has it open (docs/planner.md, "Goals behind tight passages").
inline constexpr double kSensedPassageClearanceM = 0.15;

/// The base positions the robot at `from` is proven to reach through passages
/// kSensedPassageClearanceM wider than it (what the graph tests may expect it to reach).
inline ProvenBaseRegion SensedReachableRegion(const Scene& scene, const Kinematics& kinematics,
                                              const Eigen::Vector2d& from) {
  BaseOpennessOptions openness;
  openness.clearance_m = kSensedPassageClearanceM;
  BaseReachabilityOptions grid;
  grid.resolution_m = 0.02;  // a quarter of the 1 cm default's cells (the proof stays conservative)
  return ProvenBaseRegion(scene, kinematics, from, openness, grid);
}

/// A goal configuration (arm bent, random yaw) r_min-r_max m from `from`, exactly clear of
/// `scene` by 0.3 m and whose base the base at `from` can be proven to reach through passages
/// kSensedPassageClearanceM wider than the robot (nullopt if none in 20 000 draws).
inline std::optional<WholeBodyState> ReachableGoal(const Scene& scene, const Kinematics& kinematics,
                                                   const Eigen::Vector2d& from, double r_min, double r_max,
                                                   Rng* rng) {
  const ProvenBaseRegion region = SensedReachableRegion(scene, kinematics, from);
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
