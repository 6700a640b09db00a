// FindUnseenPocket on maps built from simulated LiDAR scans (sim/lidar, the robot's sensor at
// 0.22 m, 2 cm range noise) of benchmark rooms from 40 poses: the share of box centres enclosed
// (refused targets: the figure of docs/reliability.md, finding 35), and how seldom a point
// clear of every box, or a target above a table top (where the missions' lie), is.
//
// One layer of such a map through a box's centre (*), 0.41 x 0.35 m and turned, 5 cm voxels
// ('#' occupied, '.' seen free, ' ' never seen): its side is a band of occupied and free
// voxels, not a closed line, while its inside is one unseen pocket, its rim mostly occupied.
//   .............#...........
//   ...........##............
//   .........#.# ##..........
//   ........#     .#.........
//   ........#     ##...... ..
//   .......##   *   ## ......
//   ........#         .. ....
//   ........##      #..  ....
//   .........###   #..  .....
//   ..........##  ...  ......
//   ...........## #.. .......
//   ............##. .........

#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/map/occupancy_map.h"
#include "core/map/unseen_pocket.h"
#include "tests/core/map/scanned_room.h"

namespace topay {
namespace {

constexpr double kNoiseSigmaM = 0.02;  // the Mid-360's range noise (LidarOptions default)

struct ScannedMap {
  testing::ScannedRoom room;
  OccupancyMap map;
};

ScannedMap BuildMap(SceneKind kind, std::uint64_t seed, int num_poses) {
  ScannedMap m{testing::ScanRoom(kind, seed, num_poses, kNoiseSigmaM), OccupancyMap(OccupancyMapOptions{})};
  for (const testing::WorldScan& scan : m.room.scans) m.map.InsertScan(scan.p_WS, scan.p_WP, nullptr);
  return m;
}

bool IsObject(const OrientedBox& box) { return box.size_m.maxCoeff() < 2.0; }  // not a wall

// A table's top: a thin slab above the floor (TableGroupOptions).
bool IsTableTop(const OrientedBox& box) {
  return box.size_m.z() < 0.1 && box.center_W_m.z() - 0.5 * box.size_m.z() > 0.3;
}

// The shared map is built once: scans from 40 poses of a Cuboids room.
class UnseenPocketSceneTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { cuboids_ = new ScannedMap(BuildMap(SceneKind::kCuboids, 3, 40)); }
  static void TearDownTestSuite() { delete cuboids_; }

  UnseenPocketSceneTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  static UnseenPocket Find(const ScannedMap& m, const Eigen::Vector3d& p_W) {
    return FindUnseenPocket(m.map.geometry(), m.map.states(), p_W);
  }

