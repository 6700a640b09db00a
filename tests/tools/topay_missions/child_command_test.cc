#include "tools/topay_missions/child_command.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace topay::tools {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RunChildCommand, GivesTheExitCodeAndTheOutput) {
  const std::string out = (std::filesystem::temp_directory_path() / "child_command_test.out").string();
  ChildCommandOptions options;
  options.output_path = out;
  int polls = 0;
  options.poll_period_s = 0.01;
  options.on_poll = [&] { ++polls; };
  const ChildCommandResult r = RunChildCommand({"/bin/sh", "-c", "echo hello; echo oops >&2; exit 3"}, options);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.timed_out);
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(ReadAll(out), "hello\noops\n");
  EXPECT_GE(polls, 1);  // once after the exit at least
}

TEST(RunChildCommand, AMissingProgramIsNamed) {
  ChildCommandOptions options;
  options.output_path = (std::filesystem::temp_directory_path() / "child_command_missing.out").string();
  const ChildCommandResult r = RunChildCommand({"/nonexistent/topay-nothing"}, options);
  EXPECT_EQ(r.exit_code, 127);
  EXPECT_NE(ReadAll(options.output_path).find("cannot run /nonexistent/topay-nothing"), std::string::npos);
  EXPECT_FALSE(r.error.empty());
}

TEST(RunChildCommand, TheTimeLimitInterruptsIt) {
  ChildCommandOptions options;
  options.timeout_s = 0.2;
  options.poll_period_s = 0.02;
  const auto start = std::chrono::steady_clock::now();
  const ChildCommandResult r = RunChildCommand({"/bin/sleep", "30"}, options);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.exit_code, 128 + 2);  // SIGINT
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(RunChildCommand, AStopRequestInterruptsIt) {
  ChildCommandOptions options;
  options.poll_period_s = 0.02;
  int polls = 0;
  options.stop_requested = [&] { return ++polls > 3; };
  const ChildCommandResult r = RunChildCommand({"/bin/sleep", "30"}, options);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 128 + 2);
}

}  // namespace
}  // namespace topay::tools
