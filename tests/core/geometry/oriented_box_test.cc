#include "core/geometry/oriented_box.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/geometry/brute_force_geometry.h"

namespace topay {
namespace {

OrientedBox RandomBox(Rng& rng) {
  OrientedBox box;
  box.center_W_m = {rng.Uniform(-2, 2), rng.Uniform(-2, 2), rng.Uniform(0, 1)};
  box.size_m = {rng.Uniform(0.2, 1.5), rng.Uniform(0.2, 1.5), rng.Uniform(0.2, 1.5)};
  box.yaw_rad = rng.Uniform(-3.2, 3.2);
  return box;
}

// Inside test from the box frame only (independent of the distance code).
bool Inside(const OrientedBox& box, const Eigen::Vector3d& p_W) {
  return (box.ToBoxFrame(p_W).cwiseAbs().array() < box.HalfSize().array()).all();
}

TEST(OrientedBoxTest, ToBoxFrameInvertsThePose) {
  OrientedBox box;
  box.center_W_m = {1.0, -2.0, 0.5};
  box.yaw_rad = 0.7;
  const Eigen::Vector3d p_B(0.3, -0.2, 0.1);
  const Eigen::Vector3d p_W =
      box.center_W_m + Eigen::AngleAxisd(box.yaw_rad, Eigen::Vector3d::UnitZ()) * p_B;
  EXPECT_TRUE(box.ToBoxFrame(p_W).isApprox(p_B, 1e-12));
}

TEST(OrientedBoxTest, WorldBoundsAreTheTightAabbOfTheCorners) {
  Rng rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const OrientedBox box = RandomBox(rng);
    Eigen::AlignedBox3d corners;
    for (const Eigen::Vector3d& p : testing::SampleBoxSurface(box, 1)) corners.extend(p);
    const Eigen::AlignedBox3d bounds = box.WorldBounds();
    EXPECT_TRUE(bounds.min().isApprox(corners.min(), 1e-12));
    EXPECT_TRUE(bounds.max().isApprox(corners.max(), 1e-12));
  }
}

// Signed distance vs the distance to a dense sample of the surface (sign from the inside
// test): the samples are at most spacing / sqrt(2) from any surface point.
TEST(OrientedBoxTest, SignedDistanceMatchesSurfaceSampling) {
  Rng rng(2);
  for (int trial = 0; trial < 8; ++trial) {
    const OrientedBox box = RandomBox(rng);
    const int n = 150;
    const testing::Points surface = testing::SampleBoxSurface(box, n);
    const double tolerance = box.size_m.maxCoeff() / n;
    for (int k = 0; k < 25; ++k) {
      const Eigen::Vector3d p = box.center_W_m + Eigen::Vector3d(rng.Uniform(-1.5, 1.5),
                                                                 rng.Uniform(-1.5, 1.5),
                                                                 rng.Uniform(-1.5, 1.5));
      double nearest = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& s : surface) nearest = std::min(nearest, (s - p).norm());
      const double expected = Inside(box, p) ? -nearest : nearest;
      const double distance = SignedDistanceToBox(box, p);
      EXPECT_NEAR(distance, expected, tolerance);
      // Sampled surface points are never nearer than the exact distance.
      EXPECT_LE(std::abs(distance), nearest + 1e-12);
    }
  }
}

TEST(OrientedBoxTest, GradientMatchesFiniteDifferences) {
  Rng rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const OrientedBox box = RandomBox(rng);
    const Eigen::Vector3d p = box.center_W_m + Eigen::Vector3d(rng.Uniform(-1.5, 1.5),
                                                               rng.Uniform(-1.5, 1.5),
                                                               rng.Uniform(-1.5, 1.5));
    Eigen::Vector3d gradient;
    const double distance = SignedDistanceToBox(box, p, &gradient);
    EXPECT_EQ(distance, SignedDistanceToBox(box, p));
    const double h = 1e-6;
    Eigen::Vector3d numeric;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(i);
      numeric(i) = (SignedDistanceToBox(box, p + e) - SignedDistanceToBox(box, p - e)) / (2 * h);
    }
    // Skip points within 1e-4 of a kink (inside: equidistant from two faces).
    const Eigen::Vector3d excess = box.ToBoxFrame(p).cwiseAbs() - box.HalfSize();
    if (distance < 0.0) {
      Eigen::Vector3d sorted = excess;
      std::sort(sorted.data(), sorted.data() + 3);
      if (sorted(2) - sorted(1) < 1e-4) continue;
    }
    EXPECT_TRUE(gradient.isApprox(numeric, 1e-5)) << gradient.transpose() << " vs "
                                                  << numeric.transpose();
    EXPECT_NEAR(gradient.norm(), 1.0, 1e-12);
  }
}

TEST(OrientedBoxTest, FootprintDistanceMatchesEdgeSampling) {
  Rng rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    const OrientedBox box = RandomBox(rng);
    // The footprint's edges, n points each, from the corners of the box frame.
    const int n = 4000;
    const Eigen::Vector2d h = box.HalfSize().head<2>();
    const Eigen::Rotation2Dd R_WB(box.yaw_rad);
    std::vector<Eigen::Vector2d> edges;
    for (int i = 0; i <= n; ++i) {
      const double t = 2.0 * i / n - 1.0;
      for (const Eigen::Vector2d& p_B : {Eigen::Vector2d(t * h.x(), h.y()),
                                         Eigen::Vector2d(t * h.x(), -h.y()),
                                         Eigen::Vector2d(h.x(), t * h.y()),
                                         Eigen::Vector2d(-h.x(), t * h.y())}) {
        edges.push_back(box.center_W_m.head<2>() + R_WB * p_B);
      }
    }
    ASSERT_FALSE(edges.empty());
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector2d p = box.center_W_m.head<2>() +
                                Eigen::Vector2d(rng.Uniform(-1.5, 1.5), rng.Uniform(-1.5, 1.5));
      double nearest = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector2d& e : edges) nearest = std::min(nearest, (e - p).norm());
      const bool inside =
          Inside(box, Eigen::Vector3d(p.x(), p.y(), box.center_W_m.z()));
      EXPECT_NEAR(SignedDistanceToFootprint(box, p), inside ? -nearest : nearest,
                  box.size_m.maxCoeff() / n + 1e-9);
    }
  }
}

}  // namespace
}  // namespace topay
