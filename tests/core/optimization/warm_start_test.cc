#include "core/optimization/warm_start.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/planning/discrete_se2.h"
#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::ReadyJoints;
using testing::StraightPath;

constexpr int kPanels = 12;

class WarmStartTest : public ::testing::Test {
 protected:
  WarmStartTest() : model_(testing::LoadTopayModel()) {}
  // The authors' code's 1.5 s pieces unless the test says otherwise (the default is 1.0 s).
  static WarmStartOptions FactsSheetPieces() {
    WarmStartOptions options;
    options.piece_duration_s = 1.5;
    return options;
  }
  WarmStart Make(const WholeBodyPath& path, const WholeBodyState& start,
                 const WarmStartOptions& options = FactsSheetPieces()) const {
    return MakeWarmStart(path, start, limits_, model_.joint_limits, kPanels, options);
  }
  RobotModel model_;
  BaseLimits limits_;  // v 1, a 0.8, omega 0.9, beta 1
};

// A 6 m straight drive: one trapezoid, 1.25 s ramps of 0.625 m at 0.8 m/s^2 and 4.75 s at
// 1 m/s: 7.25 s, so M = ceil(7.25 / 1.5) = 5 pieces of 1.45 s.
TEST_F(WarmStartTest, StraightDriveFollowsOneTrapezoid) {
  const WholeBodyState start = MakeState(1.0, 2.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(7.0, 2.0, 0.0, ReadyJoints());
  const WarmStart warm = Make(StraightPath(start, goal), start);
  EXPECT_NEAR(warm.total_duration_s, 7.25, 1e-9);
  ASSERT_EQ(warm.num_pieces, 5);
  EXPECT_TRUE(warm.durations_s.isApprox(Eigen::VectorXd::Constant(5, 1.45), 1e-12));
  // s at t = 1.45 s: 0.625 m + 0.2 s at 1 m/s.
  EXPECT_NEAR(warm.waypoints(0, 0), 0.825, 1e-9);
  EXPECT_NEAR(warm.end(0), 6.0, 1e-12);
  EXPECT_NEAR(warm.end(1), 0.0, 1e-12);
  EXPECT_TRUE(warm.end.tail(7).isApprox(ReadyJoints(), 1e-12));
  // The reference starts at the start and ends at the goal.
  EXPECT_TRUE(warm.reference.p_W.col(0).isApprox(Eigen::Vector2d(1.0, 2.0), 1e-12));
  EXPECT_TRUE(
      warm.reference.p_W.col(5 * (kPanels + 1) - 1).isApprox(Eigen::Vector2d(7.0, 2.0), 1e-9));
  EXPECT_EQ(warm.reference.p_W.cols(), 5 * (kPanels + 1));
  // Same as DiscreteSE2's trapezoid.
  EXPECT_NEAR(warm.total_duration_s, TrapezoidArrivalTime(6.0, 6.0, 1.0, 0.8), 1e-12);
}

TEST_F(WarmStartTest, ArcLengthIsSignedWhenDrivingBackwards) {
  const WholeBodyState start = MakeState(0.0, 0.0, std::numbers::pi, ReadyJoints());
  WholeBodyPath path;
  for (int i = 0; i <= 4; ++i) {
    path.states.push_back(MakeState(0.5 * i, 0.0, std::numbers::pi, ReadyJoints()));
    path.times_s.push_back(i);
  }
  const WarmStart warm = Make(path, start);
  EXPECT_NEAR(warm.end(0), -2.0, 1e-12);
  EXPECT_LT(warm.waypoints(0, 0), 0.0);
}

// A half turn in place across the +-pi wrap: s stays 0, yaw is unwrapped continuously, and
// the time is the yaw trapezoid's (omega 0.9, beta 1).
TEST_F(WarmStartTest, TurnInPlaceKeepsArcLengthAndUnwrapsYaw) {
  const WholeBodyState start = MakeState(0.0, 0.0, 2.5, ReadyJoints());
  const WholeBodyState goal = MakeState(0.0, 0.0, 2.5 + 2.0 - 2 * std::numbers::pi, ReadyJoints());
  const WarmStart warm = Make(StraightPath(start, goal), start);
  EXPECT_NEAR(warm.end(1), 4.5, 1e-12);  // continuous, not wrapped to -1.78
  EXPECT_EQ(warm.end(0), 0.0);
  for (int i = 0; i < warm.waypoints.cols(); ++i) EXPECT_EQ(warm.waypoints(0, i), 0.0);
  EXPECT_NEAR(warm.total_duration_s, TrapezoidArrivalTime(2.0, 2.0, 0.9, 1.0), 1e-12);
  EXPECT_EQ(warm.num_pieces, 3);  // 2.9 s / 1.5 s -> 2, at least 3
}

// Arm-only motion: the slowest joint's trapezoid (2.35 rad/s, 6.28 rad/s^2) sets the time.
TEST_F(WarmStartTest, ArmOnlyMotionIsTimedByTheSlowestJoint) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  Eigen::VectorXd q = ReadyJoints();
  q(2) += 2.0;
  q(5) -= 0.5;
  const WarmStart warm = Make(StraightPath(start, MakeState(0.0, 0.0, 0.0, q)), start);
  EXPECT_NEAR(warm.total_duration_s, TrapezoidArrivalTime(2.0, 2.0, 2.35, 6.28), 1e-12);
  EXPECT_NEAR(warm.end(4), q(2), 1e-12);
}

