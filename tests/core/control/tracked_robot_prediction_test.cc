// The tracked robot's prediction (finding 34): where the tracker will have brought a robot
// that is off its trajectory, against the tracker itself on a delayed plant, and against the
// robot carried along with its error unchanged (what drift replans started from before).

#include "core/control/tracked_robot_prediction.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/common/angles.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::ReferenceInputs;
using testing::StateAt;
using testing::SyntheticReference;
using testing::TopayLimits;
using testing::Trapezoid;

// 0.6 m/s into a bend of radius 1 m (0.6 rad/s from 2 s for 3 s), the joints moving at 0.5 rad/s.
SyntheticReference Bend() {
  return SyntheticReference(
      [](double t) {
        ReferenceInputs in;
        in.v_mps = Trapezoid(t, 0.0, 12.0, 0.6, 0.6);
        in.omega_radps = Trapezoid(t, 2.0, 5.0, 0.6, 1.0);
        in.qd_radps.setConstant(Trapezoid(t, 0.0, 12.0, 0.5, 3.0));
        return in;
      },
      12.0, StateAt(0, 0, 0, 0));
}

// The reference's robot at t_s moved by (behind_m along its heading, left_m across it), its yaw
// by dyaw_rad and its joints by dq_rad, moving at `speed_share` of the reference's rates.
MeasuredRobot OffTheReference(const SyntheticReference& reference, double t_s, double behind_m, double left_m,
                              double dyaw_rad, double dq_rad, double speed_share) {
  const TrajectorySample& at = reference.At(t_s);
  MeasuredRobot robot;
  robot.state = at.state;
  const double c = std::cos(at.state.yaw_rad), s = std::sin(at.state.yaw_rad);
  robot.state.x_m += -behind_m * c - left_m * s;
  robot.state.y_m += -behind_m * s + left_m * c;
  robot.state.yaw_rad += dyaw_rad;
  robot.state.q_rad.array() += dq_rad;
  robot.state_time_s = t_s;
  robot.rates = ControlCommand::Zero(kJoints);
  robot.rates.v_mps = speed_share * at.v_mps;
  robot.rates.omega_radps = speed_share * at.omega_radps;
  robot.rates.qd_radps = speed_share * at.qd_radps;
  return robot;
}

// Where the process's tracker (its options, latency 20 ms) brings the robot by until_s on an
// ideal plant that applies each command 20 ms after it was sent: the truth the prediction
// approximates (it leaves the latency out).
WholeBodyState TrackedOnADelayedPlant(const TrackerReference& reference, const MeasuredRobot& robot, double until_s) {
  NmpcOptions options;
  options.time_budget_s = 10.0;
  NmpcTracker tracker(options, TopayLimits());
  tracker.ContinueFrom(robot.rates);
  CommandHistory history(64, kJoints);
  history.Push(robot.state_time_s - 0.02, robot.rates);  // what moved the robot before
  WholeBodyState state = robot.state;
  for (double now_s = robot.state_time_s; now_s < until_s - 1e-9; now_s += 0.02) {
    const TrackerInput input{now_s, &state, now_s, &reference};
    history.Push(now_s, tracker.Step(input).command);
    PredictState(history, 0.02, now_s, now_s + 0.02, &state);
  }
  return state;
}

// The robot carried along the reference with its error (the planner's DriftedRobot): the
// reference at until_s plus the offset at the state's time turned with the reference.
WholeBodyState Carried(const SyntheticReference& reference, const MeasuredRobot& robot, double until_s) {
  const WholeBodyState& then = reference.At(robot.state_time_s).state;
  WholeBodyState carried = reference.At(until_s).state;
  const Eigen::Vector2d offset(robot.state.x_m - then.x_m, robot.state.y_m - then.y_m);
  const Eigen::Vector2d turned = Eigen::Rotation2Dd(carried.yaw_rad - then.yaw_rad) * offset;
  carried.x_m += turned.x();
  carried.y_m += turned.y();
  carried.yaw_rad += robot.state.yaw_rad - then.yaw_rad;
  carried.q_rad += robot.state.q_rad - then.q_rad;
  return carried;
}

