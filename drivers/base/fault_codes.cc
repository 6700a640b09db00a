#include "drivers/base/fault_codes.h"

#include <array>

namespace topay::base {

std::uint16_t FaultBit(BaseFault fault) {
  return static_cast<std::uint16_t>(1u << (static_cast<unsigned>(fault) - 1));
}

const char* FaultCodeName(std::uint8_t code) {
  static constexpr std::array<const char*, kMaxFaultCode + 1> kNames = {
      "no fault",
      "over-current",
      "over-voltage",
      "under-voltage",
      "motor over-temperature",
      "driver over-temperature",
      "encoder fault",
      "emergency stop input",
      "CAN bus error",
      "left motor stall",
      "right motor stall"};
  return code <= kMaxFaultCode ? kNames[code] : "unknown fault";
}

std::string DescribeFaultBits(std::uint16_t bits) {
  std::string names;
  for (int code = 1; code <= 16; ++code) {
    if ((bits & (1u << (code - 1))) == 0) continue;
    if (!names.empty()) names += ", ";
    names += FaultCodeName(static_cast<std::uint8_t>(code));
  }
  return names.empty() ? "none" : names;
}

}  // namespace topay::base