  static ScannedMap* cuboids_;
  RobotModel model_;
  Kinematics kinematics_;
};

ScannedMap* UnseenPocketSceneTest::cuboids_ = nullptr;

TEST_F(UnseenPocketSceneTest, BoxCentresSeenAroundAreEnclosed) {
  int objects = 0, enclosed = 0;
  for (const OrientedBox& box : cuboids_->room.scene.boxes) {
    if (!IsObject(box) || !cuboids_->map.geometry().Contains(box.center_W_m)) continue;
    ++objects;
    enclosed += Find(*cuboids_, box.center_W_m).enclosed;
  }
  std::printf("cuboids room 3, 40 scan poses: %d of %d box centres enclosed\n", enclosed, objects);
  ASSERT_GT(objects, 100);
  // Measured: 83 of 160 (the others: a side not seen, a gap in a side, or the pocket joined to
  // a neighbour's beyond the reach). A third is a floor well below it: the check must catch a good share
  // of what a map shows closed, or it is not worth its refusals.
  EXPECT_GT(enclosed, objects / 3);
}

// Points clear of every box, by their clearance: how many are enclosed (refused targets).
TEST_F(UnseenPocketSceneTest, PointsClearOfEveryBoxAreAlmostNeverEnclosed) {
  const SceneClearanceChecker checker(kinematics_, cuboids_->room.scene);
  Rng rng(11);
  constexpr double kBands_m[] = {0.05, 0.1, 0.2, 0.3};
  int clear[4] = {0, 0, 0, 0}, enclosed[4] = {0, 0, 0, 0};
  while (clear[0] < 40000) {
    const Eigen::Vector3d p_W(rng.Uniform(-9.5, 9.5), rng.Uniform(-9.5, 9.5), rng.Uniform(0.1, 1.5));
    const double clearance_m = checker.PointClearance(p_W, 1.0);
    if (clearance_m < kBands_m[0]) continue;
    const UnseenPocket p = Find(*cuboids_, p_W);
    for (int b = 0; b < 4; ++b) {
      if (clearance_m < kBands_m[b]) break;
      ++clear[b];
      enclosed[b] += p.enclosed;
    }
    if (p.enclosed) {
      std::printf("enclosed: (%.2f, %.2f, %.2f) m, %.3f m clear of every box: %d voxels, rim %d of %d occupied\n",
                  p_W.x(), p_W.y(), p_W.z(), clearance_m, p.voxels, p.rim_occupied, p.rim_occupied + p.rim_free);
    }
  }
  for (int b = 0; b < 4; ++b) {
    std::printf("points >= %.2f m clear of every box: %d of %d enclosed\n", kBands_m[b], enclosed[b], clear[b]);
  }
  // A nook between boxes (or a box and a wall) that no ray entered is one pocket with the boxes'
  // insides, walled by their outer faces: the map cannot tell it from one box. Measured: 16 of
  // 40,000 points, all nearer than 0.2 m to a box.
  EXPECT_LE(enclosed[0], clear[0] / 1000);
  EXPECT_EQ(enclosed[2], 0);
}

TEST_F(UnseenPocketSceneTest, TargetsAboveTableTopsAreAlmostNeverEnclosed) {
  const ScannedMap tables = BuildMap(SceneKind::kTables, 5, 40);
  const SceneClearanceChecker checker(kinematics_, tables.room.scene);
  Rng rng(12);
  int targets = 0, enclosed = 0;
  for (const OrientedBox& top : tables.room.scene.boxes) {
    if (!IsTableTop(top)) continue;
    const Eigen::Rotation2Dd R_WB(top.yaw_rad);
    for (int k = 0; k < 20; ++k) {
      // Over the top's inner 80 %, 3-15 cm above it (the scenarios' goals: docs/demo.md), clear
      // of the boxes standing through some tables.
      const Eigen::Vector2d p_B(0.4 * top.size_m.x() * rng.Uniform(-1.0, 1.0),
                                0.4 * top.size_m.y() * rng.Uniform(-1.0, 1.0));
      const Eigen::Vector2d p_W2 = top.center_W_m.head<2>() + R_WB * p_B;
      const Eigen::Vector3d p_W(p_W2.x(), p_W2.y(), top.center_W_m.z() + 0.5 * top.size_m.z() + rng.Uniform(0.03, 0.15));
      if (checker.PointClearance(p_W, 1.0) < 0.03) continue;
      ++targets;
      const UnseenPocket p = Find(tables, p_W);
      enclosed += p.enclosed;
      if (p.enclosed) {
        std::printf("enclosed above a table: (%.2f, %.2f, %.2f) m: %d voxels, rim %d of %d occupied\n", p_W.x(),
                    p_W.y(), p_W.z(), p.voxels, p.rim_occupied, p.rim_occupied + p.rim_free);
      }
    }
  }
  std::printf("tables room 5, 40 scan poses: %d of %d targets above table tops enclosed\n", enclosed, targets);
  // Measured: 0 of 1,466.
  ASSERT_GT(targets, 500);
  EXPECT_LE(enclosed, targets / 500);
}

}  // namespace
}  // namespace topay
