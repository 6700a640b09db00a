#pragma once
// Test support for the viz server's tests: a callback recorder, a Beast WebSocket client and
// raw TCP / HTTP helpers, each on its own io_context with every operation time-limited (a
// misbehaving server fails the test instead of hanging it). Loopback TCP only.

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <boost/asio/buffer.hpp>
#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "procs/viz/server/ws_server.h"

namespace topay::viz::testing {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

inline constexpr char kSubprotocol[] = "foxglove.websocket.v1";

/// Polls `done` every millisecond until it holds or `timeout_s` passed; its last value.
inline bool WaitUntil(const std::function<bool()>& done, double timeout_s = 5.0) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeout_s));
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

/// Seconds since `start`.
inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Options for a test server: loopback, an ephemeral port, a short close timeout (most test
/// clients do not read when the server stops, so they never answer its close frame).
inline WsServerOptions TestOptions() {
  WsServerOptions options;
  options.port = 0;
  options.close_timeout_s = 0.25;
  return options;
}

/// Records the server's callbacks (thread-safe).
class CallbackLog {
 public:
  struct Message {
    ClientId client;
    std::string data;
    bool binary;
  };

  WsServerCallbacks Callbacks() {
    WsServerCallbacks callbacks;
    callbacks.on_open = [this](ClientId id) { Locked([&] { opened_.push_back(id); }); };
    callbacks.on_close = [this](ClientId id) { Locked([&] { closed_.push_back(id); }); };
    callbacks.on_text = [this](ClientId id, std::string_view data) {
      Locked([&] { messages_.push_back({id, std::string(data), false}); });
    };
    callbacks.on_binary = [this](ClientId id, std::string_view data) {
      Locked([&] { messages_.push_back({id, std::string(data), true}); });
    };
    return callbacks;
  }

  std::vector<ClientId> opened() const { return Copy(opened_); }
  std::vector<ClientId> closed() const { return Copy(closed_); }
  std::vector<Message> messages() const { return Copy(messages_); }

  /// Waits for the `n`-th on_open (1-based) and returns its client; 0 on timeout.
  ClientId WaitOpened(std::size_t n, double timeout_s = 5.0) const {
    if (!WaitUntil([&] { return opened().size() >= n; }, timeout_s)) return 0;
    return opened()[n - 1];
  }
  /// Waits until on_close was called for `client`.
  bool WaitClosed(ClientId client, double timeout_s = 5.0) const {
    return WaitUntil([&] {
      for (ClientId id : closed()) {
        if (id == client) return true;
      }
      return false;
    }, timeout_s);
  }

 private:
  template <typename F>
  void Locked(F&& f) {
    std::lock_guard lock(mutex_);
    f();
  }
  template <typename T>
  T Copy(const T& value) const {
    std::lock_guard lock(mutex_);
    return value;
  }

  mutable std::mutex mutex_;
  std::vector<ClientId> opened_;
  std::vector<ClientId> closed_;
  std::vector<Message> messages_;
};

/// Runs `io` until the operation started by `start(handler)` completes; its error code.
template <typename Start>
beast::error_code Await(asio::io_context& io, Start&& start) {
  beast::error_code result = asio::error::would_block;
  start([&result](beast::error_code error, auto&&...) { result = error; });
  io.restart();
  io.run();
  return result;
}

/// A WebSocket client (Beast) whose every operation has a time limit.
class TestClient {
 public:
  explicit TestClient(int port) : port_(port), ws_(io_) {}

  /// Connects and completes the handshake offering `subprotocols` ("" : no header) and,
  /// when `deflate`, permessage-deflate.
  beast::error_code Connect(std::string subprotocols = kSubprotocol, bool deflate = false,
                            std::string target = "/") {
    beast::error_code error = ConnectTcp();
    if (error) return error;
    websocket::permessage_deflate options;
    options.client_enable = deflate;
    ws_.set_option(options);
    ws_.set_option(websocket::stream_base::decorator([subprotocols](websocket::request_type& r) {
      if (!subprotocols.empty()) r.set(http::field::sec_websocket_protocol, subprotocols);
    }));
    ws_.read_message_max(0);  // unlimited: the tests send large frames
    Expire(5.0);
    return Await(io_, [&](auto handler) {
      ws_.async_handshake(response_, "127.0.0.1", target, handler);
    });
  }

  beast::error_code Write(std::string_view payload, bool binary = false) {
    ws_.binary(binary);
    Expire(5.0);
    return Await(io_, [&](auto handler) {
      ws_.async_write(asio::buffer(payload.data(), payload.size()), handler);
    });
  }

  /// Reads one whole message into `message` (and its kind into `binary`).
  beast::error_code Read(std::string* message, bool* binary = nullptr, double timeout_s = 5.0) {
    beast::flat_buffer buffer;
    Expire(timeout_s);
    const beast::error_code error =
        Await(io_, [&](auto handler) { ws_.async_read(buffer, handler); });
    if (!error) {
      *message = beast::buffers_to_string(buffer.data());
      if (binary) *binary = ws_.got_binary();
    }
    return error;
  }

  beast::error_code Close() {
    Expire(5.0);
    return Await(io_, [&](auto handler) {
      ws_.async_close(websocket::close_code::normal, handler);
    });
  }

  /// Drops the TCP connection without a close frame.
  void Drop() {
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  const websocket::response_type& response() const { return response_; }
  websocket::stream<beast::tcp_stream>& ws() { return ws_; }

 private:
  beast::error_code ConnectTcp() {
    Expire(5.0);
    const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"),
                                 static_cast<unsigned short>(port_));
    return Await(io_, [&](auto handler) {
      beast::get_lowest_layer(ws_).async_connect(endpoint, handler);
    });
  }
  void Expire(double seconds) {
    beast::get_lowest_layer(ws_).expires_after(
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(seconds)));
  }

  int port_;
  asio::io_context io_;
  websocket::stream<beast::tcp_stream> ws_;
  websocket::response_type response_;
};

