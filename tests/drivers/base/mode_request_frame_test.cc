// The mode request frame: every request round trips, corrupted or unknown requests are refused.
#include "drivers/base/mode_request_frame.h"

#include <gtest/gtest.h>

namespace topay::base {
namespace {

TEST(ModeRequestFrameTest, EveryRequestRoundTrips) {
  std::string error;
  for (const ModeRequest request : {ModeRequest::kStandby, ModeRequest::kCanCommand,
                                    ModeRequest::kQuickStop, ModeRequest::kFaultReset}) {
    const auto frame = EncodeModeRequest(request, 3, &error);
    ASSERT_TRUE(frame) << error;
    EXPECT_EQ(frame->id, 0x103u);
    EXPECT_EQ(frame->dlc, 2);
    EXPECT_EQ(frame->data[0] + frame->data[1], 0xFF);
    const auto decoded = DecodeModeRequest(*frame, 3, &error);
    ASSERT_TRUE(decoded) << error;
    EXPECT_EQ(*decoded, request);
  }
}

TEST(ModeRequestFrameTest, CanCommandModeLayout) {
  const auto frame = EncodeModeRequest(ModeRequest::kCanCommand, 1, nullptr);
  ASSERT_TRUE(frame);
  EXPECT_EQ(can::ToString(*frame), "101#01FE");
}

TEST(ModeRequestFrameTest, RejectsBadRequests) {
  std::string error;
  EXPECT_FALSE(EncodeModeRequest(static_cast<ModeRequest>(4), 1, &error));
  EXPECT_EQ(error, "mode request (0x101): unknown request code 4");
  EXPECT_FALSE(EncodeModeRequest(ModeRequest::kStandby, 128, &error));
  EXPECT_EQ(error, "mode request: node id 128 is outside 1..127");

  EXPECT_FALSE(DecodeModeRequest(can::CanFrame::Standard(0x101, {0x01, 0xFF}), 1, &error));
  EXPECT_EQ(error,
            "mode request (0x101): byte 1 (255) is not the complement of the request code 1");
  EXPECT_FALSE(DecodeModeRequest(can::CanFrame::Standard(0x101, {0x07, 0xF8}), 1, &error));
  EXPECT_EQ(error, "mode request (0x101): unknown request code 7");
  EXPECT_FALSE(DecodeModeRequest(can::CanFrame::Standard(0x101, {0x01}), 1, &error));
  EXPECT_EQ(error, "mode request (0x101): DLC 1, expected 2");
  EXPECT_FALSE(
      DecodeModeRequest(can::CanFrame::Standard(0x101, {0x01, 0xFE, 0, 0, 0, 0, 0, 0}), 1, &error));
  EXPECT_EQ(error, "mode request (0x101): DLC 8, expected 2");
  EXPECT_FALSE(DecodeModeRequest(can::CanFrame::Standard(0x181, {0x01, 0xFE}), 1, &error));
  EXPECT_EQ(error, "mode request (0x101): wrong id 0x181");
}

}  // namespace
}  // namespace topay::base
