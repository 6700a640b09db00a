// The counters' snapshot and the peak queue bytes (raised only).
#include "procs/viz/server/ws_server_stats.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace topay::viz {
namespace {

TEST(WsServerStatsTest, SnapshotCopiesEveryCounter) {
  ServerCounters counters;
  Increment(counters.clients);
  counters.frames_sent += 5;
  counters.bytes_sent += 1234;
  Increment(counters.protocol_errors);
  const WsServerStats stats = counters.Snapshot();
  EXPECT_EQ(stats.clients, 1u);
  EXPECT_EQ(stats.frames_sent, 5u);
  EXPECT_EQ(stats.bytes_sent, 1234u);
  EXPECT_EQ(stats.protocol_errors, 1u);
  EXPECT_EQ(stats.frames_dropped, 0u);
}

TEST(WsServerStatsTest, PeakQueueBytesOnlyRises) {
  ServerCounters counters;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&counters, t] {
      for (std::uint64_t i = 0; i < 1000; ++i) counters.NotePeakQueueBytes(i * 4 + t);
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(counters.Snapshot().peak_queue_bytes, 3999u);
  counters.NotePeakQueueBytes(10);
  EXPECT_EQ(counters.Snapshot().peak_queue_bytes, 3999u);
}

}  // namespace
}  // namespace topay::viz
