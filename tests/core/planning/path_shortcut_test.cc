#include "core/planning/path_shortcut.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <stop_token>
#include <thread>

#include <tbb/task_arena.h>

#include "core/planning/base_path.h"
#include "tests/core/planning/stop_latency.h"
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

// Zigzag detours above the pillar (free at kRequired), n of them at growing heights.
std::vector<std::vector<Eigen::Vector2d>> Detours(int n) {
  std::vector<std::vector<Eigen::Vector2d>> raws;
  for (int k = 0; k < n; ++k) {
    const double h = 1.5 + 1.5 * k / n;
    raws.push_back({{-5, 0}, {-4, h + 1.5}, {-2, h}, {0, h + 2}, {2, h}, {4, h + 1.5}, {5, 0}});
  }
  return raws;
}

TEST(PathShortcutTest, StoppedBeforeStartReturnsTheInputs) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0)}));
  const BaseFreeSpace space(field, kRequired);
  const std::vector<std::vector<Eigen::Vector2d>> raws = Detours(4);
  std::stop_source source;
  source.request_stop();
  EXPECT_EQ(ShortcutPath(space, raws[0], {}, source.get_token()), raws[0]);
  EXPECT_EQ(ShortcutPaths(space, raws, {}, source.get_token()), raws);
  // Not stopped: the same call does shorten them (so the equality above is the stop's doing).
  const auto shortened = ShortcutPaths(space, raws, {}, std::stop_source().get_token());
  for (std::size_t k = 0; k < raws.size(); ++k) {
    EXPECT_LT(PolylineLength(shortened[k]), PolylineLength(raws[k]) - 1.0) << k;
  }
}

// A stop while shortcutting is honoured: unstopped, this work takes seconds. The latency is a
// speed figure (printed; 0.06-0.11 ms of CPU on one thread when measured), so the unit test
// bounds the CPU time spent after the stop (which a loaded machine does not inflate): the
// calling thread's with all work on it (1-thread TBB arena), every thread's with the default
// arena.
TEST(PathShortcutTest, StopDuringShortcuttingIsHonoured) {
  const Scene scene = Room({Pillar(0, 0)});
  const SignedDistanceField2 field = BaseField(scene);
  const BaseFreeSpace space(field, kRequired);
  // A fine resampling step makes every pass slow: 400 paths take seconds unstopped.
  PathShortcutOptions options;
  options.resample_step_m = 0.002;
  const std::vector<std::vector<Eigen::Vector2d>> raws = Detours(400);
  for (const int threads : {1, 0}) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    std::vector<std::vector<Eigen::Vector2d>> out;
    const testing::StopLatency latency = testing::MeasureStopLatency(30, [&](std::stop_token stop) {
      arena.execute([&] { out = ShortcutPaths(space, raws, options, stop); });
    });
    std::cout << (threads == 1 ? "1 thread" : "all threads") << ": shortcut stop latency "
              << latency.wall_ms << " ms wall, " << latency.cpu_ms << " ms CPU (all threads "
              << latency.process_cpu_ms << " ms)\n";
    EXPECT_LT(threads == 1 ? latency.cpu_ms : latency.process_cpu_ms, 20.0);
    // Whatever was returned is still a free path between the same end points, never longer;
    // some paths were left as they came (the stop cut the work short).
    ASSERT_EQ(out.size(), raws.size());
    int unchanged = 0;
    for (std::size_t k = 0; k < raws.size(); ++k) {
      EXPECT_EQ(out[k].front(), raws[k].front());
      EXPECT_EQ(out[k].back(), raws[k].back());
      EXPECT_LE(PolylineLength(out[k]), PolylineLength(raws[k]) + 1e-9);
      if (out[k] == raws[k]) {
        ++unchanged;
      } else {
        ExpectPathCollisionFree(scene, field, out[k]);
      }
    }
    EXPECT_GT(unchanged, 0);
  }
}

}  // namespace
}  // namespace topay
