// The plant's state while the simulator stalls (sim/motors/stalled_plant.h): the latest state
// while fresh; stale, carried on the drives' command (a unicycle and the joint rates) from when
// it arrived, for carry_on_s, then held still; a fresh state takes over at once.

#include "sim/motors/stalled_plant.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::sim::motors {
namespace {

PlantState StateAt(double x, double yaw, double v) {
  PlantState s;
  s.state.x_m = x;
  s.state.yaw_rad = yaw;
  s.state.q_rad = Eigen::VectorXd::Zero(7);
  s.qdot_radps = Eigen::VectorXd::Zero(7);
  s.v_mps = v;
  return s;
}

ActuatorCommand Command(double v, double omega, double qdot0) {
  ActuatorCommand c;
  c.v_mps = v;
  c.omega_radps = omega;
  c.qdot_radps = Eigen::VectorXd::Zero(7);
  c.qdot_radps[0] = qdot0;
  return c;
}

TEST(StalledPlant, NothingBeforeTheFirstStateAndTheLatestWhileFresh) {
  StalledPlant plant;
  EXPECT_EQ(plant.At(0.0, Command(0, 0, 0)), nullptr);
  plant.OnPlantState(StateAt(1.0, 0.0, 0.8), 0.100);
  const PlantState* s = plant.At(0.115, Command(0.0, 0.0, 0.0));  // 15 ms old: fresh (stale after 20 ms)
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->state.x_m, 1.0);
  EXPECT_EQ(s->v_mps, 0.8);  // not the command's: the plant's own
  EXPECT_FALSE(plant.stale());
  EXPECT_EQ(plant.counts().stalls, 0);
}

TEST(StalledPlant, AStaleStateIsCarriedOnTheCommandFromWhenItArrived) {
  StalledPlant plant;
  plant.OnPlantState(StateAt(1.0, 0.0, 0.8), 0.0);
  // The drives brake to 0.2 m/s and turn at 1 rad/s; the arm's joint 1 at 0.5 rad/s.
  const ActuatorCommand braking = Command(0.2, 1.0, 0.5);
  const PlantState* s = plant.At(0.025, braking);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(plant.stale());
  EXPECT_EQ(s->v_mps, 0.2);
  EXPECT_NEAR(s->state.yaw_rad, 0.025, 1e-12);
  EXPECT_NEAR(s->state.x_m, 1.0 + 0.2 * std::cos(0.0125) * 0.025, 1e-12);
  EXPECT_NEAR(s->state.q_rad[0], 0.5 * 0.025, 1e-12);
  EXPECT_EQ(s->qdot_radps[0], 0.5);
  // Step by step (5 ms) to 0.5 s: an arc of radius 0.2 m through 0.5 rad (the midpoint steps
  // shorten a step's chord by dyaw^2 / 24: under a micrometre here).
  for (int k = 6; k <= 100; ++k) s = plant.At(0.005 * k, braking);
  const double yaw = 0.5, r = 0.2;
  EXPECT_NEAR(s->state.yaw_rad, yaw, 1e-12);
  EXPECT_NEAR(s->state.x_m, 1.0 + r * std::sin(yaw), 1e-6);
  EXPECT_NEAR(s->state.y_m, r * (1.0 - std::cos(yaw)), 1e-6);
  EXPECT_NEAR(s->state.q_rad[0], 0.25, 1e-12);
  EXPECT_EQ(plant.counts().stalls, 1);
  EXPECT_NEAR(plant.counts().carried_s, 0.5, 1e-12);
}

TEST(StalledPlant, AfterTheCatchUpTheStateIsHeldStillAndAFreshOneTakesOver) {
  StalledPlantOptions options;
  options.carry_on_s = 0.3;
  StalledPlant plant(options);
  plant.OnPlantState(StateAt(0.0, 0.0, 0.5), 0.0);
  const ActuatorCommand cruise = Command(0.5, 0.0, 0.0);
  const PlantState* s = nullptr;
  for (int k = 1; k <= 200; ++k) s = plant.At(0.005 * k, cruise);  // 1 s stalled
  EXPECT_NEAR(s->state.x_m, 0.15, 1e-12);  // 0.3 s at 0.5 m/s, then still
  EXPECT_EQ(s->v_mps, 0.0);
  EXPECT_NEAR(plant.counts().held_s, 0.7, 1e-9);
  EXPECT_NEAR(plant.counts().longest_stall_s, 1.0, 1e-12);
  plant.OnPlantState(StateAt(0.4, 0.1, 0.3), 1.002);
  s = plant.At(1.005, cruise);
  EXPECT_FALSE(plant.stale());
  EXPECT_EQ(s->state.x_m, 0.4);
  EXPECT_EQ(s->v_mps, 0.3);
  // The next stall counts again and carries from the new state.
  s = plant.At(1.1, cruise);
  EXPECT_EQ(plant.counts().stalls, 2);
  EXPECT_NEAR(s->state.x_m, 0.4 + 0.5 * std::cos(0.1) * 0.098, 1e-12);
}

TEST(StalledPlant, ABrokenCommandHoldsTheRobotStill) {
  StalledPlant plant;
  plant.OnPlantState(StateAt(2.0, 0.0, 0.5), 0.0);
  ActuatorCommand broken = Command(NAN, 0.0, 0.0);
  broken.qdot_radps.resize(3);  // the wrong joint count
  const PlantState* s = plant.At(0.5, broken);
  EXPECT_EQ(s->state.x_m, 2.0);
  EXPECT_EQ(s->v_mps, 0.0);
  EXPECT_TRUE(s->state.q_rad.isZero());
  EXPECT_TRUE(s->qdot_radps.isZero());
}

TEST(StalledPlant, OptionsAreChecked) {
  StalledPlantOptions o;
  EXPECT_EQ(CheckStalledPlantOptions(o), "");
  o.stale_after_s = 0.0;
  EXPECT_NE(CheckStalledPlantOptions(o), "");
  o = {};
  o.carry_on_s = NAN;
  EXPECT_NE(CheckStalledPlantOptions(o), "");
}

}  // namespace
}  // namespace topay::sim::motors
