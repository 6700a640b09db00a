#include "procs/msgs/cloud_input.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace topay::msgs {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A sound message: two points, the sensor 0.2 m up, yawed by 90 deg.
point_cloud_t GoodMessage() {
  point_cloud_t m;
  m.utime = 1700000000000000;
  m.sensor_frame = "lidar";
  m.p_WS[0] = 1.0, m.p_WS[1] = 2.0, m.p_WS[2] = 0.2;
  const double s = std::sqrt(0.5);
  m.quat_WS[0] = s, m.quat_WS[1] = 0.0, m.quat_WS[2] = 0.0, m.quat_WS[3] = s;
  m.p_SP = {1.0f, 0.0f, 0.0f, 2.0f, 3.0f, 4.0f};
  m.num_coords = 6;
  return m;
}

// The error's text for a message, or "" if it passed.
std::string ErrorOf(const point_cloud_t& m, const CloudInputOptions& options = {}) {
  CheckedCloud cloud;
  const auto error = CheckCloud(m, options, &cloud);
  return error ? error->ToString() : "";
}

TEST(CloudInputTest, ASoundMessageGivesItsPoseAndPoints) {
  CheckedCloud cloud;
  ASSERT_FALSE(CheckCloud(GoodMessage(), {}, &cloud));
  EXPECT_EQ(cloud.utime, 1700000000000000);
  ASSERT_EQ(cloud.p_SP.size(), 2u);
  EXPECT_EQ(cloud.p_SP[1], Eigen::Vector3f(2, 3, 4));
  EXPECT_TRUE(cloud.X_WS.translation().isApprox(Eigen::Vector3d(1, 2, 0.2)));
  // S's x axis is W's y axis (yaw 90 deg).
  const Eigen::Vector3d p_WP = cloud.X_WS * cloud.p_SP[0].cast<double>();
  EXPECT_TRUE(p_WP.isApprox(Eigen::Vector3d(1, 3, 0.2), 1e-12));
}

TEST(CloudInputTest, AnEmptyCloudIsSound) {
  point_cloud_t m = GoodMessage();
  m.p_SP.clear();
  m.num_coords = 0;
  CheckedCloud cloud;
  cloud.p_SP.resize(5);  // reused: emptied
  ASSERT_FALSE(CheckCloud(m, {}, &cloud));
  EXPECT_TRUE(cloud.p_SP.empty());
}

TEST(CloudInputTest, BadSizesAreRejectedNamingFieldAndValue) {
  point_cloud_t m = GoodMessage();
  m.num_coords = -3;
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.num_coords: -3: negative");
  m = GoodMessage();
  m.num_coords = 5;
  m.p_SP.resize(5);
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.num_coords: 5: not a multiple of 3 (x, y, z)");
  m = GoodMessage();
  m.num_coords = 9;  // the array holds 6
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.num_coords: 9: the p_SP array holds 6 floats");
}

TEST(CloudInputTest, MoreThanMaxPointsIsRejected) {
  point_cloud_t m = GoodMessage();
  CloudInputOptions options;
  options.max_points = 1;
  EXPECT_EQ(ErrorOf(m, options), "point_cloud_t.p_SP: 2 points: more than max_points (1)");
  options.max_points = 2;
  EXPECT_EQ(ErrorOf(m, options), "");
  // The default admits ten Mid-360 scans and no more.
  m.p_SP.assign(3 * 200001, 1.0f);
  m.num_coords = 3 * 200001;
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.p_SP: 200001 points: more than max_points (200000)");
}

TEST(CloudInputTest, NonFinitePoseEntriesAreRejected) {
  point_cloud_t m = GoodMessage();
  m.p_WS[2] = kNaN;
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.p_WS[2]: nan: not finite");
  m = GoodMessage();
  m.quat_WS[1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ErrorOf(m), "point_cloud_t.quat_WS[1]: inf: not finite");
}

TEST(CloudInputTest, NonUnitQuaternionsAreRejectedSmallDeviationsRenormalised) {
  point_cloud_t m = GoodMessage();
  for (double& q : m.quat_WS) q *= 1.1;
  EXPECT_EQ(ErrorOf(m).rfind("point_cloud_t.quat_WS: norm 1.1", 0), 0u) << ErrorOf(m);
  m = GoodMessage();
  for (double& q : m.quat_WS) q = 0.0;
  EXPECT_NE(ErrorOf(m).find("quat_WS: norm 0"), std::string::npos);
  m = GoodMessage();
  for (double& q : m.quat_WS) q *= 1.0005;  // within the 1e-3 tolerance
  CheckedCloud cloud;
  ASSERT_FALSE(CheckCloud(m, {}, &cloud));
  const Eigen::Matrix3d R = cloud.X_WS.linear();
  EXPECT_TRUE((R * R.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
}

TEST(CloudInputTest, NonFinitePointsPassForTheFilterToCount) {
  point_cloud_t m = GoodMessage();
  m.p_SP[0] = std::numeric_limits<float>::quiet_NaN();
  m.p_SP[4] = std::numeric_limits<float>::infinity();
  CheckedCloud cloud;
  ASSERT_FALSE(CheckCloud(m, {}, &cloud));
  EXPECT_EQ(cloud.p_SP.size(), 2u);
  EXPECT_FALSE(cloud.p_SP[0].allFinite());
}

}  // namespace
}  // namespace topay::msgs