/// A raw TCP connection for hostile bytes.
class RawConnection {
 public:
  explicit RawConnection(int port) : stream_(io_) {
    const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"),
                                 static_cast<unsigned short>(port));
    stream_.expires_after(std::chrono::seconds(5));
    connect_error_ = Await(io_, [&](auto handler) { stream_.async_connect(endpoint, handler); });
  }

  beast::error_code connect_error() const { return connect_error_; }

  beast::error_code Write(std::string_view bytes) {
    stream_.expires_after(std::chrono::seconds(5));
    return Await(io_, [&](auto handler) {
      asio::async_write(stream_, asio::buffer(bytes.data(), bytes.size()), handler);
    });
  }

  /// Reads until `needle` was read (true) or the connection ended or `timeout_s` passed.
  bool ReadUntil(std::string_view needle, double timeout_s = 5.0) {
    const auto start = std::chrono::steady_clock::now();
    while (received_.find(needle) == std::string::npos) {
      if (ReadSome(timeout_s - SecondsSince(start))) return false;
    }
    return true;
  }

  /// Reads until the server closes the connection (true: EOF or reset within `timeout_s`).
  bool ReadUntilClosed(double timeout_s = 5.0) {
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      const beast::error_code error = ReadSome(timeout_s - SecondsSince(start));
      if (error) return error != beast::error::timeout;
    }
  }

  /// Everything read so far.
  const std::string& received() const { return received_; }

  /// Closes the socket now; `reset`: with SO_LINGER 0 (the peer sees a reset).
  void Drop(bool reset = false) {
    beast::error_code ignored;
    if (reset) stream_.socket().set_option(asio::socket_base::linger(true, 0), ignored);
    stream_.socket().close(ignored);
  }

 private:
  beast::error_code ReadSome(double timeout_s) {
    if (timeout_s <= 0) return beast::error::timeout;
    char chunk[4096];
    std::size_t got = 0;
    stream_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(timeout_s)));
    beast::error_code result;
    stream_.async_read_some(asio::buffer(chunk), [&](beast::error_code error, std::size_t n) {
      result = error;
      got = n;
    });
    io_.restart();
    io_.run();
    received_.append(chunk, got);
    return result;
  }

  asio::io_context io_;
  beast::tcp_stream stream_;
  beast::error_code connect_error_;
  std::string received_;
};

/// A WebSocket upgrade request for "/" offering `subprotocol`.
inline std::string UpgradeRequest(std::string_view subprotocol = kSubprotocol) {
  return "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
         "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
         "Sec-WebSocket-Protocol: " + std::string(subprotocol) + "\r\n\r\n";
}

/// A client frame (FIN set) with `opcode`, masked with a fixed key when `masked`.
inline std::string ClientFrame(std::uint8_t opcode, std::string_view payload, bool masked = true) {
  std::string frame;
  frame.push_back(static_cast<char>(0x80 | opcode));
  const char mask_bit = masked ? static_cast<char>(0x80) : 0;
  if (payload.size() < 126) {
    frame.push_back(static_cast<char>(mask_bit | payload.size()));
  } else if (payload.size() <= 0xffff) {
    frame.push_back(static_cast<char>(mask_bit | 126));
    frame.push_back(static_cast<char>(payload.size() >> 8));
    frame.push_back(static_cast<char>(payload.size() & 0xff));
  } else {
    frame.push_back(static_cast<char>(mask_bit | 127));
    for (int shift = 56; shift >= 0; shift -= 8) {
      frame.push_back(static_cast<char>((payload.size() >> shift) & 0xff));
    }
  }
  const char key[4] = {0x12, 0x34, 0x56, 0x78};
  if (masked) frame.append(key, 4);
  for (std::size_t i = 0; i < payload.size(); ++i) {
    frame.push_back(masked ? static_cast<char>(payload[i] ^ key[i % 4]) : payload[i]);
  }
  return frame;
}

/// The response to one HTTP request (`target` sent as is), with an error code.
struct HttpResult {
  beast::error_code error;
  http::response<http::string_body> response;
};

/// Sends `method` `target` (HTTP/1.1, Connection: close) and reads the response.
inline HttpResult HttpRequestOnce(int port, http::verb method, std::string target) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.expires_after(std::chrono::seconds(5));
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"),
                               static_cast<unsigned short>(port));
  HttpResult result;
  result.error = Await(io, [&](auto handler) { stream.async_connect(endpoint, handler); });
  if (result.error) return result;
  http::request<http::string_body> request{method, target, 11};
  request.set(http::field::host, "127.0.0.1");
  request.keep_alive(false);
  request.prepare_payload();
  result.error = Await(io, [&](auto handler) { http::async_write(stream, request, handler); });
  if (result.error) return result;
  http::response_parser<http::string_body> parser;
  parser.skip(method == http::verb::head);
  beast::flat_buffer buffer;
  result.error =
      Await(io, [&](auto handler) { http::async_read(stream, buffer, parser, handler); });
  result.response = parser.release();
  return result;
}

}  // namespace topay::viz::testing
