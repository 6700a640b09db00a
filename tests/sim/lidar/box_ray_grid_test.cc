#include "sim/lidar/box_ray_grid.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "sim/scenes/benchmark_scene.h"
#include "tests/common/make_box.h"

namespace topay::sim {
namespace {

Eigen::Vector3d RandomUnit(Rng& rng) {
  const double z = rng.Uniform(-1, 1), a = rng.Uniform(0, 6.283185307179586);
  const double r = std::sqrt(1 - z * z);
  return {r * std::cos(a), r * std::sin(a), z};
}

// Scattered boxes, grounded, floating and some sharing faces exactly (as table parts do).
std::vector<OrientedBox> RandomBoxes(int count, Rng& rng) {
  std::vector<OrientedBox> boxes;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d size(rng.Uniform(0.05, 1.5), rng.Uniform(0.05, 1.5),
                               rng.Uniform(0.05, 1.5));
    const double bottom = rng.Uniform01() < 0.6 ? 0.0 : rng.Uniform(0.2, 1.2);
    boxes.push_back(MakeBox({rng.Uniform(-8, 8), rng.Uniform(-8, 8), bottom + 0.5 * size.z()},
                            size, rng.Uniform01() < 0.3 ? 0.0 : rng.Uniform(-3.2, 3.2)));
    if (i % 10 == 0) {  // an axis-aligned neighbour sharing the +x face
      OrientedBox next = boxes.back();
      next.yaw_rad = 0.0;
      boxes.back().yaw_rad = 0.0;
      next.center_W_m.x() += next.size_m.x();
      boxes.push_back(next);
      ++i;
    }
  }
  return boxes;
}

void ExpectSameAsBruteForce(BoxRayGrid& grid, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                            double t_max, int* hits) {
  const BoxRayGrid::Hit fast = grid.FirstHit(o, d, t_max);
  const BoxRayGrid::Hit slow = grid.FirstHitBruteForce(o, d, t_max);
  ASSERT_EQ(fast.box, slow.box) << o.transpose() << " / " << d.transpose();
  ASSERT_EQ(fast.t_m, slow.t_m);
  if (fast.box >= 0) ++*hits;
}

TEST(BoxRayGridTest, EqualsBruteForceOnRandomRays) {
  Rng rng(3);
  for (double cell : {0.25, 0.5, 1.3}) {
    BoxRayGrid grid(cell);
    grid.Build(RandomBoxes(300, rng));
    int hits = 0;
    for (int k = 0; k < 20000; ++k) {
      // Origins inside and outside the boxes' extent, any direction, short and long ranges.
      const Eigen::Vector3d o(rng.Uniform(-12, 12), rng.Uniform(-12, 12), rng.Uniform(-1, 3));
      const double t_max = rng.Uniform01() < 0.2 ? rng.Uniform(0.1, 3.0) : 40.0;
      ExpectSameAsBruteForce(grid, o, RandomUnit(rng), t_max, &hits);
    }
    EXPECT_GT(hits, 3000) << cell;
  }
}

TEST(BoxRayGridTest, EqualsBruteForceAlongAxesAndThroughCellCorners) {
  Rng rng(4);
  BoxRayGrid grid(0.5);
  grid.Build(RandomBoxes(200, rng));
  int hits = 0;
  for (int k = 0; k < 4000; ++k) {
    // Origins on cell borders, directions along the axes and the diagonals.
    const Eigen::Vector3d o(0.5 * std::round(rng.Uniform(-20, 20)),
                            0.5 * std::round(rng.Uniform(-20, 20)), rng.Uniform(0, 1.5));
    const int kind = k % 4;
    Eigen::Vector3d d = kind == 0   ? Eigen::Vector3d(1, 0, 0)
                        : kind == 1 ? Eigen::Vector3d(0, -1, 0)
                        : kind == 2 ? Eigen::Vector3d(1, 1, 0).normalized()
                                    : Eigen::Vector3d(-1, 1, 0.2).normalized();
    ExpectSameAsBruteForce(grid, o, d, 40.0, &hits);
  }
  EXPECT_GT(hits, 500);
}

TEST(BoxRayGridTest, TablesRoomTestsFewBoxesPerRay) {
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 5).scene;
  ASSERT_GT(scene.boxes.size(), 400u);
  BoxRayGrid grid(0.5);
  grid.Build(scene.boxes);
  Rng rng(5);
  int hits = 0;
  const int rays = 5000;
  for (int k = 0; k < rays; ++k) {
    const Eigen::Vector3d o(rng.Uniform(-9, 9), rng.Uniform(-9, 9), 0.22);
    Eigen::Vector3d d = RandomUnit(rng);
    d.z() = std::abs(d.z()) * 0.8 - 0.1;
    ExpectSameAsBruteForce(grid, o, d.normalized(), 40.0, &hits);
  }
  // The grid examines a small share of the boxes that brute force tests for every ray.
  EXPECT_LT(static_cast<double>(grid.box_tests()) / rays, 0.1 * scene.boxes.size());
}

TEST(BoxRayGridTest, EmptyAndRebuiltWorlds) {
  BoxRayGrid grid;
  grid.Build({});
  EXPECT_EQ(grid.FirstHit({0, 0, 0}, {1, 0, 0}, 40).box, -1);
  grid.Build({MakeBox({3, 0, 0}, {1, 1, 1})});
  const BoxRayGrid::Hit hit = grid.FirstHit({0, 0, 0}, {1, 0, 0}, 40);
  EXPECT_EQ(hit.box, 0);
  EXPECT_DOUBLE_EQ(hit.t_m, 2.5);
  EXPECT_EQ(grid.FirstHit({0, 0, 0}, {1, 0, 0}, 2.4).box, -1);  // beyond t_max
  grid.Build({MakeBox({-3, 0, 0}, {1, 1, 1})});
  EXPECT_EQ(grid.FirstHit({0, 0, 0}, {1, 0, 0}, 40).box, -1);
}

TEST(BoxRayGridTest, NearerBoxWinsAndTiesGoToTheLowerIndex) {
  BoxRayGrid grid(0.5);
  // Box 0 behind box 1; boxes 2 and 3 share the face x = 5 at y = 3.
  grid.Build({MakeBox({6, 0, 0.5}, {1, 1, 1}), MakeBox({3, 0, 0.5}, {1, 1, 1}),
              MakeBox({5.5, 3, 0.5}, {1, 1, 1}), MakeBox({5.5, 3, 0.5}, {1, 1, 1})});
  EXPECT_EQ(grid.FirstHit({0, 0, 0.5}, {1, 0, 0}, 40).box, 1);
  EXPECT_EQ(grid.FirstHit({0, 3, 0.5}, {1, 0, 0}, 40).box, 2);
}

}  // namespace
}  // namespace topay::sim
