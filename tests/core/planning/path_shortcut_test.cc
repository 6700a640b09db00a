#include "core/planning/path_shortcut.h"

#include <gtest/gtest.h>

#include "core/planning/base_path.h"
#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;

TEST(ResampleUniformTest, EqualSpacingAndEndPoints) {
  const std::vector<Eigen::Vector2d> path{{0, 0}, {3, 0}, {3, 1}};  // length 4
  const std::vector<Eigen::Vector2d> points = ResampleUniform(path, 9);
  ASSERT_EQ(points.size(), 9u);
  EXPECT_TRUE(points.front().isApprox(path.front()));
  EXPECT_TRUE(points.back().isApprox(path.back()));
  for (std::size_t i = 1; i < points.size(); ++i) {
    // Arc-length spacing 0.5; the corner (3, 0) is sample 6, so chords equal
    // arcs.
    EXPECT_NEAR((points[i] - points[i - 1]).norm(), 0.5, 1e-12) << i;
  }
  EXPECT_TRUE(points[6].isApprox(Eigen::Vector2d(3, 0)));
  EXPECT_EQ(ResampleUniform({{1, 2}}, 3).size(), 3u);
}

TEST(PathShortcutTest, StraightensAFreeDetourAndStaysFree) {
  const Scene scene = Room({Pillar(0, 0)});
  const SignedDistanceField2 field = BaseField(scene);
  const BaseFreeSpace space(field, kRequired);
  // A detour above the pillar with needless zigzags.
  const std::vector<Eigen::Vector2d> raw{{-5, 0},  {-4, 3}, {-2, 1.5}, {0, 3.5},
                                         {2, 1.5}, {4, 3},  {5, 0}};
  for (std::size_t i = 1; i < raw.size(); ++i) ASSERT_TRUE(space.IsSegmentFree(raw[i - 1], raw[i]));
  const std::vector<Eigen::Vector2d> shortcut = ShortcutPath(space, raw);
  EXPECT_TRUE(shortcut.front().isApprox(raw.front()));
  EXPECT_TRUE(shortcut.back().isApprox(raw.back()));
  EXPECT_LT(PolylineLength(shortcut), PolylineLength(raw) - 1.0);
  EXPECT_LE(shortcut.size(), 5u);
  ExpectPathCollisionFree(scene, field, shortcut);
  EXPECT_GT(CrossingY(shortcut, 0.0),
            0.5);  // still above the pillar: same class
  // Near-optimal: the shortest path hugging the 0.5 m inflated pillar is
  // about 10.3 m.
  EXPECT_LT(PolylineLength(shortcut), 10.6);
}

TEST(PathShortcutTest, FreeStraightLineBecomesOneSegment) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0)}));
  const BaseFreeSpace space(field, kRequired);
  const std::vector<Eigen::Vector2d> raw{{-5, 3}, {-1, 4}, {5, 3}};
  const std::vector<Eigen::Vector2d> shortcut = ShortcutPath(space, raw);
  ASSERT_EQ(shortcut.size(), 2u);
}

TEST(PathShortcutTest, ParallelVersionMatchesSerial) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0), Pillar(2, -3)}));
  const BaseFreeSpace space(field, kRequired);
  std::vector<std::vector<Eigen::Vector2d>> raws;
  for (int k = 0; k < 12; ++k) {
    const double h = 1.5 + 0.2 * k;
    raws.push_back({{-5, 0}, {-3, h}, {0, h + 0.5}, {3, h}, {5, 0}});
  }
  const auto parallel = ShortcutPaths(space, raws);
  ASSERT_EQ(parallel.size(), raws.size());
  for (std::size_t k = 0; k < raws.size(); ++k) {
    const auto serial = ShortcutPath(space, raws[k]);
    ASSERT_EQ(parallel[k].size(), serial.size());
    for (std::size_t i = 0; i < serial.size(); ++i) EXPECT_EQ(parallel[k][i], serial[i]);
  }
}

}  // namespace
}  // namespace topay
