// The terminal summary of the crafted run names the result, the counts and the files.

#include "tools/report/summary_format.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

TEST(SummaryFormat, NamesResultStepsCountsAndMalformedMessages) {
  const std::string path = test::FreshTestDir("format") + "/graph.lcmlog";
  test::WriteCraftedRunLog(path);
  RunSummary summary = Summarize(path);
  summary.files.path_png = "/x/path.png";
  const std::string text = FormatSummary(summary);
  for (const std::string& expected :
       {std::string("mission 'two_goals': SUCCEEDED after 9.0 s (3 of 3 steps seen)"),
        std::string("goto pickup"), std::string("4.0 s, 2 attempts"),
        std::string("gripper close                    0.5 s\n"),
        std::string("4.0 s, 1 attempt\n"), std::string("replans: 3 over 4 goals"),
        std::string("3 TRAJECTORY messages (2 rebuilt); 1 stopping trajectory"),
        std::string("3 plans, total median 200.0 ms, p95 290.0 ms, max 300.0 ms; 2 failed goals"),
        std::string("failed 1x: target unreachable"),
        std::string("ground-truth collisions: 2 contact events, 7 steps in contact, max depth 0.0120 m; 2 SIM_CONTACT"),
        std::string("position RMS 0.0250 m, max 0.0400 m"), std::string("median 2.500 ms, p99 3.970 ms, max 4.000 ms"),
        std::string("driven: 7.00 m; boxes appeared: 2"), std::string("box 40 'crate' at (1.50, 2.50, 0.40) m"),
        std::string("3 decode failures"), std::string("(1 malformed)"), std::string("log: " + path),
        std::string("path plot: /x/path.png")}) {
    EXPECT_NE(text.find(expected), std::string::npos) << "missing: " << expected << "\n" << text;
  }
}

TEST(SummaryFormat, NoMissionStatusIsSaid) {
  RunSummary summary;
  EXPECT_NE(FormatSummary(summary).find("mission: no MISSION_STATUS in the log"), std::string::npos);
}

}  // namespace
}  // namespace topay::report
