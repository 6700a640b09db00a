// RobotStateIntake (procs/msgs/robot_state_intake.h): ROBOT_STATE as the consumers take it.
// Bit-flipped copies of real messages (what topay-faults' hostile-payloads sends) never move
// the state; a stream that really jumped is taken after the gate's re-anchor count.

#include "procs/msgs/robot_state_intake.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <cstring>
#include <random>
#include <vector>

#include "topay_msgs/checked_decode.h"

namespace topay::msgs {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;

robot_state_t Message(int i, double x0 = 0.0) {
  RobotStateEstimate e;
  e.utime = kT0 + i * 10'000;
  e.state.x_m = x0 + 0.005 * i;  // 0.5 m/s at 100 Hz
  e.state.y_m = 1.0;
  e.state.yaw_rad = 0.2;
  e.state.q_rad = Eigen::VectorXd::Constant(7, 0.3);
  e.qdot_radps = Eigen::VectorXd::Zero(7);
  e.v_mps = 0.5;
  return ToMessage(e);
}

TEST(RobotStateIntake, TakesGoodMessagesAndNamesWhatIsWrongWithBadOnes) {
  RobotStateIntake intake(7);
  std::string error;
  ASSERT_TRUE(intake.Take(Message(0), &error)) << error;
  robot_state_t nan = Message(1);
  nan.pose.x_m = std::nan("");
  EXPECT_FALSE(intake.Take(nan, &error));
  EXPECT_EQ(error, "robot_state_t.pose: not finite");
  robot_state_t six = Message(1);
  six.joints.num_joints = 6;
  six.joints.names.pop_back();
  six.joints.position_rad.pop_back();
  six.joints.velocity_radps.pop_back();
  six.joints.effort_Nm.pop_back();
  EXPECT_FALSE(intake.Take(six, &error));
  EXPECT_EQ(error, "6 joints, the robot has 7");
  EXPECT_FALSE(intake.Take(Message(0), &error));  // a repeat
  EXPECT_NE(error.find("stamped at or before the last state"), std::string::npos) << error;
  EXPECT_TRUE(intake.Take(Message(1), &error)) << error;
  EXPECT_EQ(intake.malformed(), 2);
  EXPECT_EQ(intake.refused(), 3);
  EXPECT_EQ(intake.Report(), "2 malformed; 2 taken, 0 re-anchored; refused: 1 stale, 0 gap, 0 jump, 0 joints, 0 not finite");
}

// Random single-bit flips of each message, sent after it (what topay-faults' hostile-payloads
// does): a copy that still decodes is taken only as nearly the same state (a flip in the stamp's
// low bits, in a low mantissa bit, in a field the state does not carry); a stamp pushed ahead may
// refuse the good
// messages before it, but never more than the gate's re-anchor count in a row.
TEST(RobotStateIntake, BitFlippedCopiesNeverMoveTheState) {
  RobotStateIntake intake(7);
  std::string error;
  std::mt19937 random(7);
  int decoded = 0, good_refused_in_a_row = 0, most_good_refused_in_a_row = 0;
  for (int i = 0; i < 300; ++i) {
    const robot_state_t good = Message(i);
    const std::optional<RobotStateEstimate> expected = FromMessage(good, &error);
    if (intake.Take(good, &error)) {
      good_refused_in_a_row = 0;
    } else {
      most_good_refused_in_a_row = std::max(most_good_refused_in_a_row, ++good_refused_in_a_row);
    }
    std::vector<std::uint8_t> bytes(good.getEncodedSize());
    good.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    for (int flip = 0; flip < 4; ++flip) {
      std::vector<std::uint8_t> copy = bytes;
      const std::size_t bit = std::uniform_int_distribution<std::size_t>(64, copy.size() * 8 - 1)(random);
      copy[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
      std::string decode_error;
      const auto hostile = CheckedDecode<robot_state_t>(copy.data(), copy.size(), &decode_error);
      if (!hostile) continue;
      ++decoded;
      const std::optional<RobotStateEstimate> took = intake.Take(*hostile, &error);
      if (!took) continue;
      EXPECT_GE(took->utime, good.utime) << i;
      EXPECT_LT(took->utime - good.utime, 1'000'000) << i;
      EXPECT_NEAR(took->state.x_m, expected->state.x_m, 0.12) << i;
      EXPECT_NEAR(took->state.y_m, expected->state.y_m, 0.12) << i;
      EXPECT_NEAR(took->state.yaw_rad, expected->state.yaw_rad, 0.14) << i;
      EXPECT_LE((took->state.q_rad - expected->state.q_rad).cwiseAbs().maxCoeff(), 0.14) << i;
    }
  }
  EXPECT_GT(decoded, 600);  // most flips land in numbers, which decode
  EXPECT_LT(most_good_refused_in_a_row, 5);
}

TEST(RobotStateIntake, AJumpedStreamIsTakenAfterTheReanchorCount) {
  RobotStateIntake intake(7);
  std::string error;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(intake.Take(Message(i), &error)) << error;
  int first = -1;
  for (int i = 10; i < 20 && first < 0; ++i) {
    if (intake.Take(Message(i, 3.0), &error)) first = i;
  }
  EXPECT_EQ(first, 14);
  EXPECT_EQ(intake.last_verdict(), ContinuityVerdict::kReanchored);
  EXPECT_NE(intake.gate_reason().find("re-anchored"), std::string::npos);
}

TEST(RobotStateIntake, LogsTheFirstRefusalsThenPowersOfTen) {
  RobotStateIntake intake(7);
  std::string error;
  ASSERT_TRUE(intake.Take(Message(0), &error));
  std::vector<std::int64_t> logged;
  for (int k = 0; k < 1000; ++k) {
    intake.Take(Message(0), &error);
    if (intake.LogRefusal()) logged.push_back(intake.refused());
  }
  EXPECT_EQ(logged, (std::vector<std::int64_t>{1, 2, 3, 10, 100, 1000}));
}

}  // namespace
}  // namespace topay::msgs
