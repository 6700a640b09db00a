#include "core/geometry/box_overlap.h"

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay {
namespace {

OrientedBox RandomBox(Rng& rng) {
  OrientedBox box;
  box.center_W_m = {rng.Uniform(-0.7, 0.7), rng.Uniform(-0.7, 0.7), rng.Uniform(0, 0.8)};
  box.size_m = {rng.Uniform(0.1, 1.0), rng.Uniform(0.1, 1.0), rng.Uniform(0.1, 1.0)};
  box.yaw_rad = rng.Uniform(-3.2, 3.2);
  return box;
}

bool Inside(const OrientedBox& box, const Eigen::Vector3d& p_W) {
  return (box.ToBoxFrame(p_W).cwiseAbs().array() < box.HalfSize().array()).all();
}

// Brute force: a grid of points over the first box's interior, any inside the second.
bool SampledOverlap(const OrientedBox& a, const OrientedBox& b, int n) {
  const Eigen::Vector3d h = a.HalfSize();
  const Eigen::AngleAxisd R_WA(a.yaw_rad, Eigen::Vector3d::UnitZ());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d p_A(h.x() * (2.0 * (i + 0.5) / n - 1.0),
                                  h.y() * (2.0 * (j + 0.5) / n - 1.0),
                                  h.z() * (2.0 * (k + 0.5) / n - 1.0));
        if (Inside(b, a.center_W_m + R_WA * p_A)) return true;
      }
    }
  }
  return false;
}

TEST(BoxOverlapTest, AgreesWithPointSampling) {
  Rng rng(5);
  int overlaps = 0;
  int disagreements = 0;
  const int trials = 400;
  for (int trial = 0; trial < trials; ++trial) {
    const OrientedBox a = RandomBox(rng);
    const OrientedBox b = RandomBox(rng);
    const bool exact = BoxesOverlap(a, b);
    EXPECT_EQ(exact, BoxesOverlap(b, a));
    const bool sampled = SampledOverlap(a, b, 30) || SampledOverlap(b, a, 30);
    // Sampling can miss a sliver overlap, never invent one.
    if (sampled) {
      EXPECT_TRUE(exact) << "trial " << trial;
    }
    if (exact != sampled) ++disagreements;
    overlaps += exact;
  }
  EXPECT_GT(overlaps, trials / 5);
  EXPECT_LT(overlaps, trials * 4 / 5);
  EXPECT_LE(disagreements, trials / 50);
}

TEST(BoxOverlapTest, TouchingFacesDoNotOverlap) {
  OrientedBox a;
  a.center_W_m = {0.0, 0.0, 0.5};
  OrientedBox b = a;
  b.center_W_m.x() = 1.0;
  EXPECT_FALSE(BoxesOverlap(a, b));
  b.center_W_m.x() = 0.999;
  EXPECT_TRUE(BoxesOverlap(a, b));
  b.center_W_m = {0.0, 0.0, 1.5};  // stacked
  EXPECT_FALSE(BoxesOverlap(a, b));
}

TEST(BoxOverlapTest, DiamondFacingACornerIsSeparatedAlongTheDiagonal) {
  // A unit square and a 45-degree-yawed unit square whose edge faces the first one's corner
  // (1, 1) at a gap of 0.05 m along the diagonal: the AABBs overlap, the boxes do not; 0.1 m
  // nearer they do.
  OrientedBox a;
  a.center_W_m = {0.0, 0.0, 0.5};
  OrientedBox b = a;
  b.yaw_rad = 0.785398163397448;
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  b.center_W_m = Eigen::Vector3d(0.5, 0.5, 0.5) + (0.5 + 0.05) * diagonal;
  EXPECT_TRUE(a.WorldBounds().intersects(b.WorldBounds()));
  EXPECT_FALSE(BoxesOverlap(a, b));
  b.center_W_m -= 0.1 * diagonal;
  EXPECT_TRUE(BoxesOverlap(a, b));
}

}  // namespace
}  // namespace topay