// An L of two 4 m drives with a quarter turn in place at the corner: the warm start is timed
// rest to rest (drive, turn, drive), but its piece count comes from the continuous profile,
// one trapezoid over the 8 m (authors' code: total time / 1.5 s).
TEST_F(WarmStartTest, PieceCountFollowsTheContinuousProfile) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const double half_pi = 0.5 * std::numbers::pi;
  WholeBodyPath path;
  path.states = {start, MakeState(4.0, 0.0, 0.0, ReadyJoints()),
                 MakeState(4.0, 0.0, half_pi, ReadyJoints()),
                 MakeState(4.0, 4.0, half_pi, ReadyJoints())};
  path.times_s = {0.0, 1.0, 2.0, 3.0};
  const WarmStart warm = Make(path, start);
  const double drive = TrapezoidArrivalTime(4.0, 4.0, 1.0, 0.8);
  const double turn = TrapezoidArrivalTime(half_pi, half_pi, 0.9, 1.0);
  EXPECT_NEAR(warm.total_duration_s, 2.0 * drive + turn, 1e-9);
  const double continuous = TrapezoidArrivalTime(8.0, 8.0, 1.0, 0.8);  // 9.25 s
  EXPECT_NEAR(warm.continuous_duration_s, continuous, 1e-12);
  ASSERT_EQ(warm.num_pieces, static_cast<int>(std::ceil(continuous / 1.5)));  // 7, not 9
  EXPECT_TRUE(warm.durations_s.isApprox(
      Eigen::VectorXd::Constant(warm.num_pieces, warm.total_duration_s / warm.num_pieces), 1e-12));
  EXPECT_NEAR(warm.end(0), 8.0, 1e-12);
  EXPECT_NEAR(warm.end(1), half_pi, 1e-12);
}

TEST_F(WarmStartTest, PieceCountOptions) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyPath path = StraightPath(start, MakeState(20.0, 0.0, 0.0, ReadyJoints()));
  WarmStartOptions options = FactsSheetPieces();
  options.min_pieces = options.max_pieces = 10;
  EXPECT_EQ(Make(path, start, options).num_pieces, 10);
  const WarmStart slow = [&] {
    WarmStartOptions half = FactsSheetPieces();
    half.rate_fraction = 0.5;
    return Make(path, start, half);
  }();
  EXPECT_GT(slow.total_duration_s, 1.9 * Make(path, start).total_duration_s);
  // A path that does not move at all still gets min_duration_s and 3 pieces.
  WholeBodyPath still;
  still.states = {start, start};
  still.times_s = {0.0, 1.0};
  const WarmStart warm = Make(still, start);
  EXPECT_EQ(warm.num_pieces, 3);
  EXPECT_NEAR(warm.total_duration_s, 1.0, 1e-12);
  EXPECT_TRUE(warm.reference.p_W.allFinite());
}

