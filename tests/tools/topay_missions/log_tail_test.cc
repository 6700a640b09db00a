#include "tools/topay_missions/log_tail.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace topay::tools {
namespace {

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("log_tail_test_" + name)).string();
}

TEST(LogTail, ReturnsCompleteLinesOnceAndWaitsForTheRest) {
  const std::string path = TempPath("grow.log");
  std::filesystem::remove(path);
  LogTail tail(path);
  EXPECT_TRUE(tail.NewLines().empty());  // no file yet
  std::ofstream out(path);
  out << "first\nsecond\nthi" << std::flush;
  EXPECT_EQ(tail.NewLines(), (std::vector<std::string>{"first", "second"}));
  EXPECT_TRUE(tail.NewLines().empty());
  out << "rd\nfour" << std::flush;
  EXPECT_EQ(tail.NewLines(), (std::vector<std::string>{"third"}));
  EXPECT_EQ(tail.NewLines(true), (std::vector<std::string>{"four"}));  // the writer ended
  EXPECT_TRUE(tail.NewLines(true).empty());
}

TEST(LogTail, StartsOverWhenTheFileIsTruncated) {
  const std::string path = TempPath("truncated.log");
  { std::ofstream(path) << "a long first line\n"; }
  LogTail tail(path);
  EXPECT_EQ(tail.NewLines().size(), 1u);
  { std::ofstream(path) << "new\n"; }
  EXPECT_EQ(tail.NewLines(), (std::vector<std::string>{"new"}));
}

}  // namespace
}  // namespace topay::tools
