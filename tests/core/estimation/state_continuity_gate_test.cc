#include "core/estimation/state_continuity_gate.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace topay {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;  // us
constexpr std::int64_t kCycleUs = 10'000;            // 100 Hz

WholeBodyState State(double x, double y, double yaw, double q1 = 0.0) {
  WholeBodyState s;
  s.x_m = x;
  s.y_m = y;
  s.yaw_rad = yaw;
  s.q_rad = Eigen::VectorXd::Constant(7, 0.1);
  s.q_rad(0) = q1;
  return s;
}

// A robot driving at 0.5 m/s along x, turning 0.3 rad/s, joint 1 at 1 rad/s: state i.
WholeBodyState Driving(int i) { return State(0.005 * i, 0.0, 0.003 * i, 0.01 * i); }

TEST(StateContinuityGateTest, TakesAStreamWithinTheLimits) {
  StateContinuityGate gate;
  for (int i = 0; i < 300; ++i) ASSERT_EQ(gate.Check(kT0 + i * kCycleUs, Driving(i)), ContinuityVerdict::kTaken) << i;
  EXPECT_EQ(gate.summary().taken, 300);
  EXPECT_EQ(gate.summary().refused(), 0);
  EXPECT_TRUE(gate.last_reason().empty());
}

TEST(StateContinuityGateTest, RefusesARepeatedOrOlderStamp) {
  StateContinuityGate gate;
  ASSERT_EQ(gate.Check(kT0, Driving(0)), ContinuityVerdict::kTaken);
  ASSERT_EQ(gate.Check(kT0 + kCycleUs, Driving(1)), ContinuityVerdict::kTaken);
  // A corrupted copy of the last message: same stamp, a changed number.
  EXPECT_EQ(gate.Check(kT0 + kCycleUs, State(0.3, 0.0, 0.0)), ContinuityVerdict::kRefusedStale);
  EXPECT_NE(gate.last_reason().find("before the last state"), std::string::npos) << gate.last_reason();
  EXPECT_EQ(gate.Check(kT0, Driving(0)), ContinuityVerdict::kRefusedStale);  // reordered
  EXPECT_EQ(gate.Check(kT0 + 2 * kCycleUs, Driving(2)), ContinuityVerdict::kTaken);
  EXPECT_EQ(gate.summary().refused_stale, 2);
}

TEST(StateContinuityGateTest, RefusesJumpsOfBasePositionYawAndJoints) {
  StateContinuityGate gate;
  ASSERT_EQ(gate.Check(kT0, Driving(0)), ContinuityVerdict::kTaken);
  const std::int64_t t = kT0 + kCycleUs;  // 10 ms later: at most 2 m/s x 0.01 s + 0.1 m = 0.12 m
  EXPECT_EQ(gate.Check(t, State(0.13, 0.0, 0.0)), ContinuityVerdict::kRefusedJump);
  EXPECT_NE(gate.last_reason().find("moved 0.130 m (at most 0.120)"), std::string::npos) << gate.last_reason();
  EXPECT_EQ(gate.Check(t, State(0.0, 0.0, 0.15)), ContinuityVerdict::kRefusedJump);  // > 0.14 rad
  EXPECT_EQ(gate.Check(t, State(0.0, 0.0, 0.0, 0.15)), ContinuityVerdict::kRefusedJump);  // joint > 0.14 rad
  EXPECT_EQ(gate.Check(t, State(0.11, 0.0, 0.13, 0.13)), ContinuityVerdict::kTaken);  // each just inside
  EXPECT_EQ(gate.summary().refused_jump, 3);
}

TEST(StateContinuityGateTest, YawIsComparedAcrossTheWrap) {
  StateContinuityGate gate;
  ASSERT_EQ(gate.Check(kT0, State(0, 0, 3.13)), ContinuityVerdict::kTaken);
  EXPECT_EQ(gate.Check(kT0 + kCycleUs, State(0, 0, -3.13)), ContinuityVerdict::kTaken);  // 0.023 rad apart
}

