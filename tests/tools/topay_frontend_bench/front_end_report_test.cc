#include "tools/topay_frontend_bench/front_end_report.h"

#include <sstream>

#include <gtest/gtest.h>

namespace topay::frontend_bench {
namespace {

TEST(FrontEndReportTest, TableRowHasTheCellAndTheRatesWithCounts) {
  FrontEndBenchOptions options;
  options.scene = "tables";
  options.range = "large";
  FrontEndTally tally;
  tally.tasks = 4;
  tally.tasks_ok = 3;
  tally.unreachable = 1;
  tally.total_ms = {10.0, 20.0, 30.0, 40.0};
  tally.jobs_succeeded = 5;
  tally.jobs_finished = 10;
  tally.exact_failures = {"task 2: base hits box 9"};
  std::ostringstream out;
  WriteFrontEndReport(options, tally, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("| tables | large | 4 |"), std::string::npos) << text;
  EXPECT_NE(text.find("20.0 / 40.0"), std::string::npos) << text;   // median / p95, nearest rank
  EXPECT_NE(text.find("75.0 % (3/4)"), std::string::npos) << text;  // tasks with a path
  EXPECT_NE(text.find("100.0 % (3/3)"), std::string::npos) << text; // reachable ones
  EXPECT_NE(text.find("50.0 % (5/10)"), std::string::npos) << text; // RRT* per path
  EXPECT_NE(text.find("exact check: task 2: base hits box 9"), std::string::npos) << text;
}

}  // namespace
}  // namespace topay::frontend_bench
