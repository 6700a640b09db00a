#include "core/planning/discrete_se2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/common/angles.h"

namespace topay {
namespace {

constexpr double kPi = std::numbers::pi;

BaseLimits Limits() {
  BaseLimits limits;
  limits.v_max_mps = 1.0;
  limits.a_max_mps2 = 0.8;
  limits.omega_max_radps = 0.9;
  limits.beta_max_radps2 = 1.0;
  return limits;
}

/// Every transition is either a straight move along the yaw (yaw unchanged) at most delta_l
/// long, or a turn in place of at most max_turn_step.
void ExpectWellFormed(const DiscreteSE2Path& path, const DiscreteSE2Options& options) {
  ASSERT_FALSE(path.layers.empty());
  EXPECT_EQ(path.layers.front().time_s, 0.0);
  EXPECT_EQ(path.layers.front().step_time_s, 0.0);
  for (int l = 1; l < path.num_layers(); ++l) {
    const Se2Layer& a = path.layers[l - 1];
    const Se2Layer& b = path.layers[l];
    const Eigen::Vector2d d(b.x_m - a.x_m, b.y_m - a.y_m);
    EXPECT_GT(b.step_time_s, 0.0) << "layer " << l;
    EXPECT_NEAR(b.time_s - a.time_s, b.step_time_s, 1e-12);
    if (b.turn_in_place) {
      EXPECT_EQ(d.norm(), 0.0) << "layer " << l;
      EXPECT_LE(std::abs(b.yaw_rad - a.yaw_rad), options.max_turn_step_rad + 1e-12);
      EXPECT_GT(std::abs(b.yaw_rad - a.yaw_rad), 0.0);
      EXPECT_EQ(b.arc_length_m, a.arc_length_m);
      // A turn of dyaw takes at least dyaw / omega_max.
      EXPECT_GE(b.step_time_s, std::abs(b.yaw_rad - a.yaw_rad) / Limits().omega_max_radps - 1e-12);
    } else {
      EXPECT_EQ(b.yaw_rad, a.yaw_rad) << "layer " << l;
      EXPECT_GT(d.norm(), 0.0);
      EXPECT_LE(d.norm(), options.delta_l_m + 1e-12);
      EXPECT_NEAR(std::atan2(d.y(), d.x()), WrapAngle(b.yaw_rad), 1e-9) << "layer " << l;
      EXPECT_NEAR(b.arc_length_m - a.arc_length_m, d.norm(), 1e-12);
      EXPECT_GE(b.step_time_s, d.norm() / Limits().v_max_mps - 1e-12);
    }
  }
}

TEST(DiscreteSE2Test, LShapedPathHasTurnsAtStartVertexAndGoal) {
  DiscreteSE2Options options;
  options.delta_l_m = 1.0;
  const std::vector<Eigen::Vector2d> waypoints{{0.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}};
  const DiscreteSE2Path path = DiscreteSE2(waypoints, kPi / 2.0, kPi, Limits(), options);
  ExpectWellFormed(path, options);

  // Start: pi/2 -> 0 in ceil((pi/2) / (pi/4)) = 2 turns; 3 moves of 1 m; vertex turn 0 -> pi/2
  // in 2; 2 moves of 1 m; goal turn pi/2 -> pi in 2. Plus the first layer.
  ASSERT_EQ(path.num_layers(), 1 + 2 + 3 + 2 + 2 + 2);
  EXPECT_EQ(path.layers.front().yaw_rad, kPi / 2.0);
  EXPECT_EQ(path.layers.front().x_m, 0.0);
  EXPECT_NEAR(path.layers[2].yaw_rad, 0.0, 1e-12);
  EXPECT_TRUE(path.layers[1].turn_in_place);
  // Spacing along the first segment: 1 m apart, yaw 0.
  for (int l = 3; l <= 5; ++l) {
    EXPECT_NEAR(path.layers[l].x_m, l - 2.0, 1e-12);
    EXPECT_FALSE(path.layers[l].turn_in_place);
  }
  // Turn in place at the vertex (3, 0).
  for (int l = 6; l <= 7; ++l) {
    EXPECT_TRUE(path.layers[l].turn_in_place);
    EXPECT_EQ(path.layers[l].x_m, 3.0);
    EXPECT_EQ(path.layers[l].y_m, 0.0);
  }
  EXPECT_NEAR(path.layers[7].yaw_rad, kPi / 2.0, 1e-12);
  const Se2Layer& last = path.layers.back();
  EXPECT_EQ(last.x_m, 3.0);
  EXPECT_EQ(last.y_m, 2.0);
  EXPECT_NEAR(WrapAngle(last.yaw_rad - kPi), 0.0, 1e-12);
  EXPECT_NEAR(last.arc_length_m, 5.0, 1e-12);
}

TEST(DiscreteSE2Test, StraightRunTimesFollowTheTrapezoid) {
  DiscreteSE2Options options;
  options.delta_l_m = 0.5;
  const BaseLimits limits = Limits();
  const double length = 4.0;  // > v^2 / a = 1.25 m: reaches v_max
  const DiscreteSE2Path path = DiscreteSE2({{0.0, 0.0}, {length, 0.0}}, 0.0, 0.0, limits, options);
  ExpectWellFormed(path, options);
  ASSERT_EQ(path.num_layers(), 9);
  // Rest-to-rest trapezoid: T = D / v + v / a.
  EXPECT_NEAR(path.total_time_s(), length / limits.v_max_mps + limits.v_max_mps / limits.a_max_mps2,
              1e-12);
  // First layer at 0.5 m is still accelerating: s = a t^2 / 2.
  EXPECT_NEAR(path.layers[1].time_s, std::sqrt(2.0 * 0.5 / limits.a_max_mps2), 1e-12);
  // Symmetric profile: step times mirror each other.
  for (int l = 1; l < path.num_layers(); ++l) {
    EXPECT_NEAR(path.layers[l].step_time_s, path.layers[path.num_layers() - l].step_time_s, 1e-12);
  }
}

TEST(DiscreteSE2Test, TrapezoidArrivalTimeRespectsRateAndAcceleration) {
  for (const double total : {0.3, 1.0, 5.0}) {
    const double v = 1.0, a = 0.8;
    const int n = 2000;
    double previous_t = 0.0, previous_rate = 0.0, previous_dt = 0.0;
    for (int k = 1; k <= n; ++k) {
      const double s = total * k / n;
      const double t = TrapezoidArrivalTime(s, total, v, a);
      ASSERT_GT(t, previous_t);
      const double dt = t - previous_t;
      const double rate = (total / n) / dt;  // mean rate over the interval
      EXPECT_LE(rate, v * (1.0 + 1e-9));
      if (k > 1) {
        // With |rate'| <= a, mean rates of adjacent intervals differ by at most a times the
        // time between the intervals' midpoints.
        EXPECT_LE(std::abs(rate - previous_rate), a * 0.5 * (dt + previous_dt) + 1e-9)
            << total << " " << k;
      }
      previous_t = t;
      previous_rate = rate;
      previous_dt = dt;
    }
    // Triangle for short runs: T = 2 sqrt(D / a).
    if (total < v * v / a) {
      EXPECT_NEAR(previous_t, 2.0 * std::sqrt(total / a), 1e-12);
    }
  }
}

TEST(DiscreteSE2Test, CollinearWaypointsMergeWithoutTurns) {
  DiscreteSE2Options options;
  options.delta_l_m = 1.414;
  const DiscreteSE2Path path =
      DiscreteSE2({{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {2.0, 2.0}, {3.0, 3.0}}, kPi / 4.0,
                  kPi / 4.0, Limits(), options);
  ExpectWellFormed(path, options);
  for (const Se2Layer& layer : path.layers) EXPECT_FALSE(layer.turn_in_place);
  // One run of 3 sqrt(2) m: ceil(4.243 / 1.414) = 4 steps; timed as one trapezoid.
  EXPECT_EQ(path.num_layers(), 5);
  const double length = 3.0 * std::sqrt(2.0);
  EXPECT_NEAR(path.total_time_s(), length + 1.0 / 0.8, 1e-12);
}

TEST(DiscreteSE2Test, TurnsTakeTheShorterWayAndKeepYawContinuous) {
  DiscreteSE2Options options;
  // Start facing 3 rad, path heading -3 rad: the short way is +0.283 rad through pi.
  const DiscreteSE2Path path =
      DiscreteSE2({{0.0, 0.0}, {std::cos(-3.0), std::sin(-3.0)}}, 3.0, -3.0, Limits(), options);
  ExpectWellFormed(path, options);
  ASSERT_GE(path.num_layers(), 3);
  EXPECT_NEAR(path.layers[1].yaw_rad, 3.0 + (2.0 * kPi - 6.0), 1e-12);
  EXPECT_GT(path.layers[1].yaw_rad, kPi);  // continuous, not wrapped
}

// Finding 29's third case: a path that begins (and ends) behind the robot turns half a turn;
// asked, that turn goes the longer way round, the rest of the sequence as before.
TEST(DiscreteSE2Test, AnEndTurnGoesTheOtherWayRoundWhenAsked) {
  DiscreteSE2Options options;
  // Facing -y (3.0 rad short of a half turn), the path heads +y, the goal yaw is +x.
  const std::vector<Eigen::Vector2d> waypoints = {{0.0, 0.0}, {0.0, 2.0}};
  const double start_yaw = kPi / 2.0 - 3.0, goal_yaw = 0.0;
  const DiscreteSE2Path shorter = DiscreteSE2(waypoints, start_yaw, goal_yaw, Limits(), options);
  const DiscreteSE2Path start_other = DiscreteSE2(waypoints, start_yaw, goal_yaw, Limits(), options, {true, false});
  const DiscreteSE2Path goal_other = DiscreteSE2(waypoints, start_yaw, goal_yaw, Limits(), options, {false, true});
  for (const DiscreteSE2Path* path : {&shorter, &start_other, &goal_other}) {
    ExpectWellFormed(*path, options);
    EXPECT_NEAR(WrapAngle(path->layers.back().yaw_rad - goal_yaw), 0.0, 1e-12);
  }
  EXPECT_NEAR(StartTurnRad(shorter), 3.0, 1e-12);
  EXPECT_NEAR(StartTurnRad(start_other), 3.0 - 2.0 * kPi, 1e-12);
  EXPECT_NEAR(StartTurnRad(goal_other), 3.0, 1e-12);
  EXPECT_NEAR(GoalTurnRad(shorter), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(GoalTurnRad(start_other), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(GoalTurnRad(goal_other), 3.0 * kPi / 2.0, 1e-12);
  // The longer turn takes longer: 5 steps of at most pi / 4 for 3.28 rad, 4 for 3.0 rad.
  EXPECT_EQ(start_other.num_layers(), shorter.num_layers() + 1);
  EXPECT_GT(start_other.total_time_s(), shorter.total_time_s());
  // A path without turns at its ends has none to turn the other way.
  const DiscreteSE2Path straight = DiscreteSE2(waypoints, kPi / 2.0, kPi / 2.0, Limits(), options, {true, true});
  EXPECT_EQ(StartTurnRad(straight), 0.0);
  EXPECT_EQ(GoalTurnRad(straight), 0.0);
  EXPECT_EQ(straight.num_layers(), DiscreteSE2(waypoints, kPi / 2.0, kPi / 2.0, Limits(), options).num_layers());
  // One waypoint: its one turn goes the other way for either flag.
  EXPECT_NEAR(StartTurnRad(DiscreteSE2({{1.0, 2.0}}, 0.0, -kPi / 2.0, Limits(), options, {true, false})),
              3.0 * kPi / 2.0, 1e-12);
  EXPECT_NEAR(GoalTurnRad(DiscreteSE2({{1.0, 2.0}}, 0.0, -kPi / 2.0, Limits(), options, {false, true})),
              3.0 * kPi / 2.0, 1e-12);
}

TEST(DiscreteSE2Test, SingleWaypointTurnsInPlaceOnly) {
  DiscreteSE2Options options;
  const DiscreteSE2Path path = DiscreteSE2({{1.0, 2.0}}, 0.0, -kPi / 2.0, Limits(), options);
  ExpectWellFormed(path, options);
  EXPECT_EQ(path.num_layers(), 3);
  EXPECT_NEAR(path.layers.back().yaw_rad, -kPi / 2.0, 1e-12);
  // Same pose at both ends: one layer.
  EXPECT_EQ(DiscreteSE2({{1.0, 2.0}}, 0.5, 0.5, Limits(), options).num_layers(), 1);
}

TEST(DiscreteSE2Test, StateUsesTheLayersBase) {
  const DiscreteSE2Path path = DiscreteSE2({{0.0, 0.0}, {2.0, 0.0}}, 0.0, 0.0, Limits());
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(7, 0.1, 0.7);
  const WholeBodyState state = path.State(1, q);
  EXPECT_EQ(state.x_m, path.layers[1].x_m);
  EXPECT_EQ(state.yaw_rad, path.layers[1].yaw_rad);
  EXPECT_EQ(state.q_rad, q);
}

TEST(DiscreteSE2Test, BadInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(DiscreteSE2({}, 0.0, 0.0, Limits()), std::invalid_argument);
  EXPECT_THROW(DiscreteSE2({{0.0, 0.0}, {nan, 1.0}}, 0.0, 0.0, Limits()), std::invalid_argument);
  EXPECT_THROW(DiscreteSE2({{0.0, 0.0}}, nan, 0.0, Limits()), std::invalid_argument);
  DiscreteSE2Options bad;
  bad.delta_l_m = 0.0;
  EXPECT_THROW(DiscreteSE2({{0.0, 0.0}, {1.0, 0.0}}, 0.0, 0.0, Limits(), bad),
               std::invalid_argument);
  BaseLimits slow = Limits();
  slow.omega_max_radps = -1.0;
  EXPECT_THROW(DiscreteSE2({{0.0, 0.0}, {1.0, 0.0}}, 0.0, 0.0, slow), std::invalid_argument);
}

}  // namespace
}  // namespace topay
