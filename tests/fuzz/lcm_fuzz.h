#pragma once
// LCM messages from a fuzzer's bytes, decoded as every subscriber decodes them
// (CheckedDecode, lcmtypes/include/topay_msgs/checked_decode.h), and the record format the
// multi-channel targets read: [selector byte][u16 length][bytes], repeated. The selector's low
// seven bits pick the channel (modulo the target's channel count); its high bit replaces the
// first 8 bytes by the type's fingerprint, so that mutations reach the message body.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_check.h"
#include "tests/fuzz/fuzz_reader.h"
#include "topay_msgs/checked_decode.h"

namespace topay::fuzz {

struct LcmRecord {
  int channel = 0;               ///< selector & 0x7f
  bool fix_fingerprint = false;  ///< selector & 0x80
  std::span<const std::uint8_t> bytes;
};

inline LcmRecord NextLcmRecord(FuzzReader& in) {
  const std::uint8_t selector = in.Byte();
  return {selector & 0x7f, (selector & 0x80) != 0, in.LengthPrefixed()};
}

/// `bytes` as one Msg, through CheckedDecode on a buffer of exactly their size. A message that
/// decodes must encode back to exactly the bytes it came from (the hardened decoders accept
/// nothing that would not): checked.
template <class Msg>
std::optional<Msg> DecodeFuzzed(std::span<const std::uint8_t> bytes, bool fix_fingerprint) {
  std::vector<std::uint8_t> buffer(bytes.begin(), bytes.end());
  if (fix_fingerprint && buffer.size() >= 8) {
    const auto hash = static_cast<std::uint64_t>(Msg::getHash());
    for (int i = 0; i < 8; ++i) buffer[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(hash >> (56 - 8 * i));
  }
  std::string error;
  std::optional<Msg> msg = CheckedDecode<Msg>(buffer.data(), buffer.size(), &error);
  if (!msg) {
    FuzzCheck(!error.empty(), "a refused message comes with a reason");
    return msg;
  }
  const int size = msg->getEncodedSize();
  FuzzCheck(size == static_cast<int>(buffer.size()), "a decoded message has the size it was decoded from");
  std::vector<std::uint8_t> again(static_cast<std::size_t>(size));
  FuzzCheck(msg->encode(again.data(), 0, size) == size, "a decoded message encodes");
  FuzzCheck(again == buffer, "a decoded message encodes back to the same bytes");
  return msg;
}

}  // namespace topay::fuzz
