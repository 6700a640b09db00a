// candump -l logs: writing, reading back, and the errors on bad lines.
#include "drivers/can/candump_log.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <stdexcept>

#include "drivers/can/can_error.h"

namespace topay::can {
namespace {

TEST(CandumpLogTest, FormatsLikeCandump) {
  EXPECT_EQ(FormatCandumpLine({1700000000123456, "can0", CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF})}),
            "(1700000000.123456) can0 123#DEADBEEF");
  EXPECT_EQ(FormatCandumpLine({5, "vcan0", CanFrame::Extended(0x12345678, {0})}),
            "(0000000000.000005) vcan0 12345678#00");
  EXPECT_EQ(FormatCandumpLine({1000000, "can1", CanFrame::Remote(0x7FF)}), "(0000000001.000000) can1 7FF#R");
}

TEST(CandumpLogTest, FormatRefusesWhatCouldNotBeReadBack) {
  EXPECT_THROW(FormatCandumpLine({-1, "can0", CanFrame::Standard(1)}), std::invalid_argument);
  EXPECT_THROW(FormatCandumpLine({0, "", CanFrame::Standard(1)}), std::invalid_argument);
  EXPECT_THROW(FormatCandumpLine({0, "can 0", CanFrame::Standard(1)}), std::invalid_argument);
  CanFrame bad = CanFrame::Standard(1);
  bad.dlc = 9;
  EXPECT_THROW(FormatCandumpLine({0, "can0", bad}), std::invalid_argument);
}

TEST(CandumpLogTest, WriteReadRoundTrip) {
  const std::vector<CandumpRecord> records = {
      {1700000000123456, "can0", CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF})},
      {1700000000123457, "can0", CanFrame::Extended(0x1FFFFFFF, {1, 2, 3, 4, 5, 6, 7, 8})},
      {1700000000200000, "can1", CanFrame::Remote(0x100, 2)},
      {1700000000300000, "can0", CanFrame::Standard(0x0)},
      {1700000000400000, "can0", MakeCanErrorFrame(0x40 /* CAN_ERR_BUSOFF */)},
  };
  std::ostringstream out;
  CandumpLogWriter writer(out);
  for (const CandumpRecord& record : records) writer.Write(record);
  writer.Write(1700000000500000999, "can0", CanFrame::Standard(0x42, {0x42}));  // ns: truncated to us

  std::istringstream in(out.str());
  std::vector<CandumpRecord> back;
  std::string error;
  ASSERT_TRUE(ReadCandumpLog(in, &back, &error)) << error;
  ASSERT_EQ(back.size(), records.size() + 1);
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(back[i].timestamp_us, records[i].timestamp_us) << i;
    EXPECT_EQ(back[i].interface, records[i].interface) << i;
    EXPECT_EQ(back[i].frame, records[i].frame) << i << ": " << ToString(back[i].frame);
  }
  EXPECT_EQ(back.back().timestamp_us, 1700000000500000);
}

TEST(CandumpLogTest, ReadsCanUtilsOutputVariants) {
  // Lower-case hex, extra spaces, CRLF, empty lines and candump -x's direction flag.
  std::istringstream in(
      "(1700000000.000001) can0 1a0#deadbeef\r\n"
      "\n"
      "(1700000000.000002)   can0   00000abc#R   \n"
      "(1700000000.000003) can0 123#11 T\n");
  std::vector<CandumpRecord> records;
  std::string error;
  ASSERT_TRUE(ReadCandumpLog(in, &records, &error)) << error;
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(records[0].frame, CanFrame::Standard(0x1A0, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_EQ(records[1].frame, CanFrame::Remote(0xABC, 0, true));
  EXPECT_EQ(records[2].timestamp_us, 1700000000000003);
}

std::string ReadError(const std::string& text) {
  std::istringstream in(text);
  std::vector<CandumpRecord> records;
  std::string error;
  EXPECT_FALSE(ReadCandumpLog(in, &records, &error)) << text;
  return error;
}

TEST(CandumpLogTest, BadLinesGiveTheLineNumberAndTheProblem) {
  const std::string good = "(1700000000.000001) can0 123#00\n";
  EXPECT_EQ(ReadError(good + "(1700000000.1) can0 123#00\n"),
            "line 2: timestamp '(1700000000.1)' must be (SECONDS.MICROSECONDS) with 6 decimals");
  EXPECT_EQ(ReadError(good + good + "1700000000.000001 can0 123#00\n"),
            "line 3: timestamp '1700000000.000001' must be (SECONDS.MICROSECONDS) with 6 decimals");
  EXPECT_EQ(ReadError("(1700000000.000001) can0\n"), "line 1: expected '(SECONDS.MICROSECONDS) IFACE FRAME', found 2 fields");
  EXPECT_EQ(ReadError("(1700000000.000001) can0 123#00 extra\n"),
            "line 1: expected '(SECONDS.MICROSECONDS) IFACE FRAME', found 4 fields");
  EXPECT_EQ(ReadError(good + "(1700000000.000001) can0 123#001122334455667788\n"),
            "line 2: frame '123#001122334455667788': more than 8 data bytes");
  EXPECT_EQ(ReadError("(1700000000.000001) can0 800#00\n"), "line 1: frame '800#00': standard id 0x800 is above 0x7FF");
  EXPECT_EQ(ReadError("(1700000000.000001) averyveryverylongname 123#00\n"),
            "line 1: interface name 'averyveryverylongname' is longer than 15");
  EXPECT_EQ(ReadError("(-1.000000) can0 123#00\n"),
            "line 1: timestamp '(-1.000000)' must be (SECONDS.MICROSECONDS) with 6 decimals");
}

TEST(CandumpLogTest, MangledLinesAreRejectedOrParsedNeverCrash) {
  std::mt19937 random(20);
  const std::string good = "(1700000000.123456) can0 12345678#DEADBEEF";
  const std::string alphabet = "0123456789ABCDEFabcdef#R.() \tx-";
  for (int i = 0; i < 20000; ++i) {
    std::string line = good;
    for (int k = 0; k < 1 + i % 4; ++k) {
      const std::size_t at = random() % (line.size() + 1);
      const char c = alphabet[random() % alphabet.size()];
      switch (random() % 3) {
        case 0: if (at < line.size()) line[at] = c; break;
        case 1: line.insert(line.begin() + at, c); break;
        default: if (at < line.size()) line.erase(at, 1); break;
      }
    }
    std::string error;
    const std::optional<CandumpRecord> record = ParseCandumpLine(line, &error);
    if (record) {
      EXPECT_EQ(CheckCanFrame(record->frame), "") << line;
      // What parses prints back to a line that parses to the same record.
      const std::optional<CandumpRecord> again = ParseCandumpLine(FormatCandumpLine(*record), &error);
      ASSERT_TRUE(again) << line << ": " << error;
      EXPECT_EQ(again->frame, record->frame) << line;
      EXPECT_EQ(again->timestamp_us, record->timestamp_us) << line;
    } else {
      EXPECT_FALSE(error.empty()) << line;
    }
  }
}

}  // namespace
}  // namespace topay::can
