// MapperStats (procs/mapper/mapper_stats.h): bounded per-scan samples, the status line and the
// exit report.
#include "procs/mapper/mapper_stats.h"

#include <gtest/gtest.h>

namespace topay::mapper {
namespace {

TEST(MapperStatsTest, SamplesKeepTheNewestAndStayBounded) {
  std::vector<double> sample;
  for (std::size_t k = 0; k < 2 * kMaxSamples; ++k) AddSample(&sample, static_cast<double>(k));
  EXPECT_EQ(sample.size(), 2 * kMaxSamples);
  AddSample(&sample, -1.0);  // the oldest half goes
  ASSERT_EQ(sample.size(), kMaxSamples + 1);
  EXPECT_EQ(sample.front(), static_cast<double>(kMaxSamples));
  EXPECT_EQ(sample.back(), -1.0);
  for (int k = 0; k < 10 * static_cast<int>(kMaxSamples); ++k) AddSample(&sample, 0.0);
  EXPECT_LE(sample.size(), 2 * kMaxSamples);
}

TEST(MapperStatsTest, StatusAndReportCarryTheFigures) {
  MapperStats stats;
  stats.clouds = 3;
  stats.clouds_rejected = 1;
  ScanMapperSummary scan;
  scan.filter.total_ms = 0.5;
  scan.insert.total_s = 0.004;
  scan.insert.num_changes = 120;
  stats.AddScan(scan);
  AddSample(&stats.scan_to_update_ms, 5.0);
  const std::string status = stats.StatusLine({.occupied = 7, .free = 8, .unknown = 9});
  EXPECT_NE(status.find("occupied 7 free 8 unknown 9"), std::string::npos) << status;
  EXPECT_NE(status.find("insert 4.0"), std::string::npos) << status;
  const std::string report = stats.Report();
  EXPECT_NE(report.find("3 clouds (1 rejected"), std::string::npos) << report;
  EXPECT_NE(report.find("scan in -> MAP_UPDATE"), std::string::npos) << report;
  EXPECT_NE(report.find("median   120.00"), std::string::npos) << report;  // changes per scan
}

}  // namespace
}  // namespace topay::mapper
