#pragma once
// Shared by the planner's graph tests: the room the simulator runs and the planner has never
// seen, written out so that the test knows it exactly too (goals, box places). What the robot
// can be expected to reach (kSensedPassageClearanceM, SensedReachableRegion, ReachableGoal) is
// sim/scenarios/sensed_reachability.h.

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
#include "sim/scenarios/sensed_reachability.h"
#include "sim/scenarios/unseen_room.h"
#include "sim/scenes/scene_json.h"

namespace topay::test {

/// The Tables room of seed 3 with nothing within 1.2 m of the start (the origin, where the
/// simulator puts the robot), written to `path` as scene JSON (topay-sim --scene path).
inline Scene WriteUnseenTablesRoom(const std::string& path) {
  Scene room = UnseenTablesRoom(3, 1.2).scene;
  WriteSceneJson(path, room, nullptr);
  return room;
}

/// ReachableGoal (sim/scenarios/sensed_reachability.h) with the arm in the tests' bent pose.
inline std::optional<WholeBodyState> ReachableGoal(const Scene& scene, const Kinematics& kinematics,
                                                   const Eigen::Vector2d& from, double r_min, double r_max,
                                                   Rng* rng) {
  return topay::ReachableGoal(scene, kinematics, from, r_min, r_max, BentArmState(0, 0, 0).q_rad, rng);
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

}  // namespace topay::test
