// The simulated wheel controller (sim/motors/wheel_controller_node.h) against the base protocol's
// host-side codecs: the mode switch into CAN command mode, commands followed only there, the
// watchdog braking to zero, wheel speeds and odometry matching the plant's motion, malformed
// frames refused and counted, a fault frame before the status that reports it.

#include "sim/motors/wheel_controller_node.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "drivers/base/fault_frame.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"

namespace topay::sim::motors {
namespace {

constexpr int kNode = 16;
using base::BaseMode;

can::CanFrame Request(base::ModeRequest request) { return *base::EncodeModeRequest(request, kNode, nullptr); }

can::CanFrame Command(double v, double omega, std::uint8_t counter) {
  return *base::EncodeVelocityCommand({v, omega, counter}, kNode, nullptr);
}

// The frames of `kind` in `frames`.
std::vector<can::CanFrame> OfKind(const std::vector<can::CanFrame>& frames, base::BaseFrameKind kind) {
  std::vector<can::CanFrame> out;
  for (const can::CanFrame& f : frames) {
    if (base::IdentifyFrame(f, kNode, nullptr) == kind) out.push_back(f);
  }
  return out;
}

std::optional<base::BaseStatus> LastStatus(const std::vector<can::CanFrame>& frames) {
  const std::vector<can::CanFrame> status = OfKind(frames, base::BaseFrameKind::kStatus);
  if (status.empty()) return std::nullopt;
  return base::DecodeStatus(status.back(), kNode, nullptr);
}

TEST(WheelControllerNodeTest, FollowsCommandsOnlyInCanCommandMode) {
  WheelControllerNode node({}, 0.0);
  std::vector<can::CanFrame> out;
  node.Step(0.0, std::nullopt, &out);
  ASSERT_TRUE(LastStatus(out));
  EXPECT_EQ(LastStatus(out)->mode, BaseMode::kStandby);

  EXPECT_TRUE(node.OnFrame(Command(0.5, 0.2, 0), 0.005));
  node.Step(0.005, std::nullopt, &out);
  EXPECT_EQ(node.counts().commands_ignored, 1);
  EXPECT_EQ(node.command().v_m_per_s, 0.0);

  out.clear();
  EXPECT_TRUE(node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.01));
  node.Step(0.01, std::nullopt, &out);
  ASSERT_TRUE(LastStatus(out)) << "a mode change is reported at once";
  EXPECT_EQ(LastStatus(out)->mode, BaseMode::kCanCommand);

  node.OnFrame(Command(0.5, 0.2, 1), 0.015);
  node.Step(0.015, std::nullopt, &out);
  EXPECT_EQ(node.counts().commands, 1);
  EXPECT_NEAR(node.command().v_m_per_s, 0.5, 1e-9);
  EXPECT_NEAR(node.command().omega_rad_per_s, 0.2, 1e-9);
  EXPECT_FALSE(node.OnFrame(can::CanFrame::Standard(0x201, {0, 0, 0, 0, 0, 0, 0, 0}), 0.02)) << "node 1's id: not ours";
}

TEST(WheelControllerNodeTest, CommandTimeoutBrakesToZero) {
  WheelControllerNode node({}, 0.0);
  std::vector<can::CanFrame> out;
  node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.0);
  double t = 0.0;
  std::uint8_t counter = 0;
  for (; t < 0.5; t += 0.005) {  // commands at 200 Hz
    node.OnFrame(Command(0.8, 0.0, counter++), t);
    node.Step(t, std::nullopt, &out);
  }
  EXPECT_NEAR(node.command().v_m_per_s, 0.8, 1e-9);
  EXPECT_EQ(node.mode(), BaseMode::kCanCommand);
  // Silence: the watchdog (0.05 s) trips, quick stop ramps to zero at 1 m/s^2.
  const double last_command_s = t - 0.005;
  for (; t < last_command_s + 0.049; t += 0.005) node.Step(t, std::nullopt, &out);
  EXPECT_EQ(node.mode(), BaseMode::kCanCommand);
  node.Step(last_command_s + 0.06, std::nullopt, &out);
  EXPECT_EQ(node.mode(), BaseMode::kQuickStop);
  EXPECT_EQ(node.counts().timeouts, 1);
  EXPECT_LT(node.command().v_m_per_s, 0.8);
  for (t = last_command_s + 0.06; t < last_command_s + 1.2; t += 0.005) node.Step(t, std::nullopt, &out);
  EXPECT_EQ(node.command().v_m_per_s, 0.0);
  ASSERT_TRUE(LastStatus(out));
  EXPECT_EQ(LastStatus(out)->mode, BaseMode::kQuickStop);
  // Quick stop is left through standby only.
  node.OnFrame(Request(base::ModeRequest::kCanCommand), t);
  EXPECT_EQ(node.mode(), BaseMode::kQuickStop);
  EXPECT_EQ(node.counts().mode_refused, 1);
}

