#include "tools/viz/shapes.h"

#include <numbers>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

void ExpectNear(const Eigen::Vector2d& actual, const Eigen::Vector2d& expected) {
  EXPECT_LT((actual - expected).norm(), 1e-12) << actual.transpose();
}

TEST(ShapesTest, RectangleCornersAreRotatedAboutTheCentre) {
  const auto corners = RectangleCorners({1, 2}, {4, 2}, 0.5 * std::numbers::pi);
  // Turned by 90 deg: the 4 m side now runs along y.
  ExpectNear(corners[0], {2, 0});
  ExpectNear(corners[1], {2, 4});
  ExpectNear(corners[2], {0, 4});
  ExpectNear(corners[3], {0, 0});
  // Counter-clockwise: positive signed area (shoelace formula) equal to 4 x 2.
  double twice_area = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % 4];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(0.5 * twice_area, 8.0, 1e-12);
}

TEST(ShapesTest, ArrowHeadPointsAlongItsDirection) {
  const auto head = ArrowHead({10, 0}, {1, 0}, 4, 2);
  ExpectNear(head[0], {10, 0});
  ExpectNear(head[1], {6, 1});
  ExpectNear(head[2], {6, -1});
}

}  // namespace
}  // namespace topay::viz
