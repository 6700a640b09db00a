// The bus load figure: exact frame lengths over a sliding window at the bit rate; and the
// latency summary (median, p99, max) the bridge reports.
#include "procs/canbridge/bus_load_meter.h"

#include <gtest/gtest.h>

#include "drivers/can/can_frame_bits.h"
#include "procs/canbridge/latency_stats.h"

namespace topay::canbridge {
namespace {

TEST(BusLoadMeterTest, ShareOfTheBitRateOverTheWindow) {
  BusLoadMeter meter(1e6);
  const can::CanFrame sync = can::CanFrame::Standard(0x080);
  const int bits = can::CanFrameLengthBits(sync);  // 51
  double t = 10.0;
  for (int i = 0; i < 2000; ++i) meter.Add(sync, t += 0.001);  // 1000 frames/s for 2 s
  EXPECT_NEAR(meter.LoadPercent(t), 100.0 * 1000 * bits / 1e6, 0.2);
  EXPECT_EQ(meter.total_bits(), 2000LL * bits);
  EXPECT_NEAR(meter.LoadPercent(t + 0.5), 100.0 * 500 * bits / 1e6, 0.2);  // half the window left
  EXPECT_EQ(meter.LoadPercent(t + 2.0), 0.0);
}

TEST(LatencyStatsTest, MedianP99Max) {
  LatencyStats stats(1000);
  EXPECT_EQ(stats.Summary().count, 0);
  for (int i = 1; i <= 100; ++i) stats.Add(i * 1e-3);  // 1..100 ms
  const LatencySummary s = stats.Summary();
  EXPECT_EQ(s.count, 100);
  EXPECT_DOUBLE_EQ(s.median_ms, 50.0);
  EXPECT_DOUBLE_EQ(s.p99_ms, 99.0);
  EXPECT_DOUBLE_EQ(s.max_ms, 100.0);
  EXPECT_NE(stats.Text().find("p99 99.000 ms"), std::string::npos) << stats.Text();
}

TEST(LatencyStatsTest, KeepsTheLastSamplesAndTheMaxOfAll) {
  LatencyStats stats(10);
  stats.Add(1.0);
  for (int i = 0; i < 20; ++i) stats.Add(1e-3);
  EXPECT_DOUBLE_EQ(stats.Summary().p99_ms, 1.0);
  EXPECT_DOUBLE_EQ(stats.Summary().max_ms, 1000.0);
  EXPECT_EQ(stats.Summary().count, 21);
}

}  // namespace
}  // namespace topay::canbridge
