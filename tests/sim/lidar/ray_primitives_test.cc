#include "sim/lidar/ray_primitives.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/common/make_box.h"

namespace topay::sim {
namespace {

TEST(RayPrimitivesTest, AxisAlignedBoxFaceDistance) {
  const OrientedBox box = MakeBox({0, 0, 0.5}, {1, 1, 1});
  EXPECT_DOUBLE_EQ(RayBoxEntry(box, {-5, 0, 0.5}, {1, 0, 0}), 4.5);
  EXPECT_DOUBLE_EQ(RayBoxEntry(box, {0, 0, 3}, {0, 0, -1}), 2.0);
  EXPECT_EQ(RayBoxEntry(box, {-5, 0, 0.5}, {-1, 0, 0}), kNoHit);  // pointing away
  EXPECT_EQ(RayBoxEntry(box, {-5, 0, 1.5}, {1, 0, 0}), kNoHit);   // passes above
  EXPECT_EQ(RayBoxEntry(box, {0.1, 0.2, 0.3}, {0, 1, 0}), 0.0);   // starts inside
}

TEST(RayPrimitivesTest, RotatedBoxDiagonalFace) {
  // A 1 x 1 box yawed 45 deg: its corner points at -x, at distance sqrt(2)/2 from the centre.
  const OrientedBox box = MakeBox({0, 0, 0.5}, {1, 1, 1}, 0.25 * 3.14159265358979323846);
  EXPECT_NEAR(RayBoxEntry(box, {-5, 0, 0.5}, {1, 0, 0}), 5.0 - std::sqrt(0.5), 1e-12);
}

// Random rays and boxes: a hit lies on the box surface and every point before it is outside;
// a miss never enters the box (sampled every 5 mm).
TEST(RayPrimitivesTest, RandomRaysAgreeWithTheSignedDistance) {
  Rng rng(7);
  int hits = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const OrientedBox box =
        MakeBox({rng.Uniform(-2, 2), rng.Uniform(-2, 2), rng.Uniform(0, 1.5)},
                {rng.Uniform(0.1, 1.5), rng.Uniform(0.1, 1.5), rng.Uniform(0.1, 1.5)},
                rng.Uniform(-3.2, 3.2));
    const Eigen::Vector3d o(rng.Uniform(-4, 4), rng.Uniform(-4, 4), rng.Uniform(-0.5, 2));
    const Eigen::Vector3d d = (box.center_W_m +
                               Eigen::Vector3d(rng.Uniform(-1, 1), rng.Uniform(-1, 1),
                                               rng.Uniform(-1, 1)) - o).normalized();
    const double t = RayBoxEntry(box, o, d);
    const double end = t == kNoHit ? 10.0 : t;
    if (SignedDistanceToBox(box, o) > 0.0) {
      for (double s = 0.0; s < end - 0.005; s += 0.005) {
        ASSERT_GT(SignedDistanceToBox(box, o + s * d), 0.0) << trial << " at " << s;
      }
    }
    if (t != kNoHit) {
      ++hits;
      if (t > 0.0) {
        EXPECT_NEAR(SignedDistanceToBox(box, o + t * d), 0.0, 1e-9) << trial;
      }
    }
  }
  EXPECT_GT(hits, 400);
}

TEST(RayPrimitivesTest, Sphere) {
  EXPECT_DOUBLE_EQ(RaySphereEntry({3, 0, 0}, 0.5, {0, 0, 0}, {1, 0, 0}), 2.5);
  EXPECT_EQ(RaySphereEntry({3, 0, 0}, 0.5, {0, 0, 0}, {-1, 0, 0}), kNoHit);
  EXPECT_EQ(RaySphereEntry({3, 0.6, 0}, 0.5, {0, 0, 0}, {1, 0, 0}), kNoHit);
  EXPECT_EQ(RaySphereEntry({0, 0, 0}, 0.5, {0.1, 0, 0}, {1, 0, 0}), 0.0);
  // Off-centre chord: half chord sqrt(r^2 - y^2).
  EXPECT_NEAR(RaySphereEntry({3, 0.3, 0}, 0.5, {0, 0, 0}, {1, 0, 0}), 3.0 - 0.4, 1e-12);
}

TEST(RayPrimitivesTest, VerticalCylinderSideCapsAndInside) {
  const VerticalCylinder c{{0, 0}, 0.4, 0.0, 0.155};
  EXPECT_NEAR(RayCylinderEntry(c, {-2, 0, 0.1}, {1, 0, 0}), 1.6, 1e-12);        // side
  EXPECT_NEAR(RayCylinderEntry(c, {0.1, 0.1, 1.0}, {0, 0, -1}), 0.845, 1e-12);  // top cap
  EXPECT_EQ(RayCylinderEntry(c, {-2, 0, 0.2}, {1, 0, 0}), kNoHit);              // above
  EXPECT_EQ(RayCylinderEntry(c, {0.5, 0.5, 1.0}, {0, 0, -1}), kNoHit);          // beside
  EXPECT_EQ(RayCylinderEntry(c, {0, 0, 0.1}, {1, 0, 0}), 0.0);                  // inside
  // A descending ray from a sensor above the top, 0.3 m off axis, looking back over it.
  const Eigen::Vector3d d = Eigen::Vector3d(-1, 0, -0.1).normalized();
  const double t = RayCylinderEntry(c, {0.3, 0, 0.22}, d);
  EXPECT_NEAR((0.22 + t * d.z()), 0.155, 1e-12);  // lands on the top cap
}

TEST(RayPrimitivesTest, Ground) {
  EXPECT_NEAR(RayGroundEntry({0, 0, 1}, Eigen::Vector3d(1, 0, -1).normalized()), std::sqrt(2.0),
              1e-12);
  EXPECT_EQ(RayGroundEntry({0, 0, 1}, {1, 0, 0}), kNoHit);
  EXPECT_EQ(RayGroundEntry({0, 0, -0.1}, {1, 0, 0}), 0.0);
}

}  // namespace
}  // namespace topay::sim
