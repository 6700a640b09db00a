#include "sim/lidar/lidar_scanner.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/primitive_box_distance.h"
#include "sim/lidar/ray_primitives.h"
#include "sim/scenes/benchmark_scene.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

WholeBodyState ArmState(double x, double y, double yaw, const Eigen::VectorXd& q) {
  WholeBodyState state;
  state.x_m = x;
  state.y_m = y;
  state.yaw_rad = yaw;
  state.q_rad = q;
  return state;
}

class LidarScannerTest : public ::testing::Test {
 protected:
  LidarScannerTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  WholeBodyState Upright(double x = 0, double y = 0, double yaw = 0) const {
    return ArmState(x, y, yaw, Eigen::VectorXd::Zero(model_.num_joints()));
  }
  WholeBodyState Stowed(double x = 0, double y = 0, double yaw = 0) const {
    return ArmState(x, y, yaw, model_.stow_q_rad);
  }
  static LidarOptions Exact() {
    LidarOptions o;
    o.range_noise_sigma_m = 0.0;
    return o;
  }
  // The nearest box along the ray by testing every box (the reference).
  static double BruteForceRange(const std::vector<OrientedBox>& boxes, const Eigen::Vector3d& o,
                                const Eigen::Vector3d& d, int* box) {
    double best = kNoHit;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
      const double t = RayBoxEntry(boxes[i], o, d);
      if (t < best) best = t, *box = i;
    }
    return best;
  }
  // Signed distance of a world point to the robot's body at the state of the last scan.
  double BodyDistance(const WholeBodyState& state, const Eigen::Vector3d& p_W) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(state, &cache);
    double best = kNoHit;
    for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
      best = std::min(best, (p_W - cache.p_WS[s]).norm() - model_.spheres[s].radius_m);
    }
    // The base cylinder: a solid of revolution about the base axis, z in [0, height].
    const double radial =
        (p_W.head<2>() - cache.X_WB.translation().head<2>()).norm() - model_.base_cylinder.radius_m;
    const double vertical =
        std::max(-p_W.z(), p_W.z() - model_.base_cylinder.height_m);
    return std::min(best, CombineProductSignedDistance(radial, vertical));
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(LidarScannerTest, PointsLieOnBoxSurfacesWithinTheNoise) {
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 11).scene;
  LidarOptions options;  // sigma 2 cm
  LidarScanner scanner(options, kinematics_, 42);
  scanner.SetWorld(scene.boxes);
  double sum = 0.0, sum_squares = 0.0;
  int checked = 0;
  for (const Eigen::Vector3d& pose : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-6, 4, 2.0)}) {
    const WholeBodyState state = Stowed(pose.x(), pose.y(), pose.z());
    const LidarScan scan = scanner.Scan(state, 1.0);
    ASSERT_EQ(scan.rays, 20000);
    ASSERT_GT(scan.p_SP.size(), 10000u);
    const Eigen::Vector3d o = scan.X_WS.translation();
    for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
      if (scan.target[k] < 0) continue;
      const Eigen::Vector3d p_SP = scan.p_SP[k].cast<double>();
      const double range = p_SP.norm();
      const Eigen::Vector3d d_W = scan.X_WS.linear() * (p_SP / range);
      int box = -1;
      const double exact = BruteForceRange(scene.boxes, o, d_W, &box);
      ASSERT_LT(exact, 40.0);
      // The self-hit check came first: the body is not nearer than the box.
      ASSERT_GT(BodyDistance(state, o + exact * d_W), -1e-6);
      const double z = (range - exact) / options.range_noise_sigma_m;
      ASSERT_LT(std::abs(z), 6.0) << k;
      if (box != scan.target[k]) {  // only where two boxes are hit at the same range
        EXPECT_NEAR(RayBoxEntry(scene.boxes[scan.target[k]], o, d_W), exact, 1e-5);
      }
      sum += z;
      sum_squares += z * z;
      ++checked;
    }
  }
  // The range errors are N(0, sigma^2): mean and standard deviation of ~30,000 draws.
  const double mean = sum / checked;
  EXPECT_NEAR(mean, 0.0, 0.03);
  EXPECT_NEAR(std::sqrt(sum_squares / checked - mean * mean), 1.0, 0.03);
}

