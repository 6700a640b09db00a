// The replay's log player (procs/launch/log_player.h) over memq://: pace by the speed factor,
// start offset, channel filter and the excluded (replayed processes' own) channels.

#include "procs/launch/log_player.h"

#include <gtest/gtest.h>

#include <vector>

#include "graph_test_support.h"

namespace topay::launch {
namespace {

using Clock = LogPlayer::Clock;

// A log of 10 events per channel A, B, C, one every 100 ms (A at 0, B at 10 ms, C at 20 ms).
std::string WriteLog() {
  const std::string path = test::TestDir("log_player") + "/test.lcmlog";
  lcm::LogFile log(path, "w");
  std::vector<std::uint8_t> data = {1, 2, 3};
  for (int i = 0; i < 10; ++i) {
    for (int c = 0; c < 3; ++c) {
      lcm::LogEvent event;
      event.timestamp = 1'000'000'000 + i * 100'000 + c * 10'000;
      event.channel = std::string(1, static_cast<char>('A' + c));
      event.datalen = static_cast<int32_t>(data.size());
      event.data = data.data();
      log.writeEvent(&event);
    }
  }
  return path;
}

struct Received {
  std::map<std::string, int> counts;
  void On(const lcm::ReceiveBuffer*, const std::string& channel) { ++counts[channel]; }
};

// Plays the log into memq, pumping in real time; returns the counts and the time it took.
std::map<std::string, int> Play(const ReplayOptions& options, const std::set<std::string>& excluded, double* took_s) {
  lcm::LCM bus("memq://");
  Received received;
  bus.subscribe(".*", &Received::On, &received);
  LogPlayer player(options, excluded);
  const Clock::time_point start = Clock::now();
  player.Start(start);
  while (!player.Pump(Clock::now(), &bus)) {
    while (bus.handleTimeout(0) > 0) {
    }
    std::this_thread::sleep_until(std::min(player.NextDue(), Clock::now() + std::chrono::milliseconds(50)));
  }
  while (bus.handleTimeout(0) > 0) {
  }
  *took_s = std::chrono::duration<double>(Clock::now() - start).count();
  return received.counts;
}

TEST(LogPlayer, PlaysEveryChannelButTheExcludedOnesAtTheRecordedPace) {
  ReplayOptions options;
  options.log_path = WriteLog();
  double took = 0.0;
  const auto counts = Play(options, {"B"}, &took);
  EXPECT_EQ(counts.at("A"), 10);
  EXPECT_FALSE(counts.contains("B"));
  EXPECT_EQ(counts.at("C"), 10);
  EXPECT_GT(took, 0.85);  // the last event is 0.92 s after the first
}

TEST(LogPlayer, SpeedFactorStartOffsetAndChannelFilter) {
  ReplayOptions options;
  options.log_path = WriteLog();
  options.speed = 4.0;
  options.start_offset_s = 0.5;
  options.channels = "A|B";
  double took = 0.0;
  const auto counts = Play(options, {}, &took);
  EXPECT_EQ(counts.at("A"), 5);  // events 5..9
  EXPECT_EQ(counts.at("B"), 5);
  EXPECT_FALSE(counts.contains("C"));
  EXPECT_LT(took, 0.35);  // 0.41 s of log at 4x: 0.10 s (at 1x it would take 0.41 s)
  EXPECT_GT(took, 0.08);
}

TEST(LogPlayer, NamesAFileThatIsNotALog) {
  ReplayOptions options;
  options.log_path = test::TestDir("log_player_bad") + "/missing.lcmlog";
  try {
    LogPlayer player(options, {});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.lcmlog"), std::string::npos);
  }
}

}  // namespace
}  // namespace topay::launch
