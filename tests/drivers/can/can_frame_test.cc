// CanFrame: validation, conversion to and from struct can_frame, cansend syntax.
#include "drivers/can/can_frame.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace topay::can {
namespace {

TEST(CanFrameTest, FactoriesBuildValidFrames) {
  const CanFrame standard = CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF});
  EXPECT_EQ(standard.id, 0x123u);
  EXPECT_FALSE(standard.extended);
  EXPECT_EQ(standard.dlc, 4);
  EXPECT_EQ(CheckCanFrame(standard), "");
  const CanFrame extended = CanFrame::Extended(0x1FFFFFFF, {0});
  EXPECT_TRUE(extended.extended);
  EXPECT_EQ(CheckCanFrame(extended), "");
  const CanFrame remote = CanFrame::Remote(0x7FF, 3);
  EXPECT_TRUE(remote.remote);
  EXPECT_EQ(remote.dlc, 3);
}

TEST(CanFrameTest, ValidationNamesTheProblem) {
  CanFrame frame = CanFrame::Standard(0x10, {1, 2});
  frame.dlc = 9;
  EXPECT_EQ(CheckCanFrame(frame), "DLC 9 is above 8");
  frame = CanFrame::Standard(0x10);
  frame.id = 0x800;
  EXPECT_EQ(CheckCanFrame(frame), "standard id 0x800 is above 0x7FF (use an extended id)");
  frame.extended = true;
  EXPECT_EQ(CheckCanFrame(frame), "");
  frame.id = 0x20000000;
  EXPECT_EQ(CheckCanFrame(frame), "extended id 0x20000000 is above 0x1FFFFFFF");
  frame = CanFrame{};
  frame.error = true;
  frame.remote = true;
  EXPECT_EQ(CheckCanFrame(frame), "an error frame cannot be a remote frame");
}

TEST(CanFrameTest, FactoriesThrowOnInvalidFrames) {
  EXPECT_THROW(CanFrame::Standard(0x800), std::invalid_argument);
  EXPECT_THROW(CanFrame::Extended(0x20000000), std::invalid_argument);
  EXPECT_THROW(CanFrame::Standard(0x1, {1, 2, 3, 4, 5, 6, 7, 8, 9}), std::invalid_argument);
  EXPECT_THROW(CanFrame::Remote(0x1, 9), std::invalid_argument);
  try {
    CanFrame::Standard(0x800);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0x800 is above 0x7FF"), std::string::npos) << e.what();
  }
}

TEST(CanFrameTest, LinuxFrameRoundTrip) {
  for (const CanFrame& frame :
       {CanFrame::Standard(0x123, {0xDE, 0xAD}), CanFrame::Extended(0x12345678, {1, 2, 3, 4, 5, 6, 7, 8}),
        CanFrame::Standard(0x0), CanFrame::Remote(0x42, 8), CanFrame::Remote(0x1ABCDEF, 0, true)}) {
    const struct can_frame linux_frame = ToLinuxFrame(frame);
    std::string error;
    const std::optional<CanFrame> back = FromLinuxFrame(linux_frame, &error);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(*back, frame) << ToString(frame);
  }
}

TEST(CanFrameTest, LinuxFrameFlagsAndPayload) {
  const struct can_frame out = ToLinuxFrame(CanFrame::Extended(0x1234, {0xAA}));
  EXPECT_EQ(out.can_id, 0x1234u | CAN_EFF_FLAG);
  EXPECT_EQ(out.len, 1);
  EXPECT_EQ(out.data[0], 0xAA);
  EXPECT_EQ(out.data[1], 0);
  EXPECT_EQ(ToLinuxFrame(CanFrame::Remote(0x12, 2)).can_id, 0x12u | CAN_RTR_FLAG);
}

TEST(CanFrameTest, MalformedLinuxFramesAreRejected) {
  struct can_frame in{};
  in.can_id = 0x123;
  in.len = 9;
  std::string error;
  EXPECT_FALSE(FromLinuxFrame(in, &error));
  EXPECT_EQ(error, "DLC 9 is above 8");
  in.len = 1;
  in.can_id = 0x800;  // no EFF flag: standard, but 12 bits
  EXPECT_FALSE(FromLinuxFrame(in, &error));
  EXPECT_NE(error.find("standard id 0x800"), std::string::npos) << error;
  EXPECT_THROW(ToLinuxFrame(CanFrame{0x800}), std::invalid_argument);
}

