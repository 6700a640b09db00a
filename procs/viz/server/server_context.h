#pragma once
// What every connection of one WsServer shares: the options, the user's callbacks, the file
// handler, the counters and the registry of open clients. Owned by WsServer; it outlives
// every session (WsServer::Stop destroys them all).

#include <atomic>
#include <cstddef>
#include <exception>
#include <utility>

#include <spdlog/spdlog.h>

#include "procs/viz/server/client_registry.h"
#include "procs/viz/server/http_files.h"
#include "procs/viz/server/ws_server_callbacks.h"
#include "procs/viz/server/ws_server_options.h"
#include "procs/viz/server/ws_server_stats.h"

namespace topay::viz {

class WsSession;

/// The state shared by the listener and every session of one WsServer.
struct ServerContext {
  /// `options` must have passed CheckWsServerOptions.
  ServerContext(WsServerOptions options_in, WsServerCallbacks callbacks_in)
      : options(std::move(options_in)),
        callbacks(std::move(callbacks_in)),
        files(options.web_root) {}

  const WsServerOptions options;
  const WsServerCallbacks callbacks;
  const HttpFiles files;
  ServerCounters counters;
  /// The clients between on_open and on_close.
  ClientRegistry<WsSession> registry;
  /// The next client's id.
  std::atomic<ClientId> next_client_id{1};
  /// WebSocket sessions alive (in their handshake or open): bounded by max_clients.
  std::atomic<std::size_t> ws_sessions{0};
  /// Set by WsServer::Stop: handshakes completing from now on are not opened.
  std::atomic<bool> stopping{false};
  /// TCP connections still speaking HTTP: bounded by max_http_connections.
  std::atomic<std::size_t> http_connections{0};
};

/// Calls `callback(args...)` when set; an exception it throws is logged (as `name`) and
/// swallowed so that it never unwinds through the I/O thread.
template <typename Callback, typename... Args>
void InvokeCallback(const Callback& callback, const char* name, Args&&... args) {
  if (!callback) return;
  try {
    callback(std::forward<Args>(args)...);
  } catch (const std::exception& error) {
    spdlog::error("viz server: the {} callback threw: {}", name, error.what());
  } catch (...) {
    spdlog::error("viz server: the {} callback threw a non-exception", name);
  }
}

}  // namespace topay::viz
