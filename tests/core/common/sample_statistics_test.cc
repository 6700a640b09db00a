#include "core/common/sample_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay {
namespace {

TEST(SampleStatisticsTest, MeanOfHandValues) {
  EXPECT_DOUBLE_EQ(Mean({1.0, 2.0, 6.0}), 3.0);
  EXPECT_TRUE(std::isnan(Mean({})));
}

TEST(SampleStatisticsTest, MedianOfOddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(Median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(Median({4.0, 1.0, 3.0, 10.0}), 3.5);  // (3 + 4) / 2
  EXPECT_DOUBLE_EQ(Median({7.0}), 7.0);
  EXPECT_TRUE(std::isnan(Median({})));
}

TEST(SampleStatisticsTest, NearestRankP95) {
  // 1..20: rank ceil(0.95 * 20) = 19 -> 19 (not 20: 19 of 20 = 95 % are <= 19).
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);
  EXPECT_DOUBLE_EQ(NearestRankQuantile(v, 0.95), 19.0);
  // 1..10: rank ceil(9.5) = 10 -> 10.
  std::vector<double> w;
  for (int i = 1; i <= 10; ++i) w.push_back(i);
  EXPECT_DOUBLE_EQ(NearestRankQuantile(w, 0.95), 10.0);
  EXPECT_DOUBLE_EQ(NearestRankQuantile(w, 0.5), 5.0);
  EXPECT_DOUBLE_EQ(NearestRankQuantile({42.0}, 0.95), 42.0);
  EXPECT_TRUE(std::isnan(NearestRankQuantile({}, 0.95)));
}

}  // namespace
}  // namespace topay
