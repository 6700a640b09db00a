#include "core/map/voxel_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay {
namespace {

using Voxel = std::tuple<int, int, int>;

// A small grid with a non-round origin and resolution: 7 x 5 x 4 voxels of 0.13 m.
GridGeometry3 SmallGrid() {
  GridGeometry3 g;
  g.origin_W_m = Eigen::Vector3d(-0.37, 0.21, -0.05);
  g.resolution_m = 0.13;
  g.dims = Eigen::Vector3i(7, 5, 4);
  return g;
}

// The voxels the walk visits, in order; checks each index against GridGeometry3::Index.
std::vector<Voxel> Walk(const GridGeometry3& g, const Eigen::Vector3d& p_WS,
                        const Eigen::Vector3d& p_WP) {
  std::vector<Voxel> voxels;
  const int n = TraverseVoxelRay(g, p_WS, p_WP, [&](const Eigen::Vector3i& v, std::int64_t i) {
    EXPECT_EQ(i, g.Index(v.x(), v.y(), v.z()));
    voxels.emplace_back(v.x(), v.y(), v.z());
  });
  EXPECT_EQ(n, static_cast<int>(voxels.size()));
  return voxels;
}

// The segment parameter interval [t_in, t_out] (within [0, 1]) inside the closed voxel box,
// by the slab method in grid units; t_in > t_out if they do not meet.
std::pair<double, double> VoxelInterval(const GridGeometry3& g, const Eigen::Vector3d& p_WS,
                                        const Eigen::Vector3d& p_WP, const Voxel& voxel) {
  const int index[3] = {std::get<0>(voxel), std::get<1>(voxel), std::get<2>(voxel)};
  double t_in = 0.0, t_out = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double low = g.origin_W_m(a) + index[a] * g.resolution_m;
    const double high = low + g.resolution_m;
    const double d = p_WP(a) - p_WS(a);
    if (d == 0.0) {
      if (p_WS(a) < low || p_WS(a) > high) return {1.0, 0.0};
      continue;
    }
    const double t0 = (low - p_WS(a)) / d, t1 = (high - p_WS(a)) / d;
    t_in = std::max(t_in, std::min(t0, t1));
    t_out = std::min(t_out, std::max(t0, t1));
  }
  return {t_in, t_out};
}

// Brute force: every voxel of the grid whose box the segment crosses over a length above
// `min_length_m`, ordered by where the segment is in it.
std::vector<Voxel> BruteForce(const GridGeometry3& g, const Eigen::Vector3d& p_WS,
                              const Eigen::Vector3d& p_WP, double min_length_m) {
  const double length = (p_WP - p_WS).norm();
  std::vector<std::pair<double, Voxel>> found;
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const auto [t_in, t_out] = VoxelInterval(g, p_WS, p_WP, {ix, iy, iz});
        if (t_out >= t_in && (t_out - t_in) * length > min_length_m) {
          found.push_back({0.5 * (t_in + t_out), {ix, iy, iz}});
        }
      }
  std::sort(found.begin(), found.end());
  std::vector<Voxel> voxels;
  for (const auto& [t, v] : found) voxels.push_back(v);
  return voxels;
}

// Dense sampling: the voxel of each of `samples` + 1 evenly spaced points inside the grid, in
// order, consecutive repeats removed.
std::vector<Voxel> DenseSamples(const GridGeometry3& g, const Eigen::Vector3d& p_WS,
                                const Eigen::Vector3d& p_WP, int samples) {
  std::vector<Voxel> voxels;
  for (int k = 0; k <= samples; ++k) {
    const Eigen::Vector3d p = p_WS + (p_WP - p_WS) * (static_cast<double>(k) / samples);
    if (!g.Contains(p)) continue;
    const Eigen::Vector3i v = g.CellOf(p);
    const Voxel voxel{v.x(), v.y(), v.z()};
    if (voxels.empty() || voxels.back() != voxel) voxels.push_back(voxel);
  }
  return voxels;
}

