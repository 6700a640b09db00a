#include "core/planning/uvd_equivalence.h"

#include <gtest/gtest.h>

#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;

class UvdEquivalenceTest : public ::testing::Test {
 protected:
  UvdEquivalenceTest() : field_(BaseField(Room({Pillar(0, 0)}))), space_(field_, kRequired) {}
  SignedDistanceField2 field_;
  BaseFreeSpace space_;
  const std::vector<Eigen::Vector2d> above_{{-5, 0}, {-1.5, 1.5}, {1.5, 1.5}, {5, 0}};
  // Same class as above_, with a detour further up.
  const std::vector<Eigen::Vector2d> above_detour_{{-5, 0}, {-3, 3}, {0, 3.5}, {2, 1.5}, {5, 0}};
  const std::vector<Eigen::Vector2d> below_{{-5, 0}, {-1.5, -1.5}, {1.5, -1.5}, {5, 0}};
};

TEST_F(UvdEquivalenceTest, DetourInsideOneClassIsEquivalent) {
  EXPECT_TRUE(UvdEquivalent(space_, above_, above_detour_, 0.1));
  EXPECT_TRUE(UvdEquivalent(space_, above_detour_, above_, 0.1));
  EXPECT_TRUE(UvdEquivalent(space_, above_, above_, 0.1));
}

TEST_F(UvdEquivalenceTest, OppositeSidesOfAPillarAreNot) {
  EXPECT_FALSE(UvdEquivalent(space_, above_, below_, 0.1));
  EXPECT_FALSE(UvdEquivalent(space_, below_, above_detour_, 0.1));
}

TEST_F(UvdEquivalenceTest, PruningMergesTheDetourAndKeepsTheShorter) {
  const std::vector<int> kept = PruneEquivalentPaths(space_, {above_detour_, below_, above_});
  // below_ and above_ have the same length; the stable sort keeps input order
  // among equals.
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0], 1);
  EXPECT_EQ(kept[1], 2);
}

TEST_F(UvdEquivalenceTest, PruningFiltersByLengthRatioAndCount) {
  const std::vector<Eigen::Vector2d> long_below{{-5, 0}, {-4, -5.4}, {4, -5.4}, {5, 0}};
  UvdPruningOptions options;
  options.max_length_ratio = 1.2;
  // long_below is another path below (maybe same class, but too long anyway).
  EXPECT_EQ(PruneEquivalentPaths(space_, {above_, long_below}, options).size(), 1u);
  options.max_length_ratio = 2.0;
  options.max_paths = 1;
  EXPECT_EQ(PruneEquivalentPaths(space_, {above_, below_}, options).size(), 1u);
}

}  // namespace
}  // namespace topay
