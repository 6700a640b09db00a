// Latency statistics (procs/lcm_latency/latency_summary.h): nearest-rank percentiles.

#include "procs/lcm_latency/latency_summary.h"

#include <gtest/gtest.h>

namespace topay::latency {
namespace {

TEST(LatencySummary, NearestRankPercentiles) {
  std::vector<double> samples;
  for (int i = 100; i >= 1; --i) samples.push_back(i);
  const LatencySummary s = Summarize(samples);
  EXPECT_EQ(s.count, 100);
  EXPECT_EQ(s.median_us, 50.0);
  EXPECT_EQ(s.p95_us, 95.0);
  EXPECT_EQ(s.p99_us, 99.0);
  EXPECT_EQ(s.max_us, 100.0);
  EXPECT_EQ(Summarize({}).count, 0);
  EXPECT_EQ(Summarize({7.0}).p99_us, 7.0);
  EXPECT_NE(Format(s).find("median 50.0 us"), std::string::npos);
}

}  // namespace
}  // namespace topay::latency
