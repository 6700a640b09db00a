// A client that never reads must not hurt the sender nor the other clients: 20,000 frames of
// 10 kB Sent to it and to a reading client; Send never blocks (all the calls together take
// well under a second), the reading client gets every frame in order, the stuck one's frames
// are dropped (oldest first) and its queue never exceeds max_queue_bytes.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <memory>
#include <thread>

#include "procs/viz/server/ws_server.h"
#include "tests/common/sanitizer_build.h"
#include "tests/procs/viz/server/ws_test_client.h"

namespace topay::viz {
namespace {

using namespace topay::viz::testing;

constexpr int kFrames = 20000;
constexpr std::size_t kFrameBytes = 10000;
constexpr std::size_t kMaxQueueBytes = 2 << 20;  // 209 frames of 10 kB
// The sender waits whenever the reading client lags more than this many frames, so that the
// reading client (unlike the stuck one) never overflows its queue.
constexpr int kMaxLag = 150;

// A frame of kFrameBytes starting with its number.
OutgoingFrame NumberedFrame(int number) {
  std::string bytes(kFrameBytes, 'x');
  const std::string prefix = std::to_string(number) + ";";
  bytes.replace(0, prefix.size(), prefix);
  return {std::make_shared<const std::string>(std::move(bytes)), true};
}

// Resident memory of this process [kB] (0 if unknown).
long ResidentKb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return 0;
}

TEST(WsServerSlowClientTest, AStuckClientNeitherBlocksSendNorStarvesOthers) {
  WsServerOptions options = TestOptions();
  options.max_queue_bytes = kMaxQueueBytes;
  options.max_queue_frames = 512;
  CallbackLog log;
  WsServer server(options, log.Callbacks());
  std::string error;
  ASSERT_TRUE(server.Start(&error)) << error;

  TestClient stuck(server.port());  // connects, then never reads
  ASSERT_FALSE(stuck.Connect());
  const ClientId stuck_id = log.WaitOpened(1);
  TestClient reader(server.port());
  ASSERT_FALSE(reader.Connect());
  const ClientId reader_id = log.WaitOpened(2);
  ASSERT_NE(reader_id, 0u);

  std::atomic<int> received{0};
  std::atomic<bool> in_order{true};
  std::thread reading([&] {
    for (int i = 0; i < kFrames; ++i) {
      std::string message;
      if (reader.Read(&message, nullptr, 20.0)) break;
      if (message.size() != kFrameBytes || message.rfind(std::to_string(i) + ";", 0) != 0) {
        in_order = false;
      }
      received = i + 1;
    }
  });

  const long rss_before_kb = ResidentKb();
  double send_seconds = 0.0;
  double longest_send_s = 0.0;
  for (int i = 0; i < kFrames; ++i) {
    if (i % 50 == 0) {
      ASSERT_TRUE(WaitUntil([&] { return i - received.load() <= kMaxLag; }, 20.0))
          << "the reading client stalled at " << received.load();
    }
    const OutgoingFrame frame = NumberedFrame(i);
    const auto start = std::chrono::steady_clock::now();
    server.Send(stuck_id, frame);
    server.Send(reader_id, frame);
    const double seconds = SecondsSince(start);
    send_seconds += seconds;
    longest_send_s = std::max(longest_send_s, seconds);
  }
  reading.join();
  const long rss_after_kb = ResidentKb();

  // Send never waited on the network: 40,000 calls, each a queue push (about 0.1 s in all
  // on a loaded 2-core machine; the bound is for "never blocks", not for speed).
  EXPECT_LT(send_seconds, 1.0);
  // The reading client got everything, in order, nothing dropped.
  EXPECT_EQ(received.load(), kFrames);
  EXPECT_TRUE(in_order.load());
  std::optional<ClientStats> reader_stats;
  EXPECT_TRUE(WaitUntil([&] {  // the server counts a frame once its write completed
    reader_stats = server.client_stats(reader_id);
    return reader_stats && reader_stats->frames_sent == static_cast<std::uint64_t>(kFrames);
  }));
  ASSERT_TRUE(reader_stats);
  EXPECT_EQ(reader_stats->frames_dropped, 0u);
  // The stuck client's queue stayed within its bounds and dropped the excess.
  const std::optional<ClientStats> stuck_stats = server.client_stats(stuck_id);
  ASSERT_TRUE(stuck_stats);
  EXPECT_GT(stuck_stats->frames_dropped, 0u);
  EXPECT_LE(stuck_stats->peak_queue_bytes, kMaxQueueBytes);
  EXPECT_LE(stuck_stats->queued_bytes, kMaxQueueBytes);
  EXPECT_LT(stuck_stats->frames_sent, static_cast<std::uint64_t>(kFrames) / 2);
  const WsServerStats stats = server.stats();
  EXPECT_EQ(stats.frames_dropped, stuck_stats->frames_dropped);
  EXPECT_LE(stats.peak_queue_bytes, kMaxQueueBytes);
  EXPECT_LE(stats.queued_bytes, 2 * kMaxQueueBytes);
  // 200 MB went through the server; its memory did not follow (generous: the test's own
  // allocations share the process).
  // (Not in sanitizer builds: ASan's quarantine keeps freed memory resident.)
  if (rss_before_kb > 0 && !topay::testing::kAddressSanitizerBuild &&
      !topay::testing::kThreadSanitizerBuild) {
    EXPECT_LT(rss_after_kb - rss_before_kb, 64 * 1024);
  }
  std::printf("Send: %.3f s in total for %d calls (longest %.1f ms); stuck client: %lu sent, "
              "%lu dropped, peak queue %zu bytes; RSS %+ld kB\n",
              send_seconds, 2 * kFrames, longest_send_s * 1e3,
              static_cast<unsigned long>(stuck_stats->frames_sent),
              static_cast<unsigned long>(stuck_stats->frames_dropped),
              stuck_stats->peak_queue_bytes, rss_after_kb - rss_before_kb);

  // Others are still served, and Stop does not hang on the stuck client.
  TestClient late(server.port());
  ASSERT_FALSE(late.Connect());
  const ClientId late_id = log.WaitOpened(3);
  server.Send(late_id, TextFrame("still here"));
  std::string message;
  ASSERT_FALSE(late.Read(&message));
  EXPECT_EQ(message, "still here");
  const auto stop_start = std::chrono::steady_clock::now();
  server.Stop();
  EXPECT_LT(SecondsSince(stop_start), options.close_timeout_s + 1.0);
  EXPECT_EQ(log.closed().size(), 3u);
}

}  // namespace
}  // namespace topay::viz
