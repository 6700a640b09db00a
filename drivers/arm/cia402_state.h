#pragma once
// The CiA 402 power drive system states (CiA 402-2 §6.2.1 / IEC 61800-7-201 Figure "state
// machine"), the statusword (object 0x6041) bits that encode them and the controlword (object
// 0x6040) commands that move between them.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace topay::cia402 {

enum class DriveState {
  kNotReadyToSwitchOn,
  kSwitchOnDisabled,
  kReadyToSwitchOn,
  kSwitchedOn,
  kOperationEnabled,
  kQuickStopActive,
  kFaultReactionActive,
  kFault,
};

/// "Not ready to switch on", "Switch on disabled", ..., "Fault".
std::string_view ToString(DriveState state);

/// Statusword bits (object 0x6041, CiA 402-2 Table 30).
namespace statusword {
inline constexpr std::uint16_t kReadyToSwitchOn = 1u << 0;
inline constexpr std::uint16_t kSwitchedOn = 1u << 1;
inline constexpr std::uint16_t kOperationEnabled = 1u << 2;
inline constexpr std::uint16_t kFault = 1u << 3;
inline constexpr std::uint16_t kVoltageEnabled = 1u << 4;
inline constexpr std::uint16_t kQuickStop = 1u << 5;  ///< 0 = quick stop active.
inline constexpr std::uint16_t kSwitchOnDisabled = 1u << 6;
inline constexpr std::uint16_t kWarning = 1u << 7;
inline constexpr std::uint16_t kRemote = 1u << 9;
inline constexpr std::uint16_t kTargetReached = 1u << 10;
inline constexpr std::uint16_t kInternalLimitActive = 1u << 11;
}  // namespace statusword

/// The state encoded in a statusword (CiA 402-2 Table 31): bits 0-3, 5 and 6 under the
/// state's mask (0x4F for the states where bit 5 is "don't care", else 0x6F); the other bits
/// (voltage enabled, warning, remote, mode-specific ones) are ignored. nullopt with *error
/// (when not null) for a combination that is no state, e.g. "statusword 0x0002: bits
/// 0-3,5,6 = 0x02 encode no CiA 402 state".
std::optional<DriveState> DecodeStatusword(std::uint16_t statusword, std::string* error);

/// The state bits of `state` (the canonical value DecodeStatusword maps back to it, with the
/// "don't care" bit 5 cleared where it is one), OR'ed with `other_bits` outside bits 0-3, 5, 6.
std::uint16_t EncodeStatusword(DriveState state, std::uint16_t other_bits = 0);

/// Controlword bits (object 0x6040, CiA 402-2 Table 27).
namespace controlword {
inline constexpr std::uint16_t kSwitchOn = 1u << 0;
inline constexpr std::uint16_t kEnableVoltage = 1u << 1;
inline constexpr std::uint16_t kQuickStop = 1u << 2;  ///< 0 = quick stop.
inline constexpr std::uint16_t kEnableOperation = 1u << 3;
inline constexpr std::uint16_t kFaultReset = 1u << 7;  ///< Acts on its 0 -> 1 edge.
inline constexpr std::uint16_t kHalt = 1u << 8;
}  // namespace controlword

/// Device control commands (CiA 402-2 Table 28). kDisableOperation and kSwitchOn share the bit
/// pattern 0xxx 0111: which one it is depends on the state (Operation enabled -> transition 5).
enum class Command {
  kShutdown,          ///< 0xxx x110: transitions 2, 6, 8.
  kSwitchOn,          ///< 0xxx 0111: transition 3 (5 from Operation enabled).
  kEnableOperation,   ///< 0xxx 1111: transitions 4, 16 (3 + 4 from Ready to switch on).
  kDisableVoltage,    ///< 0xxx xx0x: transitions 7, 9, 10, 12.
  kQuickStop,         ///< 0xxx x01x: transitions 7, 10, 11.
  kDisableOperation,  ///< 0xxx 0111 (= kSwitchOn's bits): transition 5.
  kFaultReset,        ///< 0 -> 1 edge of bit 7: transition 15.
};

/// "shutdown", "switch on", ...
std::string_view ToString(Command command);

/// The controlword that sends `command` (the lowest bits that do: e.g. shutdown 0x0006, switch
/// on 0x0007, enable operation 0x000F, disable voltage 0x0000, quick stop 0x0002, disable
/// operation 0x0007, fault reset 0x0080).
std::uint16_t ControlwordOf(Command command);

/// The command in bits 0-3 of `controlword` (bit 7 and the others ignored); 0xxx 0111 decodes
/// as kSwitchOn.
Command DecodeControlwordCommand(std::uint16_t controlword);

/// True when bit 7 (fault reset) rose from `previous` to `current`.
bool IsFaultResetEdge(std::uint16_t previous, std::uint16_t current);

}  // namespace topay::cia402
