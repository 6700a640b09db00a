// The tracker's safe behaviour: which situations stop, and the stop itself (within the
// acceleration limits, reaching zero).

#include "core/control/safe_stop.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::TopayLimits;

TrackerSituation Tracking() {
  TrackerSituation situation;
  situation.has_reference = true;
  situation.t_along_s = 1.0;
  situation.reference_duration_s = 5.0;
  situation.state_age_s = 0.01;
  return situation;
}

TEST(SafeStopTest, ModeFollowsTheSituation) {
  const NmpcOptions options;
  EXPECT_EQ(ChooseTrackerMode(Tracking(), options), TrackerMode::kTrack);
  TrackerSituation none = Tracking();
  none.has_reference = false;
  EXPECT_EQ(ChooseTrackerMode(none, options), TrackerMode::kStopNoReference);
  TrackerSituation ended = Tracking();
  ended.t_along_s = 5.0 + options.end_settle_s + 0.01;
  EXPECT_EQ(ChooseTrackerMode(ended, options), TrackerMode::kStopReferenceEnded);
  ended.t_along_s = 5.0 + 0.5 * options.end_settle_s;  // settling on the end point
  EXPECT_EQ(ChooseTrackerMode(ended, options), TrackerMode::kTrack);
  TrackerSituation stale = Tracking();
  stale.state_age_s = 0.101;
  EXPECT_EQ(ChooseTrackerMode(stale, options), TrackerMode::kStopStaleState);
  stale.state_age_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ChooseTrackerMode(stale, options), TrackerMode::kStopStaleState);
  stale.state_age_s = 0.099;
  EXPECT_EQ(ChooseTrackerMode(stale, options), TrackerMode::kTrack);
  // A stale state wins over everything.
  none.state_age_s = 1.0;
  EXPECT_EQ(ChooseTrackerMode(none, options), TrackerMode::kStopStaleState);
  EXPECT_STREQ(TrackerModeName(TrackerMode::kStopStaleState), "stop (stale state)");
}

TEST(SafeStopTest, StopDeceleratesWithinLimitsToZero) {
  const TrackerLimits limits = TopayLimits();
  ControlCommand last = ControlCommand::Zero(kJoints);
  last.v_mps = 0.7;
  last.omega_radps = -0.27;  // on the diamond: 0.7 + 0.3 = 1
  for (int j = 0; j < kJoints; ++j) last.qd_radps(j) = (j % 2 ? -1.0 : 1.0) * 0.3 * (j + 1);
  const double dt = 0.02;
  const double stop_s = StopDurationS(last, limits);
  EXPECT_NEAR(stop_s, 0.7 / 0.8, 1e-12);
  const int steps = static_cast<int>(std::ceil(stop_s / dt)) + 5;
  InputSequence stop = InputSequence::Zero(steps, kJoints);
  StopSequence(last, dt, limits, &stop);
  EXPECT_LE(WorstInputLimitRatio(last, dt, dt, limits, stop), 1.0 + 1e-12);
  // Zero by the stop duration (rounded up to a step), and monotone towards it.
  const int zero_from = static_cast<int>(std::ceil(stop_s / dt - 1e-9)) - 1;
  EXPECT_EQ(stop.u_base.col(zero_from).norm(), 0.0);
  EXPECT_EQ(stop.qd_radps.col(zero_from).norm(), 0.0);
  EXPECT_GT(std::abs(stop.u_base(0, zero_from - 1)), 0.0);  // not earlier than the limit allows
  for (int k = 1; k < steps; ++k) {
    EXPECT_LE(std::abs(stop.u_base(0, k)), std::abs(stop.u_base(0, k - 1)));
    EXPECT_LE(std::abs(stop.u_base(1, k)), std::abs(stop.u_base(1, k - 1)));
  }
  // StopStep is the sequence's first step.
  ControlCommand next = ControlCommand::Zero(kJoints);
  StopStep(last, dt, limits, &next);
  EXPECT_DOUBLE_EQ(next.v_mps, stop.u_base(0, 0));
  EXPECT_DOUBLE_EQ(next.omega_radps, stop.u_base(1, 0));
  EXPECT_TRUE(next.qd_radps.isApprox(stop.qd_radps.col(0)));
}

TEST(SafeStopTest, StopFromRestStaysAtRest) {
  const TrackerLimits limits = TopayLimits();
  InputSequence stop = InputSequence::Zero(5, kJoints);
  stop.u_base.setConstant(1.0);
  StopSequence(ControlCommand::Zero(kJoints), 0.02, limits, &stop);
  EXPECT_EQ(stop.u_base.norm(), 0.0);
  EXPECT_EQ(StopDurationS(ControlCommand::Zero(kJoints), limits), 0.0);
}

}  // namespace
}  // namespace topay
