// The host side of the base protocol: the mode requests towards the wanted mode through the
// allowed transitions (repeated until shown), the velocity command's rolling counter, the
// feedback decoded, the lost base.
#include "procs/canbridge/base_link.h"

#include <gtest/gtest.h>

#include "drivers/base/mode_request_frame.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"

namespace topay::canbridge {
namespace {

using base::BaseMode;
using base::ModeRequest;

constexpr int kNode = 16;

std::optional<ModeRequest> RequestIn(const std::vector<can::CanFrame>& frames) {
  for (const can::CanFrame& frame : frames) {
    if (auto request = base::DecodeModeRequest(frame, kNode, nullptr)) return request;
  }
  return std::nullopt;
}

std::vector<can::CanFrame> CycleFrames(BaseLink& link, double now_s) {
  std::vector<can::CanFrame> frames;
  link.CycleFrames(now_s, 0, 0, &frames);
  return frames;
}

can::CanFrame Status(BaseMode mode, std::uint16_t faults = 0) {
  return *base::EncodeStatus({mode, static_cast<std::uint8_t>(faults ? 1 : 0), faults, 47.5, 0}, kNode, nullptr);
}

TEST(BaseLinkTest, ModeRequestsFollowTheAllowedTransitions) {
  BaseLink link(BaseLinkOptions{});
  std::string error;
  link.SetTargetMode(BaseMode::kCanCommand);
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.0)), ModeRequest::kCanCommand);  // mode unknown: ask
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.05)), std::nullopt);             // not yet repeated
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.1)), ModeRequest::kCanCommand);  // repeated at 100 ms
  ASSERT_EQ(link.Handle(Status(BaseMode::kQuickStop), 0.11, &error), FrameResult::kDecoded);
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.12)), ModeRequest::kStandby);  // quick stop -> standby first
  link.Handle(Status(BaseMode::kStandby), 0.13, &error);
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.14)), ModeRequest::kCanCommand);
  link.Handle(Status(BaseMode::kCanCommand), 0.15, &error);
  EXPECT_TRUE(link.at_target());
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.5)), std::nullopt);
  link.SetTargetMode(BaseMode::kQuickStop);
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.51)), ModeRequest::kQuickStop);
  // A fault: nothing but a fault reset, and only when armed.
  link.Handle(Status(BaseMode::kFault, 0x0001), 0.6, &error);
  EXPECT_TRUE(link.faulted());
  link.SetTargetMode(BaseMode::kCanCommand);
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.7)), std::nullopt);
  link.ArmFaultReset();
  EXPECT_EQ(RequestIn(CycleFrames(link, 0.8)), ModeRequest::kFaultReset);
}

TEST(BaseLinkTest, VelocityCommandsCountAndFeedbackDecodes) {
  BaseLink link(BaseLinkOptions{});
  const auto a = base::DecodeVelocityCommand(link.VelocityFrame(0.25, -0.5), kNode, std::nullopt, nullptr);
  const auto b = base::DecodeVelocityCommand(link.VelocityFrame(0.0, 0.0), kNode, a->counter, nullptr);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->v_m_per_s, 0.25);
  EXPECT_EQ(a->omega_rad_per_s, -0.5);
  EXPECT_EQ(static_cast<std::uint8_t>(a->counter + 1), b->counter);
  std::string error;
  EXPECT_EQ(link.Handle(*base::EncodeWheelSpeeds({3.0, 5.0, 0}, kNode, nullptr), 1.0, &error), FrameResult::kDecoded);
  const auto velocity = link.TakeNewVelocity();
  ASSERT_TRUE(velocity);
  EXPECT_NEAR(velocity->v_m_per_s, 0.4, 1e-12);         // 0.1 * (3 + 5) / 2
  EXPECT_NEAR(velocity->omega_rad_per_s, 0.4, 1e-12);   // 0.1 * (5 - 3) / 0.5
  EXPECT_FALSE(link.TakeNewVelocity());
  EXPECT_EQ(link.Handle(link.VelocityFrame(0, 0), 1.0, &error), FrameResult::kHostFrame);
  EXPECT_EQ(link.Handle(can::CanFrame::Standard(0x190, {1, 2}), 1.0, &error), FrameResult::kMalformed);
  EXPECT_NE(error.find("status"), std::string::npos) << error;
  EXPECT_EQ(link.Handle(can::CanFrame::Standard(0x191, {1, 2}), 1.0, &error), FrameResult::kNotMine);
  EXPECT_FALSE(link.lost(10.0));  // no status yet: not lost, not seen
  link.Handle(Status(BaseMode::kStandby), 10.0, &error);
  EXPECT_NEAR(link.battery_v(), 47.5, 1e-9);
  EXPECT_FALSE(link.lost(10.25));
  EXPECT_TRUE(link.lost(10.26));
}

}  // namespace
}  // namespace topay::canbridge
