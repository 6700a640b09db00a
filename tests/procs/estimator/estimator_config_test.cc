// topay-estimator's options: the shipped config/estimator/estimator.yaml restates every default;
// a misspelt key or a bad value is a ConfigError naming the file and the field.

#include "procs/estimator/estimator_config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "tests/common/config_test_file.h"

namespace topay::estimator {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  return topay::test::WriteTestFile("estimator_config", name, text);
}

std::string ErrorOf(const std::string& path) {
  return topay::test::ConfigErrorOf([&] { LoadEstimatorProcessOptions(path); });
}

TEST(EstimatorConfig, ShippedConfigRestatesTheDefaults) {
  const EstimatorProcessOptions o =
      LoadEstimatorProcessOptions(std::string(TOPAY_SOURCE_DIR) + "/config/estimator/estimator.yaml");
  const EstimatorProcessOptions d;
  const EstimatorOptions& f = o.filter;
  const EstimatorOptions& df = d.filter;
  EXPECT_DOUBLE_EQ(o.publish_rate_hz, d.publish_rate_hz);
  EXPECT_DOUBLE_EQ(o.odometry_timeout_s, d.odometry_timeout_s);
  EXPECT_DOUBLE_EQ(o.joints_timeout_s, d.joints_timeout_s);
  EXPECT_DOUBLE_EQ(o.pose_timeout_s, d.pose_timeout_s);
  EXPECT_DOUBLE_EQ(o.gripper_timeout_s, d.gripper_timeout_s);
  EXPECT_DOUBLE_EQ(o.max_future_s, d.max_future_s);
  EXPECT_EQ(o.num_joints, d.num_joints);
  EXPECT_DOUBLE_EQ(o.max_speed_mps, d.max_speed_mps);
  EXPECT_DOUBLE_EQ(o.max_yaw_rate_radps, d.max_yaw_rate_radps);
  EXPECT_DOUBLE_EQ(f.translation_var_m2_per_m, df.translation_var_m2_per_m);
  EXPECT_DOUBLE_EQ(f.rotation_var_rad2_per_rad, df.rotation_var_rad2_per_rad);
  EXPECT_DOUBLE_EQ(f.rotation_var_rad2_per_m, df.rotation_var_rad2_per_m);
  EXPECT_DOUBLE_EQ(f.diffusion_xy_m2_per_s, df.diffusion_xy_m2_per_s);
  EXPECT_DOUBLE_EQ(f.diffusion_yaw_rad2_per_s, df.diffusion_yaw_rad2_per_s);
  EXPECT_DOUBLE_EQ(f.pose_xy_stddev_m, df.pose_xy_stddev_m);
  EXPECT_DOUBLE_EQ(f.pose_yaw_stddev_rad, df.pose_yaw_stddev_rad);
  EXPECT_DOUBLE_EQ(f.gate_chi2, df.gate_chi2);
  EXPECT_EQ(f.reinit_after_rejections, df.reinit_after_rejections);
  EXPECT_EQ(f.history_capacity, df.history_capacity);
  EXPECT_DOUBLE_EQ(f.max_delay_s, df.max_delay_s);
}

TEST(EstimatorConfig, ValuesAreRead) {
  const EstimatorProcessOptions o = LoadEstimatorProcessOptions(
      Write("values.yaml", "publish_rate_hz: 50\nnum_joints: 6\nfilter:\n  gate_chi2: 9.0\n  history_capacity: 64\n"));
  EXPECT_DOUBLE_EQ(o.publish_rate_hz, 50.0);
  EXPECT_EQ(o.num_joints, 6);
  EXPECT_DOUBLE_EQ(o.filter.gate_chi2, 9.0);
  EXPECT_EQ(o.filter.history_capacity, 64);
}

TEST(EstimatorConfig, ErrorsNameTheFileAndTheField) {
  const std::string typo = Write("typo.yaml", "filter:\n  gate_chi: 9\n");
  EXPECT_NE(ErrorOf(typo).find("filter.gate_chi"), std::string::npos) << ErrorOf(typo);
  EXPECT_NE(ErrorOf(typo).find("typo.yaml"), std::string::npos) << ErrorOf(typo);
  const std::string top_typo = Write("top_typo.yaml", "publish_rate: 9\n");
  EXPECT_NE(ErrorOf(top_typo).find("publish_rate"), std::string::npos) << ErrorOf(top_typo);
  const std::string bad_filter = Write("bad_filter.yaml", "filter:\n  pose_xy_stddev_m: -1\n");
  EXPECT_NE(ErrorOf(bad_filter).find("pose_xy_stddev_m"), std::string::npos) << ErrorOf(bad_filter);
  const std::string bad_yaw = Write("bad_yaw.yaml", "max_yaw_rate_radps: 0\n");
  EXPECT_NE(ErrorOf(bad_yaw).find("max_yaw_rate_radps"), std::string::npos) << ErrorOf(bad_yaw);
  const std::string bad_rate = Write("bad_rate.yaml", "publish_rate_hz: 0\n");
  EXPECT_NE(ErrorOf(bad_rate).find("publish_rate_hz"), std::string::npos) << ErrorOf(bad_rate);
  const std::string bad_type = Write("bad_type.yaml", "odometry_timeout_s: soon\n");
  EXPECT_NE(ErrorOf(bad_type).find("odometry_timeout_s"), std::string::npos) << ErrorOf(bad_type);
  const std::string missing = (std::filesystem::path(TOPAY_BINARY_DIR) / "no_such_estimator.yaml").string();
  EXPECT_NE(ErrorOf(missing).find("no_such_estimator.yaml"), std::string::npos);
}

}  // namespace
}  // namespace topay::estimator
