#include "core/geometry/primitive_box_distance.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/geometry/brute_force_geometry.h"

namespace topay {
namespace {

using testing::BruteForceConvexSignedDistance;

OrientedBox MakeBox(Eigen::Vector3d center, Eigen::Vector3d size, double yaw) {
  OrientedBox box;
  box.center_W_m = center;
  box.size_m = size;
  box.yaw_rad = yaw;
  return box;
}

// Random box near the origin, and a cylinder / sphere placed at a random offset, so the cases
// cover apart, touching-ish and overlapping configurations.
struct Case {
  OrientedBox box;
  VerticalCylinder cylinder;
  Eigen::Vector3d p_WS;
  double sphere_radius_m;
};

Case RandomCase(Rng& rng) {
  Case c;
  c.box = MakeBox({rng.Uniform(-0.3, 0.3), rng.Uniform(-0.3, 0.3), rng.Uniform(0.0, 0.8)},
                  {rng.Uniform(0.1, 1.0), rng.Uniform(0.1, 1.0), rng.Uniform(0.05, 0.8)},
                  rng.Uniform(-3.2, 3.2));
  c.cylinder.axis_W_m = {rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)};
  c.cylinder.radius_m = rng.Uniform(0.1, 0.5);
  c.cylinder.bottom_z_m = rng.Uniform(-0.2, 0.4);
  c.cylinder.height_m = rng.Uniform(0.1, 0.5);
  c.p_WS = c.box.center_W_m + Eigen::Vector3d(rng.Uniform(-0.7, 0.7), rng.Uniform(-0.7, 0.7),
                                              rng.Uniform(-0.6, 0.6));
  c.sphere_radius_m = rng.Uniform(0.03, 0.3);
  return c;
}

TEST(PrimitiveBoxDistanceTest, CylinderMatchesBruteForceSupportSearch) {
  Rng rng(11);
  int apart = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Case c = RandomCase(rng);
    const double exact = SignedDistanceCylinderToBox(c.box, c.cylinder);
    const double brute =
        BruteForceConvexSignedDistance(testing::SampleCylinderSurface(c.cylinder, 360, 1),
                                       testing::SampleBoxSurface(c.box, 2));
    EXPECT_NEAR(exact, brute, 2e-4) << "trial " << trial;
    (exact > 0.0 ? apart : overlapping)++;
  }
  EXPECT_GE(apart, 4);
  EXPECT_GE(overlapping, 4);
}

TEST(PrimitiveBoxDistanceTest, SphereMatchesBruteForceSupportSearch) {
  Rng rng(12);
  int apart = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const Case c = RandomCase(rng);
    const double exact = SignedDistanceSphereToBox(c.box, c.p_WS, c.sphere_radius_m);
    const double brute = BruteForceConvexSignedDistance(
        testing::SampleSphereSurface(c.p_WS, c.sphere_radius_m, 8000),
        testing::SampleBoxSurface(c.box, 2));
    EXPECT_NEAR(exact, brute, 2e-4) << "trial " << trial;
    (exact > 0.0 ? apart : overlapping)++;
  }
  EXPECT_GE(apart, 3);
  EXPECT_GE(overlapping, 3);
}

// When apart, the distance is the smallest distance from a cylinder surface point to the box
// (an independent check through the point distance).
TEST(PrimitiveBoxDistanceTest, CylinderApartMatchesNearestSurfacePoint) {
  Rng rng(13);
  int checked = 0;
  for (int trial = 0; trial < 60 && checked < 15; ++trial) {
    const Case c = RandomCase(rng);
    const double exact = SignedDistanceCylinderToBox(c.box, c.cylinder);
    if (exact <= 0.0) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : testing::SampleCylinderSurface(c.cylinder, 720, 100)) {
      nearest = std::min(nearest, SignedDistanceToBox(c.box, p));
    }
    EXPECT_NEAR(exact, nearest, 3e-3);
    EXPECT_LE(exact, nearest + 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 15);
}

TEST(PrimitiveBoxDistanceTest, CylinderUnderATableTopAndBesideALeg) {
  const OrientedBox top = MakeBox({0.0, 0.0, 0.725}, {1.0, 1.0, 0.05}, 0.3);
  VerticalCylinder base{{0.1, -0.2}, 0.4, 0.0, 0.155};
  // Under the top: only the vertical gap, 0.7 - 0.155.
  EXPECT_NEAR(SignedDistanceCylinderToBox(top, base), 0.7 - 0.155, 1e-12);
  // Overlapping in z and xy: minus the smaller depth (here the z overlap 0.05 - 0.02).
  base.height_m = 0.72;
  EXPECT_NEAR(SignedDistanceCylinderToBox(top, base), -(0.72 - 0.7), 1e-12);
  // A leg beside the base, apart in xy only.
  const OrientedBox leg = MakeBox({1.0, 0.0, 0.35}, {0.05, 0.05, 0.7}, 0.0);
  const VerticalCylinder low{{0.0, 0.0}, 0.4, 0.0, 0.155};
  EXPECT_NEAR(SignedDistanceCylinderToBox(leg, low), 1.0 - 0.025 - 0.4, 1e-12);
}

TEST(PrimitiveBoxDistanceTest, CombineProductSignedDistance) {
  EXPECT_DOUBLE_EQ(CombineProductSignedDistance(3.0, 4.0), 5.0);
  EXPECT_DOUBLE_EQ(CombineProductSignedDistance(3.0, -4.0), 3.0);
  EXPECT_DOUBLE_EQ(CombineProductSignedDistance(-3.0, 4.0), 4.0);
  EXPECT_DOUBLE_EQ(CombineProductSignedDistance(-3.0, -4.0), -3.0);
  EXPECT_DOUBLE_EQ(CombineProductSignedDistance(0.0, -1.0), 0.0);
}

}  // namespace
}  // namespace topay
