// Fault injection (sim/motors/fault_injection.h): seeded loss within binomial bounds and
// repeatable, FIFO delay and delay bursts, bus-off error frames and silence, heartbeat-loss
// windows, scripted and run-time faults, malformed faults refused.

#include "sim/motors/fault_injection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/can/can_error.h"

namespace topay::sim::motors {
namespace {

can::CanFrame Frame(int i) { return can::CanFrame::Standard(0x181, {static_cast<std::uint8_t>(i & 0xFF)}); }

std::int64_t PassedOf(std::uint64_t seed, double percent, int n) {
  FaultInjectionOptions options;
  options.seed = seed;
  options.rx_loss_percent = percent;
  FaultInjector injector(options, 7);
  for (int i = 0; i < n; ++i) injector.PushReceived(Frame(i), i * 1e-4);
  return static_cast<std::int64_t>(injector.TakeReceived(1.0).size());
}

TEST(FaultInjectionTest, LossRateIsWithinBinomialBoundsAndRepeatable) {
  const int n = 10000;
  const std::int64_t passed = PassedOf(7, 20.0, n);
  // Binomial(10000, 0.8): mean 8000, sd 40; 5 sd either way.
  EXPECT_NEAR(static_cast<double>(passed), 8000.0, 200.0);
  EXPECT_EQ(PassedOf(7, 20.0, n), passed) << "same seed, same losses";
  EXPECT_EQ(PassedOf(7, 0.0, n), n);
  EXPECT_EQ(PassedOf(7, 100.0, n), 0);
}

TEST(FaultInjectionTest, TxLossOnlyTouchesSentFrames) {
  FaultInjectionOptions options;
  options.tx_loss_percent = 50.0;
  FaultInjector injector(options, 7);
  for (int i = 0; i < 1000; ++i) {
    injector.PushReceived(Frame(i), 0.0);
    injector.PushSent(Frame(i), 0.0);
  }
  EXPECT_EQ(injector.TakeReceived(0.0).size(), 1000u);
  EXPECT_NEAR(static_cast<double>(injector.TakeSent(0.0).size()), 500.0, 5 * std::sqrt(250.0));
  EXPECT_EQ(injector.tx_counts().lost + injector.tx_counts().passed, 1000);
}

TEST(FaultInjectionTest, DelayKeepsTheOrder) {
  FaultInjector injector({}, 7);
  FaultEvent delay;
  delay.kind = FaultKind::kDelay;
  delay.value = 20.0;  // ms
  ASSERT_EQ(injector.Inject(delay, 0.0), "");
  injector.Advance(0.0);
  injector.PushReceived(Frame(1), 0.0);
  EXPECT_TRUE(injector.TakeReceived(0.019).empty());
  delay.value = 0.0;  // a shorter delay must not let a later frame overtake
  injector.Inject(delay, 0.005);
  injector.Advance(0.005);
  injector.PushReceived(Frame(2), 0.005);
  EXPECT_TRUE(injector.TakeReceived(0.006).empty());
  const std::vector<can::CanFrame> due = injector.TakeReceived(0.0201);
  ASSERT_EQ(due.size(), 2u);
  EXPECT_EQ(due[0].data[0], 1);
  EXPECT_EQ(due[1].data[0], 2);
  EXPECT_EQ(injector.rx_counts().delayed, 2);
}

TEST(FaultInjectionTest, DelayBurstsFromTheOptions) {
  FaultInjectionOptions options;
  options.delay_ms = 10.0;
  options.delay_burst_s = 0.1;
  options.delay_period_s = 1.0;
  FaultInjector injector(options, 7);
  EXPECT_DOUBLE_EQ(injector.delay_s(0.05), 0.01);
  EXPECT_DOUBLE_EQ(injector.delay_s(0.5), 0.0);
  EXPECT_DOUBLE_EQ(injector.delay_s(2.02), 0.01);
  FaultEvent clear;
  clear.kind = FaultKind::kClear;
  injector.Inject(clear, 2.03);
  injector.Advance(2.03);
  EXPECT_DOUBLE_EQ(injector.delay_s(3.05), 0.0);
}

TEST(FaultInjectionTest, BusOffPutsAnErrorFrameOnTheBusAndSilencesTheNodes) {
  FaultInjector injector({}, 7);
  injector.PushSent(Frame(1), 0.9);  // in flight: delivered before the bus-off
  EXPECT_EQ(injector.TakeSent(0.9).size(), 1u);
  FaultEvent bus_off;
  bus_off.kind = FaultKind::kBusOff;
  bus_off.duration_s = 0.2;
  ASSERT_EQ(injector.Inject(bus_off, 1.0), "");
  FaultInjector::Actions actions = injector.Advance(1.0);
  ASSERT_EQ(actions.error_frames.size(), 1u);
  EXPECT_TRUE(actions.error_frames[0].error);
  EXPECT_TRUE(can::DecodeCanErrorFrame(actions.error_frames[0]).bus_off);
  EXPECT_TRUE(injector.bus_off());
  injector.PushSent(Frame(2), 1.1);
  injector.PushReceived(Frame(3), 1.1);
  EXPECT_TRUE(injector.TakeSent(1.1).empty());
  EXPECT_TRUE(injector.TakeReceived(1.1).empty());
  EXPECT_TRUE(injector.Advance(1.19).error_frames.empty());
  actions = injector.Advance(1.2);
  ASSERT_EQ(actions.error_frames.size(), 1u);
  EXPECT_TRUE(can::DecodeCanErrorFrame(actions.error_frames[0]).restarted);
  EXPECT_FALSE(injector.bus_off());
  injector.PushSent(Frame(4), 1.21);
  EXPECT_EQ(injector.TakeSent(1.21).size(), 1u);
  EXPECT_EQ(injector.tx_counts().silenced, 1);
  EXPECT_EQ(injector.rx_counts().silenced, 1);
  EXPECT_EQ(injector.counts().bus_offs, 1);
}

TEST(FaultInjectionTest, ScriptedFaultsFireOnceAtTheirTime) {
  FaultInjectionOptions options;
  FaultEvent fault;
  fault.kind = FaultKind::kDriveFault;
  fault.joint = 4;
  fault.at_s = 0.5;
  FaultEvent heartbeat;
  heartbeat.kind = FaultKind::kHeartbeatLoss;
  heartbeat.joint = 2;
  heartbeat.at_s = 0.2;
  heartbeat.duration_s = 0.3;
  options.events = {fault, heartbeat};  // out of order on purpose
  FaultInjector injector(options, 7);
  EXPECT_TRUE(injector.Advance(0.1).node_faults.empty());
  EXPECT_FALSE(injector.HeartbeatSuppressed(2, 0.1));
  injector.Advance(0.2);
  EXPECT_TRUE(injector.HeartbeatSuppressed(2, 0.3));
  EXPECT_FALSE(injector.HeartbeatSuppressed(3, 0.3));
  EXPECT_FALSE(injector.HeartbeatSuppressed(2, 0.5));
  const FaultInjector::Actions actions = injector.Advance(0.5);
  ASSERT_EQ(actions.node_faults.size(), 1u);
  EXPECT_EQ(actions.node_faults[0].joint, 4);
  EXPECT_TRUE(injector.Advance(0.6).node_faults.empty());
}

TEST(FaultInjectionTest, RefusesMalformedFaults) {
  FaultInjector injector({}, 7);
  FaultEvent e;
  e.kind = FaultKind::kDriveFault;
  e.joint = 8;
  EXPECT_NE(injector.Inject(e, 0.0), "");
  e.kind = FaultKind::kBusOff;
  e.duration_s = 0.0;
  EXPECT_NE(injector.Inject(e, 0.0), "");
  e.kind = FaultKind::kRxLoss;
  e.value = 150.0;
  EXPECT_NE(injector.Inject(e, 0.0), "");
  e.kind = FaultKind::kBaseFault;
  e.code = 11;
  EXPECT_NE(injector.Inject(e, 0.0), "");
  EXPECT_EQ(injector.counts().rejected, 4);
  FaultInjectionOptions options;
  options.delay_burst_s = 2.0;
  EXPECT_NE(CheckFaultInjectionOptions(options, 7), "") << "a burst longer than its period";
  EXPECT_THROW(FaultInjector(options, 7), std::invalid_argument);
  FaultKind kind;
  EXPECT_TRUE(ParseFaultKind("heartbeat_loss", &kind));
  EXPECT_EQ(kind, FaultKind::kHeartbeatLoss);
  EXPECT_FALSE(ParseFaultKind("meltdown", &kind));
}

}  // namespace
}  // namespace topay::sim::motors
