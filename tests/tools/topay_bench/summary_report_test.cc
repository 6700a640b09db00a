#include "tools/topay_bench/summary_report.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::bench {
namespace {

MethodSummary Summary(const std::string& method, int successes) {
  MethodSummary s;
  s.method = method;
  s.tasks = 4;
  s.successes = successes;
  s.success_rate = successes / 4.0;
  s.unreachable_tasks = 1;
  s.success_rate_reachable = successes / 3.0;
  s.tp_ms_mean = 120.24;
  s.tp_ms_median = 100.0;
  s.tp_ms_p95 = 300.0;
  s.tp_ms_median_all = 150.0;
  s.td_s_mean = 9.5;
  s.common_tasks = 2;
  s.common_tp_ms_mean = successes > 0 ? 110.0 : std::nan("");
  s.common_td_s_mean = 9.0;
  for (int i = 0; i < 4 - successes; ++i) {
    s.failures.Add(i == 0 ? FailureCategory::kNoGoal : FailureCategory::kStartRefused);
  }
  return s;
}

BenchRunInfo Info() {
  BenchRunInfo info;
  info.scene = "cuboids";
  info.range = "small";
  info.seed = 3;
  info.threads = 2;
  info.time_limit_ms = 3000.0;
  info.base_limits = "benchmark";
  return info;
}

TEST(SummaryReportTest, JsonHasTheRequiredKeysPerMethod) {
  const nlohmann::json j = nlohmann::json::parse(
      SummaryJson({Summary("topay", 3), Summary("flatness", 0)}, Info()).dump());
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 2u);
  for (const char* key :
       {"method", "scene", "range", "seed", "tasks", "success_rate", "tp_ms_mean", "tp_ms_median",
        "tp_ms_p95", "td_s_mean", "common_tp_ms_mean", "common_td_s_mean", "common_tasks",
        "successes", "threads", "time_limit_ms", "tp_ms_median_all", "unreachable_tasks",
        "success_rate_reachable"}) {
    EXPECT_TRUE(j[0].contains(key)) << key;
  }
  EXPECT_EQ(j[0]["method"], "topay");
  EXPECT_EQ(j[0]["success_rate"], 0.75);
  EXPECT_EQ(j[0]["scene"], "cuboids");
  EXPECT_EQ(j[0]["seed"], 3);
  EXPECT_EQ(j[0]["tp_ms_mean"], 120.24);
  EXPECT_EQ(j[1]["success_rate"], 0.0);
  EXPECT_TRUE(j[1]["common_tp_ms_mean"].is_null());  // NaN
}

TEST(SummaryReportTest, FailuresByReasonAndTheCell) {
  BenchRunInfo info = Info();
  nlohmann::json j = nlohmann::json::parse(SummaryJson({Summary("flatness", 0)}, info).dump());
  EXPECT_EQ(j[0]["cell"], "cuboids small");
  EXPECT_EQ(j[0]["tight"], false);
  EXPECT_TRUE(j[0]["tight_clearance_max_m"].is_null());
  const nlohmann::json& f = j[0]["failures_by_reason"];
  EXPECT_EQ(f.size(), kFailureCategories.size());  // every category, zeros too
  EXPECT_EQ(f["start_refused"], 3);
  EXPECT_EQ(f["no_goal"], 1);
  EXPECT_EQ(f["time_limit"], 0);
  info.tight = true;
  info.tight_clearance_max_m = 0.05;
  j = nlohmann::json::parse(SummaryJson({Summary("flatness", 0)}, info).dump());
  EXPECT_EQ(j[0]["cell"], "cuboids small tight");
  EXPECT_EQ(j[0]["tight"], true);
  EXPECT_EQ(j[0]["tight_clearance_max_m"], 0.05);
  const std::string table = SummaryMarkdown({Summary("topay", 4), Summary("flatness", 0)}, info);
  EXPECT_NE(table.find("topay failures by reason: none\n"), std::string::npos) << table;
  EXPECT_NE(table.find("flatness failures by reason: 3 start refused, 1 no goal\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("Cell cuboids small tight: "), std::string::npos) << table;
  EXPECT_NE(table.find("within 5.0 cm of a box"), std::string::npos) << table;
}

TEST(SummaryReportTest, MarkdownHasOneRowPerMethod) {
  const std::string table = SummaryMarkdown({Summary("topay", 3), Summary("flatness", 0)}, Info());
  EXPECT_NE(table.find("| topay | 4 | 75.0 | 1 | 100.0 | 120.2 | 100.0 | 300.0 | 9.50 | 110.0 | 9.00 |"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| flatness | 4 | 0.0 | 1 | 0.0 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| - |"), std::string::npos) << table;  // the NaN common T.P.
  EXPECT_NE(table.find("successful tasks"), std::string::npos) << table;
}

}  // namespace
}  // namespace topay::bench