// The walk equals the brute-force set of voxels crossed over a positive length, in order; a
// voxel the segment touches only within 1e-9 m (an edge or corner, rounding) may be added.
void ExpectMatchesBruteForce(const GridGeometry3& g, const Eigen::Vector3d& p_WS,
                             const Eigen::Vector3d& p_WP, int* extra_voxels) {
  const std::vector<Voxel> walk = Walk(g, p_WS, p_WP);
  const std::vector<Voxel> reference = BruteForce(g, p_WS, p_WP, 1e-9);
  const std::set<Voxel> walked(walk.begin(), walk.end());
  ASSERT_EQ(walked.size(), walk.size()) << "a voxel visited twice";
  const std::set<Voxel> expected(reference.begin(), reference.end());
  std::vector<Voxel> walk_in_reference;
  for (const Voxel& v : walk) {
    if (expected.count(v)) {
      walk_in_reference.push_back(v);
      continue;
    }
    ++*extra_voxels;
    const auto [t_in, t_out] = VoxelInterval(g, p_WS, p_WP, v);
    EXPECT_GE(t_out - t_in, -1e-9) << "visited a voxel the segment does not touch";
  }
  EXPECT_EQ(walk_in_reference, reference) << "missing voxels or wrong order";
  // Every densely sampled voxel is walked, in the same order.
  std::size_t at = 0;
  for (const Voxel& v : DenseSamples(g, p_WS, p_WP, 2000)) {
    while (at < walk.size() && walk[at] != v) ++at;
    ASSERT_LT(at, walk.size()) << "a sampled voxel missing or out of order";
  }
}

TEST(VoxelRayTest, RandomSegmentsMatchBruteForce) {
  const GridGeometry3 g = SmallGrid();
  const Eigen::AlignedBox3d box = g.Bounds();
  Rng rng(17);
  int extra = 0, inside_starts = 0, empty = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Endpoints in the grid's box grown by 30 %: many start or end outside.
    Eigen::Vector3d p[2];
    for (auto& q : p) {
      for (int a = 0; a < 3; ++a) {
        const double margin = 0.3 * (box.max()(a) - box.min()(a));
        q(a) = rng.Uniform(box.min()(a) - margin, box.max()(a) + margin);
      }
    }
    inside_starts += g.Contains(p[0]);
    ExpectMatchesBruteForce(g, p[0], p[1], &extra);
    empty += Walk(g, p[0], p[1]).empty();
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(inside_starts, 300);
  EXPECT_GT(empty, 30);
  EXPECT_LE(extra, 3);  // touches at an edge happen with probability zero
}

TEST(VoxelRayTest, EndsInTheVoxelOfAnInsideEndpoint) {
  const GridGeometry3 g = SmallGrid();
  Rng rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Vector3d p_WS, p_WP;
    for (int a = 0; a < 3; ++a) {
      p_WS(a) = rng.Uniform(g.Bounds().min()(a) - 1.0, g.Bounds().max()(a) + 1.0);
      p_WP(a) = rng.Uniform(g.Bounds().min()(a), g.Bounds().max()(a));
    }
    if (!g.Contains(p_WP)) continue;
    const std::vector<Voxel> walk = Walk(g, p_WS, p_WP);
    const Eigen::Vector3i v = g.CellOf(p_WP);
    ASSERT_FALSE(walk.empty());
    EXPECT_EQ(walk.back(), Voxel(v.x(), v.y(), v.z()));
    if (g.Contains(p_WS)) {
      const Eigen::Vector3i s = g.CellOf(p_WS);
      EXPECT_EQ(walk.front(), Voxel(s.x(), s.y(), s.z()));
    }
  }
}

