// The protective field's scan intake: a simulated LiDAR scan (sim/lidar: the robot's own base
// and arm in view) comes out in W with every self hit removed and every obstacle point kept;
// scans it cannot use (malformed, no robot state near their time) say why.

#include "procs/tracker/field_scan_intake.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/io/robot_loader.h"
#include "procs/sim/sim_messages.h"
#include "core/geometry/oriented_box.h"
#include "sim/lidar/lidar_scanner.h"

namespace topay::tracker {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;

class FieldScanIntakeTest : public ::testing::Test {
 protected:
  FieldScanIntakeTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {
    state_.x_m = 1.0;
    state_.y_m = 2.0;
    state_.yaw_rad = 0.3;
    state_.q_rad = Eigen::VectorXd::Zero(model_.num_joints());
    state_.q_rad(1) = 0.6;  // the arm leaning forward, in the LiDAR's view
    box_.center_W_m = Eigen::Vector3d(1.0, 2.0, 0.25) + 1.5 * Eigen::Vector3d(std::cos(0.3), std::sin(0.3), 0.0);
    box_.size_m = Eigen::Vector3d(0.3, 0.6, 0.5);
    box_.yaw_rad = 0.3;
  }

  // A scan of the box with the robot at state_, as topay-sim publishes it.
  point_cloud_t ScanMessage(sim::LidarScan* scan_out) {
    sim::LidarScanner scanner(sim::LidarOptions{}, kinematics_, 7);
    scanner.SetWorld({box_});
    *scan_out = scanner.Scan(state_, 0.0);
    return simproc::ToPointCloud({scan_out->t_s, scan_out->X_WS, scan_out->p_SP}, kT0, "lidar");
  }

  RobotModel model_;
  Kinematics kinematics_;
  WholeBodyState state_;
  OrientedBox box_;
};

TEST_F(FieldScanIntakeTest, SelfHitsAreRemovedAndTheObstacleKeptInTheWorld) {
  sim::LidarScan scan;
  const point_cloud_t msg = ScanMessage(&scan);
  int box_points = 0;
  for (const std::int32_t target : scan.target) box_points += target == 0 ? 1 : 0;
  ASSERT_GT(scan.self_hits, 100);  // the test means something: the robot sees itself
  ASSERT_GT(box_points, 100);

  FieldScanIntake intake(model_, 0.12);
  intake.AddState(kT0 - 10'000, state_);
  intake.AddState(kT0 + 10'000, state_);
  std::vector<Eigen::Vector3f> p_WP;
  const std::optional<std::string> error = intake.Take(msg, &p_WP);
  ASSERT_FALSE(error) << *error;
  EXPECT_EQ(intake.last_self_points(), scan.self_hits);
  EXPECT_EQ(static_cast<int>(p_WP.size()), box_points);
  for (const Eigen::Vector3f& p : p_WP) {  // on the box's surface, within the range noise
    EXPECT_LT(SignedDistanceToBox(box_, p.cast<double>()), 0.12);
    EXPECT_GT(SignedDistanceToBox(box_, p.cast<double>()), -0.12);
  }
}

TEST_F(FieldScanIntakeTest, AScanWithoutARobotStateNearItsTimeIsNotUsed) {
  sim::LidarScan scan;
  const point_cloud_t msg = ScanMessage(&scan);
  FieldScanIntake intake(model_, 0.12);
  std::vector<Eigen::Vector3f> p_WP{Eigen::Vector3f::Zero()};
  std::optional<std::string> error = intake.Take(msg, &p_WP);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("no robot state"), std::string::npos) << *error;
  EXPECT_TRUE(p_WP.empty());
  intake.AddState(kT0 - 500'000, state_);  // 0.5 s before the scan: too old to filter it with
  error = intake.Take(msg, &p_WP);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("no robot state"), std::string::npos) << *error;
}

TEST_F(FieldScanIntakeTest, AMalformedScanSaysWhichField) {
  sim::LidarScan scan;
  point_cloud_t msg = ScanMessage(&scan);
  FieldScanIntake intake(model_, 0.12);
  intake.AddState(kT0, state_);
  std::vector<Eigen::Vector3f> p_WP;
  msg.num_coords -= 1;
  std::optional<std::string> error = intake.Take(msg, &p_WP);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("num_coords"), std::string::npos) << *error;
  msg.num_coords += 1;
  msg.quat_WS[0] = std::nan("");
  error = intake.Take(msg, &p_WP);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("quat_WS"), std::string::npos) << *error;
  EXPECT_THROW(FieldScanIntake(model_, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace topay::tracker