TEST(WheelControllerNodeTest, WheelSpeedsAndOdometryFollowThePlant) {
  WheelControllerNode node({}, 0.0);
  const base::UnicycleVelocity plant{0.4, 0.3};
  std::vector<can::CanFrame> out;
  for (int k = 0; k <= 200; ++k) node.Step(k * 0.005, plant, &out);  // 1 s
  const std::vector<can::CanFrame> speeds = OfKind(out, base::BaseFrameKind::kWheelSpeeds);
  const std::vector<can::CanFrame> odometry = OfKind(out, base::BaseFrameKind::kOdometry);
  EXPECT_EQ(speeds.size(), 101u);  // 100 Hz over [0, 1] s of passed-in time
  ASSERT_EQ(odometry.size(), speeds.size());
  const base::DriveGeometry geometry;
  const base::WheelSpeeds expected = base::UnicycleToWheelSpeeds(plant, geometry);
  const auto last_speeds = base::DecodeWheelSpeeds(speeds.back(), kNode, nullptr);
  ASSERT_TRUE(last_speeds);
  EXPECT_NEAR(last_speeds->left_rad_per_s, expected.left_rad_per_s, 1e-3);
  EXPECT_NEAR(last_speeds->right_rad_per_s, expected.right_rad_per_s, 1e-3);
  // The tick counts over the second: each wheel's angle (rate x 1 s) in ticks.
  const auto first = base::DecodeOdometry(odometry.front(), kNode, std::nullopt, nullptr);
  const auto last = base::DecodeOdometry(odometry.back(), kNode, std::nullopt, nullptr);
  ASSERT_TRUE(first && last);
  const double ticks_per_rad = geometry.ticks_per_rev / (2.0 * std::numbers::pi);
  EXPECT_NEAR(base::WheelTickDelta(first->left_ticks, last->left_ticks), expected.left_rad_per_s * ticks_per_rad, 2.0);
  EXPECT_NEAR(base::WheelTickDelta(first->right_ticks, last->right_ticks), expected.right_rad_per_s * ticks_per_rad, 2.0);
  // Counters run +1 per frame of a kind (the host's stale check passes on every frame).
  std::optional<std::uint8_t> counter;
  for (const can::CanFrame& f : odometry) {
    const auto o = base::DecodeOdometry(f, kNode, counter, nullptr);
    ASSERT_TRUE(o);
    counter = o->counter;
  }
}

// Found by the motorsim_inputs fuzz target: a plant velocity that overflows the wheel angle
// (-inf) was cast to an integer tick count (undefined behaviour). Such a step leaves the angles
// as they were; the encoder counts stay decodable and go on from there.
TEST(WheelControllerNodeTest, ABrokenPlantVelocityLeavesTheWheelAnglesAsTheyWere) {
  WheelControllerNode node({}, 0.0);
  std::vector<can::CanFrame> out;
  for (int k = 0; k <= 20; ++k) node.Step(k * 0.005, base::UnicycleVelocity{0.4, 0.0}, &out);
  const auto before = base::DecodeOdometry(OfKind(out, base::BaseFrameKind::kOdometry).back(), kNode, std::nullopt, nullptr);
  out.clear();
  node.Step(0.105, base::UnicycleVelocity{-1e308, 0.0}, &out);
  node.Step(0.110, base::UnicycleVelocity{0.0, 0.0}, &out);
  const std::vector<can::CanFrame> odometry = OfKind(out, base::BaseFrameKind::kOdometry);
  ASSERT_FALSE(odometry.empty());
  const auto after = base::DecodeOdometry(odometry.back(), kNode, std::nullopt, nullptr);
  ASSERT_TRUE(before && after);
  EXPECT_EQ(after->left_ticks, before->left_ticks);
  EXPECT_EQ(after->right_ticks, before->right_ticks);
}

