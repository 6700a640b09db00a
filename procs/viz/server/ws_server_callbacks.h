#pragma once
// What the WebSocket server tells its user (the Foxglove protocol layer) about its clients.

#include <functional>
#include <string_view>

#include "procs/viz/server/outgoing_frame.h"

namespace topay::viz {

/// Every callback is optional and runs on the server's own I/O thread, one at a time: it must
/// be quick (queue work elsewhere) and must not wait on the server (WsServer::Send and
/// WsServer::Close are fine; WsServer::Stop is not). An exception thrown by a callback is
/// logged and ignored.
struct WsServerCallbacks {
  /// A client completed its WebSocket handshake; frames may now be sent to it.
  std::function<void(ClientId)> on_open;
  /// A whole text message (valid UTF-8) from a client. The view is valid during the call only.
  std::function<void(ClientId, std::string_view)> on_text;
  /// A whole binary message from a client. The view is valid during the call only.
  std::function<void(ClientId, std::string_view)> on_binary;
  /// A client is gone (closed, failed, timed out or refused after on_open). Called exactly
  /// once for every on_open, at the latest during WsServer::Stop().
  std::function<void(ClientId)> on_close;
};

}  // namespace topay::viz
