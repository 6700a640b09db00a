#include "procs/mapper/scan_filter_options.h"

#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay::mapper {
namespace {

ScanFilterOptions Load(const std::string& yaml, const std::string& prefix = "") {
  return LoadScanFilterOptions(YAML::Load(yaml), "mapper.yaml", prefix);
}

// The message of the ConfigError a YAML text raises, or "" if it loads.
std::string ErrorOf(const std::string& yaml) {
  try {
    Load(yaml, "filter");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ScanFilterOptionsTest, DefaultsAreValidAndAnEmptyOrMissingSectionKeepsThem) {
  EXPECT_NO_THROW(CheckScanFilterOptions(ScanFilterOptions{}));
  const ScanFilterOptions o = LoadScanFilterOptions(YAML::Node(), "mapper.yaml");
  EXPECT_EQ(o.voxel_leaf_m, 0.05);
  EXPECT_EQ(o.ground_max_z_m, 0.05);
  EXPECT_EQ(o.outlier_method, OutlierMethod::kNone);
  EXPECT_EQ(o.input.max_points, 200000);
  EXPECT_EQ(o.source, "mapper.yaml");
}

TEST(ScanFilterOptionsTest, EveryKeyIsRead) {
  const ScanFilterOptions o = Load(R"(
input: {max_points: 1000, quaternion_norm_tolerance: 0.01}
range_min_m: 0.2
range_max_m: 12
ground_max_z_m: 0.1
self_margin_m: 0.1
voxel_leaf_m: 0
outlier_method: statistical
outlier_radius_m: 0.3
outlier_min_neighbors: 4
outlier_mean_k: 12
outlier_stddev_mul: 1.5
)");
  EXPECT_EQ(o.input.max_points, 1000);
  EXPECT_EQ(o.input.quaternion_norm_tolerance, 0.01);
  EXPECT_EQ(o.range_min_m, 0.2);
  EXPECT_EQ(o.range_max_m, 12.0);
  EXPECT_EQ(o.ground_max_z_m, 0.1);
  EXPECT_EQ(o.self_margin_m, 0.1);
  EXPECT_EQ(o.voxel_leaf_m, 0.0);
  EXPECT_EQ(o.outlier_method, OutlierMethod::kStatistical);
  EXPECT_EQ(o.outlier_radius_m, 0.3);
  EXPECT_EQ(o.outlier_min_neighbors, 4);
  EXPECT_EQ(o.outlier_mean_k, 12);
  EXPECT_EQ(o.outlier_stddev_mul, 1.5);
  EXPECT_EQ(Load("outlier_method: radius").outlier_method, OutlierMethod::kRadius);
}

TEST(ScanFilterOptionsTest, ErrorsNameFileAndKey) {
  EXPECT_EQ(ErrorOf("range_max_m: 0.05"),
            "mapper.yaml: filter.range_max_m: expected a finite range > range_min_m (0.100000 m)");
  EXPECT_EQ(ErrorOf("outlier_method: median"),
            "mapper.yaml: filter.outlier_method: expected none, radius or statistical, got "
            "'median'");
  EXPECT_NE(ErrorOf("voxel_size: 0.1").find("mapper.yaml: filter.voxel_size"), std::string::npos);
  EXPECT_NE(ErrorOf("input: {max_point: 3}").find("filter.input.max_point"), std::string::npos);
  EXPECT_NE(ErrorOf("self_margin_m: -0.1").find("filter.self_margin_m"), std::string::npos);
  EXPECT_NE(ErrorOf("self_margin_m: big").find("filter.self_margin_m"), std::string::npos);
  EXPECT_NE(ErrorOf("voxel_leaf_m: 0.001").find("filter.voxel_leaf_m: 0.001"), std::string::npos);
  EXPECT_NE(ErrorOf("outlier_min_neighbors: 0").find("filter.outlier_min_neighbors"),
            std::string::npos);
  EXPECT_NE(ErrorOf("input: {quaternion_norm_tolerance: 1}").find(
                "filter.input.quaternion_norm_tolerance"),
            std::string::npos);
  EXPECT_NE(ErrorOf("[1, 2]").find("mapper.yaml: filter: expected a map"), std::string::npos);
}

}  // namespace
}  // namespace topay::mapper
