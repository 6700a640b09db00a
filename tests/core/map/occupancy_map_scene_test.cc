// The occupancy map built from simulated LiDAR scans of a Tables room (sim/lidar) against the
// room's exact boxes.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/io/robot_loader.h"
#include "core/map/occupancy_map.h"
#include "core/map/voxel_ray.h"
#include "tests/core/map/scanned_room.h"

namespace topay {
namespace {

constexpr double kNoiseSigmaM = 0.02;  // the Mid-360's range noise (LidarOptions default)

class OccupancyMapSceneTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    room_ = new testing::ScannedRoom(testing::ScanRoom(SceneKind::kTables, 4, 8, kNoiseSigmaM));
    OccupancyMapOptions options;
    options.bounds_W_m = room_->scene.bounds_W_m;
    map_ = new OccupancyMap(options);
    for (const testing::WorldScan& scan : room_->scans) {
      const ScanInsertSummary s = map_->InsertScan(scan.p_WS, scan.p_WP, nullptr);
      EXPECT_EQ(s.num_points_skipped, 0);
      EXPECT_GT(s.num_voxels_hit, 1000);
    }
  }
  static void TearDownTestSuite() {
    delete map_;
    delete room_;
  }

  OccupancyMapSceneTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        checker_(kinematics_, room_->scene) {}

  // Distance (m) from a voxel's centre to the nearest box surface (negative inside).
  double CentreClearance(const Eigen::Vector3i& v) const {
    return checker_.PointClearance(map_->geometry().CellCenter(v.x(), v.y(), v.z()), 2.0);
  }

  static testing::ScannedRoom* room_;
  static OccupancyMap* map_;
  RobotModel model_;
  Kinematics kinematics_;
  SceneClearanceChecker checker_;
};

testing::ScannedRoom* OccupancyMapSceneTest::room_ = nullptr;
OccupancyMap* OccupancyMapSceneTest::map_ = nullptr;

// A return lies within its noise of a box surface (6 sigma bounds every draw here); its voxel
// centre within half a voxel diagonal of the return.
double SurfaceBandM(double resolution_m) {
  return 0.5 * std::sqrt(3.0) * resolution_m + 6.0 * kNoiseSigmaM;
}

TEST_F(OccupancyMapSceneTest, VoxelsWithReturnsAreOccupied) {
  const GridGeometry3& g = map_->geometry();
  int hit = 0, occupied = 0;
  // The last scan's returns: their voxels were hit last (later scans cannot have cleared them).
  for (const Eigen::Vector3f& p : room_->scans.back().p_WP) {
    const Eigen::Vector3d p_W = p.cast<double>();
    if (!g.Contains(p_W) || (p_W - room_->scans.back().p_WS).norm() > 10.0) continue;
    const Eigen::Vector3i v = g.CellOf(p_W);
    ++hit;
    occupied += map_->state(v.x(), v.y(), v.z()) == VoxelState::kOccupied;
  }
  ASSERT_GT(hit, 2000);
  // A voxel grazed by many rays of earlier scans from elsewhere (the 5 cm voxel reaches past
  // the surface) may hold a return and still be free after a single hit: few do.
  EXPECT_GT(static_cast<double>(occupied) / hit, 0.97) << occupied << " of " << hit;
  std::cout << "returns of the last scan in occupied voxels: " << occupied << " of " << hit
            << "\n";
}

TEST_F(OccupancyMapSceneTest, VoxelsAlongRaysFarFromBoxesAreFree) {
  const GridGeometry3& g = map_->geometry();
  const double band_m = SurfaceBandM(g.resolution_m);
  int checked = 0;
  for (const testing::WorldScan& scan : room_->scans) {
    for (std::size_t k = 0; k < scan.p_WP.size(); k += 40) {
      Eigen::Vector3d p_WE = scan.p_WP[k].cast<double>();
      const double range = (p_WE - scan.p_WS).norm();
      if (range > 10.0) p_WE = scan.p_WS + (p_WE - scan.p_WS) * (10.0 / range);
      TraverseVoxelRay(g, scan.p_WS, p_WE, [&](const Eigen::Vector3i& v, std::int64_t) {
        if (CentreClearance(v) <= band_m) return;
        ++checked;
        EXPECT_EQ(map_->state(v.x(), v.y(), v.z()), VoxelState::kFree)
            << v.transpose() << " clearance " << CentreClearance(v);
      });
    }
  }
  EXPECT_GT(checked, 20000);
  std::cout << "voxels far from boxes checked along rays: " << checked << "\n";
}

TEST_F(OccupancyMapSceneTest, OccupiedVoxelsLieOnBoxSurfaces) {
  const GridGeometry3& g = map_->geometry();
  const double band_m = SurfaceBandM(g.resolution_m);
  int occupied = 0;
  double worst_m = -1.0;
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        if (map_->state(ix, iy, iz) != VoxelState::kOccupied) continue;
        ++occupied;
        worst_m = std::max(worst_m, CentreClearance({ix, iy, iz}));
      }
  EXPECT_EQ(map_->CountStates().occupied, occupied);
  EXPECT_GT(occupied, 20000);
  EXPECT_LE(worst_m, band_m);
  std::cout << "occupied voxels: " << occupied << ", farthest centre from a box: " << worst_m
            << " m (bound " << band_m << " m)\n";
}

}  // namespace
}  // namespace topay
