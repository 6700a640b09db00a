#include "tools/topay_bench/method_summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::bench {
namespace {

BenchRecord Record(int task, const std::string& method, bool success, double tp_ms, double td_s) {
  BenchRecord r;
  r.task = task;
  r.method = method;
  r.success = success;
  r.timings.total_ms = tp_ms;
  r.duration_s = success ? td_s : std::nan("");
  r.map_ms = 10.0 * (task + 1);
  return r;
}

// Tasks 0..3. A solves 0, 1, 2; B solves 1, 2, 3. Common: {1, 2}.
std::vector<BenchRecord> Records() {
  return {Record(0, "A", true, 100, 10),  Record(0, "B", false, 3000, 0),
          Record(1, "A", true, 200, 20),  Record(1, "B", true, 400, 40),
          Record(2, "A", true, 600, 30),  Record(2, "B", true, 800, 50),
          Record(3, "A", false, 3000, 0), Record(3, "B", true, 1000, 60)};
}

TEST(MethodSummaryTest, HandComputedFigures) {
  const std::vector<MethodSummary> s = SummarizeMethods(Records(), {"A", "B"});
  ASSERT_EQ(s.size(), 2u);
  const MethodSummary& a = s[0];
  EXPECT_EQ(a.method, "A");
  EXPECT_EQ(a.tasks, 4);
  EXPECT_EQ(a.successes, 3);
  EXPECT_DOUBLE_EQ(a.success_rate, 0.75);
  EXPECT_DOUBLE_EQ(a.tp_ms_mean, 300.0);  // (100 + 200 + 600) / 3, successes only
  EXPECT_DOUBLE_EQ(a.tp_ms_median, 200.0);
  EXPECT_DOUBLE_EQ(a.tp_ms_p95, 600.0);         // rank ceil(2.85) = 3
  EXPECT_DOUBLE_EQ(a.tp_ms_median_all, 400.0);  // (200 + 600) / 2 of {100, 200, 600, 3000}
  EXPECT_DOUBLE_EQ(a.td_s_mean, 20.0);          // (10 + 20 + 30) / 3
  EXPECT_EQ(a.common_tasks, 2);
  EXPECT_DOUBLE_EQ(a.common_tp_ms_mean, 400.0);  // tasks 1, 2: (200 + 600) / 2
  EXPECT_DOUBLE_EQ(a.common_td_s_mean, 25.0);
  EXPECT_DOUBLE_EQ(a.map_ms_mean, 25.0);  // (10 + 20 + 30 + 40) / 4

  const MethodSummary& b = s[1];
  EXPECT_EQ(b.successes, 3);
  EXPECT_DOUBLE_EQ(b.tp_ms_mean, 2200.0 / 3.0);
  EXPECT_DOUBLE_EQ(b.tp_ms_median, 800.0);
  EXPECT_EQ(b.common_tasks, 2);
  EXPECT_DOUBLE_EQ(b.common_tp_ms_mean, 600.0);  // (400 + 800) / 2
  EXPECT_DOUBLE_EQ(b.common_td_s_mean, 45.0);
}

TEST(MethodSummaryTest, UnreachableTasksAreCountedAndLeftOutOfTheReachableRate) {
  std::vector<BenchRecord> records = Records();
  for (BenchRecord& r : records) r.base_unreachable = r.task == 3;  // A failed it, B solved it
  const std::vector<MethodSummary> s = SummarizeMethods(records, {"A", "B"});
  EXPECT_EQ(s[0].unreachable_tasks, 1);
  EXPECT_DOUBLE_EQ(s[0].success_rate, 0.75);           // all tasks still count
  EXPECT_DOUBLE_EQ(s[0].success_rate_reachable, 1.0);  // 3 of the 3 others
  EXPECT_DOUBLE_EQ(s[1].success_rate_reachable, 2.0 / 3.0);
  const std::vector<MethodSummary> none = SummarizeMethods(Records(), {"A"});
  EXPECT_EQ(none[0].unreachable_tasks, 0);
  EXPECT_DOUBLE_EQ(none[0].success_rate_reachable, 0.75);
}

TEST(MethodSummaryTest, FailuresAreCountedByReasonPerMethod) {
  std::vector<BenchRecord> records = Records();  // A failed task 3, B task 0
  for (BenchRecord& r : records) {
    if (r.task == 3 && r.method == "A") r.failure = FailureCategory::kStartRefused;
    if (r.task == 0 && r.method == "B") r.failure = FailureCategory::kNoGoal;
  }
  BenchRecord late = Record(4, "A", false, 3500, 0);
  late.failure = FailureCategory::kTimeLimit;
  BenchRecord uncategorised = Record(5, "A", false, 100, 0);  // kNone on a failure: "other"
  BenchRecord refused = Record(6, "A", false, 5, 0);
  refused.failure = FailureCategory::kStartRefused;
  records.insert(records.end(), {late, uncategorised, refused});
  const std::vector<MethodSummary> s = SummarizeMethods(records, {"A", "B"});
  const FailureTally& a = s[0].failures;
  EXPECT_EQ(a.Count(FailureCategory::kStartRefused), 2);
  EXPECT_EQ(a.Count(FailureCategory::kTimeLimit), 1);
  EXPECT_EQ(a.Count(FailureCategory::kOther), 1);
  EXPECT_EQ(a.Count(FailureCategory::kNoGoal), 0);
  EXPECT_EQ(a.Total(), s[0].tasks - s[0].successes);
  EXPECT_EQ(a.Text(), "2 start refused, 1 time limit, 1 other");
  EXPECT_EQ(s[1].failures.Count(FailureCategory::kNoGoal), 1);
  EXPECT_EQ(s[1].failures.Total(), 1);
}

TEST(MethodSummaryTest, OneMethodHasItsSuccessesAsCommonTasks) {
  const std::vector<MethodSummary> s = SummarizeMethods(Records(), {"A"});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].common_tasks, 3);
  EXPECT_DOUBLE_EQ(s[0].common_tp_ms_mean, 300.0);
}

TEST(MethodSummaryTest, NoSuccessGivesNaNTimesAndZeroRate) {
  const std::vector<MethodSummary> s =
      SummarizeMethods({Record(0, "A", false, 50, 0), Record(1, "A", false, 70, 0)}, {"A"});
  EXPECT_EQ(s[0].successes, 0);
  EXPECT_DOUBLE_EQ(s[0].success_rate, 0.0);
  EXPECT_TRUE(std::isnan(s[0].tp_ms_mean));
  EXPECT_TRUE(std::isnan(s[0].td_s_mean));
  EXPECT_TRUE(std::isnan(s[0].common_tp_ms_mean));
  EXPECT_DOUBLE_EQ(s[0].tp_ms_median_all, 60.0);
  EXPECT_EQ(s[0].common_tasks, 0);
}

}  // namespace
}  // namespace topay::bench
