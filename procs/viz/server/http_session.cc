#include "procs/viz/server/http_session.h"

#include <chrono>
#include <utility>

#include <boost/beast/http/error.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/write.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <spdlog/spdlog.h>

#include "procs/viz/server/upgrade_checks.h"
#include "procs/viz/server/ws_session.h"

namespace topay::viz {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;

std::chrono::steady_clock::duration Seconds(double seconds) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(seconds));
}

bool IsParseError(beast::error_code error) {
  return error.category() == beast::error_code(http::error::bad_target).category();
}

}  // namespace

HttpSession::HttpSession(asio::ip::tcp::socket socket, ServerContext& context)
    : stream_(std::move(socket)), context_(context) {
  context_.http_connections.fetch_add(1);
}

HttpSession::~HttpSession() { context_.http_connections.fetch_sub(1); }

void HttpSession::Start() { DoRead(); }

void HttpSession::DoRead() {
  parser_.emplace();
  parser_->header_limit(kMaxRequestHeaderBytes);
  parser_->body_limit(kMaxRequestBodyBytes);
  stream_.expires_after(Seconds(context_.options.handshake_timeout_s));
  http::async_read(stream_, buffer_, *parser_,
                   [self = shared_from_this()](beast::error_code error, std::size_t bytes) {
                     self->OnRead(error, bytes);
                   });
}

void HttpSession::OnRead(beast::error_code error, std::size_t bytes) {
  if (error) {
    OnReadError(error);
    return;
  }
  Increment(context_.counters.http_requests);
  HttpRequest request = parser_->release();
  if (beast::websocket::is_upgrade(request)) {
    Upgrade(std::move(request));
    return;
  }
  Reply(context_.files.Respond(request));
}

void HttpSession::OnReadError(beast::error_code error) {
  if (IsParseError(error) && error != http::error::end_of_stream &&
      error != http::error::partial_message) {
    spdlog::debug("viz server: malformed HTTP request: {}", error.message());
    Reply(PlainResponse(http::status::bad_request, "Malformed request.\n", 11, false));
    return;
  }
  if (error == beast::error::timeout) {
    // A request too slow to arrive (slowloris) is an error; an idle keep-alive is not.
    if (parser_->got_some()) Increment(context_.counters.http_errors);
    stream_.close();
    return;
  }
  if (error == http::error::partial_message) Increment(context_.counters.http_errors);
  Shutdown();
}

void HttpSession::Upgrade(HttpRequest request) {
  if (!OffersSubprotocol(request, context_.options.subprotocol)) {
    Increment(context_.counters.connections_refused);
    Reply(MissingSubprotocolResponse(request, context_.options.subprotocol));
    return;
  }
  if (context_.ws_sessions.fetch_add(1) >= context_.options.max_clients) {
    context_.ws_sessions.fetch_sub(1);
    Increment(context_.counters.connections_refused);
    Reply(TooManyClientsResponse(request));
    return;
  }
  stream_.expires_never();
  // Bytes read past the request belong to the WebSocket; a client must wait for the 101
  // first (RFC 6455 4.1), so there are none unless it misbehaves, and they are dropped.
  std::make_shared<WsSession>(std::move(stream_), context_)->Start(std::move(request));
}

void HttpSession::Reply(HttpResponse response) {
  if (response.result_int() >= 400) Increment(context_.counters.http_errors);
  response_ = std::move(response);
  stream_.expires_after(Seconds(context_.options.handshake_timeout_s));
  http::async_write(stream_, response_,
                    [self = shared_from_this()](beast::error_code error, std::size_t bytes) {
                      self->OnWrite(error, bytes);
                    });
}

void HttpSession::OnWrite(beast::error_code error, std::size_t bytes) {
  if (error || !response_.keep_alive()) {
    Shutdown();
    return;
  }
  response_ = {};
  DoRead();
}

void HttpSession::Shutdown() {
  beast::error_code ignored;
  stream_.socket().shutdown(asio::ip::tcp::socket::shutdown_send, ignored);
  // Closing with unread input would reset the connection and could destroy the response
  // before the client reads it: read (and discard) until the client closes, time-limited.
  stream_.expires_after(Seconds(context_.options.handshake_timeout_s));
  Drain();
}

void HttpSession::Drain() {
  buffer_.clear();
  stream_.async_read_some(buffer_.prepare(kDrainChunkBytes),
                          [self = shared_from_this()](beast::error_code error, std::size_t) {
                            if (error) {
                              self->stream_.close();
                              return;
                            }
                            self->Drain();
                          });
}

}  // namespace topay::viz
