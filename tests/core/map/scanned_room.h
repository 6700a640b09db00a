#pragma once

// Shared by the occupancy-map tests and benchmark: simulated LiDAR scans (sim/lidar, Mid-360
// defaults) of a seeded benchmark room from robot poses clear of its boxes, as the mapper gets
// them: points in W, the floor (below z 0.05 m) and the robot's own body dropped.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "sim/lidar/lidar_scanner.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay::testing {

/// One scan in W: the sensor origin and the kept returns.
struct WorldScan {
  Eigen::Vector3d p_WS = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3f> p_WP;
};

/// Scans of a room and the room itself.
struct ScannedRoom {
  Scene scene;
  std::vector<WorldScan> scans;
};

/// `num_poses` scans of the benchmark room (kind, seed) from seeded poses with the base at
/// least 0.1 m from every box (arm stowed), with the given range noise (m, 1 sigma). The
/// scenes have no ceiling (most up-going rays return nothing); `with_ceiling` adds one to the
/// scanner's world, a slab at 2.5 m over the whole room (above the map volume: its returns
/// give no hits, their rays clear), so that nearly every ray returns as indoors.
inline ScannedRoom ScanRoom(SceneKind kind, std::uint64_t seed, int num_poses,
                            double range_noise_sigma_m, bool with_ceiling = false) {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
  const RobotModel model = LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
  const Kinematics kinematics(model);
  ScannedRoom room;
  room.scene = GenerateBenchmarkScene(kind, seed).scene;
  const SceneClearanceChecker checker(kinematics, room.scene);
  sim::LidarOptions options;
  options.range_noise_sigma_m = range_noise_sigma_m;
  sim::LidarScanner scanner(options, kinematics, seed + 1);
  std::vector<OrientedBox> world = room.scene.boxes;
  if (with_ceiling) {
    OrientedBox ceiling;
    ceiling.center_W_m = Eigen::Vector3d(0.0, 0.0, 2.55);
    ceiling.size_m = Eigen::Vector3d(30.0, 30.0, 0.1);
    world.push_back(ceiling);
  }
  scanner.SetWorld(world);
  Rng rng(seed + 2);
  while (static_cast<int>(room.scans.size()) < num_poses) {
    WholeBodyState state;
    state.x_m = rng.Uniform(-9.0, 9.0);
    state.y_m = rng.Uniform(-9.0, 9.0);
    state.yaw_rad = rng.Uniform(-3.14159, 3.14159);
    state.q_rad = model.stow_q_rad;
    if (checker.BaseClearance({state.x_m, state.y_m}, 1.0) < 0.1) continue;
    const sim::LidarScan scan = scanner.Scan(state, 0.1 * room.scans.size());
    WorldScan world;
    world.p_WS = scan.X_WS.translation();
    const Eigen::Isometry3f X_WS = scan.X_WS.cast<float>();
    for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
      if (scan.target[k] == sim::kTargetSelf) continue;
      const Eigen::Vector3f p_WP = X_WS * scan.p_SP[k];
      if (p_WP.z() < 0.05f) continue;
      world.p_WP.push_back(p_WP);
    }
    room.scans.push_back(std::move(world));
  }
  return room;
}

}  // namespace topay::testing
