#pragma once
// Decoding of LCM messages from untrusted bytes that never throws, never over-allocates and
// accepts only a buffer that is exactly one message of the expected type.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <string>

namespace topay {

// Largest buffer CheckedDecode accepts, bytes. lcm-gen's decoders take `int` lengths and
// compute `sizeof(element) * count` in `int`; below this bound that product cannot overflow
// for any element type (8 bytes at most), so no length check is defeated by wrap-around.
inline constexpr std::size_t kMaxCheckedDecodeBytes =
    static_cast<std::size_t>(std::numeric_limits<int>::max()) / 8;

namespace internal {

// Sets *error (if given) to "<type>: <what>" and returns no message.
template <class Msg>
std::optional<Msg> DecodeFailure(std::string* error, const std::string& what) {
  if (error != nullptr) *error = std::string(Msg::getTypeName()) + ": " + what;
  return std::nullopt;
}

// The 64-bit fingerprint at the start of an encoded LCM message (big-endian on the wire).
inline std::int64_t ReadFingerprint(const unsigned char* bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  return static_cast<std::int64_t>(value);
}

}  // namespace internal

// Decodes `size` bytes at `data` as one message of type Msg (an lcm-gen C++ type, e.g.
// topay::robot_state_t). Returns the message, or std::nullopt with *error (when error is not
// null) naming the type and the reason: too large, too short for a fingerprint, wrong
// fingerprint (another type, or a changed .lcm definition), truncated or corrupted contents
// (the decoder returned an error or threw), or trailing bytes after the message.
// Relies on the decoders being hardened (lcmtypes/harden_lcm_cpp.cmake) for allocation bounds.
template <class Msg>
std::optional<Msg> CheckedDecode(const void* data, std::size_t size, std::string* error) {
  using internal::DecodeFailure;
  if (data == nullptr && size != 0) return DecodeFailure<Msg>(error, "null buffer");
  if (size > kMaxCheckedDecodeBytes) {
    return DecodeFailure<Msg>(error, "buffer of " + std::to_string(size) +
                                         " bytes exceeds the limit of " +
                                         std::to_string(kMaxCheckedDecodeBytes));
  }
  if (size < 8) {
    return DecodeFailure<Msg>(error, "buffer of " + std::to_string(size) +
                                         " bytes is too short for the 8-byte fingerprint");
  }
  if (internal::ReadFingerprint(static_cast<const unsigned char*>(data)) != Msg::getHash()) {
    return DecodeFailure<Msg>(error, "fingerprint mismatch (another message type, or a "
                                     "different version of this type)");
  }
  Msg msg;
  int decoded = -1;
  try {
    decoded = msg.decode(data, 0, static_cast<int>(size));
  } catch (const std::exception& e) {
    return DecodeFailure<Msg>(error, std::string("decoder threw: ") + e.what());
  } catch (...) {
    return DecodeFailure<Msg>(error, "decoder threw a non-standard exception");
  }
  if (decoded < 0) {
    return DecodeFailure<Msg>(error, "truncated or corrupted buffer of " +
                                         std::to_string(size) + " bytes");
  }
  if (static_cast<std::size_t>(decoded) != size) {
    return DecodeFailure<Msg>(error, "message ends after " + std::to_string(decoded) +
                                         " of " + std::to_string(size) + " bytes");
  }
  return msg;
}

}  // namespace topay