TEST(CanFrameTest, EqualityIgnoresBytesBeyondDlc) {
  CanFrame a = CanFrame::Standard(0x1, {1, 2});
  CanFrame b = a;
  b.data[5] = 7;
  EXPECT_EQ(a, b);
  b.data[1] = 3;
  EXPECT_NE(a, b);
  EXPECT_NE(CanFrame::Standard(0x1), CanFrame::Extended(0x1));
  EXPECT_NE(CanFrame::Standard(0x1), CanFrame::Remote(0x1));
}

TEST(CanFrameTest, ToStringLikeCandump) {
  EXPECT_EQ(ToString(CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF})), "123#DEADBEEF");
  EXPECT_EQ(ToString(CanFrame::Extended(0x12345678, {0x00})), "12345678#00");
  EXPECT_EQ(ToString(CanFrame::Extended(0x5, {})), "00000005#");
  EXPECT_EQ(ToString(CanFrame::Remote(0x123)), "123#R");
  EXPECT_EQ(ToString(CanFrame::Remote(0x123, 3)), "123#R3");
  EXPECT_EQ(ToString(CanFrame::Standard(0x7)), "007#");
  CanFrame error_frame;
  error_frame.error = true;
  error_frame.id = 0x40;  // CAN_ERR_BUSOFF
  error_frame.dlc = 8;
  EXPECT_EQ(ToString(error_frame), "20000040#0000000000000000");
}

TEST(CanFrameTest, ParseCansendSyntax) {
  std::string error;
  EXPECT_EQ(ParseCanFrame("123#DEADBEEF", &error), CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_EQ(ParseCanFrame("123#de.ad.be.ef", &error), CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_EQ(ParseCanFrame("12345678#00", &error), CanFrame::Extended(0x12345678, {0}));
  EXPECT_EQ(ParseCanFrame("00000123#", &error), CanFrame::Extended(0x123));
  EXPECT_EQ(ParseCanFrame("123#", &error), CanFrame::Standard(0x123));
  EXPECT_EQ(ParseCanFrame("123#R", &error), CanFrame::Remote(0x123));
  EXPECT_EQ(ParseCanFrame("123#R5", &error), CanFrame::Remote(0x123, 5));
  const std::optional<CanFrame> error_frame = ParseCanFrame("20000040#0000000000000000", &error);
  ASSERT_TRUE(error_frame) << error;
  EXPECT_TRUE(error_frame->error);
  EXPECT_EQ(error_frame->id, 0x40u);
}

TEST(CanFrameTest, ParseErrorsNameTheBadPart) {
  const auto error_of = [](const char* text) {
    std::string error;
    EXPECT_FALSE(ParseCanFrame(text, &error)) << text;
    return error;
  };
  EXPECT_EQ(error_of("123DEAD"), "'123DEAD': no '#' between the id and the data (expected e.g. 123#DEADBEEF)");
  EXPECT_EQ(error_of("12#00"), "'12#00': the id must have 3 hex digits (standard) or 8 (extended), found 2");
  EXPECT_EQ(error_of("800#00"), "'800#00': standard id 0x800 is above 0x7FF");
  EXPECT_EQ(error_of("A0000040#00"), "'A0000040#00': error frame id 0xA0000040 has EFF/RTR flag bits set");
  EXPECT_EQ(error_of("40000000#00"), "'40000000#00': extended id 0x40000000 is above 0x1FFFFFFF");
  EXPECT_EQ(error_of("G23#00"), "'G23#00': bad hex digit 'G' in the id");
  EXPECT_EQ(error_of("123#0011223344556677889"), "'123#0011223344556677889': more than 8 data bytes");
  EXPECT_EQ(error_of("123#ABC"), "'123#ABC': data byte 1 is not two hex digits (at 'C')");
  EXPECT_EQ(error_of("123#R9"), "'123#R9': a remote frame is 'R' or 'R' and one length digit 0-8, found 'R9'");
  EXPECT_EQ(error_of("123##100"), "'123##100': CAN FD frames ('##') are not supported (classic CAN only)");
}

TEST(CanFrameTest, PrintParseRoundTrip) {
  for (const CanFrame& frame :
       {CanFrame::Standard(0x0), CanFrame::Standard(0x7FF, {0, 1, 2, 3, 4, 5, 6, 0xFF}),
        CanFrame::Extended(0x0), CanFrame::Extended(0x1FFFFFFF, {0x12, 0x34}), CanFrame::Remote(0x100, 8),
        CanFrame::Remote(0x100, 0, true)}) {
    std::string error;
    const std::optional<CanFrame> back = ParseCanFrame(ToString(frame), &error);
    ASSERT_TRUE(back) << ToString(frame) << ": " << error;
    EXPECT_EQ(*back, frame) << ToString(frame);
    EXPECT_EQ(ToString(*back), ToString(frame));
  }
}

}  // namespace
}  // namespace topay::can
