#pragma once
// The base controller's modes and the host's mode requests (docs/base_protocol.md, "Modes").

#include <cstdint>

namespace topay::base {

/// The controller's mode, as reported in the status frame (byte 0).
enum class BaseMode : std::uint8_t {
  kStandby = 0,     ///< Motors enabled at zero speed; velocity commands are ignored.
  kCanCommand = 1,  ///< Wheels follow the velocity commands (watchdog armed).
  kQuickStop = 2,   ///< Decelerating to (or holding) zero at the quick-stop deceleration.
  kFault = 3,       ///< Motors disabled until a fault reset.
};
inline constexpr std::uint8_t kMaxBaseModeCode = 3;

/// The host's mode request (mode request frame, byte 0).
enum class ModeRequest : std::uint8_t {
  kStandby = 0,
  kCanCommand = 1,
  kQuickStop = 2,
  kFaultReset = 3,
};
inline constexpr std::uint8_t kMaxModeRequestCode = 3;

/// "standby", "CAN command", "quick stop", "fault".
const char* ModeName(BaseMode mode);
/// "standby", "CAN command", "quick stop", "fault reset".
const char* ModeRequestName(ModeRequest request);

}  // namespace topay::base
