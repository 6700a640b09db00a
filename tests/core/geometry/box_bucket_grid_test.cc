#include "core/geometry/box_bucket_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Boxes of mixed sizes (small clutter and a few long walls) over a 20 x 20 m floor.
std::vector<Eigen::AlignedBox3d> RandomBounds(int count, Rng& rng) {
  std::vector<Eigen::AlignedBox3d> bounds;
  for (int i = 0; i < count; ++i) {
    const double size = i % 37 == 0 ? rng.Uniform(2.0, 12.0) : rng.Uniform(0.02, 0.6);
    const Eigen::Vector3d lo(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(0, 1));
    const Eigen::Vector3d extent(size, rng.Uniform(0.02, 0.6), rng.Uniform(0.05, 0.5));
    bounds.emplace_back(lo, lo + extent);
  }
  return bounds;
}

double XyGap(const Eigen::AlignedBox3d& box, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const double gx = std::max({box.min().x() - hi.x(), lo.x() - box.max().x(), 0.0});
  const double gy = std::max({box.min().y() - hi.y(), lo.y() - box.max().y(), 0.0});
  return std::hypot(gx, gy);
}

// Every box whose xy gap to the query is within the bound is visited, each box at most once.
TEST(BoxBucketGridTest, VisitsEveryBoxWithinTheBoundExactlyOnce) {
  Rng rng(3);
  const std::vector<Eigen::AlignedBox3d> bounds = RandomBounds(2000, rng);
  for (double bucket_m : {0.0, 0.05, 0.7, 50.0}) {
    const BoxBucketGrid grid(bounds, bucket_m);
    for (int q = 0; q < 300; ++q) {
      const Eigen::Vector2d lo(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
      const Eigen::Vector2d hi = lo + Eigen::Vector2d(rng.Uniform(0, 1), rng.Uniform(0, 1));
      const double bound = q % 10 == 0 ? kInf : rng.Uniform(0.0, 2.0);
      std::vector<int> visits(bounds.size(), 0);
      grid.VisitNear(lo, hi, [bound] { return bound; }, [&](int i) { ++visits[i]; });
      for (std::size_t i = 0; i < bounds.size(); ++i) {
        ASSERT_LE(visits[i], 1) << "box " << i << " visited twice, bucket " << bucket_m;
        if (XyGap(bounds[i], lo, hi) <= bound) {
          ASSERT_EQ(visits[i], 1) << "box " << i << " within the bound not visited, bucket "
                                  << bucket_m;
        }
      }
    }
  }
}

// The point of the grid: a query near few boxes looks at few boxes, whatever the scene size.
TEST(BoxBucketGridTest, AQueryLooksAtTheBoxesNearItOnly) {
  Rng rng(5);
  std::vector<Eigen::AlignedBox3d> bounds;
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Vector3d lo(rng.Uniform(-10, 10), rng.Uniform(-10, 10), 0.0);
    bounds.emplace_back(lo, lo + Eigen::Vector3d(0.05, 0.05, 0.1));
  }
  const BoxBucketGrid grid(bounds);
  const Eigen::Vector2d p(0.3, -0.2);
  int visited = 0;
  grid.VisitNear(p, p, [] { return 0.2; }, [&](int) { ++visited; });
  // 100000 boxes on 400 m^2: about 250 per m^2, so some tens within 0.2 m + a bucket.
  EXPECT_GT(visited, 0);
  EXPECT_LT(visited, 1000);
}

TEST(BoxBucketGridTest, EmptyAndDegenerateInputs) {
  const BoxBucketGrid empty(std::vector<Eigen::AlignedBox3d>{});
  int visited = 0;
  empty.VisitNear(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), [] { return kInf; },
                  [&](int) { ++visited; });
  EXPECT_EQ(visited, 0);
  // One point-sized box, and an empty (inverted) box that is listed nowhere.
  std::vector<Eigen::AlignedBox3d> bounds{
      Eigen::AlignedBox3d(Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 1, 0)),
      Eigen::AlignedBox3d(Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(1, 1, 0))};
  const BoxBucketGrid grid(bounds);
  std::vector<int> seen;
  grid.VisitNear(Eigen::Vector2d(-50, -50), Eigen::Vector2d(-50, -50), [] { return kInf; },
                 [&](int i) { seen.push_back(i); });
  EXPECT_EQ(seen, std::vector<int>{0});
  EXPECT_THROW(BoxBucketGrid(bounds, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay
