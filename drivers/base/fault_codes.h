#pragma once
// The base controller's faults (docs/base_protocol.md, "Fault codes"): each fault has a bit in
// the 16-bit fault word (status and fault frames) and a code (bit index + 1) in the one-byte
// error code field; code 0 is "no fault".

#include <cstdint>
#include <string>

namespace topay::base {

enum class BaseFault : std::uint8_t {
  kOverCurrent = 1,
  kOverVoltage = 2,
  kUnderVoltage = 3,
  kMotorOverTemperature = 4,
  kDriverOverTemperature = 5,
  kEncoderFault = 6,
  kEmergencyStopInput = 7,
  kCanBusError = 8,
  kLeftMotorStall = 9,
  kRightMotorStall = 10,
};
inline constexpr std::uint8_t kMaxFaultCode = 10;
/// The bits of the fault word that are defined (0x03FF); the others must be zero.
inline constexpr std::uint16_t kDefinedFaultBits = (1u << kMaxFaultCode) - 1;

/// The fault's bit in the fault word: 1 << (code - 1).
std::uint16_t FaultBit(BaseFault fault);

/// e.g. "over-current"; "no fault" for code 0, "unknown fault" for codes above 10.
const char* FaultCodeName(std::uint8_t code);

/// The names of the faults set in `bits`, comma-separated ("none" when no bit is set).
std::string DescribeFaultBits(std::uint16_t bits);

}  // namespace topay::base
