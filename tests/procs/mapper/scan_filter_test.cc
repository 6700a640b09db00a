#include "procs/mapper/scan_filter.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "sim/scenes/benchmark_scene.h"
#include "tests/core/robot/robot_test_model.h"
#include "tests/procs/mapper/mapper_test_support.h"

namespace topay::mapper {
namespace {

using testing::CloudOf;

// Every stage off but the one under test (ranges wide open, no ground, no margin, no grid).
ScanFilterOptions AllOff() {
  ScanFilterOptions o;
  o.range_min_m = 0.0;
  o.range_max_m = 20.0;  // the default: wide enough, and voxel leaves of 5 cm fit
  o.ground_max_z_m = -1000.0;
  o.self_margin_m = 0.0;
  o.no_state_radius_m = 0.0;
  o.voxel_leaf_m = 0.0;
  o.outlier_method = OutlierMethod::kNone;
  return o;
}

msgs::CheckedCloud CloudAt(const Eigen::Vector3d& p_WS, std::vector<Eigen::Vector3f> p_SP) {
  msgs::CheckedCloud cloud;
  cloud.X_WS.translation() = p_WS;
  cloud.p_SP = std::move(p_SP);
  return cloud;
}

// A square of side `side_m` in the plane x = `x_m` of S (z from 0.5 m up), points `step_m`
// apart, offset by a quarter step so that none lies on a leaf boundary of 2 steps.
std::vector<Eigen::Vector3f> Square(float x_m, float side_m, float step_m) {
  std::vector<Eigen::Vector3f> points;
  const int n = static_cast<int>(std::lround(side_m / step_m));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      points.emplace_back(x_m, (i + 0.25f) * step_m, 0.5f + (j + 0.25f) * step_m);
    }
  }
  return points;
}

class ScanFilterTest : public ::testing::Test {
 protected:
  ScanFilterTest() : model_(topay::testing::LoadTopayModel()), kinematics_(model_) {}

  ScanFilterSummary Run(const ScanFilterOptions& options, const msgs::CheckedCloud& cloud,
                        const std::optional<WholeBodyState>& state = std::nullopt) {
    ScanFilter filter(options, kinematics_);
    return filter.Filter(cloud, state, &out_);
  }

  RobotModel model_;
  Kinematics kinematics_;
  std::vector<Eigen::Vector3f> out_;
};

TEST_F(ScanFilterTest, RangeCropKeepsPointsWithinTheRangesAndMovesThemToW) {
  ScanFilterOptions o = AllOff();
  o.range_min_m = 0.1;
  o.range_max_m = 20.0;
  const msgs::CheckedCloud cloud =
      CloudAt({1, 2, 0.3}, {{0.05f, 0, 0}, {0.5f, 0, 0}, {0, 19.9f, 0}, {25.0f, 0, 0}});
  const ScanFilterSummary s = Run(o, cloud);
  EXPECT_EQ(s.num_input, 4);
  EXPECT_EQ(s.num_after_range, 2);
  ASSERT_EQ(out_.size(), 2u);
  EXPECT_TRUE(out_[0].isApprox(Eigen::Vector3f(1.5f, 2, 0.3f)));
  EXPECT_TRUE(out_[1].isApprox(Eigen::Vector3f(1, 21.9f, 0.3f)));
}

TEST_F(ScanFilterTest, NonFinitePointsAreDroppedAndCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const msgs::CheckedCloud cloud =
      CloudAt({0, 0, 0.3}, {{nan, 0, 0}, {1, inf, 0}, {1, 0, -inf}, {3, 0, 0}, {nan, nan, nan}});  // 3 m: beyond no_state_radius_m
  const ScanFilterSummary s = Run(ScanFilterOptions{}, cloud);
  EXPECT_EQ(s.num_non_finite, 4);
  EXPECT_EQ(s.num_output, 1);
  ASSERT_EQ(out_.size(), 1u);
  EXPECT_TRUE(out_[0].allFinite());
}

TEST_F(ScanFilterTest, GroundPointsOfASimulatedFloorAreRemovedObstaclesKept) {
  sim::LidarOptions lidar;  // 2 cm range noise
  lidar.ground_plane = true;
  sim::LidarScanner scanner(lidar, kinematics_, 5);
  const GeneratedScene room = GenerateBenchmarkScene(SceneKind::kTables, 4);
  scanner.SetWorld(room.scene.boxes);
  Rng rng(8);
  const WholeBodyState state =
      testing::ClearState(kinematics_, room.scene, 0.3, &rng, model_.stow_q_rad);
  const sim::LidarScan scan = scanner.Scan(state, 0.0);
  ScanFilterOptions o = AllOff();
  o.ground_max_z_m = 0.05;
  const ScanFilterSummary floor =
      Run(o, CloudOf(scan, [](int target) { return target == sim::kTargetGround; }));
  EXPECT_GT(floor.num_input, 1000);
  EXPECT_EQ(floor.num_after_ground, 0) << floor.Report();
  const ScanFilterSummary boxes = Run(o, CloudOf(scan, [](int target) { return target >= 0; }));
  // Box points lower than 5 cm (table legs' feet) go too: a few percent at most.
  EXPECT_GT(boxes.num_after_ground, 0.95 * boxes.num_input) << boxes.Report();
}

