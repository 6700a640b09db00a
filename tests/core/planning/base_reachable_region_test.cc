#include "core/planning/base_reachable_region.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/common/random.h"
#include "core/planning/jump_point_search.h"
#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;

TEST(BaseReachableRegionTest, AWallSplitsTheRoomAndAGapJoinsIt) {
  std::vector<OrientedBox> closed = WallWithGap(0.0, 0.0);
  const SignedDistanceField2 closed_field = BaseField(Room(closed));
  const BaseReachableRegion split(closed_field, Eigen::Vector2d(-4, 0), kRequired);
  ASSERT_TRUE(split.start_joins_grid());
  EXPECT_TRUE(split.Contains(Eigen::Vector2d(-2, 3)));
  EXPECT_FALSE(split.Contains(Eigen::Vector2d(4, 0)));
  EXPECT_FALSE(split.Contains(Eigen::Vector2d(0, 0)));  // in the wall

  const SignedDistanceField2 open_field = BaseField(Room(WallWithGap(2.0, 1.6)));
  const BaseReachableRegion joined(open_field, Eigen::Vector2d(-4, 0), kRequired);
  EXPECT_TRUE(joined.Contains(Eigen::Vector2d(4, 0)));
  EXPECT_GT(joined.num_cells(), split.num_cells());
  // The same gap is too narrow for a larger safe distance.
  const BaseReachableRegion too_wide(open_field, Eigen::Vector2d(-4, 0), 0.85);
  EXPECT_FALSE(too_wide.Contains(Eigen::Vector2d(4, 0)));
}

// The region is exactly what JumpPointSearch can reach: on random rooms, JPS between the
// start and a random free position succeeds if and only if the region contains it.
TEST(BaseReachableRegionTest, AgreesWithJumpPointSearch) {
  Rng rng(7);
  int inside = 0, outside = 0;
  for (int room = 0; room < 5; ++room) {
    const SignedDistanceField2 field = BaseField(Room(RandomBoxes(rng, 30)));
    const BaseFreeSpace space(field, kRequired);
    Eigen::Vector2d start;
    do {
      start = Eigen::Vector2d(rng.Uniform(-7.5, 7.5), rng.Uniform(-5.5, 5.5));
    } while (!space.IsFree(start));
    const BaseReachableRegion region(field, start, kRequired);
    ASSERT_TRUE(region.start_joins_grid());
    JumpPointSearchOptions options;
    options.safe_distance_m = kRequired;
    options.shortcut = false;
    for (int task = 0; task < 20; ++task) {
      Eigen::Vector2d goal;
      do {
        goal = Eigen::Vector2d(rng.Uniform(-7.5, 7.5), rng.Uniform(-5.5, 5.5));
      } while (!space.IsFree(goal));
      const bool jps_ok = JumpPointSearch(field, start, goal, options).ok();
      EXPECT_EQ(region.Contains(goal), jps_ok) << "room " << room << " goal " << goal.transpose();
      (jps_ok ? inside : outside) += 1;
    }
  }
  // Both outcomes occur, so the comparison means something.
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 3);
}

TEST(BaseReachableRegionTest, BadStartGivesAnEmptyRegion) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0)}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Eigen::Vector2d& start :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(nan, 0), Eigen::Vector2d(20, 0)}) {
    const BaseReachableRegion region(field, start, kRequired);
    EXPECT_FALSE(region.start_joins_grid());
    EXPECT_EQ(region.num_cells(), 0);
    EXPECT_FALSE(region.Contains(Eigen::Vector2d(-4, 0)));
  }
  const BaseReachableRegion region(field, Eigen::Vector2d(-4, 0), kRequired);
  EXPECT_FALSE(region.Contains(Eigen::Vector2d(nan, 1)));
}

}  // namespace
}  // namespace topay
