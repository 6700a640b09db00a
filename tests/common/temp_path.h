#pragma once

#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace topay {

/// A temporary file path unique to the running test case and process, so test cases that
/// ctest runs in parallel (each in its own process) never share a file.
inline std::string UniqueTempPath(const std::string& name) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test =
      info ? std::string(info->test_suite_name()) + "." + info->name() : std::string("no_test");
  return ::testing::TempDir() + "topay_" + test + "_" + std::to_string(::getpid()) + "_" + name;
}

}  // namespace topay
