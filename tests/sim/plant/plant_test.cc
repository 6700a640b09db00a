// The robot plant (sim/plant/plant.h): first-order step responses against the analytic model,
// latency, speed and acceleration limits, joint end stops, the brake on command loss and on a
// rejected command, the gripper's stroke time, a commanded circle that closes, wheel slip and
// determinism.

#include "sim/plant/plant.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "plant_test_robot.h"

namespace topay::sim {
namespace {

using test::TopayRobot;

ActuatorCommand Cmd(double v, double w, double qdot0 = 0.0, double gripper = 0.0) {
  ActuatorCommand c;
  c.v_mps = v;
  c.omega_radps = w;
  c.qdot_radps = Eigen::VectorXd::Zero(TopayRobot().num_joints());
  c.qdot_radps[0] = qdot0;
  c.gripper = gripper;
  return c;
}

// Steps n times, re-sending `cmd` every `every` steps (as a 50 Hz tracker would: every 10).
void Drive(Plant* plant, const ActuatorCommand& cmd, int n, int every = 10) {
  for (int i = 0; i < n; ++i) {
    if (i % every == 0) {
      EXPECT_EQ(plant->Command(cmd), "");
    }
    plant->Step();
  }
}

TEST(Plant, StepResponseMatchesTheFirstOrderModelAfterTheLatency) {
  PlantOptions o;
  o.base.latency_s = 0.02;
  o.base.v_tau_s = 0.1;
  o.base.omega_tau_s = 0.2;
  o.joints.tau_s = 0.05;
  o.joints.latency_s = 0.01;
  Plant plant(TopayRobot(), o, 1);
  const double u_v = 0.05, u_w = 0.04, u_q = 0.1;  // small: below the acceleration limits
  plant.Command(Cmd(u_v, u_w, u_q));
  double max_error_v = 0.0, max_error_w = 0.0, max_error_q = 0.0;
  for (int k = 1; k <= 500; ++k) {
    if (k % 10 == 0) plant.Command(Cmd(u_v, u_w, u_q));
    plant.Step();
    const double t = k * o.step_s;
    const auto response = [&](double u, double latency, double tau) {
      return t < latency + 1e-12 ? 0.0 : u * (1.0 - std::exp(-(t - latency) / tau));
    };
    max_error_v = std::max(max_error_v, std::abs(plant.measured().v_mps - response(u_v, 0.02, 0.1)));
    max_error_w = std::max(max_error_w, std::abs(plant.measured().omega_radps - response(u_w, 0.02, 0.2)));
    max_error_q = std::max(max_error_q, std::abs(plant.state().qdot_radps[0] - response(u_q, 0.01, 0.05)));
    if (k == 10) {
      EXPECT_EQ(plant.measured().v_mps, 0.0) << "moved before the latency";
    }
    if (k == 11) {
      EXPECT_GT(plant.measured().v_mps, 0.0) << "did not move right after the latency";
    }
  }
  EXPECT_LT(max_error_v, 1e-12);
  EXPECT_LT(max_error_w, 1e-12);
  EXPECT_LT(max_error_q, 1e-12);
  // Position: the integral of the lagged speed, x(t) = u (t' - tau (1 - exp(-t'/tau))), t' = t - L.
  const double tp = 1.0 - 0.02;
  EXPECT_NEAR(plant.state().state.x_m, u_v * (tp - 0.1 * (1.0 - std::exp(-tp / 0.1))), 1e-4);
}

TEST(Plant, LatencyShiftsTheWholeResponse) {
  for (const double latency_s : {0.0, 0.02, 0.1}) {
    PlantOptions o;
    o.base.latency_s = latency_s;
    Plant plant(TopayRobot(), o, 1);
    int first_moving_step = -1;
    for (int k = 0; k < 200 && first_moving_step < 0; ++k) {
      if (k % 10 == 0) plant.Command(Cmd(0.3, 0.0));
      plant.Step();
      if (plant.measured().v_mps > 0.0) first_moving_step = k;
    }
    EXPECT_EQ(first_moving_step, std::lround(latency_s / o.step_s)) << latency_s;
  }
}

TEST(Plant, SaturatesAtTheRobotsSpeedAndAccelerationLimits) {
  PlantOptions o;
  o.base.v_tau_s = 0.0;  // no lag: the acceleration limit alone shapes the ramp
  o.base.omega_tau_s = 0.0;
  o.joints.tau_s = 0.0;
  Plant plant(TopayRobot(), o, 1);
  const BaseLimits& b = TopayRobot().base_limits;
  const JointLimits& j = TopayRobot().joint_limits;
  double previous_v = 0.0, max_accel = 0.0, max_qdot = 0.0;
  for (int k = 0; k < 2000; ++k) {
    if (k % 10 == 0) plant.Command(Cmd(5.0, 0.0, 50.0));
    plant.Step();
    max_accel = std::max(max_accel, (plant.measured().v_mps - previous_v) / o.step_s);
    previous_v = plant.measured().v_mps;
    max_qdot = std::max(max_qdot, std::abs(plant.state().qdot_radps[0]));
  }
  EXPECT_NEAR(plant.measured().v_mps, b.v_max_mps, 1e-12);
  EXPECT_NEAR(plant.measured().omega_radps, 0.0, 1e-12);
  EXPECT_LE(max_accel, b.a_max_mps2 + 1e-9);
  EXPECT_GT(max_accel, 0.99 * b.a_max_mps2);  // the ramp runs at the limit
  EXPECT_LE(max_qdot, j.qd_max_radps[0] + 1e-12);
  // Turning in place saturates at omega_max.
  Drive(&plant, Cmd(0.0, -5.0), 3000);
  EXPECT_NEAR(plant.measured().v_mps, 0.0, 1e-12);
  EXPECT_NEAR(plant.measured().omega_radps, -b.omega_max_radps, 1e-12);
}

// Speed and yaw rate together stay inside the coupled bound |v| / v_max + |omega| /
// omega_max <= 1 (eq. (9)), scaled down together so that the curvature is the commanded one.
TEST(Plant, KeepsSpeedAndYawRateInsideTheCoupledBound) {
  PlantOptions o;
  o.base.v_tau_s = 0.0;
  o.base.omega_tau_s = 0.0;
  Plant plant(TopayRobot(), o, 1);
  const BaseLimits& b = TopayRobot().base_limits;
  const double v_cmd = 0.9 * b.v_max_mps, w_cmd = 0.8 * b.omega_max_radps;  // load 1.7
  double max_load = 0.0;
  for (int k = 0; k < 3000; ++k) {
    if (k % 10 == 0) plant.Command(Cmd(v_cmd, w_cmd));
    plant.Step();
    max_load = std::max(max_load, std::abs(plant.measured().v_mps) / b.v_max_mps +
                                      std::abs(plant.measured().omega_radps) / b.omega_max_radps);
  }
  EXPECT_LE(max_load, 1.0 + 1e-12);
  EXPECT_NEAR(plant.measured().v_mps, v_cmd / 1.7, 1e-9);
  EXPECT_NEAR(plant.measured().omega_radps, w_cmd / 1.7, 1e-9);
  EXPECT_NEAR(plant.measured().omega_radps / plant.measured().v_mps, w_cmd / v_cmd, 1e-9);
  // Inside the bound a command is followed as it is.
  Drive(&plant, Cmd(0.5 * b.v_max_mps, 0.3 * b.omega_max_radps), 3000);
  EXPECT_NEAR(plant.measured().v_mps, 0.5 * b.v_max_mps, 1e-9);
  EXPECT_NEAR(plant.measured().omega_radps, 0.3 * b.omega_max_radps, 1e-9);
}

TEST(Plant, JointsStopAtTheirPositionLimits) {
  PlantOptions o;
  o.initial.q_rad = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  Plant plant(TopayRobot(), o, 1);
  const JointLimits& j = TopayRobot().joint_limits;
  int limited = -1;
  for (int i = 0; i < j.q_max_rad.size(); ++i) {
    if (std::isfinite(j.q_max_rad[i])) limited = i;
  }
  ASSERT_GE(limited, 0) << "the test robot has no joint with a finite upper limit";
  ActuatorCommand c = Cmd(0.0, 0.0);
  c.qdot_radps[limited] = 2.0;
  Drive(&plant, c, 5000);
  EXPECT_DOUBLE_EQ(plant.state().state.q_rad[limited], j.q_max_rad[limited]);
  EXPECT_LE(plant.state().qdot_radps[limited], 0.0);
}

TEST(Plant, BrakesToAStopWithinTheDecelerationLimitsWhenCommandsStop) {
  PlantOptions o;
  Plant plant(TopayRobot(), o, 1);
  Drive(&plant, Cmd(0.8, 0.1, 1.0), 2500);  // 5 s: at speed (inside the coupled bound)
  ASSERT_NEAR(plant.measured().v_mps, 0.8, 1e-6);
  EXPECT_FALSE(plant.braking());
  const BaseLimits& b = TopayRobot().base_limits;
  // The last command (sent at the start of the last 10 steps) reached the drives after the latency;
  // nothing else comes. Until the timeout the drives hold the speed, then they ramp down.
  const int steps_to_timeout = static_cast<int>(std::lround((o.command_timeout_s) / o.step_s));
  double previous_v = plant.measured().v_mps;
  int stopped_at = -1;
  for (int k = 0; k < 2000; ++k) {
    plant.Step();
    const double v = plant.measured().v_mps;
    EXPECT_GE((previous_v - v) / o.step_s, -1e-9);                // never speeds up
    EXPECT_LE((previous_v - v) / o.step_s, b.a_max_mps2 + 1e-9);  // decelerates within the limit
    previous_v = v;
    if (stopped_at < 0 && v == 0.0 && plant.measured().omega_radps == 0.0 && plant.state().qdot_radps.isZero()) stopped_at = k;
  }
  EXPECT_TRUE(plant.braking());
  EXPECT_EQ(plant.counts().command_timeouts, 1);
  ASSERT_GE(stopped_at, 0);
  // Timeout (counted from the last command's arrival), then v / a_max (the base is the slowest).
  const double expected_s = o.command_timeout_s + 0.8 / b.a_max_mps2;
  EXPECT_NEAR(stopped_at * o.step_s, expected_s, 0.05) << "steps to timeout " << steps_to_timeout;
}

TEST(Plant, RejectsNonFiniteAndWrongSizedCommandsAndBrakes) {
  Plant plant(TopayRobot(), {}, 1);
  Drive(&plant, Cmd(0.5, 0.0), 1500);
  ASSERT_NEAR(plant.measured().v_mps, 0.5, 1e-6);
  ActuatorCommand nan = Cmd(std::nan(""), 0.0);
  EXPECT_EQ(plant.Command(nan), "v_mps is not finite");
  ActuatorCommand wrong = Cmd(0.5, 0.0);
  wrong.qdot_radps = Eigen::VectorXd::Zero(3);
  EXPECT_NE(plant.Command(wrong).find("3 joint rates for a robot with 7 joints"), std::string::npos);
  ActuatorCommand inf_joint = Cmd(0.5, 0.0);
  inf_joint.qdot_radps[4] = INFINITY;
  EXPECT_EQ(plant.Command(inf_joint), "qdot_radps[4] is not finite");
  EXPECT_EQ(plant.counts().commands_rejected, 3);
  // Braking starts when the rejection reaches the drives (the latency), long before the timeout.
  for (int k = 0; k < 15; ++k) plant.Step();
  EXPECT_TRUE(plant.braking());
  EXPECT_LT(plant.measured().v_mps, 0.5);
  for (int k = 0; k < 500; ++k) plant.Step();
  EXPECT_EQ(plant.measured().v_mps, 0.0);
  EXPECT_EQ(plant.state().v_mps, 0.0);
  // A valid command drives again.
  Drive(&plant, Cmd(0.2, 0.0), 1000);
  EXPECT_NEAR(plant.measured().v_mps, 0.2, 1e-6);
  EXPECT_FALSE(plant.braking());
}

TEST(Plant, GripperTakesItsStrokeTime) {
  PlantOptions o;
  o.gripper.open_time_s = 0.8;
  Plant plant(TopayRobot(), o, 1);
  int closed_at = -1;
  for (int k = 0; k < 1000 && closed_at < 0; ++k) {
    if (k % 10 == 0) plant.Command(Cmd(0.0, 0.0, 0.0, 1.0));
    plant.Step();
    if (plant.state().gripper >= 1.0) closed_at = k + 1;
  }
  EXPECT_NEAR(closed_at * o.step_s, o.gripper.latency_s + 0.8, 2 * o.step_s);
}

TEST(Plant, GripperAloneMovesTheGripperButFeedsNoWatchdog) {
  PlantOptions o;
  o.gripper.open_time_s = 0.5;
  Plant plant(TopayRobot(), o, 1);
  EXPECT_EQ(plant.CommandGripper(1.0), "");
  for (int k = 0; k < 400; ++k) plant.Step();  // 0.8 s
  EXPECT_EQ(plant.state().gripper, 1.0);
  EXPECT_TRUE(plant.braking()) << "the base and joint drives had no command";
  EXPECT_EQ(plant.counts().commands_accepted, 0);
  EXPECT_NE(plant.CommandGripper(1.5), "");
  EXPECT_NE(plant.CommandGripper(std::nan("")), "");
  EXPECT_EQ(plant.counts().commands_rejected, 2);
  for (int k = 0; k < 100; ++k) plant.Step();
  EXPECT_EQ(plant.state().gripper, 1.0) << "a rejected target changes nothing";
}

TEST(Plant, CommandedCircleCloses) {
  Plant plant(TopayRobot(), {}, 1);
  const double v = 0.4, w = 0.4;  // radius 1 m, period 5 pi s, inside the coupled bound
  Drive(&plant, Cmd(v, w), 2000);   // 4 s: steady
  const WholeBodyState start = plant.state().state;
  const int period_steps = static_cast<int>(std::lround(2.0 * M_PI / w / plant.step_s()));
  double max_radius_error = 0.0;
  // The centre of the circle: 1 m to the left of the heading.
  const Eigen::Vector2d centre(start.x_m - v / w * std::sin(start.yaw_rad), start.y_m + v / w * std::cos(start.yaw_rad));
  for (int k = 0; k < period_steps; ++k) {
    if (k % 10 == 0) plant.Command(Cmd(v, w));
    plant.Step();
    const Eigen::Vector2d p(plant.state().state.x_m, plant.state().state.y_m);
    max_radius_error = std::max(max_radius_error, std::abs((p - centre).norm() - v / w));
  }
  const WholeBodyState& end = plant.state().state;
  EXPECT_LT(std::hypot(end.x_m - start.x_m, end.y_m - start.y_m), 2e-3);
  EXPECT_LT(std::abs(std::remainder(end.yaw_rad - start.yaw_rad, 2 * M_PI)), 2e-3);
  EXPECT_LT(max_radius_error, 1e-6);
}

TEST(Plant, WheelSlipMovesTheBaseOtherThanTheWheelsSayButRepeatably) {
  PlantOptions o;
  o.wheels.slip_stddev = 0.05;
  Plant a(TopayRobot(), o, 7), b(TopayRobot(), o, 7), c(TopayRobot(), o, 8), none(TopayRobot(), {}, 7);
  for (Plant* p : {&a, &b, &c, &none}) Drive(p, Cmd(0.6, 0.2), 3000);
  EXPECT_EQ(a.state().state.x_m, b.state().state.x_m);  // same seed: bit for bit
  EXPECT_EQ(a.state().state.y_m, b.state().state.y_m);
  EXPECT_NE(a.state().state.x_m, c.state().state.x_m);  // another seed: another path
  EXPECT_GT(std::hypot(a.state().state.x_m - none.state().state.x_m, a.state().state.y_m - none.state().state.y_m), 1e-3);
  // The wheels' odometry does not see the slip: it equals the slip-free plant's.
  EXPECT_EQ(a.measured().v_mps, none.measured().v_mps);
  EXPECT_NEAR(a.measured().wheel_left_radps, (0.6 - 0.2 * 0.25) / 0.1, 1e-9);
}

}  // namespace
}  // namespace topay::sim

