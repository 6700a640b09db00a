// Percentiles (linear between closest ranks), RMS and max, worked out by hand.

#include "tools/report/sample_stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::report {
namespace {

TEST(SampleStats, PercentilesInterpolateBetweenClosestRanks) {
  const std::vector<double> x = {4.0, 1.0, 3.0, 2.0};  // sorted 1 2 3 4
  EXPECT_DOUBLE_EQ(Percentile(x, 50.0), 2.5);       // rank 1.5
  EXPECT_DOUBLE_EQ(Percentile(x, 95.0), 3.85);      // rank 2.85
  EXPECT_DOUBLE_EQ(Percentile(x, 99.0), 3.97);      // rank 2.97
  EXPECT_DOUBLE_EQ(Percentile(x, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(Percentile(x, 100.0), 4.0);
  EXPECT_DOUBLE_EQ(Percentile({7.0}, 99.0), 7.0);
  EXPECT_DOUBLE_EQ(Percentile({}, 50.0), 0.0);
}

TEST(SampleStats, RmsAndMaxOfErrorsUseMagnitudes) {
  const ErrorStats e = SummarizeErrors({0.02, -0.04, 0.0, 0.02});
  EXPECT_EQ(e.count, 4);
  EXPECT_DOUBLE_EQ(e.rms, std::sqrt(6e-4));  // (4 + 16 + 0 + 4) e-4 / 4
  EXPECT_DOUBLE_EQ(e.max, 0.04);
  EXPECT_DOUBLE_EQ(Rms({3.0, 4.0}), std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(Max({-1.0, -3.0}), -1.0);
  EXPECT_EQ(SummarizeErrors({}).count, 0);
  EXPECT_DOUBLE_EQ(SummarizeErrors({}).rms, 0.0);
}

TEST(SampleStats, TimingsGiveCountMedianP95P99Max) {
  const TimingStats t = SummarizeTimings({100.0, 300.0, 200.0});
  EXPECT_EQ(t.count, 3);
  EXPECT_DOUBLE_EQ(t.median, 200.0);
  EXPECT_DOUBLE_EQ(t.p95, 290.0);  // rank 1.9
  EXPECT_DOUBLE_EQ(t.p99, 298.0);  // rank 1.98
  EXPECT_DOUBLE_EQ(t.max, 300.0);
}

}  // namespace
}  // namespace topay::report
