#include "core/io/bounded_text_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/common/temp_path.h"

namespace topay {
namespace {

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Expects a ConfigError naming `path` whose message holds `part`.
void ExpectError(const std::string& path, std::size_t max_bytes, const std::string& part) {
  try {
    ReadBoundedTextFile(path, max_bytes, "test file");
    ADD_FAILURE() << "no error for " << path;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(BoundedTextFileTest, ReadsARegularFileUpToTheLimit) {
  const std::string path = UniqueTempPath("ok.txt");
  WriteText(path, "planner:\n  time_limit_s: 2\n");
  EXPECT_EQ(ReadBoundedTextFile(path, 1000, "test file"), "planner:\n  time_limit_s: 2\n");
  EXPECT_EQ(ReadBoundedTextFile(path, 27, "test file").size(), 27u);  // exactly the limit
  WriteText(path, "");
  EXPECT_EQ(ReadBoundedTextFile(path, 10, "test file"), "");
  std::remove(path.c_str());
}

TEST(BoundedTextFileTest, AFileAboveTheLimitIsAnError) {
  const std::string path = UniqueTempPath("big.txt");
  WriteText(path, std::string(101, 'x'));
  ExpectError(path, 100, "101 bytes, above its limit of 100 bytes");
  std::remove(path.c_str());
}

TEST(BoundedTextFileTest, MissingFilesAndDirectoriesAreErrors) {
  ExpectError(UniqueTempPath("missing.txt"), 100, "cannot open the test file");
  ExpectError(::testing::TempDir(), 100, "is a directory");
  ExpectError("/", 100, "is a directory");
}

TEST(BoundedTextFileTest, BinaryDataIsAnError) {
  const std::string path = UniqueTempPath("binary.txt");
  WriteText(path, std::string("ab\0cd", 5));
  ExpectError(path, 100, "NUL byte at offset 2");
  std::remove(path.c_str());
}

// The case: a file that never ends fails at its first block, whatever the limit.
TEST(BoundedTextFileTest, DevZeroFailsFast) {
  if (::access("/dev/zero", R_OK) != 0) GTEST_SKIP() << "no /dev/zero";
  ExpectError("/dev/zero", std::size_t{1} << 40, "NUL byte at offset 0");
}

// A pipe has no size: it is read up to the limit.
TEST(BoundedTextFileTest, PipesAreReadUpToTheLimit) {
  const std::string path = UniqueTempPath("fifo");
  std::remove(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::signal(SIGPIPE, SIG_IGN);  // the reader closes the pipe at the limit, mid-write
  auto write_then_close = [&path](std::string text) {
    return std::thread([&path, text] { std::ofstream(path, std::ios::binary) << text; });
  };
  std::thread writer = write_then_close("abc");
  EXPECT_EQ(ReadBoundedTextFile(path, 10, "test file"), "abc");
  writer.join();
  writer = write_then_close(std::string(200000, 'y'));
  ExpectError(path, 100000, "exceeds its limit of 100000 bytes");
  writer.join();
  std::remove(path.c_str());
}

}  // namespace
}  // namespace topay
