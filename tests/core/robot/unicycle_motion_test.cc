#include "core/robot/unicycle_motion.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace topay {
namespace {

WholeBodyState BaseAt(double x, double y, double yaw) {
  WholeBodyState s;
  s.x_m = x;
  s.y_m = y;
  s.yaw_rad = yaw;
  s.q_rad = Eigen::VectorXd::Constant(7, 0.3);
  return s;
}

TEST(UnicycleMotionTest, StraightLineAlongTheHeading) {
  WholeBodyState s = BaseAt(1.0, 2.0, 0.5);
  AdvanceUnicycle(0.8, 0.0, 2.5, &s);
  EXPECT_NEAR(s.x_m, 1.0 + 2.0 * std::cos(0.5), 1e-12);
  EXPECT_NEAR(s.y_m, 2.0 + 2.0 * std::sin(0.5), 1e-12);
  EXPECT_EQ(s.yaw_rad, 0.5);
  EXPECT_EQ(s.q_rad, Eigen::VectorXd::Constant(7, 0.3));  // joints untouched
}

TEST(UnicycleMotionTest, ArcsOfOneStepOrManyAgreeWithTheCircle) {
  // A full circle of radius v / omega in 1000 steps returns to the start; a quarter circle
  // ends at the analytic point.
  const double v = 0.5, w = 0.25;  // radius 2 m
  WholeBodyState s = BaseAt(0.0, 0.0, 0.0);
  const double period_s = 2.0 * std::numbers::pi / w;
  for (int k = 0; k < 1000; ++k) AdvanceUnicycle(v, w, period_s / 1000, &s);
  EXPECT_NEAR(s.x_m, 0.0, 1e-9);
  EXPECT_NEAR(s.y_m, 0.0, 1e-9);
  EXPECT_NEAR(std::remainder(s.yaw_rad, 2.0 * std::numbers::pi), 0.0, 1e-9);
  WholeBodyState quarter = BaseAt(0.0, 0.0, 0.0);
  AdvanceUnicycle(v, w, period_s / 4, &quarter);
  EXPECT_NEAR(quarter.x_m, 2.0, 1e-12);
  EXPECT_NEAR(quarter.y_m, 2.0, 1e-12);
  EXPECT_NEAR(quarter.yaw_rad, std::numbers::pi / 2, 1e-12);
}

TEST(UnicycleMotionTest, TurningInPlaceWrapsTheYaw) {
  WholeBodyState s = BaseAt(3.0, -1.0, 3.0);
  AdvanceUnicycle(0.0, 1.0, 0.5, &s);
  EXPECT_EQ(s.x_m, 3.0);
  EXPECT_EQ(s.y_m, -1.0);
  EXPECT_NEAR(s.yaw_rad, 3.5 - 2.0 * std::numbers::pi, 1e-12);
}

}  // namespace
}  // namespace topay
