#pragma once
// One buffer <-> one zlib stream (RFC 1950), with zlib itself (Debian's zlib1g). Inflating
// checks the stream against the size its sender declared, so a corrupted or hostile payload
// never makes the receiver allocate more than that size plus one byte.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace topay::msgs {

/// The zlib stream of `raw` at `level` (0 = stored, 1 = fastest ... 9 = smallest; out of
/// range throws std::invalid_argument).
std::vector<std::uint8_t> ZlibDeflate(std::span<const std::uint8_t> raw, int level);

/// Inflates `stream` into *raw, which ends up holding exactly `raw_size` bytes. False with
/// *error (a sentence, without a field name: the caller prefixes it) when the stream is not
/// valid zlib (header, data or checksum), ends early, inflates to fewer or more than raw_size
/// bytes, or has bytes after its end. Never allocates more than raw_size + 1 bytes for *raw.
bool ZlibInflateExactly(std::span<const std::uint8_t> stream, std::size_t raw_size,
                        std::vector<std::uint8_t>* raw, std::string* error);

}  // namespace topay::msgs
