#pragma once
// Emergency (EMCY, CiA 301 §7.2.7): COB-ID 0x080 + node, DLC 8: the error code (uint16), the
// error register (object 0x1001) and 5 manufacturer-specific bytes.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

/// Common emergency error codes (CiA 301 Table 21; CiA 402 adds drive-specific ones).
namespace emcy_code {
inline constexpr std::uint16_t kErrorResetOrNoError = 0x0000;  ///< Sent when errors clear.
inline constexpr std::uint16_t kGenericError = 0x1000;
inline constexpr std::uint16_t kCurrent = 0x2000;
inline constexpr std::uint16_t kVoltage = 0x3000;
inline constexpr std::uint16_t kTemperature = 0x4000;
inline constexpr std::uint16_t kDeviceHardware = 0x5000;
inline constexpr std::uint16_t kCommunication = 0x8100;
inline constexpr std::uint16_t kCanOverrun = 0x8110;
inline constexpr std::uint16_t kHeartbeatError = 0x8130;     ///< Life guard / heartbeat lost.
inline constexpr std::uint16_t kPdoLengthError = 0x8210;     ///< PDO not processed: length.
inline constexpr std::uint16_t kRpdoTimeout = 0x8250;        ///< RPDO deadline (event timer) missed.
inline constexpr std::uint16_t kFollowingError = 0x8611;     ///< CiA 402 positioning control.
}  // namespace emcy_code

/// A CAN communication error (0x81xx: overrun, error passive, heartbeat / life guard lost,
/// recovered from bus-off, ...) or an RPDO timeout (0x8250: the host's setpoints stopped
/// coming): the bus or the host failed the device, not the device itself. The other 0x82xx
/// (protocol errors such as a PDO length error) are not.
constexpr bool IsCommunicationError(std::uint16_t code) {
  return (code & 0xFF00u) == emcy_code::kCommunication || code == emcy_code::kRpdoTimeout;
}

/// Error register bits (object 0x1001, CiA 301 §7.5.2.2).
namespace error_register {
inline constexpr std::uint8_t kGeneric = 0x01;
inline constexpr std::uint8_t kCurrent = 0x02;
inline constexpr std::uint8_t kVoltage = 0x04;
inline constexpr std::uint8_t kTemperature = 0x08;
inline constexpr std::uint8_t kCommunication = 0x10;
}  // namespace error_register

struct Emcy {
  int node_id = 1;                                  ///< 1..127.
  std::uint16_t error_code = emcy_code::kErrorResetOrNoError;
  std::uint8_t error_register = 0;                  ///< Object 0x1001.
  std::array<std::uint8_t, 5> manufacturer_data{};  ///< Bytes 3..7, meaning per drive vendor.
};

/// nullopt with *error for a node id outside 1..127.
std::optional<can::CanFrame> EncodeEmcy(const Emcy& emcy, std::string* error);

/// nullopt with *error naming the frame for another id (SYNC 0x080 included) or a DLC other
/// than 8.
std::optional<Emcy> DecodeEmcy(const can::CanFrame& frame, std::string* error);

}  // namespace topay::canopen
