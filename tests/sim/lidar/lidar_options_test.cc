#include "sim/lidar/lidar_options.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/robot/kinematics.h"
#include "sim/lidar/lidar_scanner.h"
#include "tests/common/temp_path.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The ConfigError's what(), or "" if none is thrown.
template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

LidarOptions FromText(const std::string& text, const std::string& prefix = "") {
  const YAML::Node root = YAML::Load(text);
  return prefix.empty() ? LoadLidarOptions(root, "test.yaml")
                        : LoadLidarOptions(root[prefix], "test.yaml", prefix);
}

TEST(LidarOptionsTest, DefaultsAreTheMid360) {
  const LidarOptions o;
  EXPECT_EQ(o.PointsPerScan(), 20000);
  EXPECT_DOUBLE_EQ(o.ScanPeriodS(), 0.1);
  EXPECT_NEAR(o.elevation_min_rad, -7 * kPi / 180, 1e-12);
  EXPECT_NEAR(o.elevation_max_rad, 52 * kPi / 180, 1e-12);
  EXPECT_EQ(o.range_min_m, 0.1);
  EXPECT_EQ(o.range_max_m, 40.0);
  EXPECT_NO_THROW(CheckLidarOptions(o));
}

TEST(LidarOptionsTest, ShippedFileStatesTheDefaults) {
  const LidarOptions file =
      LoadLidarOptionsFile(std::string(TOPAY_SOURCE_DIR) + "/config/sim/lidar.yaml");
  const LidarOptions d;
  EXPECT_EQ(file.mount.parent_link, d.mount.parent_link);
  EXPECT_TRUE(file.mount.xyz_m.isApprox(d.mount.xyz_m));
  EXPECT_TRUE(file.mount.rpy_rad.isApprox(d.mount.rpy_rad));
  EXPECT_EQ(file.points_per_s, d.points_per_s);
  EXPECT_EQ(file.scan_rate_hz, d.scan_rate_hz);
  EXPECT_NEAR(file.elevation_min_rad, d.elevation_min_rad, 1e-12);
  EXPECT_NEAR(file.elevation_max_rad, d.elevation_max_rad, 1e-12);
  EXPECT_EQ(file.range_min_m, d.range_min_m);
  EXPECT_EQ(file.range_max_m, d.range_max_m);
  EXPECT_EQ(file.range_noise_sigma_m, d.range_noise_sigma_m);
  EXPECT_EQ(file.ground_plane, d.ground_plane);
  EXPECT_EQ(file.grid_cell_m, d.grid_cell_m);
}

TEST(LidarOptionsTest, ReadsEveryKeyAndTheMount) {
  const LidarOptions o = FromText(
      "mount: {parent_link: chassis, xyz: [0.1, 0.2, 0.3], rpy: [0, 0, 1.5707963267948966]}\n"
      "points_per_s: 100000\nscan_rate_hz: 20\nelevation_min_deg: -10\n"
      "elevation_max_deg: 30\nrange_min_m: 0.2\nrange_max_m: 12\nrange_noise_sigma_m: 0\n"
      "ground_plane: true\ngrid_cell_m: 0.25\n");
  EXPECT_EQ(o.mount.parent_link, "chassis");
  EXPECT_TRUE(o.mount.X_PS().translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  // Yaw 90 deg: S's x axis is P's y axis.
  EXPECT_TRUE((o.mount.X_PS().linear() * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_EQ(o.PointsPerScan(), 5000);
  EXPECT_NEAR(o.elevation_min_rad, -10 * kPi / 180, 1e-12);
  EXPECT_EQ(o.range_max_m, 12.0);
  EXPECT_EQ(o.range_noise_sigma_m, 0.0);
  EXPECT_TRUE(o.ground_plane);
  EXPECT_EQ(o.grid_cell_m, 0.25);
}

TEST(LidarOptionsTest, ErrorsNameTheFileAndTheKey) {
  EXPECT_EQ(ErrorOf([] { FromText("range_min_m: 5\nrange_max_m: 1\n"); }).find("test.yaml"),
            0u);
  EXPECT_NE(ErrorOf([] { FromText("range_min_m: 5\nrange_max_m: 1\n"); }).find("range_max_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("range_max_m: .nan\n"); }).find("range_max_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("range_max_m: .inf\n"); }).find("range_max_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("range_min_m: -1\n"); }).find("range_min_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("elevation_min_deg: 60\n"); }).find("elevation_max_deg"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("scan_rate_hz: 0\n"); }).find("scan_rate_hz"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("range_noise_sigma_m: -0.1\n"); }).find("range_noise_sigma_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("grid_cell_m: 0\n"); }).find("grid_cell_m"), std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("rangemax: 3\n"); }).find("rangemax: unknown field"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("mount: {xyz: [1, 2]}\n"); }).find("mount.xyz"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("mount: {rpy: [0, x, 0]}\n"); }).find("mount.rpy[1]"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FromText("mount: {link: base_link}\n"); }).find("mount.link"),
            std::string::npos);
}

TEST(LidarOptionsTest, ASectionOfALargerFileNamesItsPath) {
  const LidarOptions o = FromText("lidar:\n  range_max_m: 20\nplant: {}\n", "lidar");
  EXPECT_EQ(o.range_max_m, 20.0);
  const std::string error =
      ErrorOf([] { FromText("lidar:\n  range_min_m: 30\n  range_max_m: 20\n", "lidar"); });
  EXPECT_NE(error.find("test.yaml: lidar.range_max_m"), std::string::npos) << error;
  // An absent section: the defaults.
  EXPECT_EQ(FromText("plant: {}\n", "lidar").PointsPerScan(), 20000);
}

TEST(LidarOptionsTest, FileVariantReadsASection) {
  const std::string path = UniqueTempPath("sim.yaml");
  std::ofstream(path) << "lidar:\n  scan_rate_hz: 5\n";
  EXPECT_EQ(LoadLidarOptionsFile(path, "lidar").PointsPerScan(), 40000);
  std::ofstream(path) << "lidar: [1, 2\n";
  EXPECT_NE(ErrorOf([&] { LoadLidarOptionsFile(path, "lidar"); }).find("malformed YAML"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { LoadLidarOptionsFile("/nonexistent/lidar.yaml"); })
                .find("/nonexistent/lidar.yaml"),
            std::string::npos);
}

TEST(LidarOptionsTest, UnknownMountLinkIsAConfigErrorOfTheScanner) {
  const RobotModel model = testing::LoadTopayModel();
  const Kinematics kinematics(model);
  LidarOptions o = FromText("lidar:\n  mount: {parent_link: lidar_mast}\n", "lidar");
  const std::string error = ErrorOf([&] { LidarScanner scanner(o, kinematics, 1); });
  EXPECT_NE(error.find("test.yaml: lidar.mount.parent_link: no link 'lidar_mast'"),
            std::string::npos)
      << error;
  o.mount.parent_link = "link7";  // any link of the model will do, the arm's too
  EXPECT_NO_THROW(LidarScanner(o, kinematics, 1));
}

}  // namespace
}  // namespace topay::sim