TEST(WheelControllerNodeTest, MalformedFramesAreRefusedAndCounted) {
  WheelControllerNode node({}, 0.0);
  node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.0);
  node.OnFrame(Command(0.3, 0.0, 7), 0.001);
  ASSERT_NEAR(node.command().v_m_per_s, 0.0, 1e-12);  // not stepped yet
  std::vector<can::CanFrame> out;
  node.Step(0.001, std::nullopt, &out);
  ASSERT_NEAR(node.command().v_m_per_s, 0.3, 1e-9);

  can::CanFrame bad_checksum = Command(0.9, 0.0, 8);
  bad_checksum.data[7] ^= 0x01;
  can::CanFrame short_frame = Command(0.9, 0.0, 8);
  short_frame.dlc = 6;
  const can::CanFrame stale = Command(0.9, 0.0, 7);  // the last accepted counter again
  can::CanFrame bad_complement = Request(base::ModeRequest::kStandby);
  bad_complement.data[1] = 0x00;
  for (const can::CanFrame& f : {bad_checksum, short_frame, stale, bad_complement}) EXPECT_TRUE(node.OnFrame(f, 0.002));
  node.Step(0.002, std::nullopt, &out);
  EXPECT_EQ(node.counts().malformed, 4);
  EXPECT_FALSE(node.last_error().empty());
  EXPECT_EQ(node.mode(), BaseMode::kCanCommand);
  EXPECT_NEAR(node.command().v_m_per_s, 0.3, 1e-9) << "no refused frame changed the command";
  // A gap in the counter is counted as lost commands, not refused.
  node.OnFrame(Command(0.4, 0.0, 10), 0.003);
  node.Step(0.003, std::nullopt, &out);
  EXPECT_EQ(node.counts().counter_gaps, 2);
  EXPECT_NEAR(node.command().v_m_per_s, 0.4, 1e-9);
}

TEST(WheelControllerNodeTest, FaultFrameThenFaultStatusThenReset) {
  WheelControllerNode node({}, 0.0);
  std::vector<can::CanFrame> out;
  node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.0);
  node.OnFrame(Command(0.5, 0.0, 0), 0.0);
  node.Step(0.0, std::nullopt, &out);
  out.clear();
  node.RaiseFault(base::BaseFault::kOverCurrent, 0.01);
  node.Step(0.01, std::nullopt, &out);
  ASSERT_GE(out.size(), 2u);
  const auto fault = base::DecodeFault(out[0], kNode, nullptr);
  ASSERT_TRUE(fault) << "the fault frame comes first";
  EXPECT_EQ(fault->fault, base::BaseFault::kOverCurrent);
  EXPECT_EQ(fault->mode, BaseMode::kFault);
  ASSERT_TRUE(LastStatus(out));
  EXPECT_EQ(LastStatus(out)->mode, BaseMode::kFault);
  EXPECT_EQ(LastStatus(out)->error_code, 1);
  EXPECT_EQ(node.command().v_m_per_s, 0.0);
  node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.02);
  EXPECT_EQ(node.mode(), BaseMode::kFault);
  node.OnFrame(Request(base::ModeRequest::kFaultReset), 0.03);
  EXPECT_EQ(node.mode(), BaseMode::kStandby);
  EXPECT_EQ(node.modes().fault_bits(), 0);
}

TEST(WheelControllerNodeTest, SaturatesAtTheMotorsTopSpeedKeepingTheCurvature) {
  WheelControllerOptions options;
  options.max_wheel_speed_radps = 5.0;  // 0.5 m/s straight ahead
  WheelControllerNode node(options, 0.0);
  std::vector<can::CanFrame> out;
  node.OnFrame(Request(base::ModeRequest::kCanCommand), 0.0);
  node.OnFrame(Command(1.0, 0.4, 0), 0.0);
  node.Step(0.0, std::nullopt, &out);
  const base::WheelSpeeds wheels = base::UnicycleToWheelSpeeds(node.command(), options.geometry);
  EXPECT_NEAR(std::max(std::abs(wheels.left_rad_per_s), std::abs(wheels.right_rad_per_s)), 5.0, 1e-9);
  EXPECT_NEAR(node.command().omega_rad_per_s / node.command().v_m_per_s, 0.4, 1e-9);
}

TEST(WheelControllerNodeTest, RejectsBadOptions) {
  WheelControllerOptions options;
  options.node_id = 0;
  EXPECT_NE(CheckWheelControllerOptions(options), "");
  options = {};
  options.max_wheel_speed_radps = 31.0;
  EXPECT_NE(CheckWheelControllerOptions(options), "");
  EXPECT_THROW(WheelControllerNode(options, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay::sim::motors
