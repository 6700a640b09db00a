// goal_t <-> PlanGoal (procs/msgs/convert_goal.h): X_WE and the optional hint round trip; bad
// quaternions and hints are refused.

#include "procs/msgs/convert_goal.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::msgs {
namespace {

PlanGoal Sample(bool with_hint) {
  PlanGoal goal;
  goal.utime = 1'700'000'000'500'000;
  goal.goal_id = 42;
  goal.X_WE = Eigen::Translation3d(4.0, -2.0, 0.8) *
              Eigen::AngleAxisd(1.2, Eigen::Vector3d(0.3, -0.5, 0.8).normalized());
  if (with_hint) {
    WholeBodyState hint;
    hint.x_m = 3.1;
    hint.y_m = -2.2;
    hint.yaw_rad = 0.7;
    hint.q_rad = (Eigen::VectorXd(7) << 0.0, 0.5, 0.0, 1.2, 0.0, 0.6, -0.1).finished();
    goal.hint = hint;
  }
  return goal;
}

TEST(ConvertGoal, RoundTripsPoseAndHint) {
  for (const bool with_hint : {false, true}) {
    const PlanGoal in = Sample(with_hint);
    std::string error;
    const auto out = FromMessage(ToMessage(in), &error);
    ASSERT_TRUE(out) << error;
    EXPECT_EQ(out->utime, in.utime);
    EXPECT_EQ(out->goal_id, in.goal_id);
    EXPECT_TRUE(out->X_WE.isApprox(in.X_WE, 1e-12));
    ASSERT_EQ(out->hint.has_value(), with_hint);
    if (with_hint) {
      EXPECT_EQ(out->hint->x_m, in.hint->x_m);
      EXPECT_EQ(out->hint->yaw_rad, in.hint->yaw_rad);
      EXPECT_EQ(out->hint->q_rad, in.hint->q_rad);
    }
  }
}

TEST(ConvertGoal, QuaternionIsWxyz) {
  PlanGoal in = Sample(false);
  in.X_WE.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const goal_t msg = ToMessage(in);
  EXPECT_NEAR(msg.quat_WE[0], std::sqrt(0.5), 1e-12);  // w
  EXPECT_NEAR(msg.quat_WE[3], std::sqrt(0.5), 1e-12);  // z
}

TEST(ConvertGoal, RejectsBadQuaternionsPositionsAndHints) {
  std::string error;
  goal_t msg = ToMessage(Sample(true));
  msg.quat_WE[0] = 2.0;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("quat_WE"), std::string::npos);
  msg = ToMessage(Sample(true));
  msg.p_WE[1] = NAN;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("p_WE"), std::string::npos);
  msg = ToMessage(Sample(true));
  msg.hint.num_joints = 6;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("hint"), std::string::npos);
}

}  // namespace
}  // namespace topay::msgs
