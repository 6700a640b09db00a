#pragma once
// topay-viz's transport (docs/viewer.md): on one TCP port, the page's static files over HTTP
// and WebSocket clients speaking a required subprotocol (foxglove.websocket.v1). One I/O
// thread serves every connection; other threads Send frames to clients through bounded
// per-client queues (oldest dropped), so a slow or stuck client never blocks the sender nor
// the other clients.
//
//   WsServer server(options, {.on_open = ..., .on_text = ..., .on_close = ...});
//   if (!server.Start(&error)) ...;
//   server.Send(client, TextFrame("{...}"));   // any thread, never blocks on the network
//   server.Stop();                             // or the destructor

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "procs/viz/server/outgoing_frame.h"
#include "procs/viz/server/ws_server_callbacks.h"
#include "procs/viz/server/ws_server_options.h"
#include "procs/viz/server/ws_server_stats.h"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace topay::viz {

class Listener;
struct ServerContext;

/// The HTTP + WebSocket server (see the file comment). Owns one I/O thread between Start and
/// Stop.
class WsServer {
 public:
  /// Nothing happens before Start. The callbacks run on the I/O thread (ws_server_callbacks.h).
  WsServer(WsServerOptions options, WsServerCallbacks callbacks);
  /// Stops the server (see Stop).
  ~WsServer();
  WsServer(const WsServer&) = delete;
  WsServer& operator=(const WsServer&) = delete;

  /// Checks the options, binds and listens, and starts the I/O thread. false + `error`
  /// (e.g. "cannot bind 127.0.0.1:8765: Address already in use") when it cannot; also when
  /// already started. May be called again after Stop.
  bool Start(std::string* error);
  /// Stops accepting, closes every client (close code 1001, waiting at most close_timeout_s
  /// for their answers, then cutting them), calls on_close for each open client and joins the
  /// I/O thread. Idempotent. Not from a callback (it would wait for itself: logged, ignored).
  void Stop();
  /// Whether the server is started (and not stopped). Thread-safe, never waits.
  bool running() const { return running_.load(); }
  /// The bound port after Start (the ephemeral one when options.port was 0); 0 before.
  int port() const { return port_.load(); }
  /// The options given at construction.
  const WsServerOptions& options() const;

  /// Queues `frame` for `client` and returns at once (thread-safe, never waits on the
  /// network): beyond the per-client bounds the oldest frames are dropped (counted). An
  /// unknown, closing or closed client, or a null payload: ignored.
  void Send(ClientId client, OutgoingFrame frame);
  /// Starts closing `client` (close code 1000; its socket is cut after close_timeout_s if it
  /// does not answer); on_close follows. Unknown client: ignored. Thread-safe.
  void Close(ClientId client);
  /// The server's counters (thread-safe).
  WsServerStats stats() const;
  /// One open client's queue and traffic; nullopt when unknown or gone (thread-safe).
  std::optional<ClientStats> client_stats(ClientId client) const;

 private:
  void RunIoThread();
  void ForgetRemainingClients();

  std::unique_ptr<ServerContext> context_;
  mutable std::mutex lifecycle_mutex_;  // Start / Stop
  std::unique_ptr<boost::asio::io_context> io_context_;
  std::shared_ptr<Listener> listener_;
  std::thread io_thread_;
  std::atomic<int> port_{0};
  std::atomic<bool> running_{false};
};

}  // namespace topay::viz