double Distance(const WholeBodyState& a, const WholeBodyState& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

// Finding 34's case: a robot behind its reference in a bend (after a stall), turned and slower.
// In 1 s (the planner's replanning budget) the tracker turns the robot back onto the path while
// the lag closes or grows with the robot's speed; the prediction lands near where the tracker on
// a delayed plant does, the carried robot (its error unchanged) far from it.
TEST(TrackedRobotPredictionTest, ALaggingRobotIsPredictedWhereTheTrackerBringsIt) {
  const SyntheticReference bend = Bend();
  const TrackerReference reference{3, 0.0, bend.duration_s(), bend.Sampler()};
  TrackedRobotPredictor predictor(NmpcOptions{}, TopayLimits());
  struct Case {
    double t_s, behind_m, left_m, dyaw_rad, dq_rad, speed_share;
    bool turns;  // the robot's error turns or grows within the second (the carried robot keeps it)
  };
  for (const Case& c : {Case{2.5, 0.25, 0.0, 0.15, 0.1, 0.5, true}, Case{3.0, 0.2, 0.08, -0.1, -0.2, 0.0, true},
                        Case{1.0, 0.3, -0.05, 0.0, 0.0, 0.3, false}}) {
    const MeasuredRobot robot = OffTheReference(bend, c.t_s, c.behind_m, c.left_m, c.dyaw_rad, c.dq_rad, c.speed_share);
    const double until_s = c.t_s + 1.0;
    TrajectorySample predicted = MakeTrajectorySample(kJoints);
    predictor.Predict(reference, robot, until_s, &predicted);
    const WholeBodyState truth = TrackedOnADelayedPlant(reference, robot, until_s);
    const WholeBodyState carried = Carried(bend, robot, until_s);
    const double predicted_m = Distance(predicted.state, truth), carried_m = Distance(carried, truth);
    const double predicted_yaw = std::abs(WrapAngle(predicted.state.yaw_rad - truth.yaw_rad));
    const double carried_yaw = std::abs(WrapAngle(carried.yaw_rad - truth.yaw_rad));
    std::printf("[ figure ] %.2f m behind at %.1f s: the prediction %.3f m / %.3f rad from the tracked robot, the "
                "carried robot %.3f m / %.3f rad; joints %.3f / %.3f rad\n",
                c.behind_m, c.t_s, predicted_m, predicted_yaw, carried_m, carried_yaw,
                (predicted.state.q_rad - truth.q_rad).cwiseAbs().maxCoeff(),
                (carried.q_rad - truth.q_rad).cwiseAbs().maxCoeff());
    EXPECT_LT(predicted_m, 0.03);
    EXPECT_LT(predicted_yaw, 0.03);
    EXPECT_LT((predicted.state.q_rad - truth.q_rad).cwiseAbs().maxCoeff(), 0.03);
    EXPECT_EQ(predicted.t_s, until_s);
    EXPECT_EQ(predictor.summary().cycles, 50);
    EXPECT_EQ(predictor.summary().tracking_cycles, 50);
    if (c.turns) {
      EXPECT_GT(carried_m, 5.0 * predicted_m);
      EXPECT_GT(carried_yaw, 5.0 * predicted_yaw);
    } else {  // the base keeps its lag; the joints, slower than the reference's, fall behind
      EXPECT_GT((carried.q_rad - truth.q_rad).cwiseAbs().maxCoeff(), 0.1);
    }
  }
}

// The predicted robot moves as the tracker commands: continuous with the measured rates (the
// first command within one period's acceleration of them) and within the limits throughout,
// its rates at until_s those of the last command and its accelerations their change.
TEST(TrackedRobotPredictionTest, ThePredictedRobotMovesWithinTheLimitsFromItsMeasuredRates) {
  const SyntheticReference bend = Bend();
  const TrackerReference reference{3, 0.0, bend.duration_s(), bend.Sampler()};
  const TrackerLimits limits = TopayLimits();
  TrackedRobotPredictor predictor(NmpcOptions{}, limits);
  const MeasuredRobot robot = OffTheReference(bend, 2.5, 0.25, 0.05, 0.15, 0.1, 0.2);
  TrajectorySample before = MakeTrajectorySample(kJoints);
  before.v_mps = robot.rates.v_mps;
  before.omega_radps = robot.rates.omega_radps;
  before.qd_radps = robot.rates.qd_radps;
  int visits = 0;
  TrajectorySample predicted = MakeTrajectorySample(kJoints);
  predictor.Predict(reference, robot, 3.5, &predicted, [&](const TrajectorySample& s) {
    const double dt = 0.02;
    EXPECT_LE(std::abs(s.v_mps - before.v_mps), limits.base.a_max_mps2 * dt + 1e-9);
    EXPECT_LE(std::abs(s.omega_radps - before.omega_radps), limits.base.beta_max_radps2 * dt + 1e-9);
    EXPECT_LE(std::abs(s.v_mps) / limits.base.v_max_mps + std::abs(s.omega_radps) / limits.base.omega_max_radps,
              1.0 + 1e-9);
    EXPECT_LE(((s.qd_radps - before.qd_radps).cwiseAbs() - limits.qdd_max_radps2 * dt).maxCoeff(), 1e-9);
    EXPECT_NEAR(s.a_mps2, (s.v_mps - before.v_mps) / dt, 1e-9);
    EXPECT_NEAR(s.beta_radps2, (s.omega_radps - before.omega_radps) / dt, 1e-9);
    EXPECT_NEAR(s.t_s, 2.5 + dt * ++visits, 1e-9);
    before = s;
    return true;
  });
  EXPECT_EQ(visits, 50);
  EXPECT_EQ(predicted.v_mps, before.v_mps);
  EXPECT_GT(predicted.v_mps, 0.5);  // catching up on a reference at 0.6 m/s
}

// A reference that ends within the prediction: the tracker settles on its end and brakes, as
// the process does; the predicted robot comes to rest at the end within a few centimetres.
TEST(TrackedRobotPredictionTest, ARobotNearTheEndIsPredictedAtRestThere) {
  const SyntheticReference bend = Bend();
  const TrackerReference reference{3, 0.0, bend.duration_s(), bend.Sampler()};
  TrackedRobotPredictor predictor(NmpcOptions{}, TopayLimits());
  const MeasuredRobot robot = OffTheReference(bend, 11.5, 0.1, 0.0, 0.0, 0.0, 1.0);
  TrajectorySample predicted = MakeTrajectorySample(kJoints);
  predictor.Predict(reference, robot, 14.0, &predicted);
  EXPECT_EQ(predicted.v_mps, 0.0);
  EXPECT_EQ(predicted.omega_radps, 0.0);
  EXPECT_EQ(predicted.qd_radps.norm(), 0.0);
  EXPECT_LT(predictor.summary().tracking_cycles, predictor.summary().cycles);
  EXPECT_LT(Distance(predicted.state, bend.At(12.0).state), 0.05);
}

// The same input twice gives the same robot (no time budget: a loaded machine does not change
// it), and a visit that returns false ends the prediction at that cycle.
TEST(TrackedRobotPredictionTest, IsRepeatableAndCanEndEarly) {
  const SyntheticReference bend = Bend();
  const TrackerReference reference{3, 0.0, bend.duration_s(), bend.Sampler()};
  TrackedRobotPredictor predictor(NmpcOptions{}, TopayLimits());
  const MeasuredRobot robot = OffTheReference(bend, 2.5, 0.25, 0.0, 0.15, 0.1, 0.5);
  TrajectorySample first = MakeTrajectorySample(kJoints), second = MakeTrajectorySample(kJoints);
  predictor.Predict(reference, robot, 3.5, &first);
  predictor.Predict(reference, robot, 3.5, &second);
  EXPECT_EQ(first.state.x_m, second.state.x_m);
  EXPECT_EQ(first.state.yaw_rad, second.state.yaw_rad);
  EXPECT_EQ(first.state.q_rad, second.state.q_rad);
  int visits = 0;
  predictor.Predict(reference, robot, 3.5, &first, [&](const TrajectorySample&) { return ++visits < 10; });
  EXPECT_EQ(visits, 10);
  EXPECT_EQ(predictor.summary().cycles, 10);
  EXPECT_NEAR(first.t_s, 2.7, 1e-9);
  // until_s between cycles: the last cycle is shorter and the robot is predicted at until_s.
  predictor.Predict(reference, robot, 2.51, &first);
  EXPECT_EQ(first.t_s, 2.51);
  EXPECT_EQ(predictor.summary().cycles, 1);
}

TEST(TrackedRobotPredictionTest, BadRobotsAreRefusedByName) {
  const SyntheticReference bend = Bend();
  const TrackerReference reference{3, 0.0, bend.duration_s(), bend.Sampler()};
  TrackedRobotPredictor predictor(NmpcOptions{}, TopayLimits());
  TrajectorySample out = MakeTrajectorySample(kJoints);
  const MeasuredRobot good = OffTheReference(bend, 2.5, 0.25, 0.0, 0.15, 0.1, 0.5);
  const auto message_of = [&](const MeasuredRobot& robot, double until_s) -> std::string {
    try {
      predictor.Predict(reference, robot, until_s, &out);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  MeasuredRobot bad = good;
  bad.state.q_rad.resize(3);
  EXPECT_NE(message_of(bad, 3.0).find("q_rad"), std::string::npos);
  bad = good;
  bad.rates.omega_radps = NAN;
  EXPECT_NE(message_of(bad, 3.0).find("robot.rates.omega_radps"), std::string::npos);
  bad = good;
  bad.state.q_rad(2) = INFINITY;
  EXPECT_NE(message_of(bad, 3.0).find("robot.state.q_rad"), std::string::npos);
  EXPECT_NE(message_of(good, 2.4).find("until_s"), std::string::npos);
  EXPECT_EQ(message_of(good, 3.0), "");
}

}  // namespace
}  // namespace topay