TEST_F(LidarScannerTest, ExactPointsAreOnTheirBoxes) {
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 12).scene;
  LidarScanner scanner(Exact(), kinematics_, 1);
  scanner.SetWorld(scene.boxes);
  const LidarScan scan = scanner.Scan(Stowed(1, -2, 0.7), 0.0);
  int on_boxes = 0;
  for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
    if (scan.target[k] < 0) continue;
    const Eigen::Vector3d p_W = scan.X_WS * scan.p_SP[k].cast<double>();
    ASSERT_NEAR(SignedDistanceToBox(scene.boxes[scan.target[k]], p_W), 0.0, 1e-4);
    ++on_boxes;
  }
  EXPECT_GT(on_boxes, 6000);
}

TEST_F(LidarScannerTest, ABoxBehindAnotherIsNotSeen) {
  // From the sensor at (0.3, 0, 0.22): a 3 m wide, 1 m high wall at 2.6 m hides a small box
  // at 4.5 m (it spans 7.6 deg of azimuth and -1.5..6 deg of elevation; the wall +-30 deg and
  // -4.8..16.7 deg).
  const OrientedBox wall = MakeBox({3.0, 0, 0.5}, {0.2, 3.0, 1.0});
  const OrientedBox hidden = MakeBox({5.0, 0, 0.4}, {0.4, 0.6, 0.6});
  LidarScanner scanner(Exact(), kinematics_, 1);
  scanner.SetWorld({wall, hidden});
  const LidarScan scan = scanner.Scan(Stowed(), 0.0);
  const auto count = [&](const LidarScan& s, int target) {
    return std::count(s.target.begin(), s.target.end(), target);
  };
  EXPECT_GT(count(scan, 0), 500);
  EXPECT_EQ(count(scan, 1), 0);
  // Without the wall (the world changed at run time) the box is seen.
  scanner.SetWorld({hidden});
  const LidarScan open = scanner.Scan(Stowed(), 0.1);
  EXPECT_GT(count(open, 0), 20);
}

TEST_F(LidarScannerTest, SelfHitsLieOnTheArmAndTheChassis) {
  // Default mount: on the chassis top in front of the arm. The upright arm and the chassis
  // top behind the sensor are in view.
  LidarScanner scanner(Exact(), kinematics_, 1);
  const OrientedBox behind = MakeBox({-3.0, 0, 1.0}, {0.5, 8.0, 2.0});  // behind the arm
  scanner.SetWorld({behind});
  const WholeBodyState state = Upright();
  const LidarScan scan = scanner.Scan(state, 0.0);
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(state, &cache);
  int on_arm = 0, on_chassis = 0;
  for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
    if (scan.target[k] != kTargetSelf) continue;
    const Eigen::Vector3d p_W = scan.X_WS * scan.p_SP[k].cast<double>();
    ASSERT_NEAR(BodyDistance(state, p_W), 0.0, 1e-4);
    (p_W.z() > model_.base_cylinder.height_m + 1e-4 ? on_arm : on_chassis)++;
    // The body blocks the ray: the box behind it is farther along the same ray.
    const Eigen::Vector3d d_W = (p_W - scan.X_WS.translation()).normalized();
    int box = -1;
    EXPECT_GT(BruteForceRange({behind}, scan.X_WS.translation(), d_W, &box),
              scan.p_SP[k].norm());
  }
  EXPECT_EQ(scan.self_hits, on_arm + on_chassis);
  EXPECT_GT(on_arm, 100);
  EXPECT_GT(on_chassis, 10);
}

TEST_F(LidarScannerTest, SelfHitsAppearWhereTheArmIsAndNotWhenItIsStowedOutOfView) {
  // On a 1 m mast: the field of view (-7 deg and up) passes above the chassis and above the
  // stowed arm (no higher than 0.49 m within 0.34 m of the base axis), but the upright arm
  // (up to 1.2 m) stands in it.
  LidarOptions options = Exact();
  options.mount.xyz_m = Eigen::Vector3d(0.3, 0.0, 1.0);
  LidarScanner scanner(options, kinematics_, 1);
  scanner.SetWorld({});
  EXPECT_EQ(scanner.Scan(Stowed(), 0.0).self_hits, 0);
  const LidarScan upright = scanner.Scan(Upright(), 0.1);
  EXPECT_GT(upright.self_hits, 50);
  // The arm is behind the sensor, to its left (arm axis at (0, 0.115) in B): azimuth ~159 deg.
  for (std::size_t k = 0; k < upright.p_SP.size(); ++k) {
    ASSERT_EQ(upright.target[k], kTargetSelf);  // nothing else in this world
    const double azimuth = std::atan2(upright.p_SP[k].y(), upright.p_SP[k].x());
    EXPECT_NEAR(azimuth, std::atan2(0.115, -0.3), 0.5);
  }
}

