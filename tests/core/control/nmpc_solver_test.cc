// The NMPC tracker's solver in closed loop with an ideal delayed unicycle + integrator plant
// (control_test_support.h): convergence from an offset, limits on every solution, the
// over-budget fallback and continuity across a new reference.

#include "core/control/nmpc_solver.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/control/command_projection.h"
#include "core/control/warm_start_shift.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::ClosedLoopResult;
using testing::kJoints;
using testing::ReferenceInputs;
using testing::RunClosedLoop;
using testing::StateAt;
using testing::SyntheticReference;
using testing::TopayLimits;
using testing::Trapezoid;

constexpr double kRatioTolerance = 1e-9;

// Unit tests do not depend on timing: a budget no solve reaches (the benchmark measures).
NmpcOptions Untimed() {
  NmpcOptions options;
  options.time_budget_s = 10.0;
  return options;
}

void ExpectConverged(const ClosedLoopResult& result, double position_m, double yaw_rad,
                     double joint_rad) {
  EXPECT_LT(result.final_errors.position_m, position_m);
  EXPECT_LT(result.final_errors.yaw_rad, yaw_rad);
  EXPECT_LT(result.final_errors.joint_rad, joint_rad);
  EXPECT_LE(result.worst_limit_ratio, 1.0 + kRatioTolerance);
  EXPECT_EQ(result.fallbacks, 0);
}

TEST(NmpcSolverTest, StraightLineFromAnOffsetConverges) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 6.0, 0.8, 0.6);
        return in;
      },
      6.0, StateAt(0, 0, 0, 0));
  // 0.2 m beside, 0.1 m behind, 0.15 rad off, joints 0.1 rad off.
  WholeBodyState start = StateAt(-0.1, 0.2, 0.15, 0.1);
  const ClosedLoopResult result = RunClosedLoop(&solver, reference, start, 7.5);
  ExpectConverged(result, 0.01, 0.01, 0.005);
  EXPECT_LT(result.max_errors_last_half.position_m, 0.05);
}

TEST(NmpcSolverTest, TurnInPlaceConverges) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        in.omega_radps = Trapezoid(t, 0.0, 3.0, 0.7, 0.8);
        return in;
      },
      3.0, StateAt(1, 2, 0.5, 0));
  const ClosedLoopResult result = RunClosedLoop(&solver, reference, StateAt(1.05, 2.0, 0.3, 0), 5.0);
  ExpectConverged(result, 0.01, 0.01, 0.005);
  EXPECT_GT(std::abs(reference.At(3.0).state.yaw_rad - 0.5), 1.0);  // it did turn
}

TEST(NmpcSolverTest, ArmOnlyMotionConverges) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        for (int j = 0; j < kJoints; ++j) {
          in.qd_radps(j) = Trapezoid(t, 0.2 * j, 2.0 + 0.2 * j, (j % 2 ? -1.0 : 1.0) * (0.5 + 0.2 * j), 4.0);
        }
        return in;
      },
      4.0, StateAt(0, 0, 0, 0));
  const ClosedLoopResult result = RunClosedLoop(&solver, reference, StateAt(0, 0, 0, -0.2), 5.0);
  ExpectConverged(result, 0.005, 0.005, 0.005);
  EXPECT_LT(result.max_errors_last_half.joint_rad, 0.04);  // while moving (20 ms latency)
}

TEST(NmpcSolverTest, SharpCornerConverges) {
  NmpcSolver solver(Untimed(), TopayLimits());
  // 0.5 m/s along x, a 90 degree corner in 20 ms at t = 3 s (far beyond omega_max), then
  // along y to a stop: the robot cannot follow the corner and must catch up after it.
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 6.0, 0.5, 0.6);
        if (t >= 3.0 && t < 3.02) in.omega_radps = 0.5 * std::numbers::pi / 0.02;
        return in;
      },
      6.0, StateAt(0, 0, 0, 0));
  const ClosedLoopResult result = RunClosedLoop(&solver, reference, StateAt(0, -0.1, 0, 0), 10.0);
  // The corner leaves the robot ~0.5 m off; it catches up to a few cm (a unicycle at rest
  // does not manoeuvre for the last cm of lateral error within a 1 s horizon).
  ExpectConverged(result, 0.06, 0.02, 0.005);
  NmpcSolver corner_solver(Untimed(), TopayLimits());
  const ClosedLoopResult at_corner =
      RunClosedLoop(&corner_solver, reference, StateAt(0, -0.1, 0, 0), 3.5);
  EXPECT_GT(at_corner.final_errors.position_m, 2.0 * result.final_errors.position_m);
}

