#include "core/planning/jump_point_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <queue>
#include <stop_token>

#include "core/common/random.h"
#include "core/planning/base_free_space.h"
#include "core/planning/base_path.h"
#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;
using Status = JumpPointSearchResult::Status;

// JumpPointSearchOptions: traversable cells have value >= safe distance + 1e-6
// m.
constexpr double kTraversable = kRequired + 1e-6;

// Reference: plain Dijkstra on the 8-connected grid with the same
// traversability and the same no-corner-cutting rule; returns the optimal cost
// in cells (inf if unreachable).
double DijkstraCells(const SignedDistanceField2& field, double safe, Eigen::Vector2i s,
                     Eigen::Vector2i g) {
  const int nx = field.geometry().dims.x(), ny = field.geometry().dims.y();
  auto free = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < nx && y < ny && field.CellValue(x, y) >= safe;
  };
  std::vector<double> dist(static_cast<std::size_t>(nx) * ny,
                           std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[s.y() * nx + s.x()] = 0.0;
  open.push({0.0, s.y() * nx + s.x()});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    const int x = i % nx, y = i / nx;
    if (x == g.x() && y == g.y()) return d;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        if ((dx == 0 && dy == 0) || !free(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && !(free(x + dx, y) && free(x, y + dy))) continue;
        const double nd = d + ((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0);
        const int j = (y + dy) * nx + x + dx;
        if (nd < dist[j]) {
          dist[j] = nd;
          open.push({nd, j});
        }
      }
    }
  }
  return std::numeric_limits<double>::infinity();
}

// JPS is optimal and complete on the grid: its unshortcut path costs what
// Dijkstra finds, and it fails exactly when Dijkstra does. Random rooms of
// pillars and walls, cell-centre tasks.
TEST(JumpPointSearchTest, MatchesDijkstraOnRandomRooms) {
  Rng rng(42);
  int num_compared = 0, num_unreachable = 0;
  for (int room = 0; room < 6; ++room) {
    const Scene room_scene = Room(RandomBoxes(rng, 25));
    const SignedDistanceField2 field = BaseField(room_scene);
    const BaseFreeSpace space(field, kRequired);
    const GridGeometry2& g = field.geometry();
    JumpPointSearchOptions options;
    options.shortcut = false;
    for (int task = 0; task < 15; ++task) {
      Eigen::Vector2i s, t;
      do {
        s = Eigen::Vector2i(rng.UniformInt(0, g.dims.x() - 1), rng.UniformInt(0, g.dims.y() - 1));
      } while (field.CellValue(s.x(), s.y()) < kTraversable);
      do {
        t = Eigen::Vector2i(rng.UniformInt(0, g.dims.x() - 1), rng.UniformInt(0, g.dims.y() - 1));
      } while (field.CellValue(t.x(), t.y()) < kTraversable);
      const Eigen::Vector2d ps = g.CellCenter(s.x(), s.y()), pt = g.CellCenter(t.x(), t.y());
      if (space.IsSegmentFree(ps, pt)) continue;  // JPS returns the straight segment then
      const double reference = DijkstraCells(field, kTraversable, s, t);
      const JumpPointSearchResult result = JumpPointSearch(field, ps, pt, options);
      if (std::isinf(reference)) {
        ++num_unreachable;
        EXPECT_EQ(result.status, Status::kNoPath) << result.reason;
        EXPECT_TRUE(result.path_W_m.empty());
        continue;
      }
      ++num_compared;
      ASSERT_TRUE(result.ok()) << result.reason;
      EXPECT_NEAR(result.grid_length_m, reference * g.resolution_m, 1e-9);
      ExpectPathCollisionFree(room_scene, field, result.path_W_m);
    }
  }
  EXPECT_GT(num_compared, 30);
  EXPECT_GT(num_unreachable, 0);
}

