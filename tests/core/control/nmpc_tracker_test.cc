// The tracker's cycle: tracking with latency compensation, the safe stops (stale state, no
// reference, ended reference) and a new trajectory id without a jump.

#include "core/control/nmpc_tracker.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

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
  EXPECT_EQ(out.arm_lag_s, 0.0);  // the base keeps up: the arm on the clock
}

// Cruising straight along x at 0.8 m/s, the joints at 1 rad/s (Cruise), through a disturbed
// plant; what the arm did.
enum class Disturbance {
  // The base cannot move (wheels spinning on the spot; the plant moves only the joints).
  kStuckBase,
  // The plant frozen for 0.5 s from 2 s (a simulator that stalls on a loaded machine: no motion
  // and no new state, so the tracker brakes on the stale state), then running again 0.4 m and
  // 0.5 rad behind the clock; the joints catch up faster than the base (6.28 rad/s^2 against
  // 0.9 m/s^2).
  kFrozenPlant,
};
struct ArmOutcome {
  double joint_rad = 0.0;       ///< Joint 0 at the end.
  double arm_lag_s = 0.0;       ///< The arm's lag behind the clock at the end.
  double largest_lead_m = 0.0;  ///< After the freeze: the reference's base position at the time
                                ///< whose joints the arm has reached, minus the base's position.
};

ArmOutcome RunOnADisturbedPlant(const NmpcOptions& options, Disturbance disturbance, double run_s) {
  NmpcTracker tracker(options, TopayLimits());
  CommandHistory history(64, kJoints);
  const SyntheticReference cruise = Cruise(0.8, 1.0);
  const TrackerReference reference{3, 0.0, cruise.duration_s(), cruise.Sampler()};
  WholeBodyState state = StateAt(0, 0, 0, 0);
  double state_time_s = 0.0;
  ArmOutcome outcome;
  for (int i = 0; i * 0.02 <= run_s + 1e-9; ++i) {
    const double now_s = i * 0.02;
    const bool frozen = disturbance == Disturbance::kFrozenPlant && now_s >= 2.0 && now_s < 2.5;
    if (!frozen) state_time_s = now_s;
    const TrackerInput input{now_s, &state, state_time_s, &reference};
    const TrackerOutput& out = tracker.Step(input);
    history.Push(now_s, out.command);
    outcome.arm_lag_s = out.arm_lag_s;
    if (frozen) continue;  // the tracker stops on the stale state
    EXPECT_EQ(out.mode, TrackerMode::kTrack);
    PredictState(history, 0.02, now_s, now_s + 0.02, &state);
    if (disturbance == Disturbance::kStuckBase) state.x_m = state.y_m = state.yaw_rad = 0.0;
    if (disturbance == Disturbance::kFrozenPlant && now_s >= 2.5) {
      double arm_t_s = 0.0;  // the reference's joints rise monotonically: the last time below q
      while (arm_t_s < cruise.duration_s() && cruise.At(arm_t_s + 0.001).state.q_rad(0) <= state.q_rad(0)) {
        arm_t_s += 0.001;
      }
      outcome.largest_lead_m = std::max(outcome.largest_lead_m, cruise.At(arm_t_s).state.x_m - state.x_m);
    }
  }
  outcome.joint_rad = state.q_rad(0);
  return outcome;
}

NmpcOptions WithoutArmPacing() {
  NmpcOptions options = Untimed();
  options.arm_pacing.window_s = 0.0;
  return options;
}

// The base stuck: the arm holds the configuration of the base's progress plus the slack
// (ArmPacedTime); without pacing it runs on with the clock, onto a base pose nobody checked.
TEST(NmpcTrackerTest, AStuckBaseHoldsTheArmBack) {
  // The reference's base passes 0.05 m (the slack) at 0.41 s, where its joints are at 0.25 rad;
  // at 1 s they are at 0.83 rad.
  const ArmOutcome paced = RunOnADisturbedPlant(Untimed(), Disturbance::kStuckBase, 1.0);
  EXPECT_LT(paced.joint_rad, 0.3);
  EXPECT_GT(paced.arm_lag_s, 0.5);
  const ArmOutcome clocked = RunOnADisturbedPlant(WithoutArmPacing(), Disturbance::kStuckBase, 1.0);
  EXPECT_GT(clocked.joint_rad, 0.6);
  EXPECT_EQ(clocked.arm_lag_s, 0.0);
}

