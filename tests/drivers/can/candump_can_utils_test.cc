// Interop with can-utils' own programs, offline (no AF_CAN needed): a log our writer wrote is
// converted by `log2asc` (can-utils reads it) and back by `asc2log` (can-utils writes a candump
// log), and our reader must give back the same frames. Skipped, with the reason, where can-utils
// is not installed (make deps installs it).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/can/candump_log.h"

namespace topay::can {
namespace {

bool OnPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CandumpCanUtilsTest, LogToAscAndBackGivesTheSameFrames) {
  if (!OnPath("log2asc") || !OnPath("asc2log")) {
    GTEST_SKIP() << "can-utils (log2asc, asc2log) not installed: make deps installs it";
  }
  const std::vector<CandumpRecord> records = {
      {1700000000100000, "can0", CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF})},
      {1700000000150000, "can0", CanFrame::Extended(0x1ABCDEF0, {1, 2, 3, 4, 5, 6, 7, 8})},
      {1700000000200000, "can0", CanFrame::Standard(0x701, {0x05})},
      {1700000000250000, "can0", CanFrame::Standard(0x080)},
      {1700000000300000, "can0", CanFrame::Standard(0x7FF, {0, 0xFF})},
  };
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "topay_candump_can_utils_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "ours.log");
    CandumpLogWriter writer(out);
    for (const CandumpRecord& r : records) writer.Write(r);
  }
  // log2asc maps interface names to ASC channels (-I in, can0 -> channel 1); asc2log back.
  const std::string to_asc =
      "log2asc -I " + (dir / "ours.log").string() + " -O " + (dir / "frames.asc").string() + " can0";
  ASSERT_EQ(std::system(to_asc.c_str()), 0) << to_asc;
  const std::string asc = ReadAll(dir / "frames.asc");
  EXPECT_NE(asc.find("123"), std::string::npos) << asc;
  const std::string to_log = "asc2log -I " + (dir / "frames.asc").string() + " -O " + (dir / "back.log").string();
  ASSERT_EQ(std::system(to_log.c_str()), 0) << to_log << "\n" << asc;

  std::ifstream in(dir / "back.log");
  std::vector<CandumpRecord> back;
  std::string error;
  ASSERT_TRUE(ReadCandumpLog(in, &back, &error)) << error << "\n" << ReadAll(dir / "back.log");
  ASSERT_EQ(back.size(), records.size()) << ReadAll(dir / "back.log");
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(back[i].frame, records[i].frame) << "frame " << i << ": " << ReadAll(dir / "back.log");
    // ASC keeps times relative to the first frame: the gaps survive.
    EXPECT_EQ(back[i].timestamp_us - back[0].timestamp_us, records[i].timestamp_us - records[0].timestamp_us)
        << "frame " << i;
  }
}

}  // namespace
}  // namespace topay::can
