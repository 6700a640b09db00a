#pragma once
// One TCP connection while it speaks HTTP: reads requests (each within handshake_timeout_s,
// size-limited), answers them from the web root (keep-alive as asked), and hands WebSocket
// upgrades that offer the subprotocol to a WsSession (within max_clients). I/O thread only.

#include <cstddef>
#include <memory>
#include <optional>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/parser.hpp>

#include "procs/viz/server/http_response.h"
#include "procs/viz/server/server_context.h"

namespace topay::viz {

/// The largest request header the server reads (bytes); larger: 400 and closed.
inline constexpr std::size_t kMaxRequestHeaderBytes = 8 << 10;
/// The largest request body the server reads (bytes): GET / HEAD / upgrades carry none.
inline constexpr std::size_t kMaxRequestBodyBytes = 16 << 10;

/// Bytes read at a time while draining a connection being closed.
inline constexpr std::size_t kDrainChunkBytes = 4 << 10;

/// One connection speaking HTTP (see the file comment); owned by its pending handlers.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  /// Takes `socket` (just accepted) and counts it in context.http_connections (the
  /// destructor uncounts it).
  HttpSession(boost::asio::ip::tcp::socket socket, ServerContext& context);
  /// Uncounts the connection (context.http_connections).
  ~HttpSession();
  HttpSession(const HttpSession&) = delete;
  HttpSession& operator=(const HttpSession&) = delete;

  /// Starts reading the first request.
  void Start();

 private:
  void DoRead();
  void OnRead(boost::beast::error_code error, std::size_t bytes);
  void OnReadError(boost::beast::error_code error);
  void Upgrade(HttpRequest request);
  void Reply(HttpResponse response);
  void OnWrite(boost::beast::error_code error, std::size_t bytes);
  void Shutdown();
  void Drain();

  boost::beast::tcp_stream stream_;
  ServerContext& context_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  HttpResponse response_;
};

}  // namespace topay::viz
