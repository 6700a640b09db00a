#pragma once
// A synchronous WebSocket + HTTP client on Boost.Beast for the viewer's process tests: the
// Foxglove handshake, text requests, and reading messages with a deadline.

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <optional>
#include <string>

namespace topay::viz::test {

namespace beast = boost::beast;
namespace net = boost::asio;

/// One received WebSocket message.
struct WsMessage {
  std::string bytes;
  bool binary = false;
};

class WsTestClient {
 public:
  /// Connects to 127.0.0.1:port offering foxglove.websocket.v1; throws on failure.
  explicit WsTestClient(int port) : ws_(io_) {
    net::ip::tcp::resolver resolver(io_);
    beast::get_lowest_layer(ws_).connect(resolver.resolve("127.0.0.1", std::to_string(port)));
    ws_.set_option(beast::websocket::stream_base::decorator([](beast::websocket::request_type& req) {
      req.set(beast::http::field::sec_websocket_protocol, "foxglove.websocket.v1");
    }));
    ws_.handshake("127.0.0.1:" + std::to_string(port), "/");
  }

  void SendText(const std::string& text) {
    ws_.text(true);
    ws_.write(net::buffer(text));
  }

  /// The next message, or nullopt if none came within timeout_s (or the connection closed).
  /// After a timeout the client is unusable.
  std::optional<WsMessage> Read(double timeout_s) {
    beast::flat_buffer buffer;
    std::optional<beast::error_code> result;
    ws_.async_read(buffer, [&](beast::error_code ec, std::size_t) { result = ec; });
    io_.restart();
    io_.run_for(std::chrono::milliseconds(static_cast<int>(timeout_s * 1000)));
    if (!result) {
      beast::get_lowest_layer(ws_).cancel();
      io_.restart();
      io_.run();
      return std::nullopt;
    }
    if (*result) return std::nullopt;
    return WsMessage{beast::buffers_to_string(buffer.data()), ws_.got_binary()};
  }

 private:
  net::io_context io_;
  beast::websocket::stream<beast::tcp_stream> ws_;
};

/// GET `target` from 127.0.0.1:port: (status, body).
inline std::pair<int, std::string> HttpGet(int port, const std::string& target) {
  net::io_context io;
  beast::tcp_stream stream(io);
  net::ip::tcp::resolver resolver(io);
  stream.connect(resolver.resolve("127.0.0.1", std::to_string(port)));
  beast::http::request<beast::http::empty_body> req{beast::http::verb::get, target, 11};
  req.set(beast::http::field::host, "127.0.0.1");
  beast::http::write(stream, req);
  beast::flat_buffer buffer;
  beast::http::response<beast::http::string_body> res;
  beast::http::read(stream, buffer, res);
  return {static_cast<int>(res.result_int()), res.body()};
}

}  // namespace topay::viz::test