TEST(JumpPointSearchTest, FindsThePathThroughAGapAndShortcutsIt) {
  const Scene scene = Room(WallWithGap(2.5, 1.6));
  const SignedDistanceField2 field = BaseField(scene);
  const JumpPointSearchResult result = JumpPointSearch(field, {-5, -2}, {5, -2});
  ASSERT_TRUE(result.ok()) << result.reason;
  EXPECT_TRUE(result.reason.empty());
  EXPECT_EQ(result.path_W_m.front(), Eigen::Vector2d(-5, -2));
  EXPECT_EQ(result.path_W_m.back(), Eigen::Vector2d(5, -2));
  // Passable band at the wall: gap centre +- (gap / 2 - required), widened by
  // the field's error (at most one cell).
  EXPECT_NEAR(CrossingY(result.path_W_m, 0.0), 2.5, 0.8 - kRequired + 0.1);
  EXPECT_LE(result.length_m, result.grid_length_m);
  EXPECT_NEAR(result.length_m, PolylineLength(result.path_W_m), 1e-12);
  ExpectPathCollisionFree(scene, field, result.path_W_m);
  // Straight-line lower bound through the gap centre: 2 * |(-5,-2) ->
  // (0, 2.5)|.
  EXPECT_GE(result.length_m, 2.0 * std::hypot(5.0, 4.5) - 0.5);
}

TEST(JumpPointSearchTest, GapNarrowerThanTheBaseIsSealed) {
  // The base needs 2 x 0.5 m; a 0.8 m gap seals the wall.
  const SignedDistanceField2 field = BaseField(Room(WallWithGap(0.0, 0.8)));
  const JumpPointSearchResult result = JumpPointSearch(field, {-5, 0}, {5, 0});
  EXPECT_EQ(result.status, Status::kNoPath);
  EXPECT_FALSE(result.reason.empty());
  EXPECT_TRUE(result.path_W_m.empty());
}

TEST(JumpPointSearchTest, SealedGoalFails) {
  // A ring of four walls around the goal.
  const std::vector<OrientedBox> ring{
      MakeBox(Eigen::Vector3d(4, 1.5, 0.5), Eigen::Vector3d(3.2, 0.2, 1)),
      MakeBox(Eigen::Vector3d(4, -1.5, 0.5), Eigen::Vector3d(3.2, 0.2, 1)),
      MakeBox(Eigen::Vector3d(2.5, 0, 0.5), Eigen::Vector3d(0.2, 3.2, 1)),
      MakeBox(Eigen::Vector3d(5.5, 0, 0.5), Eigen::Vector3d(0.2, 3.2, 1))};
  const SignedDistanceField2 field = BaseField(Room(ring));
  const JumpPointSearchResult result = JumpPointSearch(field, {-5, 0}, {4, 0});
  EXPECT_EQ(result.status, Status::kNoPath) << result.reason;
  EXPECT_NE(result.reason.find("not connected"), std::string::npos) << result.reason;
}

TEST(JumpPointSearchTest, BadInputGivesAReason) {
  const SignedDistanceField2 field = BaseField(Room({Pillar(0, 0)}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(JumpPointSearch(field, {nan, 0}, {5, 0}).status, Status::kInvalidInput);
  EXPECT_EQ(JumpPointSearch(field, {-5, 0}, {5, nan}).status, Status::kInvalidInput);
  const JumpPointSearchResult start_hit = JumpPointSearch(field, {0.2, 0}, {5, 0});
  EXPECT_EQ(start_hit.status, Status::kStartBlocked);
  EXPECT_FALSE(start_hit.reason.empty());
  EXPECT_EQ(JumpPointSearch(field, {-5, 0}, {0, 0.8}).status, Status::kGoalBlocked);
  EXPECT_EQ(JumpPointSearch(field, {-5, 0}, {50, 0}).status, Status::kGoalBlocked);
  JumpPointSearchOptions bad;
  bad.safe_distance_m = nan;
  EXPECT_EQ(JumpPointSearch(field, {-5, 0}, {5, 0}, bad).status, Status::kInvalidInput);
}

TEST(JumpPointSearchTest, CancelledSearchStops) {
  const SignedDistanceField2 field = BaseField(Room(WallWithGap(4.5, 1.6)));
  std::stop_source source;
  source.request_stop();
  JumpPointSearchOptions options;
  const JumpPointSearchResult result =
      JumpPointSearch(field, {-7, -5}, {7, -5}, options, source.get_token());
  EXPECT_EQ(result.status, Status::kCancelled);
  EXPECT_TRUE(result.path_W_m.empty());
}

}  // namespace
}  // namespace topay