TEST_F(LidarScannerTest, SameSeedAndStateSameScan) {
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 3).scene;
  LidarScanner a(LidarOptions{}, kinematics_, 99), b(LidarOptions{}, kinematics_, 99),
      c(LidarOptions{}, kinematics_, 100);
  a.SetWorld(scene.boxes);
  b.SetWorld(scene.boxes);
  c.SetWorld(scene.boxes);
  const WholeBodyState state = Stowed(2, 1, -0.4);
  const LidarScan sa = a.Scan(state, 0.0), sb = b.Scan(state, 0.0), sc = c.Scan(state, 0.0);
  ASSERT_EQ(sa.p_SP.size(), sb.p_SP.size());
  EXPECT_TRUE(sa.X_WS.isApprox(sb.X_WS, 0.0));
  EXPECT_EQ(sa.target, sb.target);
  EXPECT_EQ(sa.self_hits, sb.self_hits);
  EXPECT_TRUE(std::equal(sa.p_SP.begin(), sa.p_SP.end(), sb.p_SP.begin()));
  // Another seed: the same rays and targets, other noise.
  EXPECT_EQ(sa.target, sc.target);
  EXPECT_FALSE(std::equal(sa.p_SP.begin(), sa.p_SP.end(), sc.p_SP.begin()));
}

TEST_F(LidarScannerTest, ConsecutiveScansDiffer) {
  LidarScanner scanner(Exact(), kinematics_, 1);
  scanner.SetWorld(GenerateBenchmarkScene(SceneKind::kTables, 3).scene.boxes);
  const LidarScan first = scanner.Scan(Stowed(), 0.0);
  const LidarScan second = scanner.Scan(Stowed(), 0.1);
  EXPECT_EQ(scanner.scans_done(), 2u);
  int same = 0;
  const std::size_t n = std::min(first.p_SP.size(), second.p_SP.size());
  for (std::size_t k = 0; k < n; ++k) same += first.p_SP[k] == second.p_SP[k] ? 1 : 0;
  EXPECT_EQ(same, 0);
}

TEST_F(LidarScannerTest, EveryRayOfAClosedRoomReturnsAndTheFieldOfViewIsCovered) {
  // Tall walls 10 m away on every side, a ceiling and a floor slab: every ray hits something.
  const std::vector<OrientedBox> room = {
      MakeBox({10.5, 0, 0}, {1, 22, 40}), MakeBox({-10.5, 0, 0}, {1, 22, 40}),
      MakeBox({0, 10.5, 0}, {22, 1, 40}), MakeBox({0, -10.5, 0}, {22, 1, 40}),
      MakeBox({0, 0, 3.5}, {22, 22, 1}), MakeBox({0, 0, -0.5}, {22, 22, 1})};
  LidarScanner scanner(Exact(), kinematics_, 1);
  scanner.SetWorld(room);
  const LidarScan scan = scanner.Scan(Stowed(), 0.0);
  EXPECT_EQ(static_cast<int>(scan.p_SP.size()), scan.rays);
  double low = 1.0, high = -1.0;
  std::vector<int> sectors(36, 0);
  for (const Eigen::Vector3f& p : scan.p_SP) {
    const double elevation = std::asin(p.z() / p.norm());
    low = std::min(low, elevation);
    high = std::max(high, elevation);
    double azimuth = std::atan2(p.y(), p.x());
    if (azimuth < 0) azimuth += 2 * kPi;
    ++sectors[std::min(35, static_cast<int>(azimuth / (2 * kPi) * 36))];
  }
  EXPECT_NEAR(low, -7 * kPi / 180, 0.2 * kPi / 180);
  EXPECT_NEAR(high, 52 * kPi / 180, 0.2 * kPi / 180);
  for (int c : sectors) EXPECT_NEAR(c, 20000.0 / 36, 0.1 * 20000.0 / 36);
  // Time offsets spread over the 100 ms period.
  EXPECT_GE(*std::min_element(scan.t_offset_s.begin(), scan.t_offset_s.end()), 0.0f);
  EXPECT_LT(*std::max_element(scan.t_offset_s.begin(), scan.t_offset_s.end()), 0.1f);
  EXPECT_GT(*std::max_element(scan.t_offset_s.begin(), scan.t_offset_s.end()), 0.099f);
}

