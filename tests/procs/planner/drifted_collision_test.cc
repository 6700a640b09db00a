// The drifted robot against obstacles (procs/planner/drifted_collision.h): a robot beside its
// trajectory is checked where it will be, not where the trajectory is.
#include "procs/planner/drifted_collision.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "tests/common/arm_state.h"
#include "tests/common/make_box.h"

namespace topay::planner {
namespace {

constexpr int kJoints = 7;

class DriftedCollisionTest : public ::testing::Test {
 protected:
  // 4 m along +x in 8 s from (0, 0), rest to rest, the arm folded (BentArmState's joints) all along.
  DriftedCollisionTest() {
    const Eigen::VectorXd q = BentArmState(0.0, 0.0, 0.0).q_rad;
    auto t = std::make_shared<ArcYawTrajectory>(kJoints, 4, ArcYawTrajectory::Options{});
    Eigen::MatrixXd head = Eigen::MatrixXd::Zero(2 + kJoints, 3), tail = head;
    head.block(2, 0, kJoints, 1) = tail.block(2, 0, kJoints, 1) = q;
    tail(0, 0) = 4.0;
    Eigen::MatrixXd waypoints = Eigen::MatrixXd::Zero(2 + kJoints, 3);
    waypoints.row(0) << 0.5, 2.0, 3.5;
    for (int k = 0; k < 3; ++k) waypoints.block(2, k, kJoints, 1) = q;
    t->Update({0.0, 0.0}, head, tail, waypoints, Eigen::VectorXd::Constant(4, 2.0));
    active_.trajectory_id = 5;
    active_.start_utime = 10'000'000;
    active_.trajectory = t;
    // A box beside the route, lower than the base (only the base can touch it), 0.25 m clear
    // of the base along x in [2.5, 3.5]: the trajectory passes it, a base 0.3 m to its side
    // does not.
    scene_.boxes.push_back(MakeBox({3.0, base_radius_m_ + 0.25 + 0.25, 0.05}, {1.0, 0.5, 0.1}));
  }
  // The robot at 1 s along the trajectory (x = 0.03 m), off it by dy to the side.
  msgs::RobotStateEstimate RobotOff(double dy_m) const {
    msgs::RobotStateEstimate robot;
    robot.utime = active_.start_utime + 1'000'000;
    robot.state = active_.SampleAt(robot.utime).state;
    robot.state.y_m += dy_m;
    return robot;
  }

  RobotModel model_ = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                     TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  double base_radius_m_ = model_.base_cylinder.radius_m;
  ActiveTrajectory active_;
  Scene scene_;
  TrajectoryCollisionScanOptions scan_;
};

TEST_F(DriftedCollisionTest, SmallDriftIsNotCheckedAndAnyAxisBeyondItsToleranceIs) {
  const DriftCheckOptions o;
  EXPECT_FALSE(DriftWorthChecking({0.04, 0.04, 0.04}, o));
  EXPECT_TRUE(DriftWorthChecking({0.06, 0.0, 0.0}, o));
  EXPECT_TRUE(DriftWorthChecking({0.0, 0.06, 0.0}, o));
  EXPECT_TRUE(DriftWorthChecking({0.0, 0.0, 0.06}, o));
}

TEST_F(DriftedCollisionTest, ARobotBesideItsTrajectoryCollidesWhereTheTrajectoryDoesNot) {
  const SceneClearanceChecker checker(kinematics_, scene_);
  // The trajectory itself clears the box all along.
  ASSERT_FALSE(FirstPredictedCollision(*active_.trajectory, 0.0, 8.0, checker, scan_));
  // On it (no drift): nothing within 8 s.
  const msgs::RobotStateEstimate on = RobotOff(0.0);
  EXPECT_FALSE(FirstDriftedCollision(DriftedRobot(active_, on), 8.0, checker, scan_));
  // 0.3 m towards the box: it reaches the box's near end (x = 2.5 - base radius) about 5 s in.
  const std::optional<PredictedCollision> hit = FirstDriftedCollision(DriftedRobot(active_, RobotOff(0.3)), 8.0,
                                                                      checker, scan_);
  ASSERT_TRUE(hit);
  TrajectorySample at = active_.trajectory->MakePoint();
  active_.trajectory->Evaluate(hit->t_s, &at);
  EXPECT_GT(at.state.x_m, 2.5 - base_radius_m_ - 0.05);
  EXPECT_LT(at.state.x_m, 2.5);
  EXPECT_LE(hit->clearance.obstacle_m(), 0.0);
  // 0.3 m away from the box: clear.
  EXPECT_FALSE(FirstDriftedCollision(DriftedRobot(active_, RobotOff(-0.3)), 8.0, checker, scan_));
}

TEST_F(DriftedCollisionTest, OnlyTheHorizonAheadOfTheStateIsChecked) {
  const SceneClearanceChecker checker(kinematics_, scene_);
  const DriftedRobot drifted(active_, RobotOff(0.3));
  EXPECT_DOUBLE_EQ(drifted.state_time_s(), 1.0);
  EXPECT_FALSE(FirstDriftedCollision(drifted, 2.0, checker, scan_));  // up to 3 s: x < 1.2 m
  EXPECT_TRUE(FirstDriftedCollision(drifted, 6.0, checker, scan_));
}

TEST_F(DriftedCollisionTest, BadHorizonsAndOptionsAreRefused) {
  const SceneClearanceChecker checker(kinematics_, scene_);
  const DriftedRobot drifted(active_, RobotOff(0.3));
  EXPECT_THROW(FirstDriftedCollision(drifted, 0.0, checker, scan_), std::invalid_argument);
  EXPECT_THROW(FirstDriftedCollision(drifted, std::nan(""), checker, scan_), std::invalid_argument);
  TrajectoryCollisionScanOptions bad;
  bad.sample_period_s = 0.0;
  EXPECT_THROW(FirstDriftedCollision(drifted, 2.0, checker, bad), std::invalid_argument);
}

}  // namespace
}  // namespace topay::planner
