// The tracker's cycle: tracking with latency compensation, the safe stops (stale state, no
// reference, ended reference) and a new trajectory id without a jump.

#include "core/control/nmpc_tracker.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/control/command_projection.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::ReferenceInputs;
using testing::StateAt;
using testing::SyntheticReference;
using testing::TopayLimits;
using testing::Trapezoid;

NmpcOptions Untimed() {
  NmpcOptions options;
  options.time_budget_s = 10.0;
  return options;
}

SyntheticReference Cruise(double v, double qd) {
  return SyntheticReference(
      [v, qd](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 20.0, v, 0.6);
        in.qd_radps.setConstant(Trapezoid(t, 0.0, 20.0, qd, 3.0));
        return in;
      },
      20.0, StateAt(0, 0, 0, 0));
}

// A simulated loop around the tracker: ideal plant with latency (CommandHistory), the state
// delivered with a given age.
class Loop {
 public:
  explicit Loop(NmpcTracker* tracker) : tracker_(tracker), history_(64, kJoints) {
    state_ = StateAt(0, 0, 0, 0);
  }
  const TrackerOutput& Step(const TrackerReference* reference, double state_age_s) {
    TrackerInput input;
    input.now_s = now_s_;
    input.state = &state_;
    input.state_time_s = now_s_ - state_age_s;
    input.reference = reference;
    const TrackerOutput& out = tracker_->Step(input);
    history_.Push(now_s_, out.command);
    PredictState(history_, 0.02, now_s_, now_s_ + 0.02, &state_);
    now_s_ += 0.02;
    return out;
  }
  double now_s() const { return now_s_; }

 private:
  NmpcTracker* tracker_;
  CommandHistory history_;
  WholeBodyState state_;
  double now_s_ = 0.0;
};

void ExpectWithinRates(const ControlCommand& previous, const ControlCommand& next,
                       const TrackerLimits& limits) {
  const double dt = 0.02;
  EXPECT_LE(std::abs(next.v_mps - previous.v_mps), limits.base.a_max_mps2 * dt + 1e-12);
  EXPECT_LE(std::abs(next.omega_radps - previous.omega_radps),
            limits.base.beta_max_radps2 * dt + 1e-12);
  for (int j = 0; j < kJoints; ++j) {
    EXPECT_LE(std::abs(next.qd_radps(j) - previous.qd_radps(j)),
              limits.qdd_max_radps2(j) * dt + 1e-12);
  }
}

// Drives to speed on `reference`, then runs `steps` cycles with the given situation and
// checks a decelerating stop within the limits that reaches zero.
void ExpectStop(const std::function<const TrackerOutput&(Loop*)>& stopping_step,
                TrackerMode expected_mode) {
  const TrackerLimits limits = TopayLimits();
  NmpcTracker tracker(Untimed(), limits);
  Loop loop(&tracker);
  const SyntheticReference cruise = Cruise(0.8, 1.2);
  TrackerReference reference{1, 0.0, cruise.duration_s(), cruise.Sampler()};
  for (int i = 0; i < 150; ++i) ASSERT_EQ(loop.Step(&reference, 0.0).mode, TrackerMode::kTrack);
  ControlCommand previous = tracker.last_command();
  ASSERT_GT(previous.v_mps, 0.6);
  const double stop_s = StopDurationS(previous, limits);
  const int steps = static_cast<int>(std::ceil(stop_s / 0.02)) + 2;
  for (int i = 0; i < steps; ++i) {
    const TrackerOutput& out = stopping_step(&loop);
    EXPECT_EQ(out.mode, expected_mode);
    ExpectWithinRates(previous, out.command, limits);
    EXPECT_LE(std::abs(out.command.v_mps), std::abs(previous.v_mps));
    previous = out.command;
  }
  EXPECT_EQ(previous.v_mps, 0.0);
  EXPECT_EQ(previous.omega_radps, 0.0);
  EXPECT_EQ(previous.qd_radps.norm(), 0.0);
}

