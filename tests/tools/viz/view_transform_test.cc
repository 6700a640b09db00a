#include "tools/viz/view_transform.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

const Eigen::AlignedBox2d kRoom(Eigen::Vector2d(-10, -5), Eigen::Vector2d(10, 5));

TEST(ViewTransformTest, CornersMapToTheBlockWithYUp) {
  const ViewTransform view(kRoom, 40.0, Eigen::Vector2d(7, 3));
  EXPECT_EQ(view.width_px(), 800);
  EXPECT_EQ(view.height_px(), 400);
  EXPECT_TRUE(view.ToPixel({-10, 5}).isApprox(Eigen::Vector2d(7, 3)));     // Top-left.
  EXPECT_TRUE(view.ToPixel({10, -5}).isApprox(Eigen::Vector2d(807, 403))); // Bottom-right.
  // Moving +y in the world moves up (towards smaller pixel rows).
  EXPECT_LT(view.ToPixel({0, 1}).y(), view.ToPixel({0, 0}).y());
  EXPECT_DOUBLE_EQ(view.ToPixels(0.5), 20.0);
}

TEST(ViewTransformTest, ToWorldInvertsToPixel) {
  const ViewTransform view(kRoom, 33.3, Eigen::Vector2d(12.5, -4));
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(1.25, -3.5), Eigen::Vector2d(-9.9, 4.9)}) {
    EXPECT_TRUE(view.ToWorld(view.ToPixel(p)).isApprox(p, 1e-12));
  }
}

TEST(ViewTransformTest, DirectionsFlipY) {
  const ViewTransform view(kRoom, 10.0);
  EXPECT_TRUE(view.DirectionToPixel(0.0).isApprox(Eigen::Vector2d(1, 0)));
  EXPECT_TRUE(view.DirectionToPixel(0.5 * std::numbers::pi).isApprox(Eigen::Vector2d(0, -1)));
}

TEST(ViewTransformTest, RejectsBadInput) {
  EXPECT_THROW(ViewTransform(kRoom, 0.0), std::invalid_argument);
  EXPECT_THROW(ViewTransform(kRoom, std::nan("")), std::invalid_argument);
  EXPECT_THROW(ViewTransform(Eigen::AlignedBox2d(), 40.0), std::invalid_argument);
  const Eigen::AlignedBox2d flat(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0));
  EXPECT_THROW(ViewTransform(flat, 40.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