TEST_F(WarmStartTest, RejectsBadInputNamingIt) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyPath path = StraightPath(start, MakeState(3.0, 0.0, 0.0, ReadyJoints()));
  const auto expect_message = [&](const WholeBodyPath& p, const WholeBodyState& s,
                                  const std::string& text) {
    try {
      Make(p, s);
      ADD_FAILURE() << "no exception for " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  expect_message(WholeBodyPath(), start, "no states");
  WholeBodyPath bad = path;
  bad.states[1].q_rad(3) = std::numeric_limits<double>::quiet_NaN();
  expect_message(bad, start, "path state 1 is not finite");
  bad = path;
  bad.states[2].q_rad.resize(5);
  expect_message(bad, start, "path state 2 has 5 joints");
  expect_message(path, MakeState(0.5, 0.0, 0.0, ReadyJoints()), "away from the start");
}

}  // namespace
}  // namespace topay

namespace topay {
namespace {

// Issue 18: a moving start. The 6 m straight drive of StraightDriveFollowsOneTrapezoid from
// 1 m/s needs no ramp up: 4.75 + 0.625 m at 1 m/s then 1.25 s of braking = 6.625 s; from
// 0.5 m/s: 0.625 s ramp (0.46875 m) + 4.90625 s cruise + 1.25 s brake = 6.78125 s. The
// first waypoint lies where the moving base gets to.
class MovingWarmStartTest : public ::testing::Test {
 protected:
  MovingWarmStartTest() : model_(testing::LoadTopayModel()) {
    start_ = testing::MakeState(1.0, 2.0, 0.0, testing::ReadyJoints());
    goal_ = testing::MakeState(7.0, 2.0, 0.0, testing::ReadyJoints());
    options_.piece_duration_s = 1.5;
  }
  WarmStart Make(double v_mps) const {
    WholeBodyRates rates;
    rates.v_mps = v_mps;
    return MakeWarmStart(testing::StraightPath(start_, goal_), start_, rates, limits_,
                         model_.joint_limits, kPanels, options_);
  }
  RobotModel model_;
  BaseLimits limits_;
  WholeBodyState start_, goal_;
  WarmStartOptions options_;
};

TEST_F(MovingWarmStartTest, FirstRunStartsAtTheCurrentSpeed) {
  const WarmStart fast = Make(1.0);
  EXPECT_NEAR(fast.total_duration_s, 6.625, 1e-9);
  ASSERT_EQ(fast.num_pieces, 5);  // from the continuous profile, as at rest
  // s at T = 6.625 / 5 = 1.325 s: cruising at 1 m/s from the start.
  EXPECT_NEAR(fast.waypoints(0, 0), 1.325, 1e-9);
  EXPECT_NEAR(fast.path_times_s(fast.path_times_s.size() - 1), 6.625, 1e-9);
  const WarmStart half = Make(0.5);
  EXPECT_NEAR(half.total_duration_s, 6.78125, 1e-9);
  // At T = 6.78125 / 5 = 1.35625 s: 0.46875 m + 0.73125 s at 1 m/s.
  EXPECT_NEAR(half.waypoints(0, 0), 0.46875 + (1.35625 - 0.625), 1e-9);
}

TEST_F(MovingWarmStartTest, RestOrOpposingSpeedGivesTheRestWarmStart) {
  const WarmStart rest = MakeWarmStart(testing::StraightPath(start_, goal_), start_, limits_,
                                       model_.joint_limits, kPanels, options_);
  for (double v : {0.0, -0.8}) {  // -0.8: the path drives forwards, the base backwards
    const WarmStart warm = Make(v);
    EXPECT_EQ(warm.total_duration_s, rest.total_duration_s) << v;
    EXPECT_EQ(warm.durations_s, rest.durations_s) << v;
    EXPECT_EQ(warm.waypoints, rest.waypoints) << v;
    EXPECT_EQ(warm.reference.p_W, rest.reference.p_W) << v;
  }
}

TEST_F(MovingWarmStartTest, ShorterThanTheBrakingDistanceBrakesHarder) {
  // 0.3 m at 1 m/s: one deceleration of 1 / 0.6 m/s^2 over 0.6 s.
  goal_.x_m = 1.3;
  const WarmStart warm = Make(1.0);
  EXPECT_NEAR(warm.path_times_s(warm.path_times_s.size() - 1), 0.6, 1e-6);
}

TEST_F(MovingWarmStartTest, NonFiniteRatesThrow) {
  EXPECT_THROW(Make(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace topay