namespace topay::sim {
namespace {

TEST(Plant, StepToSetsTheStateAndTheDrivesMeasureItsVelocities) {
  const RobotModel& model = test::TopayRobot();
  Plant plant(model, PlantOptions{}, 7);
  PlantState target = plant.state();
  target.state.x_m = 0.3;
  target.state.yaw_rad = 0.2;
  target.state.q_rad[2] = 0.4;
  target.v_mps = 0.5;  // (no lag, no limit: an ideal follower)
  target.omega_radps = -0.25;
  target.qdot_radps[2] = 0.7;
  plant.StepTo(target);
  EXPECT_EQ(plant.step_count(), 1);
  EXPECT_EQ(plant.state().state.x_m, 0.3);
  EXPECT_EQ(plant.state().state.q_rad[2], 0.4);
  const MeasuredActuators m = plant.measured();
  EXPECT_EQ(m.v_mps, 0.5);
  EXPECT_EQ(m.omega_radps, -0.25);
  EXPECT_EQ(m.qdot_radps[2], 0.7);
  EXPECT_FALSE(m.braking);
  const double expected_left = (0.5 + 0.25 * 0.25) / 0.1 * plant.step_s();  // default track 0.5 m, radius 0.1 m
  EXPECT_NEAR(m.wheel_left_rad, expected_left, 1e-15);
  // A command is not applied by StepTo (and a later Step runs the drives from this state).
  EXPECT_EQ(plant.Command(Cmd(-0.5, 0.0)), "");
  plant.StepTo(target);
  EXPECT_EQ(plant.measured().v_mps, 0.5);
}

}  // namespace
}  // namespace topay::sim