TEST_F(ScanFilterTest, NoPointOfTheRobotSurvivesAndFewOthersAreRemoved) {
  sim::LidarScanner scanner(sim::LidarOptions{}, kinematics_, 11);  // 2 cm range noise
  const GeneratedScene room = GenerateBenchmarkScene(SceneKind::kTables, 2);
  scanner.SetWorld(room.scene.boxes);
  const ScanFilterOptions o;  // defaults: margin 0.12 m
  ScanFilterOptions bare = o;
  bare.self_margin_m = 0.0;
  Rng rng(21);
  int self_points = 0, scans_with_arm_in_view = 0, escaped_without_margin = 0;
  for (int trial = 0; trial < 12; ++trial) {
    // Random arm states (the arm in front of, beside or behind the sensor), upright, stowed.
    Eigen::VectorXd q;
    if (trial == 0) q = Eigen::VectorXd::Zero(model_.num_joints());
    if (trial == 1) q = model_.stow_q_rad;
    const WholeBodyState state = testing::ClearState(kinematics_, room.scene, 0.3, &rng, q);
    const sim::LidarScan scan = scanner.Scan(state, 0.1 * trial);
    const msgs::CheckedCloud self_cloud =
        CloudOf(scan, [](int target) { return target == sim::kTargetSelf; });
    const ScanFilterSummary self = Run(o, self_cloud, state);
    EXPECT_EQ(self.num_output, 0) << "trial " << trial << ": " << self.Report();
    self_points += self.num_input;
    escaped_without_margin += Run(bare, self_cloud, state).num_after_self;
    if (self.num_input > 100) ++scans_with_arm_in_view;
    const ScanFilterSummary others =
        Run(o, CloudOf(scan, [](int target) { return target != sim::kTargetSelf; }), state);
    EXPECT_LE(others.num_after_ground - others.num_after_self, 0.002 * others.num_after_ground)
        << "trial " << trial << ": " << others.Report();
  }
  EXPECT_GT(self_points, 2000);
  EXPECT_GE(scans_with_arm_in_view, 4);
  // The margin does the work: the range noise puts about half the body's points outside it.
  EXPECT_GT(escaped_without_margin, self_points / 4);
  std::printf("self points %d, of which %d outside the bare body\n", self_points,
              escaped_without_margin);
}

// A mission's worth of scans of the robot standing stowed in an empty room (finding 29): with
// the 2 cm Gaussian range noise a body point lands beyond a 4 sigma margin (0.08 m) about 3
// times in 100,000; over a mission's ~600 scans some do, and each becomes a voxel hugging the
// robot that no later ray clears (the body hides it and its points are filtered). The default
// margin (6 sigma, 0.12 m) lets none through.
TEST_F(ScanFilterTest, NoPointOfTheStandingRobotSurvivesAMissionOfScans) {
  sim::LidarScanner scanner(sim::LidarOptions{}, kinematics_, 29);
  scanner.SetWorld({});
  WholeBodyState state;
  state.q_rad = model_.stow_q_rad;
  ScanFilterOptions o;
  ScanFilterOptions four_sigma = o;
  four_sigma.self_margin_m = 0.08;
  int points = 0, survivors = 0, survivors_at_four_sigma = 0;
  for (int scan = 0; scan < 600; ++scan) {
    const msgs::CheckedCloud cloud = CloudOf(scanner.Scan(state, 0.1 * scan));
    points += static_cast<int>(cloud.p_SP.size());
    survivors += Run(o, cloud, state).num_after_self;
    survivors_at_four_sigma += Run(four_sigma, cloud, state).num_after_self;
  }
  std::printf("%d body points in 600 scans: %d beyond 0.08 m, %d beyond %.2f m\n", points,
              survivors_at_four_sigma, survivors, o.self_margin_m);
  EXPECT_GT(points, 100000);
  EXPECT_GT(survivors_at_four_sigma, 0);  // what left voxels hugging the robot (measured: 6)
  EXPECT_EQ(survivors, 0);
}