TEST(NmpcSolverTest, InfeasibleReferencesGiveFeasibleCommands) {
  NmpcSolver solver(Untimed(), TopayLimits());
  // Far away: a goal 20 m off, reached instantly.
  const SyntheticReference far([](double) { return ReferenceInputs(); }, 2.0,
                               StateAt(20, -15, 3.0, 2.0));
  const ClosedLoopResult far_result = RunClosedLoop(&solver, far, StateAt(0, 0, 0, 0), 3.0);
  EXPECT_LE(far_result.worst_limit_ratio, 1.0 + kRatioTolerance);
  // Too fast: 3 m/s, 3 rad/s, joints at 5 rad/s, against limits of 1, 0.9, 2.35.
  NmpcSolver fast_solver(Untimed(), TopayLimits());
  const SyntheticReference fast(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = 3.0;
        in.omega_radps = -3.0 * std::cos(t);
        in.qd_radps.setConstant(5.0 * std::sin(3.0 * t));
        return in;
      },
      4.0, StateAt(0, 0, 0, 0));
  const ClosedLoopResult fast_result = RunClosedLoop(&fast_solver, fast, StateAt(0, 0, 0, 0), 4.0);
  EXPECT_LE(fast_result.worst_limit_ratio, 1.0 + kRatioTolerance);
  // The limits were reached (the test would not test anything otherwise).
  double max_v = 0.0;
  for (const ControlCommand& c : fast_result.commands) max_v = std::max(max_v, std::abs(c.v_mps));
  EXPECT_GT(max_v, 0.5);
}

TEST(NmpcSolverTest, EveryCommandRespectsEveryLimit) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const TrackerLimits limits = TopayLimits();
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = 1.5 * std::sin(t);
        in.omega_radps = 1.5 * std::cos(2 * t);
        in.qd_radps.setConstant(4.0 * std::sin(4.0 * t));
        return in;
      },
      5.0, StateAt(0, 0, 0, 0));
  const ClosedLoopResult result = RunClosedLoop(&solver, reference, StateAt(0.3, 0, 0, 0), 5.0);
  ControlCommand previous = ControlCommand::Zero(kJoints);
  const double dt = solver.options().control_period_s;
  for (const ControlCommand& c : result.commands) {
    ASSERT_LE(std::abs(c.v_mps), limits.base.v_max_mps + 1e-12);
    ASSERT_LE(std::abs(c.omega_radps), limits.base.omega_max_radps + 1e-12);
    ASSERT_LE(std::abs(c.v_mps) / limits.base.v_max_mps +
                  std::abs(c.omega_radps) / limits.base.omega_max_radps,
              1.0 + 1e-9);
    ASSERT_LE(std::abs(c.v_mps - previous.v_mps), limits.base.a_max_mps2 * dt + 1e-12);
    ASSERT_LE(std::abs(c.omega_radps - previous.omega_radps),
              limits.base.beta_max_radps2 * dt + 1e-12);
    for (int j = 0; j < kJoints; ++j) {
      ASSERT_LE(std::abs(c.qd_radps(j)), limits.qd_max_radps(j) + 1e-12);
      ASSERT_LE(std::abs(c.qd_radps(j) - previous.qd_radps(j)),
                limits.qdd_max_radps2(j) * dt + 1e-12);
    }
    previous = c;
  }
  EXPECT_LE(result.worst_limit_ratio, 1.0 + kRatioTolerance);
}

