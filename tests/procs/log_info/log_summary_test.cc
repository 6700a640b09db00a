// topay-log-info's summary (procs/log_info/log_summary.h) of a crafted log: types by
// fingerprint, counts, sizes, rates, span, and the messages that fail to decode per channel.

#include "procs/log_info/log_summary.h"

#include <gtest/gtest.h>

#include "../../lcm/sample_messages.h"
#include "graph_test_support.h"

namespace topay::loginfo {
namespace {

void Write(lcm::LogFile* log, std::int64_t utime, const std::string& channel, std::vector<std::uint8_t> data) {
  lcm::LogEvent event;
  event.timestamp = utime;
  event.channel = channel;
  event.datalen = static_cast<int32_t>(data.size());
  event.data = data.data();
  log->writeEvent(&event);
}

TEST(LogSummary, CountsTypesSizesRatesAndDecodeFailures) {
  const std::string path = test::TestDir("log_summary") + "/crafted.lcmlog";
  const std::vector<std::uint8_t> state = test::Encode(test::MessageSample<robot_state_t>::Make());
  const std::vector<std::uint8_t> beat = test::Encode(test::MessageSample<heartbeat_t>::Make());
  {
    lcm::LogFile log(path, "w");
    for (int i = 0; i < 11; ++i) Write(&log, 1'000'000 + i * 100'000, "ROBOT_STATE", state);  // 10 Hz for 1 s
    Write(&log, 1'050'000, "ROBOT_STATE", std::vector<std::uint8_t>(state.begin(), state.end() - 1));  // truncated
    Write(&log, 1'060'000, "ROBOT_STATE", beat);                     // a heartbeat on the wrong channel
    Write(&log, 1'500'000, "HEARTBEAT", beat);
    Write(&log, 1'600'000, "MYSTERY", {1, 2, 3, 4, 5, 6, 7, 8, 9});  // unknown fingerprint
    Write(&log, 2'500'000, "LCM_SELF_TEST", {'l', 'c', 'm'});
  }
  const LogSummary s = SummarizeLog(path);
  EXPECT_EQ(s.events, 16);
  EXPECT_DOUBLE_EQ(s.span_s(), 1.5);
  const ChannelSummary& rs = s.channels.at("ROBOT_STATE");
  EXPECT_EQ(rs.count, 13);
  EXPECT_EQ(rs.types.at("robot_state_t"), 12);  // the truncated one still has the fingerprint
  EXPECT_EQ(rs.types.at("heartbeat_t"), 1);
  EXPECT_EQ(rs.decode_failures, 1);              // truncated; the heartbeat decodes as its type
  EXPECT_EQ(rs.max_bytes, static_cast<std::int64_t>(state.size()));
  EXPECT_EQ(rs.min_bytes, static_cast<std::int64_t>(beat.size()));
  EXPECT_NEAR(rs.rate_hz(), 12.0, 1e-9);          // 13 messages over 1 s
  EXPECT_EQ(s.channels.at("HEARTBEAT").decode_failures, 0);
  EXPECT_EQ(s.channels.at("HEARTBEAT").rate_hz(), 0.0);
  EXPECT_EQ(s.channels.at("MYSTERY").types.at("unknown"), 1);
  EXPECT_EQ(s.channels.at("MYSTERY").decode_failures, 1);
  EXPECT_EQ(s.channels.at("LCM_SELF_TEST").decode_failures, 0);
  const std::string table = FormatSummary(s);
  EXPECT_NE(table.find("16 messages on 4 channels over 1.500 s"), std::string::npos) << table;
  EXPECT_NE(table.find("heartbeat_t(1),robot_state_t(12)"), std::string::npos) << table;
  EXPECT_NE(SummaryJson(s).find("\"decode_failures\": 1"), std::string::npos);
}

TEST(LogSummary, NamesAnUnreadableFile) {
  EXPECT_THROW(SummarizeLog("/no/such/file.lcmlog"), std::runtime_error);
}

}  // namespace
}  // namespace topay::loginfo
