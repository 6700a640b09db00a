#pragma once
// The options of topay-viz's HTTP + WebSocket server (docs/viewer.md): where it listens, what
// it serves, and the bounds that keep a slow or hostile client from hurting the others.

#include <cstddef>
#include <string>

namespace topay::viz {

/// How WsServer listens and bounds its clients; every field has a documented default.
struct WsServerOptions {
  /// The address to listen on (IPv4 or IPv6 literal). Default "127.0.0.1": loopback only.
  std::string bind_address = "127.0.0.1";
  /// The TCP port, 0..65535. Default 8765 (Foxglove's). 0: an ephemeral port (tests); see
  /// WsServer::port().
  int port = 8765;
  /// The folder served over HTTP GET / HEAD ("/" is its index.html). Default "": nothing is
  /// served but a short notice on "/" (404 for the rest).
  std::string web_root;
  /// The WebSocket subprotocol a client must offer in Sec-WebSocket-Protocol; the handshake
  /// selects it. An upgrade without it is refused (HTTP 400). Default "foxglove.websocket.v1".
  std::string subprotocol = "foxglove.websocket.v1";
  /// WebSocket clients at most (those in their handshake included); further upgrades are
  /// refused (HTTP 503) and counted. Default 64.
  std::size_t max_clients = 64;
  /// TCP connections still speaking HTTP (not upgraded) at most; further connections are
  /// closed at once and counted as refused (bounds the sockets a slowloris can hold). Default
  /// 256.
  std::size_t max_http_connections = 256;
  /// Per client: outgoing frames kept; beyond, the OLDEST is dropped (counted). Default 512.
  std::size_t max_queue_frames = 512;
  /// Per client: outgoing payload bytes kept; beyond, the OLDEST frames are dropped (counted).
  /// A single frame larger than this is dropped. Default 16 MiB.
  std::size_t max_queue_bytes = std::size_t{16} << 20;
  /// A client message larger than this closes its connection (close code 1009, counted).
  /// Default 64 KiB.
  std::size_t max_incoming_message_bytes = std::size_t{64} << 10;
  /// An HTTP request (and the WebSocket opening or closing handshake) must complete within
  /// this many seconds, or the connection is closed (slowloris). Default 5 s.
  double handshake_timeout_s = 5.0;
  /// A WebSocket client silent for half this time is pinged; silent for all of it, it is
  /// closed (Beast's stream timeouts). Default 60 s.
  double idle_timeout_s = 60.0;
  /// Stop() waits this long for clients to answer the close handshake, and Close() this long
  /// (at least) before cutting the socket of a client that does not. Default 1 s.
  double close_timeout_s = 1.0;
  /// Compress frames (permessage-deflate) to clients that offer it. Default true.
  bool permessage_deflate = true;
};

/// "" when `options` are usable, else what is wrong with them (e.g. "port 70000 is not in
/// 0..65535").
std::string CheckWsServerOptions(const WsServerOptions& options);

}  // namespace topay::viz
