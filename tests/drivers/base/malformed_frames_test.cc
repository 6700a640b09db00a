// Every decoder on arbitrary input: random ids near the protocol's, random lengths and bytes,
// remote/extended/error frames. None may throw or crash; each either decodes or refuses with
// an error that starts with its frame's name; every frame an encoder made decodes back.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "drivers/base/fault_frame.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"

namespace topay::base {
namespace {

constexpr int kNode = 1;

// One decoder: true when it accepted the frame; *error set when it refused.
struct NamedDecoder {
  std::string name;
  std::function<bool(const can::CanFrame&, std::string*)> decode;
};

std::vector<NamedDecoder> AllDecoders() {
  return {
      {"velocity command",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeVelocityCommand(f, kNode, std::nullopt, e).has_value();
       }},
      {"mode request",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeModeRequest(f, kNode, e).has_value();
       }},
      {"status",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeStatus(f, kNode, e).has_value();
       }},
      {"wheel speeds",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeWheelSpeeds(f, kNode, e).has_value();
       }},
      {"odometry",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeOdometry(f, kNode, std::nullopt, e).has_value();
       }},
      {"fault",
       [](const can::CanFrame& f, std::string* e) {
         return DecodeFault(f, kNode, e).has_value();
       }},
  };
}

can::CanFrame RandomFrame(std::mt19937& random) {
  static const std::vector<std::uint32_t> kBases = {0x080, 0x100, 0x180, 0x200, 0x280, 0x300};
  can::CanFrame frame;
  frame.id = kBases[random() % kBases.size()] + random() % 3;  // node 0, 1 or 2
  frame.dlc = static_cast<std::uint8_t>(random() % 9);
  for (int i = 0; i < frame.dlc; ++i) frame.data[i] = static_cast<std::uint8_t>(random());
  const unsigned kind = random() % 16;
  frame.remote = kind == 0;
  frame.extended = kind == 1;
  frame.error = kind == 2;
  return frame;
}

TEST(MalformedFramesTest, DecodersRefuseGarbageNamingTheirFrame) {
  std::mt19937 random(20);
  const std::vector<NamedDecoder> decoders = AllDecoders();
  int accepted = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const can::CanFrame frame = RandomFrame(random);
    for (const NamedDecoder& decoder : decoders) {
      std::string error;
      bool ok = false;
      ASSERT_NO_THROW(ok = decoder.decode(frame, &error));
      if (ok) {
        ++accepted;
        continue;
      }
      EXPECT_EQ(error.rfind(decoder.name, 0), 0u) << decoder.name << ": " << error;
    }
  }
  // Random bytes almost never carry a valid checksum, but a few may (1 in 256); some mode
  // requests pass too. The point is that nothing crashed.
  EXPECT_LT(accepted, 20000 * 6 / 50);
}

TEST(MalformedFramesTest, EachDecoderRefusesTheOtherFrames) {
  std::string error;
  const std::vector<can::CanFrame> frames = {
      *EncodeVelocityCommand({0.5, 0.1, 1}, kNode, &error),
      *EncodeModeRequest(ModeRequest::kCanCommand, kNode, &error),
      *EncodeStatus({}, kNode, &error),
      *EncodeWheelSpeeds({1.0, 1.0, 1}, kNode, &error),
      *EncodeOdometry({1, 2, 3}, kNode, &error),
      *EncodeFault({BaseFault::kEncoderFault, BaseMode::kFault, 0x0020, 0}, kNode, &error),
  };
  const std::vector<NamedDecoder> decoders = AllDecoders();
  ASSERT_EQ(frames.size(), decoders.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    for (std::size_t j = 0; j < decoders.size(); ++j) {
      error.clear();
      EXPECT_EQ(decoders[j].decode(frames[i], &error), i == j)
          << decoders[j].name << " on frame " << i << ": " << error;
      if (i != j) {
        EXPECT_NE(error.find("wrong id"), std::string::npos) << error;
      }
    }
  }
}

TEST(MalformedFramesTest, IdentifyFrameFindsEveryKind) {
  std::string error;
  for (const BaseFrameKind kind :
       {BaseFrameKind::kFault, BaseFrameKind::kModeRequest, BaseFrameKind::kStatus,
        BaseFrameKind::kVelocityCommand, BaseFrameKind::kWheelSpeeds, BaseFrameKind::kOdometry}) {
    const can::CanFrame frame = can::CanFrame::Standard(FrameId(kind, 9), {});
    EXPECT_EQ(IdentifyFrame(frame, 9, &error), kind) << error;
  }
}

}  // namespace
}  // namespace topay::base
