#include "tools/topay_bench/progress_line.h"

#include <gtest/gtest.h>

namespace topay::bench {
namespace {

TEST(ProgressLineTest, BarCountAndEta) {
  // 4 of 10 in 12 s: 3 s per task, 6 left -> 18 s.
  EXPECT_EQ(ProgressLine(4, 10, 12.0), "[########------------] 4/10 tasks, 12 s, ETA 18 s");
  EXPECT_EQ(ProgressLine(10, 10, 30.0), "[####################] 10/10 tasks, 30 s, ETA 0 s");
}

TEST(ProgressLineTest, NoEstimateBeforeTheFirstTask) {
  EXPECT_EQ(ProgressLine(0, 5, 0.0), "[--------------------] 0/5 tasks, 0 s, ETA ?");
}

}  // namespace
}  // namespace topay::bench
