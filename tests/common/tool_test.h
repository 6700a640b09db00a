#pragma once

// A gtest fixture for the command-line tools (tools/*): a fresh temporary folder per test, and
// Run(), which runs the built tool end to end with its output captured.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

namespace topay {

/// What one run of a tool gave.
struct RunResult {
  int exit_code = -1;  ///< -1 if the tool did not exit normally.
  std::string out;
  std::string err;
};

/// The whole file as text (empty if it cannot be read).
inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Runs a shell command; its exit code, or -1 if it did not exit normally.
inline int ExitCodeOf(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class ToolTest : public ::testing::Test {
 protected:
  /// `tool`: the executable's name in TOPAY_BINARY_DIR/bin (e.g. "topay-plan").
  explicit ToolTest(std::string tool) : tool_(std::move(tool)) {}

  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (tool_ + "_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// A path in the test's temporary folder.
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs the tool with `args` (already quoted where needed), `env` prefixed (e.g. "X=1").
  RunResult Run(const std::string& args, const std::string& env = "") const {
    const std::string command = env + (env.empty() ? "" : " ") + "'" TOPAY_BINARY_DIR "/bin/" +
                                tool_ + "' " + args + " > '" + Path("stdout.txt") + "' 2> '" +
                                Path("stderr.txt") + "'";
    RunResult result;
    result.exit_code = ExitCodeOf(command);
    result.out = ReadText(Path("stdout.txt"));
    result.err = ReadText(Path("stderr.txt"));
    return result;
  }

  std::string tool_;
  std::filesystem::path dir_;
};

}  // namespace topay
