// CiA 402 statusword decoding (every state, "don't care" bits) and controlword commands.
#include "drivers/arm/cia402_state.h"

#include <gtest/gtest.h>

namespace topay::cia402 {
namespace {

constexpr DriveState kAllStates[] = {
    DriveState::kNotReadyToSwitchOn, DriveState::kSwitchOnDisabled,
    DriveState::kReadyToSwitchOn,    DriveState::kSwitchedOn,
    DriveState::kOperationEnabled,   DriveState::kQuickStopActive,
    DriveState::kFaultReactionActive, DriveState::kFault};

TEST(Cia402StateTest, CanonicalStatuswords) {
  EXPECT_EQ(EncodeStatusword(DriveState::kNotReadyToSwitchOn), 0x0000);
  EXPECT_EQ(EncodeStatusword(DriveState::kSwitchOnDisabled), 0x0040);
  EXPECT_EQ(EncodeStatusword(DriveState::kReadyToSwitchOn), 0x0021);
  EXPECT_EQ(EncodeStatusword(DriveState::kSwitchedOn), 0x0023);
  EXPECT_EQ(EncodeStatusword(DriveState::kOperationEnabled), 0x0027);
  EXPECT_EQ(EncodeStatusword(DriveState::kQuickStopActive), 0x0007);
  EXPECT_EQ(EncodeStatusword(DriveState::kFaultReactionActive), 0x000F);
  EXPECT_EQ(EncodeStatusword(DriveState::kFault), 0x0008);
}

// Every value of the bits outside the state's mask decodes to the same state.
TEST(Cia402StateTest, DecodingIgnoresTheDontCareBits) {
  for (DriveState state : kAllStates) {
    SCOPED_TRACE(std::string(ToString(state)));
    const std::uint16_t base = EncodeStatusword(state);
    // Bit 4 (voltage enabled), 7 (warning), 8-15 (manufacturer, remote, target reached...).
    for (std::uint16_t other : {0x0000, 0x0010, 0x0080, 0x0200, 0x0400, 0xFF90, 0xFFFF}) {
      const std::uint16_t word = EncodeStatusword(state, other);
      EXPECT_EQ(word & 0x6F, base & 0x6F);
      const auto decoded = DecodeStatusword(word, nullptr);
      ASSERT_TRUE(decoded) << std::hex << word;
      EXPECT_EQ(*decoded, state) << std::hex << word;
    }
  }
  // Bit 5 (quick stop) is "don't care" in Not ready, Switch on disabled, the fault states.
  EXPECT_EQ(DecodeStatusword(0x0020, nullptr), DriveState::kNotReadyToSwitchOn);
  EXPECT_EQ(DecodeStatusword(0x0060, nullptr), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(DecodeStatusword(0x002F, nullptr), DriveState::kFaultReactionActive);
  EXPECT_EQ(DecodeStatusword(0x0028, nullptr), DriveState::kFault);
  // ...but it tells Operation enabled (1) from Quick stop active (0).
  EXPECT_EQ(DecodeStatusword(0x0637, nullptr), DriveState::kOperationEnabled);
  EXPECT_EQ(DecodeStatusword(0x0617, nullptr), DriveState::kQuickStopActive);
}

TEST(Cia402StateTest, CombinationsThatAreNoStateAreRejected) {
  std::string error;
  EXPECT_FALSE(DecodeStatusword(0x0002, &error));
  EXPECT_EQ(error, "statusword 0x0002: bits 0-3,5,6 = 0x02 encode no CiA 402 state");
  // Ready to switch on with bit 5 clear, switch on disabled with other bits, ...
  for (std::uint16_t word : {0x0001, 0x0003, 0x0041, 0x0048, 0x0061, 0x0067, 0x0009, 0x004F}) {
    EXPECT_FALSE(DecodeStatusword(word, nullptr)) << std::hex << word;
  }
}

TEST(Cia402StateTest, ControlwordCommands) {
  EXPECT_EQ(ControlwordOf(Command::kShutdown), 0x0006);
  EXPECT_EQ(ControlwordOf(Command::kSwitchOn), 0x0007);
  EXPECT_EQ(ControlwordOf(Command::kEnableOperation), 0x000F);
  EXPECT_EQ(ControlwordOf(Command::kDisableVoltage), 0x0000);
  EXPECT_EQ(ControlwordOf(Command::kQuickStop), 0x0002);
  EXPECT_EQ(ControlwordOf(Command::kDisableOperation), 0x0007);
  EXPECT_EQ(ControlwordOf(Command::kFaultReset), 0x0080);
  EXPECT_EQ(DecodeControlwordCommand(0x0006), Command::kShutdown);
  EXPECT_EQ(DecodeControlwordCommand(0x000E), Command::kShutdown);  // bit 3 don't care
  EXPECT_EQ(DecodeControlwordCommand(0x0007), Command::kSwitchOn);
  EXPECT_EQ(DecodeControlwordCommand(0x000F), Command::kEnableOperation);
  EXPECT_EQ(DecodeControlwordCommand(0x010F), Command::kEnableOperation);  // halt ignored
  for (std::uint16_t word : {0x0000, 0x0001, 0x0004, 0x0005, 0x000D}) {
    EXPECT_EQ(DecodeControlwordCommand(word), Command::kDisableVoltage) << word;
  }
  for (std::uint16_t word : {0x0002, 0x0003, 0x000A, 0x000B}) {
    EXPECT_EQ(DecodeControlwordCommand(word), Command::kQuickStop) << word;
  }
  EXPECT_TRUE(IsFaultResetEdge(0x0000, 0x0080));
  EXPECT_TRUE(IsFaultResetEdge(0x000F, 0x008F));
  EXPECT_FALSE(IsFaultResetEdge(0x0080, 0x0080));
  EXPECT_FALSE(IsFaultResetEdge(0x0080, 0x0000));
}

TEST(Cia402StateTest, NamesAreTheStandardOnes) {
  EXPECT_EQ(ToString(DriveState::kSwitchOnDisabled), "Switch on disabled");
  EXPECT_EQ(ToString(DriveState::kQuickStopActive), "Quick stop active");
  EXPECT_EQ(ToString(Command::kFaultReset), "fault reset");
}

}  // namespace
}  // namespace topay::cia402