TEST(VoxelRayTest, AxisParallelSegments) {
  const GridGeometry3 g = SmallGrid();
  // Along x through voxel row (y 2, z 1), from outside to outside: the whole row, in order.
  const Eigen::Vector3d c = g.CellCenter(0, 2, 1);
  std::vector<Voxel> walk = Walk(g, c - Eigen::Vector3d(1.0, 0, 0), c + Eigen::Vector3d(3.0, 0, 0));
  ASSERT_EQ(walk.size(), 7u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(walk[i], Voxel(i, 2, 1));
  // Along -z inside column (3, 4), from voxel z 3 to z 0.
  walk = Walk(g, g.CellCenter(3, 4, 3), g.CellCenter(3, 4, 0));
  ASSERT_EQ(walk.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(walk[i], Voxel(3, 4, 3 - i));
  // Along y on the grid's minimum x face (inside: the faces at the origin are the grid's).
  const Eigen::Vector3d on_face(g.origin_W_m.x(), c.y(), c.z());
  walk = Walk(g, on_face - Eigen::Vector3d(0, 5, 0), on_face + Eigen::Vector3d(0, 5, 0));
  EXPECT_EQ(walk.size(), 5u);
  // Parallel to x just outside the grid (above its top): nothing.
  const double z_top = g.Bounds().max().z() + 1e-6;
  EXPECT_TRUE(Walk(g, Eigen::Vector3d(-5, 0.4, z_top), Eigen::Vector3d(5, 0.4, z_top)).empty());
  // On the maximum x face (half-open, not in the grid).
  const double x_max = g.origin_W_m.x() + 7 * g.resolution_m;
  EXPECT_TRUE(Walk(g, Eigen::Vector3d(x_max, 0.3, 0.1), Eigen::Vector3d(x_max, 0.6, 0.2)).empty());
}

TEST(VoxelRayTest, ExactCornersStepAllTiedAxesAtOnce) {
  // A dyadic grid: every boundary is exact, the diagonal crosses voxel corners exactly.
  GridGeometry3 g;
  g.origin_W_m = Eigen::Vector3d(-1.0, -1.0, 0.0);
  g.resolution_m = 0.125;
  g.dims = Eigen::Vector3i(8, 8, 8);
  // Space diagonal from a voxel centre: only the voxels (i, i, i).
  std::vector<Voxel> walk = Walk(g, g.CellCenter(0, 0, 0), g.CellCenter(7, 7, 7));
  ASSERT_EQ(walk.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(walk[i], Voxel(i, i, i));
  // From the grid's corner to the opposite corner (both outside on the max side: clipped).
  walk = Walk(g, g.origin_W_m, g.Bounds().max());
  ASSERT_EQ(walk.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(walk[i], Voxel(i, i, i));
  // Diagonal in xy at a fixed z, backwards: (i, i, 2) for i from 6 down to 1.
  walk = Walk(g, g.CellCenter(6, 6, 2), g.CellCenter(1, 1, 2));
  ASSERT_EQ(walk.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(walk[i], Voxel(6 - i, 6 - i, 2));
  // Slope 1:2 in xy from a voxel corner: every x crossing is at a voxel corner (x and y
  // boundaries crossed together), exactly in binary; the walk skips the corner-touched
  // neighbours as brute force does, and leaves the grid at a corner too.
  int extra = 0;
  ExpectMatchesBruteForce(g, Eigen::Vector3d(-0.5, -0.75, 0.3), Eigen::Vector3d(0.5, 1.25, 0.3),
                          &extra);
  EXPECT_EQ(extra, 0);
}

TEST(VoxelRayTest, ZeroLengthVisitsOneVoxelInsideNoneOutside) {
  const GridGeometry3 g = SmallGrid();
  const Eigen::Vector3d p = g.CellCenter(2, 3, 1) + Eigen::Vector3d(0.01, -0.02, 0.03);
  const std::vector<Voxel> walk = Walk(g, p, p);
  ASSERT_EQ(walk.size(), 1u);
  EXPECT_EQ(walk[0], Voxel(2, 3, 1));
  const Eigen::Vector3d outside = g.origin_W_m - Eigen::Vector3d(0.1, 0, 0);
  EXPECT_TRUE(Walk(g, outside, outside).empty());
}

TEST(VoxelRayTest, StartingOutsideEntersAtTheFace) {
  const GridGeometry3 g = SmallGrid();
  // From below the grid, up through voxel column (4, 1), ending inside at z voxel 2.
  const Eigen::Vector3d top = g.CellCenter(4, 1, 2);
  const std::vector<Voxel> walk = Walk(g, top - Eigen::Vector3d(0, 0, 2.0), top);
  ASSERT_EQ(walk.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(walk[i], Voxel(4, 1, i));
}

TEST(VoxelRayTest, VisitorReturningFalseStops) {
  const GridGeometry3 g = SmallGrid();
  int calls = 0;
  const int n = TraverseVoxelRay(g, g.CellCenter(0, 0, 0), g.CellCenter(6, 0, 0),
                                 [&](const Eigen::Vector3i&, std::int64_t) { return ++calls < 3; });
  EXPECT_EQ(n, 3);
  EXPECT_EQ(calls, 3);
}

TEST(VoxelRayTest, NonFiniteInputIsRejected) {
  const GridGeometry3 g = SmallGrid();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto ignore = [](const Eigen::Vector3i&, std::int64_t) {};
  EXPECT_THROW(TraverseVoxelRay(g, Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d::Zero(), ignore),
               std::invalid_argument);
  EXPECT_THROW(TraverseVoxelRay(g, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, nan, 0), ignore),
               std::invalid_argument);
  EXPECT_THROW(TraverseVoxelRay(g, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, inf), ignore),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
