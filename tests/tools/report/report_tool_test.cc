// The built topay-report: 0 with the summary printed and the files written, 1 for a missing log
// or scene (naming it) or a file that is not a log, 2 for usage errors.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/common/tool_test.h"

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

class ReportTool : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::FreshTestDir("tool");
    out_ = dir_ + "/stdout.txt";
    err_ = dir_ + "/stderr.txt";
  }
  int Run(const std::string& args) {
    return ExitCodeOf("'" + bin_ + "' " + args + " > '" + out_ + "' 2> '" + err_ + "'");
  }
  const std::string bin_ = std::string(TOPAY_BINARY_DIR) + "/bin/topay-report";
  std::string dir_, out_, err_;
};

TEST_F(ReportTool, WritesTheReportAndExitsZero) {
  test::WriteCraftedRunLog(dir_ + "/run/graph.lcmlog");
  ASSERT_EQ(Run("--log '" + dir_ + "/run/graph.lcmlog' --out '" + dir_ + "/report' --json '" + dir_ + "/s.json'"), 0)
      << ReadText(err_);
  const std::string text = ReadText(out_);
  EXPECT_NE(text.find("SUCCEEDED after 9.0 s"), std::string::npos) << text;
  EXPECT_NE(text.find("time plots: " + dir_ + "/report/time_plots.png"), std::string::npos) << text;
  for (const char* file : {"/report/summary.json", "/report/path.png", "/report/time_plots.png", "/s.json"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir_ + file)) << file;
  }
}

TEST_F(ReportTool, AMissingLogOrSceneExitsOneNamingIt) {
  EXPECT_EQ(Run("--log '" + dir_ + "/nope.lcmlog'"), 1);
  EXPECT_NE(ReadText(err_).find(dir_ + "/nope.lcmlog"), std::string::npos) << ReadText(err_);
  std::ofstream(dir_ + "/text.lcmlog") << "hello, not a log\n";
  EXPECT_EQ(Run("--log '" + dir_ + "/text.lcmlog'"), 1);
  EXPECT_NE(ReadText(err_).find("text.lcmlog: not an LCM log"), std::string::npos) << ReadText(err_);
  test::WriteCraftedRunLog(dir_ + "/graph.lcmlog");
  EXPECT_EQ(Run("--log '" + dir_ + "/graph.lcmlog' --scene '" + dir_ + "/no_room.json'"), 1);
  EXPECT_NE(ReadText(err_).find("no_room.json"), std::string::npos) << ReadText(err_);
}

TEST_F(ReportTool, UsageErrorsExitTwo) {
  EXPECT_EQ(Run(""), 2);  // --log is required
  EXPECT_EQ(Run("--log x.lcmlog --bogus"), 2);
  EXPECT_NE(ReadText(err_).find("topay-report"), std::string::npos);
  EXPECT_EQ(Run("--help"), 0);
  EXPECT_NE(ReadText(out_).find("Exit codes"), std::string::npos);
}

}  // namespace
}  // namespace topay::report
