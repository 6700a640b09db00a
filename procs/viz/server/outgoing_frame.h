#pragma once
// One WebSocket message on its way to a client: shared, immutable bytes (the same payload is
// queued for every client that wants it without a copy) and its kind (text or binary).

#include <cstdint>
#include <memory>
#include <string>

namespace topay::viz {

/// Identifies one WebSocket client for the life of a WsServer (1, 2, ...; never reused, never 0).
using ClientId = std::uint64_t;

/// A whole WebSocket message to send. `bytes` must not be null.
struct OutgoingFrame {
  /// The message's payload, shared between the clients it is queued for.
  std::shared_ptr<const std::string> bytes;
  /// true: a binary message; false: a text message (`bytes` must then be valid UTF-8).
  bool binary = false;

  /// The payload's size in bytes (0 for a null payload).
  std::size_t size() const { return bytes ? bytes->size() : 0; }
};

/// A text message holding `text`.
inline OutgoingFrame TextFrame(std::string text) {
  return {std::make_shared<const std::string>(std::move(text)), false};
}

/// A binary message holding `bytes`.
inline OutgoingFrame BinaryFrame(std::string bytes) {
  return {std::make_shared<const std::string>(std::move(bytes)), true};
}

}  // namespace topay::viz