TEST(StateContinuityGateTest, TheReachGrowsWithTheTimeSinceTheLastState) {
  StateContinuityGate gate;
  ASSERT_EQ(gate.Check(kT0, State(0, 0, 0)), ContinuityVerdict::kTaken);
  // 0.5 s without a state (the estimator held): up to 2 m/s x 0.5 s + 0.1 m = 1.1 m.
  EXPECT_EQ(gate.Check(kT0 + 500'000, State(1.05, 0, 0)), ContinuityVerdict::kTaken);
}

TEST(StateContinuityGateTest, AStampFarAheadIsRefusedAndDoesNotBlockTheStream) {
  StateContinuityGate gate;
  ASSERT_EQ(gate.Check(kT0, Driving(0)), ContinuityVerdict::kTaken);
  // A bit flipped high in the stamp: the same state 2^40 us later.
  EXPECT_EQ(gate.Check(kT0 + (std::int64_t{1} << 40), Driving(0)), ContinuityVerdict::kRefusedGap);
  for (int i = 1; i < 50; ++i) ASSERT_EQ(gate.Check(kT0 + i * kCycleUs, Driving(i)), ContinuityVerdict::kTaken) << i;
}

// Stamps at the ends of the range (hostile messages; the director_inputs fuzz target found the
// overflow of their difference).
TEST(StateContinuityGateTest, ExtremeStampsAreJudgedWithoutOverflow) {
  StateContinuityGate gate;
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  ASSERT_EQ(gate.Check(kMin, Driving(0)), ContinuityVerdict::kTaken);
  EXPECT_EQ(gate.Check(kMax, Driving(0)), ContinuityVerdict::kRefusedGap);
  EXPECT_EQ(gate.Check(kMin, Driving(0)), ContinuityVerdict::kRefusedStale);
  StateContinuityGate high;
  ASSERT_EQ(high.Check(kMax, Driving(0)), ContinuityVerdict::kTaken);
  EXPECT_EQ(high.Check(kMin, Driving(0)), ContinuityVerdict::kRefusedStale);
  EXPECT_NE(high.last_reason().find("ms before the last state"), std::string::npos) << high.last_reason();
}

TEST(StateContinuityGateTest, IsolatedCorruptedStatesAmongGoodOnesNeverReanchor) {
  StateContinuityGate gate;
  int refused = 0;
  for (int i = 0; i < 500; ++i) {
    ASSERT_TRUE(Taken(gate.Check(kT0 + i * kCycleUs, Driving(i)))) << i;
    // After every good state, a corrupted copy of it: a far x, or the same stamp.
    const ContinuityVerdict v = gate.Check(kT0 + i * kCycleUs + (i % 2 == 0 ? 1 : 0), State(40.0 + i, 0, 0));
    ASSERT_FALSE(Taken(v)) << i;
    ++refused;
  }
  EXPECT_EQ(gate.summary().reanchored, 0);
  EXPECT_EQ(gate.summary().refused(), refused);
}

TEST(StateContinuityGateTest, AConsistentNewStreamIsTakenAfterReanchorAfterStates) {
  StateContinuityGateOptions options;
  options.reanchor_after = 5;
  StateContinuityGate gate(options);
  for (int i = 0; i < 10; ++i) ASSERT_EQ(gate.Check(kT0 + i * kCycleUs, Driving(i)), ContinuityVerdict::kTaken);
  // The estimator re-initialised 2 m away: refused four times, the fifth re-anchors.
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(gate.Check(kT0 + (10 + k) * kCycleUs, State(2.0 + 0.005 * k, 0, 0)), ContinuityVerdict::kRefusedJump);
  }
  EXPECT_EQ(gate.Check(kT0 + 14 * kCycleUs, State(2.02, 0, 0)), ContinuityVerdict::kReanchored);
  EXPECT_NE(gate.last_reason().find("re-anchored after 5"), std::string::npos) << gate.last_reason();
  EXPECT_EQ(gate.Check(kT0 + 15 * kCycleUs, State(2.025, 0, 0)), ContinuityVerdict::kTaken);
  EXPECT_EQ(gate.summary().reanchored, 1);
}

TEST(StateContinuityGateTest, StrayStatesAmongANewStreamDoNotDelayItsReanchor) {
  StateContinuityGate gate;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(Taken(gate.Check(kT0 + i * kCycleUs, Driving(i))));
  int taken_at = -1;
  for (int k = 0; k < 10 && taken_at < 0; ++k) {
    const std::int64_t t = kT0 + (10 + k) * kCycleUs;
    if (Taken(gate.Check(t, State(3.0 + 0.005 * k, 0, 0)))) taken_at = k;
    // Three strays after each (a copy with a changed number, a far one, an old stamp).
    EXPECT_FALSE(Taken(gate.Check(t, State(9.0, 0, 0))));
    EXPECT_FALSE(Taken(gate.Check(t + 1, State(-7.0 - k, 0, 0))));
    EXPECT_FALSE(Taken(gate.Check(kT0, Driving(0))));
  }
  EXPECT_EQ(taken_at, 4);
  EXPECT_EQ(gate.summary().reanchored, 1);
}

TEST(StateContinuityGateTest, AReplayStartingOverIsTakenAfterReanchorAfterStates) {
  StateContinuityGate gate;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(Taken(gate.Check(kT0 + i * kCycleUs, Driving(i))));
  int taken_at = -1;
  for (int i = 0; i < 10 && taken_at < 0; ++i) {
    if (Taken(gate.Check(kT0 - 60'000'000 + i * kCycleUs, Driving(i)))) taken_at = i;
  }
  EXPECT_EQ(taken_at, 4);  // the fifth state of the stream that went back a minute
}

TEST(StateContinuityGateTest, RefusesNotFiniteAndAnotherJointCount) {
  StateContinuityGate gate;
  WholeBodyState nan = Driving(0);
  nan.q_rad(3) = std::nan("");
  EXPECT_EQ(gate.Check(kT0, nan), ContinuityVerdict::kRefusedNotFinite);
  ASSERT_EQ(gate.Check(kT0, Driving(0)), ContinuityVerdict::kTaken);
  WholeBodyState six = Driving(1);
  six.q_rad.conservativeResize(6);
  EXPECT_EQ(gate.Check(kT0 + kCycleUs, six), ContinuityVerdict::kRefusedJoints);
  EXPECT_EQ(gate.summary().refused_not_finite, 1);
  EXPECT_EQ(gate.summary().refused_joints, 1);
}

TEST(StateContinuityGateTest, BadOptionsAreRefusedByName) {
  StateContinuityGateOptions options;
  options.reanchor_after = 0;
  try {
    StateContinuityGate gate(options);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("reanchor_after"), std::string::npos) << e.what();
  }
  options = {};
  options.max_speed_mps = std::nan("");
  EXPECT_THROW(StateContinuityGate{options}, std::invalid_argument);
}

TEST(StateContinuityGateTest, SummaryReadsAsWords) {
  StateContinuityGate gate;
  gate.Check(kT0, Driving(0));
  gate.Check(kT0, Driving(0));
  EXPECT_EQ(FormatStateContinuitySummary(gate.summary()),
            "1 taken, 0 re-anchored; refused: 1 stale, 0 gap, 0 jump, 0 joints, 0 not finite");
}

}  // namespace
}  // namespace topay
