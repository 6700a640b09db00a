#pragma once
// The server's listening socket: binds, accepts TCP connections one after the other and hands
// each to an HttpSession, closing at once those beyond max_http_connections. An accept error
// (e.g. out of file descriptors) is logged and retried a little later. I/O thread only, but
// for Open.

#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "procs/viz/server/server_context.h"

namespace topay::viz {

/// The accept loop of one WsServer (see the file comment).
class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// A closed listener on `io_context` handing connections to sessions of `context`.
  Listener(boost::asio::io_context& io_context, ServerContext& context);

  /// Opens, binds and listens on `address`:`port` (any thread, before the I/O thread runs).
  /// false + `error` (naming the address) on failure.
  bool Open(const std::string& address, int port, std::string* error);
  /// Starts accepting (call before the I/O thread runs, or on it).
  void Start();
  /// I/O thread: stops accepting and closes the socket.
  void Stop();
  /// The bound port (after Open).
  int port() const { return port_; }

 private:
  void DoAccept();
  void OnAccept(boost::beast::error_code error, boost::asio::ip::tcp::socket socket);
  void RetryLater();

  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer retry_timer_;
  ServerContext& context_;
  int port_ = 0;
};

}  // namespace topay::viz
