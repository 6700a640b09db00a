#pragma once
// Every message type of the catalogue by fingerprint, for tools that see raw bytes (log
// inspection, replay): the type's name and a checked decode of a buffer.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace topay::msgs {

struct MessageTypeInfo {
  std::string name;           ///< e.g. "robot_state_t"
  std::int64_t fingerprint;   ///< Msg::getHash()
  /// CheckedDecode<Msg>: true if the bytes are exactly one valid message; else *error.
  bool (*check)(const void* data, std::size_t size, std::string* error);
};

/// Every type of lcmtypes/ (graph_status_t included).
const std::vector<MessageTypeInfo>& AllMessageTypes();

/// The type whose fingerprint the buffer starts with, if any (nullopt: shorter than 8 bytes or
/// an unknown fingerprint).
std::optional<MessageTypeInfo> IdentifyMessage(const void* data, std::size_t size);

}  // namespace topay::msgs