TEST_F(ScanFilterTest, WithoutAStateThePointsNearTheRobotAreDroppedWithAWarning) {
  sim::LidarScanner scanner(sim::LidarOptions{}, kinematics_, 3);
  scanner.SetWorld({});
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(model_.num_joints());  // upright: in view
  const msgs::CheckedCloud cloud = CloudOf(scanner.Scan(state, 0.0));
  ASSERT_GT(cloud.p_SP.size(), 50u);
  ScanFilterOptions o = AllOff();
  o.self_margin_m = 0.08;
  o.no_state_radius_m = 1.5;
  // The world is empty: every point is the robot's own, within reach of the sensor.
  const ScanFilterSummary none = Run(o, cloud);
  EXPECT_TRUE(none.self_filter_skipped);
  EXPECT_EQ(none.num_after_self, 0);
  EXPECT_NE(none.Report().find("warning: no robot state"), std::string::npos) << none.Report();
  ScanFilterOptions keep = o;
  keep.no_state_radius_m = 0.0;  // off: kept
  const ScanFilterSummary kept = Run(keep, cloud);
  EXPECT_TRUE(kept.self_filter_skipped);
  EXPECT_EQ(kept.num_after_self, kept.num_after_ground);
  WholeBodyState bad = state;
  bad.q_rad(2) = std::numeric_limits<double>::quiet_NaN();
  const ScanFilterSummary nan = Run(o, cloud, bad);
  EXPECT_TRUE(nan.self_filter_skipped);
  EXPECT_NE(nan.warning.find("not finite"), std::string::npos) << nan.warning;
  bad.q_rad = Eigen::VectorXd::Zero(2);  // the wrong joint count
  EXPECT_TRUE(Run(o, cloud, bad).self_filter_skipped);
  const ScanFilterSummary good = Run(o, cloud, state);
  EXPECT_FALSE(good.self_filter_skipped);
  EXPECT_TRUE(good.warning.empty());
  EXPECT_EQ(good.num_output, 0);
}

TEST_F(ScanFilterTest, VoxelGridKeepsOnePointPerOccupiedLeaf) {
  ScanFilterOptions o = AllOff();
  o.voxel_leaf_m = 0.05;
  // 1 x 1 m at 2.5 cm: 1600 points, four per 5 cm leaf in the plane.
  const msgs::CheckedCloud cloud = CloudAt({0, 0, 0}, Square(2.0125f, 1.0f, 0.025f));
  const auto leaf_of = [](const Eigen::Vector3f& p) {
    const float inverse = 1.0f / 0.05f;
    return std::make_tuple(static_cast<int>(std::floor(p.x() * inverse)),
                           static_cast<int>(std::floor(p.y() * inverse)),
                           static_cast<int>(std::floor(p.z() * inverse)));
  };
  std::set<std::tuple<int, int, int>> input_leaves;
  for (const Eigen::Vector3f& p : cloud.p_SP) input_leaves.insert(leaf_of(p));
  const ScanFilterSummary s = Run(o, cloud);
  EXPECT_EQ(s.num_after_self, 1600);
  EXPECT_EQ(s.num_after_voxel, static_cast<int>(input_leaves.size()));
  EXPECT_EQ(input_leaves.size(), 400u);
  std::set<std::tuple<int, int, int>> output_leaves;
  for (const Eigen::Vector3f& p : out_) {
    EXPECT_TRUE(input_leaves.count(leaf_of(p))) << p.transpose();
    EXPECT_TRUE(output_leaves.insert(leaf_of(p)).second) << "two points in a leaf";
  }
  // Off: every point passes.
  EXPECT_EQ(Run(AllOff(), cloud).num_after_voxel, 1600);
}

TEST_F(ScanFilterTest, OutlierRemovalRemovesIsolatedPointsAndKeepsSurfaces) {
  std::vector<Eigen::Vector3f> points = Square(3.0f, 1.0f, 0.02f);  // 2500 points
  const std::vector<Eigen::Vector3f> isolated = {{5, 3, 1}, {1, -2, 0.7f}, {4, 0, 2}};
  points.insert(points.end(), isolated.begin(), isolated.end());
  const msgs::CheckedCloud cloud = CloudAt({0, 0, 0}, points);
  for (OutlierMethod method : {OutlierMethod::kRadius, OutlierMethod::kStatistical}) {
    ScanFilterOptions o = AllOff();
    o.voxel_leaf_m = 0.05;  // as by default: the outliers are removed from the leaves' points
    o.outlier_method = method;
    const ScanFilterSummary s = Run(o, cloud);
    EXPECT_EQ(s.num_after_voxel, 400 + 3) << OutlierMethodName(method);
    EXPECT_EQ(s.num_output, 400) << OutlierMethodName(method) << ": " << s.Report();
    for (const Eigen::Vector3f& p : out_) EXPECT_NEAR(p.x(), 3.0f, 1e-4f);
  }
}

TEST_F(ScanFilterTest, EmptyAndHugeCloudsPassWithoutTrouble) {
  EXPECT_EQ(Run(ScanFilterOptions{}, msgs::CheckedCloud{}).num_output, 0);
  // 200,000 points (the input limit) of noise in a 10 m cube: filtered, bounded output.
  Rng rng(1);
  std::vector<Eigen::Vector3f> points(200000);
  for (Eigen::Vector3f& p : points) {
    p = Eigen::Vector3f(rng.Uniform(-5, 5), rng.Uniform(-5, 5), rng.Uniform(-5, 5));
  }
  const ScanFilterSummary s = Run(ScanFilterOptions{}, CloudAt({0, 0, 1}, points));
  EXPECT_EQ(s.num_input, 200000);
  EXPECT_GT(s.num_output, 0);
  EXPECT_LE(s.num_output, s.num_after_self);
}

TEST_F(ScanFilterTest, InvalidOptionsAreRejected) {
  ScanFilterOptions o;
  o.range_max_m = -1.0;
  EXPECT_THROW(ScanFilter(o, kinematics_), ConfigError);
}

}  // namespace
}  // namespace topay::mapper