// The plant frozen for 0.5 s: after it the arm does not run ahead of the base along the plan, and
// once the base has caught up (1 m/s at most against the plan's 0.8: by 7 s) the arm is on the
// clock again.
TEST(NmpcTrackerTest, AfterAStallTheArmDoesNotRunAheadOfTheBase) {
  const ArmOutcome paced = RunOnADisturbedPlant(Untimed(), Disturbance::kFrozenPlant, 7.0);
  const ArmOutcome clocked = RunOnADisturbedPlant(WithoutArmPacing(), Disturbance::kFrozenPlant, 7.0);
  std::printf("[ figure ] the arm ahead of the base after a 0.5 s stall, at most: paced %.3f m, on the clock %.3f m\n",
              paced.largest_lead_m, clocked.largest_lead_m);
  EXPECT_LT(paced.largest_lead_m, 0.08);  // the slack (0.05 m) and a cycle's motion
  EXPECT_EQ(paced.arm_lag_s, 0.0);
  EXPECT_GT(clocked.largest_lead_m, 0.15);
}

// Driving 0.6 m/s into a bend of radius 1 m (0.6 rad/s from 2 s for 3 s), the plant frozen for
// freeze_s from freeze_at_s (the tracker brakes on the stale state), then catching up: how far
// the base strayed from the reference's path (its nearest point) after the freeze, and its largest
// error against the reference on the clock (the lag, which the tracker's lost_position_m bounds).
struct AfterAFreeze {
  double off_path_m = 0.0;
  double error_m = 0.0;
};
AfterAFreeze LargestOffPathAfterAFreeze(const NmpcOptions& options, double freeze_at_s, double freeze_s) {
  NmpcTracker tracker(options, TopayLimits());
  CommandHistory history(64, kJoints);
  const SyntheticReference bend(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 12.0, 0.6, 0.6);
        in.omega_radps = Trapezoid(t, 2.0, 5.0, 0.6, 1.0);
        return in;
      },
      12.0, StateAt(0, 0, 0, 0));
  const TrackerReference reference{5, 0.0, bend.duration_s(), bend.Sampler()};
  WholeBodyState state = StateAt(0, 0, 0, 0);
  double state_time_s = 0.0;
  AfterAFreeze largest;
  for (int i = 0; i * 0.02 <= 10.0; ++i) {
    const double now_s = i * 0.02;
    const bool frozen = now_s >= freeze_at_s && now_s < freeze_at_s + freeze_s;
    if (!frozen) state_time_s = now_s;
    const TrackerInput input{now_s, &state, state_time_s, &reference};
    history.Push(now_s, tracker.Step(input).command);
    if (frozen) continue;
    PredictState(history, 0.02, now_s, now_s + 0.02, &state);
    if (now_s < freeze_at_s) continue;
    double nearest_m = std::numeric_limits<double>::infinity();
    for (double t = 0.0; t <= bend.duration_s(); t += 0.002) {
      const WholeBodyState& on_path = bend.At(t).state;
      nearest_m = std::min(nearest_m, std::hypot(state.x_m - on_path.x_m, state.y_m - on_path.y_m));
    }
    largest.off_path_m = std::max(largest.off_path_m, nearest_m);
    const WholeBodyState& on_clock = bend.At(now_s + 0.02).state;
    largest.error_m = std::max(largest.error_m, std::hypot(state.x_m - on_clock.x_m, state.y_m - on_clock.y_m));
  }
  return largest;
}

// After a stall the reference is ahead in the bend: a world-frame position cost pulls the base
// along the chord towards it, inside the path (finding 34's mechanism: a base closing a lag
// after the simulator stalled, the arm on a table top); the cross-track weight (1000 against
// 100 along, with yaw at 200) closes the lag along the path.
TEST(NmpcTrackerTest, CatchingUpInABendStaysOnThePath) {
  NmpcOptions world_frame = Untimed();  // the weights before: 100 on |p - p_ref|^2, 50 on yaw
  world_frame.cross_track_weight = world_frame.position_weight;
  world_frame.yaw_weight = 50.0;
  double worst_path_frame_m = 0.0, worst_world_frame_m = 0.0;
  for (const auto& [at_s, for_s] : {std::pair{1.5, 0.3}, std::pair{2.0, 0.3}, std::pair{3.0, 0.5}}) {
    const AfterAFreeze path_frame = LargestOffPathAfterAFreeze(Untimed(), at_s, for_s);
    const AfterAFreeze world = LargestOffPathAfterAFreeze(world_frame, at_s, for_s);
    const double path_frame_m = path_frame.off_path_m, world_frame_m = world.off_path_m;
    std::printf("[ figure ] frozen %.1f s at %.1f s: off the path by at most %.3f m (%.3f m world frame); largest "
                "error on the clock %.3f m (%.3f m)\n",
                for_s, at_s, path_frame_m, world_frame_m, path_frame.error_m, world.error_m);
    EXPECT_LT(path_frame_m, 0.1);
    worst_path_frame_m = std::max(worst_path_frame_m, path_frame_m);
    worst_world_frame_m = std::max(worst_world_frame_m, world_frame_m);
  }
  EXPECT_GT(worst_world_frame_m, 0.15);  // the scenarios do cut the bend with equal weights
  EXPECT_LT(worst_path_frame_m, 0.5 * worst_world_frame_m);
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