TEST_F(LidarScannerTest, RangeLimitsDropPoints) {
  LidarOptions options = Exact();
  options.range_max_m = 5.0;
  LidarScanner scanner(options, kinematics_, 1);
  // A wall 6 m ahead is beyond range; one at 4 m is not.
  scanner.SetWorld({MakeBox({6.3 + 0.5, 0, 1}, {1, 10, 2})});
  const LidarScan far = scanner.Scan(Stowed(), 0);
  EXPECT_EQ(std::count(far.target.begin(), far.target.end(), 0), 0);
  scanner.SetWorld({MakeBox({4.3 + 0.5, 0, 1}, {1, 10, 2})});
  const LidarScan near = scanner.Scan(Stowed(), 0);
  EXPECT_GT(std::count(near.target.begin(), near.target.end(), 0), 500);
  for (const Eigen::Vector3f& p : near.p_SP) EXPECT_LE(p.norm(), 5.0f + 1e-5f);
  // The blind zone: a box whose face is 5 cm in front of the sensor. Its rays nearer than
  // range_min_m give no point and it hides the box behind it either way.
  const std::vector<OrientedBox> boxes = {MakeBox({0.35 + 0.25, 0, 0.22}, {0.5, 0.5, 0.5}),
                                          MakeBox({3.0, 0, 0.22}, {0.2, 0.2, 0.2})};
  options.range_min_m = 0.0;
  LidarScanner sighted(options, kinematics_, 1);
  sighted.SetWorld(boxes);
  const LidarScan all = sighted.Scan(Stowed(), 0);
  options.range_min_m = 0.2;
  LidarScanner blind(options, kinematics_, 1);
  blind.SetWorld(boxes);
  const LidarScan scan = blind.Scan(Stowed(), 0);
  const auto near_box = [](const LidarScan& s) {
    return std::count(s.target.begin(), s.target.end(), 0);
  };
  EXPECT_GT(near_box(all), near_box(scan) + 100);
  EXPECT_EQ(std::count(all.target.begin(), all.target.end(), 1), 0);
  EXPECT_EQ(std::count(scan.target.begin(), scan.target.end(), 1), 0);
  for (const Eigen::Vector3f& p : scan.p_SP) EXPECT_GE(p.norm(), 0.2f - 1e-6f);
}

TEST_F(LidarScannerTest, GroundPlaneOption) {
  LidarOptions options = Exact();
  options.ground_plane = true;
  LidarScanner scanner(options, kinematics_, 1);
  scanner.SetWorld({});
  const LidarScan scan = scanner.Scan(Stowed(3, 3, 1), 0);
  int ground = 0;
  for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
    if (scan.target[k] != kTargetGround) continue;
    EXPECT_NEAR((scan.X_WS * scan.p_SP[k].cast<double>()).z(), 0.0, 1e-5);
    ++ground;
  }
  EXPECT_GT(ground, 1000);
}

TEST_F(LidarScannerTest, SensorPoseIsTheMountOnTheBase) {
  LidarScanner scanner(LidarOptions{}, kinematics_, 1);
  const LidarScan scan = scanner.Scan(Stowed(1, 2, kPi / 2), 7.5);
  EXPECT_EQ(scan.t_s, 7.5);
  // Mount (0.3, 0, 0.22) in B; B yawed 90 deg at (1, 2): S at (1, 2.3, 0.22), x_S along +y.
  EXPECT_TRUE(scan.X_WS.translation().isApprox(Eigen::Vector3d(1, 2.3, 0.22), 1e-12));
  EXPECT_TRUE((scan.X_WS.linear() * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST_F(LidarScannerTest, ScanAllocatesOnlyTheResult) {
  LidarScanner scanner(LidarOptions{}, kinematics_, 1);
  scanner.SetWorld(GenerateBenchmarkScene(SceneKind::kTables, 3).scene.boxes);
  scanner.Scan(Stowed(), 0.0);
  int allocations = 0;
  {
    testing::AllocationCounter counter;
    const LidarScan scan = scanner.Scan(Stowed(0.5, 0, 0), 0.1);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 3);  // p_SP, t_offset_s, target, reserved once
}

TEST_F(LidarScannerTest, BadStateThrows) {
  LidarScanner scanner(LidarOptions{}, kinematics_, 1);
  WholeBodyState state = Stowed();
  state.x_m = std::nan("");
  EXPECT_THROW(scanner.Scan(state, 0), std::invalid_argument);
}

}  // namespace
}  // namespace topay::sim
