#include "tools/topay_bench/flatness_data_json.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay::bench {
namespace {

// Two pieces in D = 3 dimensions (x, y, one joint), rest at both ends.
FlatnessTrajectoryData HandData() {
  FlatnessTrajectoryData d;
  d.head = Eigen::MatrixXd::Zero(3, 3);
  d.head.col(0) << 0.0, 0.0, 0.1;
  d.tail = Eigen::MatrixXd::Zero(3, 3);
  d.tail.col(0) << 2.0, 1.0, 0.3;
  d.waypoints = Eigen::MatrixXd(3, 1);
  d.waypoints << 1.0, 0.4, 1.0 / 3.0;
  d.durations_s = Eigen::Vector2d(1.5, 2.25);
  d.start_yaw_rad = 0.2;
  d.end_yaw_rad = -0.7;
  return d;
}

TEST(FlatnessDataJsonTest, RoundTripsExactly) {
  const FlatnessTrajectoryData d = HandData();
  const FlatnessTrajectoryData back = FlatnessDataFromJson(FlatnessDataToJson(d), "f.json");
  EXPECT_EQ(back.head, d.head);
  EXPECT_EQ(back.tail, d.tail);
  EXPECT_EQ(back.waypoints, d.waypoints);  // 1/3 survives: shortest round-trip numbers
  EXPECT_EQ(back.durations_s, d.durations_s);
  EXPECT_EQ(back.start_yaw_rad, d.start_yaw_rad);
  EXPECT_EQ(back.end_yaw_rad, d.end_yaw_rad);
  // And it is a trajectory the baseline can evaluate.
  EXPECT_DOUBLE_EQ(FlatnessTrajectory(back).duration_s(), 3.75);
}

std::string ErrorOf(const std::string& text) {
  try {
    FlatnessDataFromJson(text, "f.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(FlatnessDataJsonTest, NamesTheFileAndFieldOfAnError) {
  std::string text = FlatnessDataToJson(HandData());
  EXPECT_NE(ErrorOf("{").find("f.json"), std::string::npos);
  EXPECT_NE(ErrorOf("[]").find("f.json"), std::string::npos);
  const std::string no_format = ErrorOf(R"({"version": 1})");
  EXPECT_NE(no_format.find("format"), std::string::npos) << no_format;
  std::string bad_duration = text;
  bad_duration.replace(bad_duration.find("1.5"), 3, "-1.5");
  EXPECT_NE(ErrorOf(bad_duration).find("durations_s[0]"), std::string::npos)
      << ErrorOf(bad_duration);
  std::string short_row = text;
  short_row.replace(short_row.find("\"head\""), 6, "\"hxad\"");
  EXPECT_NE(ErrorOf(short_row).find("head"), std::string::npos) << ErrorOf(short_row);
}

TEST(FlatnessDataJsonTest, MissingFileIsAConfigError) {
  EXPECT_THROW(ReadFlatnessDataJson("/nonexistent/f.json"), ConfigError);
}

}  // namespace
}  // namespace topay::bench
