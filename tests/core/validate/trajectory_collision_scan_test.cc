#include "core/validate/trajectory_collision_scan.h"

#include <gtest/gtest.h>

#include "core/robot/kinematics.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

// A rest-to-rest drive of 4 m along +x in 8 s from the origin, joints held at zero.
ArcYawTrajectory StraightDrive(int num_joints) {
  ArcYawTrajectory trajectory(num_joints, 4, {});
  const int D = num_joints + 2;
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(D, 3);
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(D, 3);
  tail(0, 0) = 4.0;
  Eigen::MatrixXd waypoints = Eigen::MatrixXd::Zero(D, 3);
  waypoints.row(0) << 0.5, 2.0, 3.5;
  trajectory.Update(Eigen::Vector2d::Zero(), head, tail, waypoints, Eigen::VectorXd::Constant(4, 2.0));
  return trajectory;
}

class TrajectoryCollisionScanTest : public ::testing::Test {
 protected:
  RobotModel model_ = testing::LoadTopayModel();
  Kinematics kinematics_{model_};
  ArcYawTrajectory drive_ = StraightDrive(model_.num_joints());
};

TEST_F(TrajectoryCollisionScanTest, ClearRouteHasNoCollision) {
  Scene scene;
  scene.boxes.push_back(MakeBox({2.0, 3.0, 0.5}, {1.0, 1.0, 1.0}));  // 3 m to the side
  const SceneClearanceChecker checker(kinematics_, scene);
  EXPECT_FALSE(FirstPredictedCollision(drive_, 0.0, drive_.duration_s(), checker).has_value());
}

TEST_F(TrajectoryCollisionScanTest, BoxOnTheRouteIsFoundWhereTheBaseFirstTouchesIt) {
  Scene scene;
  scene.boxes.push_back(MakeBox({3.0, 0.0, 0.5}, {0.4, 0.4, 1.0}));
  const SceneClearanceChecker checker(kinematics_, scene);
  const auto hit = FirstPredictedCollision(drive_, 0.0, drive_.duration_s(), checker);
  ASSERT_TRUE(hit.has_value());
  EXPECT_LE(hit->clearance.obstacle_m(), 0.0);
  // One period earlier the robot was still clear: the first collision, not any.
  TrajectorySample point = drive_.MakePoint();
  drive_.Evaluate(hit->t_s - 0.02, &point);
  EXPECT_GT(checker.Compute(point.state).obstacle_m(), 0.0);
  // A margin finds it earlier; a scan that ends before it finds nothing.
  TrajectoryCollisionScanOptions margin;
  margin.obstacle_margin_m = 0.3;
  const auto early = FirstPredictedCollision(drive_, 0.0, drive_.duration_s(), checker, margin);
  ASSERT_TRUE(early.has_value());
  EXPECT_LT(early->t_s, hit->t_s);
  EXPECT_FALSE(FirstPredictedCollision(drive_, 0.0, hit->t_s - 0.05, checker).has_value());
}

// Any motion, not only a trajectory's: the drive moved 1 m to the side from t = 4 s on (as a
// robot carried along it with an error would be) meets a box the drive itself passes.
TEST_F(TrajectoryCollisionScanTest, AnyMotionIsScannedAtItsOwnTimes) {
  Scene scene;
  scene.boxes.push_back(MakeBox({3.0, 1.0, 0.5}, {0.4, 0.4, 1.0}));  // 1 m to the left of the route
  const SceneClearanceChecker checker(kinematics_, scene);
  ASSERT_FALSE(FirstPredictedCollision(drive_, 0.0, drive_.duration_s(), checker).has_value());
  const TrajectorySampler beside = [&](double t_s, TrajectorySample* sample) {
    drive_.Evaluate(t_s, sample);
    if (t_s >= 4.0) sample->state.y_m += 1.0;
  };
  const auto hit = FirstPredictedCollisionOf(beside, drive_.MakePoint(), 0.0, drive_.duration_s(), checker);
  ASSERT_TRUE(hit.has_value());
  EXPECT_GE(hit->t_s, 4.0);
  EXPECT_LE(hit->clearance.obstacle_m(), 0.0);
  EXPECT_FALSE(FirstPredictedCollisionOf(beside, drive_.MakePoint(), 0.0, 3.98, checker).has_value());
  EXPECT_THROW(FirstPredictedCollisionOf(beside, drive_.MakePoint(), 0.0, 1e6, checker), std::invalid_argument);
}

TEST_F(TrajectoryCollisionScanTest, RejectsBadOptions) {
  const SceneClearanceChecker checker(kinematics_, Scene{});
  TrajectoryCollisionScanOptions bad;
  bad.sample_period_s = 0.0;
  EXPECT_THROW(FirstPredictedCollision(drive_, 0.0, 1.0, checker, bad), std::invalid_argument);
  EXPECT_THROW(FirstPredictedCollision(drive_, std::nan(""), 1.0, checker), std::invalid_argument);
}

}  // namespace
}  // namespace topay
