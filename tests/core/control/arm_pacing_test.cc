// The arm's reference time paced by the base's progress (core/control/arm_pacing.h): on the
// clock while the base keeps up, waiting for a base that lags, never ahead of the clock, within
// its window.

#include "core/control/arm_pacing.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::ReferenceInputs;
using testing::StateAt;
using testing::SyntheticReference;

constexpr double kDurationS = 4.0;

// Straight along x at 1 m/s from rest for the whole trajectory, the arm moving at 0.5 rad/s.
SyntheticReference Straight() {
  return SyntheticReference(
      [](double) {
        ReferenceInputs in;
        in.v_mps = 1.0;
        in.qd_radps.setConstant(0.5);
        return in;
      },
      kDurationS, StateAt(0, 0, 0, 0));
}

// The base turns in place at 1 rad/s (x, y fixed) for the whole trajectory.
SyntheticReference TurnInPlace() {
  return SyntheticReference(
      [](double) {
        ReferenceInputs in;
        in.omega_radps = 1.0;
        return in;
      },
      kDurationS, StateAt(0, 0, 0, 0));
}

// The base stands while the arm moves.
SyntheticReference ArmOnly() {
  return SyntheticReference(
      [](double) {
        ReferenceInputs in;
        in.qd_radps.setConstant(0.5);
        return in;
      },
      kDurationS, StateAt(0, 0, 0, 0));
}

double Paced(const SyntheticReference& reference, double clock_t_s, const WholeBodyState& base,
             const ArmPacingOptions& options = {}) {
  TrajectorySample scratch = MakeTrajectorySample(testing::kJoints);
  return ArmPacedTime(reference.Sampler(), reference.duration_s(), clock_t_s, base, options,
                      &scratch);
}

TEST(ArmPacingTest, ABaseOnItsReferenceKeepsTheArmOnTheClock) {
  const SyntheticReference reference = Straight();
  for (double t : {0.0, 0.37, 1.0, 2.5}) {
    EXPECT_EQ(Paced(reference, t, reference.At(t).state), t) << t;
  }
}

TEST(ArmPacingTest, TheArmWaitsForABaseThatLagsBeyondTheSlack) {
  const SyntheticReference reference = Straight();
  // The base 0.3 m behind at t = 2 s (where the reference was at 1.7 s): the arm may go as far
  // as the base's pose within the slack (0.05 m) of it, 1.75 s, on the search's 0.02 s grid.
  const double paced = Paced(reference, 2.0, reference.At(1.7).state);
  EXPECT_LE(paced, 1.75 + 1e-9);
  EXPECT_GE(paced, 1.73);
  // Within the slack: on the clock.
  EXPECT_EQ(Paced(reference, 2.0, reference.At(1.97).state), 2.0);
  // A larger slack lets it go further.
  ArmPacingOptions loose;
  loose.slack_m = 0.2;
  EXPECT_NEAR(Paced(reference, 2.0, reference.At(1.7).state, loose), 1.9, 1e-9);
}

TEST(ArmPacingTest, NeverAheadOfTheClock) {
  const SyntheticReference reference = Straight();
  // The base ahead of its reference (0.4 m): the arm stays on the clock.
  EXPECT_EQ(Paced(reference, 1.0, reference.At(1.4).state), 1.0);
  // Beside it (0.2 m to the left at the reference's own position): the nearest pose is now's.
  WholeBodyState beside = reference.At(1.0).state;
  beside.y_m += 0.2;
  EXPECT_EQ(Paced(reference, 1.0, beside), 1.0);
}

TEST(ArmPacingTest, TheWindowBoundsTheWait) {
  const SyntheticReference reference = Straight();
  // The base 2 m behind at t = 3 s: the arm waits at most the window (1 s) behind the clock
  // (the window's nearest pose is its first, 2 s; the slack takes it to 2.05 s).
  const double paced = Paced(reference, 3.0, reference.At(1.0).state);
  EXPECT_GE(paced, 2.0);
  EXPECT_LE(paced, 2.05 + 1e-9);
  // Off: on the clock whatever the base does.
  ArmPacingOptions off;
  off.window_s = 0.0;
  EXPECT_EQ(Paced(reference, 3.0, reference.At(1.0).state, off), 3.0);
}

TEST(ArmPacingTest, YawCountsWhenTheBaseTurnsInPlace) {
  const SyntheticReference reference = TurnInPlace();
  // The base has turned 0.5 rad of the reference's 1.5 (0.3 m per rad: 0.3 m behind).
  const double paced = Paced(reference, 1.5, reference.At(0.5).state);
  // Within the slack of the nearest: yaw 0.5 + 0.05 / 0.3 rad.
  EXPECT_LE(paced, 0.5 + 0.05 / 0.3 + 1e-9);
  EXPECT_GE(paced, 0.5 + 0.05 / 0.3 - 0.02);
}

TEST(ArmPacingTest, AnArmMovingOverAStandingBaseIsNotHeldBack) {
  const SyntheticReference reference = ArmOnly();
  // Every base pose of the window is the same: the latest is taken.
  EXPECT_EQ(Paced(reference, 2.0, reference.At(2.0).state), 2.0);
  WholeBodyState off_by_a_bit = reference.At(2.0).state;
  off_by_a_bit.x_m += 0.1;
  EXPECT_EQ(Paced(reference, 2.0, off_by_a_bit), 2.0);
}

TEST(ArmPacingTest, PastTheEndTheArmReachesItsEndOnlyWithTheBase) {
  const SyntheticReference reference = Straight();
  // Settling after the end (clock 4.3 s of 4 s), the base at the end: the clock (the end held).
  EXPECT_EQ(Paced(reference, 4.3, reference.At(kDurationS).state), 4.3);
  // The base 0.2 m short of the end: the arm waits before the end.
  const double paced = Paced(reference, 4.3, reference.At(3.8).state);
  EXPECT_LE(paced, 3.85 + 1e-9);
  EXPECT_GE(paced, 3.83);
}

TEST(ArmPacingTest, BadOptionsAreRejectedByName) {
  const auto message_of = [](const ArmPacingOptions& options) {
    try {
      options.Check();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message_of(ArmPacingOptions{}), "accepted");
  ArmPacingOptions options;
  options.window_s = -1.0;
  EXPECT_NE(message_of(options).find("window_s"), std::string::npos);
  options = {};
  options.resolution_s = 0.0;
  EXPECT_NE(message_of(options).find("resolution_s"), std::string::npos);
  options = {};
  options.window_s = 10.0;  // 500 samples at 0.02 s
  EXPECT_NE(message_of(options).find("window_s"), std::string::npos);
  options = {};
  options.slack_m = std::nan("");
  EXPECT_NE(message_of(options).find("slack_m"), std::string::npos);
}

}  // namespace
}  // namespace topay