TEST(NmpcTrackerTest, TracksWithLatencyCompensation) {
  NmpcTracker tracker(Untimed(), TopayLimits());
  Loop loop(&tracker);
  const SyntheticReference cruise = Cruise(0.8, 1.0);
  TrackerReference reference{7, 0.0, cruise.duration_s(), cruise.Sampler()};
  TrackerOutput out;
  for (int i = 0; i < 250; ++i) out = loop.Step(&reference, 0.01);
  EXPECT_EQ(out.mode, TrackerMode::kTrack);
  EXPECT_EQ(out.trajectory_id, 7);
  EXPECT_NEAR(out.t_along_s, 249 * 0.02, 1e-9);
  EXPECT_LT(out.position_error_m, 0.03);
  EXPECT_LT(out.yaw_error_rad, 0.01);
  EXPECT_LT(out.joint_error_rad, 0.03);
  EXPECT_GT(out.solve_ms, 0.0);
}

TEST(NmpcTrackerTest, StaleStateStops) {
  ExpectStop([](Loop* loop) -> const TrackerOutput& {
    static const SyntheticReference cruise = Cruise(0.8, 1.2);
    static const TrackerReference reference{1, 0.0, cruise.duration_s(), cruise.Sampler()};
    return loop->Step(&reference, 0.15);  // the state is 150 ms old
  }, TrackerMode::kStopStaleState);
}

TEST(NmpcTrackerTest, NoReferenceStops) {
  ExpectStop([](Loop* loop) -> const TrackerOutput& { return loop->Step(nullptr, 0.0); },
             TrackerMode::kStopNoReference);
}

TEST(NmpcTrackerTest, EndedReferenceStops) {
  ExpectStop([](Loop* loop) -> const TrackerOutput& {
    static const SyntheticReference cruise = Cruise(0.8, 1.2);
    // A trajectory that ended a second ago (it was cruising: the cut-off end of a
    // trajectory the planner replaced and then lost).
    static TrackerReference ended{1, 0.0, 2.0, cruise.Sampler()};
    return loop->Step(&ended, 0.0);
  }, TrackerMode::kStopReferenceEnded);
}

TEST(NmpcTrackerTest, HaltForgetsTheLastCommand) {
  NmpcTracker tracker(Untimed(), TopayLimits());
  Loop loop(&tracker);
  const SyntheticReference cruise = Cruise(0.8, 1.2);
  TrackerReference reference{1, 0.0, cruise.duration_s(), cruise.Sampler()};
  for (int i = 0; i < 150; ++i) loop.Step(&reference, 0.0);
  ASSERT_GT(tracker.last_command().v_mps, 0.6);
  tracker.Halt();  // the drives stopped the robot
  EXPECT_EQ(tracker.last_command().v_mps, 0.0);
  EXPECT_EQ(tracker.last_command().qd_radps.norm(), 0.0);
  const TrackerOutput& out = loop.Step(nullptr, 0.0);  // no reference: nothing to ramp down
  EXPECT_EQ(out.mode, TrackerMode::kStopNoReference);
  EXPECT_EQ(out.command.v_mps, 0.0);
  EXPECT_EQ(out.command.omega_radps, 0.0);
  // Without Halt the same step ramps down from 0.8 m/s (the test above): the stop step is
  // what Halt changes, not the mode.
}

TEST(NmpcTrackerTest, NewTrajectoryIdSwitchesWithoutAJump) {
  const TrackerLimits limits = TopayLimits();
  NmpcTracker tracker(Untimed(), limits);
  Loop loop(&tracker);
  const SyntheticReference cruise = Cruise(0.9, 1.5);
  TrackerReference first{1, 0.0, cruise.duration_s(), cruise.Sampler()};
  for (int i = 0; i < 150; ++i) loop.Step(&first, 0.0);
  const ControlCommand before = tracker.last_command();
  // The new trajectory: standing still where the first one is now (a stop planned late).
  const SyntheticReference halt([](double) { return ReferenceInputs(); }, 2.0,
                                cruise.At(loop.now_s()).state);
  TrackerReference second{2, loop.now_s(), 2.0, halt.Sampler()};
  const int resets = tracker.solver().summary().num_warm_resets;
  const TrackerOutput& out = loop.Step(&second, 0.0);
  EXPECT_EQ(out.trajectory_id, 2);
  EXPECT_EQ(tracker.solver().summary().num_warm_resets, resets + 1);
  ExpectWithinRates(before, out.command, limits);
  EXPECT_LT(out.command.v_mps, before.v_mps);  // it starts braking at once
}

}  // namespace
}  // namespace topay
