#pragma once
// Base64 (RFC 4648, with padding) of byte buffers and of little-endian integer arrays: how the
// viewer's JSON channels carry voxel indices and scan points (docs/viewer.md).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace topay::viz {

/// The base64 text of `bytes`.
std::string Base64Encode(std::span<const std::uint8_t> bytes);

/// The bytes of base64 `text`; nullopt if it is not valid padded base64.
std::optional<std::vector<std::uint8_t>> Base64Decode(std::string_view text);

/// Base64 of the values as little-endian uint16 / int16 (the machine's order is checked).
std::string Base64OfUint16(std::span<const std::uint16_t> values);
std::string Base64OfInt16(std::span<const std::int16_t> values);

}  // namespace topay::viz
