#include "core/planning/base_free_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/random.h"
#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;

TEST(BaseFreeSpaceTest, PointsAndSegmentsAroundAPillar) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0)}));
  const BaseFreeSpace space(field, kRequired);
  EXPECT_TRUE(space.IsFree({-3, 0}));
  EXPECT_FALSE(space.IsFree({0, 0}));
  EXPECT_FALSE(space.IsFree({0.9, 0}));  // 0.4 m from the face: closer than 0.5
  EXPECT_FALSE(space.IsFree({20, 0}));   // outside the map
  EXPECT_FALSE(space.IsFree({std::nan(""), 0}));
  EXPECT_TRUE(space.IsSegmentFree({-3, 2}, {3, 2}));
  EXPECT_FALSE(space.IsSegmentFree({-3, 0}, {3, 0}));
  EXPECT_FALSE(space.IsSegmentFree({-3, 0}, {20, 0}));
  EXPECT_FALSE(space.IsSegmentFree({-3, 0}, {std::nan(""), 0}));
  EXPECT_TRUE(space.IsSegmentFree({-3, 2}, {-3, 2}));
}

// The segment test is exact w.r.t. the field: a free segment is free at every
// sample, and a blocked one has a point below the requirement, so its 2 mm
// samples (each within 1 mm of any point, the field changing by <= sqrt 2 per
// metre) dip below requirement + 1.42 mm.
TEST(BaseFreeSpaceTest, SegmentTestAgreesWithDenseSampling) {
  std::vector<OrientedBox> boxes{Pillar(0, 0), Pillar(3, 2, 0.6), Pillar(-3, -2, 1.4)};
  boxes.push_back(MakeBox(Eigen::Vector3d(4, -3, 0.5), Eigen::Vector3d(2.0, 0.3, 1.0), 0.6));
  const SignedDistanceField2 field = BaseField(Room(boxes));
  const BaseFreeSpace space(field, kRequired);
  Rng rng(7);
  int num_free = 0, num_blocked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Mostly inside, some ending in the outer half cell (x up to 7.99 of 8).
    const Eigen::Vector2d a(rng.Uniform(-7.5, 7.5), rng.Uniform(-5.5, 5.5));
    const Eigen::Vector2d b(rng.Uniform(-7.99, 7.99), rng.Uniform(-5.99, 5.99));
    const int steps = static_cast<int>(std::ceil((b - a).norm() / 0.002));
    double min_field = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= steps; ++k) {
      min_field = std::min(min_field, field.Distance(a + (b - a) * (double(k) / steps)));
    }
    const bool free = space.IsSegmentFree(a, b);
    if (free) {
      ++num_free;
      EXPECT_GE(min_field, kRequired) << a.transpose() << " -> " << b.transpose();
    } else {
      ++num_blocked;
      EXPECT_LT(min_field, kRequired + std::sqrt(2.0) * 0.001 + 1e-9)
          << a.transpose() << " -> " << b.transpose();
    }
  }
  EXPECT_GT(num_free, 100);
  EXPECT_GT(num_blocked, 100);
}

}  // namespace
}  // namespace topay