TEST(NmpcSolverTest, OverBudgetFallsBackToTheShiftedPreviousSolution) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const NmpcOptions& options = solver.options();
  const SyntheticReference reference(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 4.0, 0.6, 0.6);
        in.omega_radps = Trapezoid(t, 0.0, 4.0, 0.3, 0.6);
        in.qd_radps.setConstant(Trapezoid(t, 0.0, 4.0, 1.0, 3.0));
        return in;
      },
      4.0, StateAt(0, 0, 0, 0));
  ReferenceHorizon horizon = ReferenceHorizon::Zero(options.horizon_steps, kJoints);
  TrajectorySample scratch = MakeTrajectorySample(kJoints);
  SampleReferenceHorizon(reference.Sampler(), reference.duration_s(), 1.0, options.step_s,
                         &scratch, &horizon);
  ControlCommand last = ControlCommand::Zero(kJoints);
  last.v_mps = 0.3;
  last.omega_radps = 0.1;
  last.qd_radps.setConstant(0.5);
  const WholeBodyState state = reference.At(1.0).state;
  const InputSequence first = solver.Solve(state, horizon, last);
  ASSERT_FALSE(solver.summary().fell_back);
  ControlCommand sent = ControlCommand::Zero(kJoints);
  first.CommandAt(0, &sent);

  solver.set_time_budget_s(1e-9);
  const InputSequence& second = solver.Solve(state, horizon, sent);
  EXPECT_TRUE(solver.summary().fell_back);
  EXPECT_EQ(solver.summary().num_over_budget, 1);
  EXPECT_EQ(solver.summary().num_solves, 2);
  InputSequence expected = InputSequence::Zero(options.horizon_steps, kJoints);
  ShiftInputSequence(first, options.control_period_s / options.step_s, &expected);
  ProjectInputSequence(sent, options.control_period_s, options.step_s, solver.limits(), &expected);
  EXPECT_TRUE(second.u_base.isApprox(expected.u_base, 1e-12));
  EXPECT_TRUE(second.qd_radps.isApprox(expected.qd_radps, 1e-12));
  EXPECT_NE(solver.summary().Report().find("FELL BACK"), std::string::npos);
}

TEST(NmpcSolverTest, NewReferenceSwitchesWithoutAJump) {
  NmpcSolver solver(Untimed(), TopayLimits());
  const TrackerLimits limits = TopayLimits();
  const SyntheticReference first(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 10.0, 0.9, 0.6);
        in.qd_radps.setConstant(Trapezoid(t, 0.0, 10.0, 1.5, 3.0));
        return in;
      },
      10.0, StateAt(0, 0, 0, 0));
  const ClosedLoopResult before = RunClosedLoop(&solver, first, StateAt(0, 0, 0, 0), 3.0);
  const ControlCommand last = before.commands.back();
  ASSERT_GT(last.v_mps, 0.7);  // at speed
  // The new trajectory: from where the robot is, backwards and turning, joints the other way.
  solver.ResetWarmStart();
  const SyntheticReference second(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = -0.5;
        in.omega_radps = 0.8;
        in.qd_radps.setConstant(-2.0);
        return in;
      },
      3.0, first.At(3.0).state);
  const NmpcOptions& options = solver.options();
  ReferenceHorizon horizon = ReferenceHorizon::Zero(options.horizon_steps, kJoints);
  TrajectorySample scratch = MakeTrajectorySample(kJoints);
  SampleReferenceHorizon(second.Sampler(), second.duration_s(), 0.0, options.step_s, &scratch,
                         &horizon);
  const InputSequence& inputs = solver.Solve(first.At(3.0).state, horizon, last);
  const double dt = options.control_period_s;
  EXPECT_LE(std::abs(inputs.u_base(0, 0) - last.v_mps), limits.base.a_max_mps2 * dt + 1e-12);
  EXPECT_LE(std::abs(inputs.u_base(1, 0) - last.omega_radps),
            limits.base.beta_max_radps2 * dt + 1e-12);
  for (int j = 0; j < kJoints; ++j) {
    EXPECT_LE(std::abs(inputs.qd_radps(j, 0) - last.qd_radps(j)),
              limits.qdd_max_radps2(j) * dt + 1e-12);
  }
  // ... and it does head for the new reference (slowing down).
  EXPECT_LT(inputs.u_base(0, 0), last.v_mps);
  EXPECT_EQ(solver.summary().num_warm_resets, 1);
}

TEST(NmpcSolverTest, SampledReferenceHoldsTheEndAtRest) {
  const SyntheticReference reference(
      [](double) {
        ReferenceInputs in;
        in.v_mps = 0.5;
        return in;
      },
      1.0, StateAt(0, 0, 0, 0));
  ReferenceHorizon horizon = ReferenceHorizon::Zero(25, kJoints);
  TrajectorySample scratch = MakeTrajectorySample(kJoints);
  SampleReferenceHorizon(reference.Sampler(), 1.0, 0.8, 0.04, &scratch, &horizon);
  EXPECT_NEAR(horizon.u_base(0, 0), 0.5, 1e-12);
  EXPECT_EQ(horizon.u_base(0, 10), 0.0);
  EXPECT_NEAR(horizon.pose(0, 25), reference.At(1.0).state.x_m, 1e-12);
  EXPECT_NEAR(horizon.pose(0, 25), 0.5, 1e-3);
}

}  // namespace
}  // namespace topay
