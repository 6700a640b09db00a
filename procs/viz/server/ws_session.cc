#include "procs/viz/server/ws_session.h"

#include <chrono>
#include <string_view>
#include <utility>

#include <boost/asio/buffer.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/http/field.hpp>
#include <boost/beast/websocket/error.hpp>
#include <spdlog/spdlog.h>

namespace topay::viz {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

/// The read buffer's capacity kept between client messages (larger: freed).
constexpr std::size_t kKeptReadBufferBytes = 16 << 10;

std::chrono::steady_clock::duration Seconds(double seconds) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(seconds));
}

websocket::permessage_deflate DeflateOptions(bool enable) {
  websocket::permessage_deflate deflate;
  deflate.server_enable = enable;
  deflate.compLevel = 3;  // fast: one I/O thread compresses for every client
  return deflate;
}

}  // namespace

WsSession::WsSession(beast::tcp_stream&& stream, ServerContext& context)
    : ws_(std::move(stream)),
      context_(context),
      id_(context.next_client_id.fetch_add(1)),
      close_timer_(ws_.get_executor()),
      watchdog_(ws_.get_executor()),
      queue_({context.options.max_queue_frames, context.options.max_queue_bytes}) {}

WsSession::~WsSession() {
  context_.counters.queued_bytes.fetch_sub(queue_.bytes(), std::memory_order_relaxed);
  context_.ws_sessions.fetch_sub(1);
}

void WsSession::ConfigureStream() {
  const WsServerOptions& options = context_.options;
  beast::get_lowest_layer(ws_).expires_never();  // the websocket stream's own timeouts rule
  websocket::stream_base::timeout timeout{};
  timeout.handshake_timeout = Seconds(options.handshake_timeout_s);
  timeout.idle_timeout = Seconds(options.idle_timeout_s);
  timeout.keep_alive_pings = true;
  ws_.set_option(timeout);
  ws_.set_option(DeflateOptions(options.permessage_deflate));
  ws_.set_option(websocket::stream_base::decorator(
      [subprotocol = options.subprotocol](websocket::response_type& response) {
        response.set(http::field::sec_websocket_protocol, subprotocol);
        response.set(http::field::server, "topay-viz");
      }));
  ws_.read_message_max(options.max_incoming_message_bytes);
  ws_.auto_fragment(false);
}

void WsSession::Start(HttpRequest request) {
  ConfigureStream();
  request_ = std::move(request);
  ws_.async_accept(request_, [self = shared_from_this()](beast::error_code error) {
    self->OnAccept(error);
  });
}

void WsSession::OnAccept(beast::error_code error) {
  request_ = {};
  if (error) {
    spdlog::debug("viz server: WebSocket handshake failed: {}", error.message());
    if (error == websocket::condition::handshake_failed) {
      Increment(context_.counters.protocol_errors);
    }
    return;  // the session ends with its last handler
  }
  if (context_.stopping.load()) return;  // the server is closing every client
  opened_ = true;
  {
    std::lock_guard lock(mutex_);
    posts_allowed_ = true;
  }
  context_.registry.Add(id_, shared_from_this());
  Increment(context_.counters.clients);
  Increment(context_.counters.clients_opened);
  InvokeCallback(context_.callbacks.on_open, "on_open", id_);
  if (closing_ || ended_) return;
  DoRead();
  ArmWatchdog();
}

void WsSession::ArmWatchdog() {
  watchdog_.expires_after(Seconds(context_.options.close_timeout_s));
  watchdog_.async_wait([self = shared_from_this()](beast::error_code error) {
    if (!error && !self->ended_) self->OnWatchdog();
  });
}

void WsSession::OnWatchdog() {
  not_open_checks_ = ws_.is_open() ? 0 : not_open_checks_ + 1;
  if (not_open_checks_ == 2) {
    // Beast waits for the client's end of the stream: make it see one (an EOF on Linux), so
    // that its read still reports why it failed the connection.
    spdlog::debug("viz server: client {} does not finish closing: input shut down", id_);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(asio::ip::tcp::socket::shutdown_receive,
                                                   ignored);
  } else if (not_open_checks_ > 2) {
    spdlog::debug("viz server: client {} does not finish closing: cut", id_);
    CutSocket();
    return;
  }
  ArmWatchdog();
}

void WsSession::DoRead() {
  ws_.async_read(read_buffer_, [self = shared_from_this()](beast::error_code error,
                                                           std::size_t bytes) {
    self->OnRead(error, bytes);
  });
}

void WsSession::OnRead(beast::error_code error, std::size_t bytes) {
  if (error) {
    End(error);
    return;
  }
  const std::string_view message(static_cast<const char*>(read_buffer_.data().data()),
                                 read_buffer_.size());
  if (ws_.got_binary()) {
    InvokeCallback(context_.callbacks.on_binary, "on_binary", id_, message);
  } else {
    InvokeCallback(context_.callbacks.on_text, "on_text", id_, message);
  }
  read_buffer_.consume(read_buffer_.size());
  // One large message must not pin its memory for the life of the connection.
  if (read_buffer_.capacity() > kKeptReadBufferBytes) read_buffer_.shrink_to_fit();
  if (!ended_) DoRead();
}

void WsSession::Enqueue(OutgoingFrame frame) {
  if (!frame.bytes) return;
  std::size_t dropped = 0;
  {
    std::lock_guard lock(mutex_);
    if (!posts_allowed_) return;
    const std::size_t before = queue_.bytes();
    dropped = queue_.Push(std::move(frame));
    context_.counters.queued_bytes.fetch_add(queue_.bytes(), std::memory_order_relaxed);
    context_.counters.queued_bytes.fetch_sub(before, std::memory_order_relaxed);
    context_.counters.NotePeakQueueBytes(queue_.peak_bytes());
    if (!write_scheduled_) {
      write_scheduled_ = true;
      // Posted under the lock: Detach (after which the I/O context may be gone) waits for it.
      asio::post(ws_.get_executor(), [self = shared_from_this()] { self->DoWrite(); });
    }
  }
  if (dropped > 0) {
    context_.counters.frames_dropped.fetch_add(dropped, std::memory_order_relaxed);
  }
}

void WsSession::DoWrite() {
  {
    std::lock_guard lock(mutex_);
    std::optional<OutgoingFrame> next = queue_.Pop();
    if (!next) {
      write_scheduled_ = false;
      return;
    }
    context_.counters.queued_bytes.fetch_sub(next->size(), std::memory_order_relaxed);
    writing_ = std::move(*next);
  }
  ws_.binary(writing_.binary);
  ws_.async_write(asio::buffer(*writing_.bytes),
                  [self = shared_from_this()](beast::error_code error, std::size_t bytes) {
                    self->OnWrite(error, bytes);
                  });
}

void WsSession::OnWrite(beast::error_code error, std::size_t bytes) {
  const std::size_t size = writing_.size();
  writing_ = {};
  if (error) {
    if (error != asio::error::operation_aborted) CutSocket();  // the read then ends the session
    return;
  }
  {
    std::lock_guard lock(mutex_);
    ++frames_sent_;
    bytes_sent_ += size;
  }
  Increment(context_.counters.frames_sent);
  context_.counters.bytes_sent.fetch_add(size, std::memory_order_relaxed);
  DoWrite();
}

void WsSession::RequestClose() {
  std::lock_guard lock(mutex_);
  if (!posts_allowed_) return;
  asio::post(ws_.get_executor(), [self = shared_from_this()] {
    self->BeginClose(websocket::close_code::normal);
  });
}

void WsSession::BeginClose(websocket::close_code code) {
  if (!opened_ || closing_ || ended_) return;
  closing_ = true;
  {
    std::lock_guard lock(mutex_);
    posts_allowed_ = false;
    context_.counters.queued_bytes.fetch_sub(queue_.bytes(), std::memory_order_relaxed);
    queue_.Clear();
  }
  ws_.async_close(code, [self = shared_from_this()](beast::error_code) {});
  close_timer_.expires_after(Seconds(context_.options.close_timeout_s));
  close_timer_.async_wait([self = shared_from_this()](beast::error_code error) {
    if (!error && !self->ended_) self->CutSocket();
  });
}

void WsSession::End(beast::error_code error) {
  if (ended_) return;
  ended_ = true;
  CountFailure(error);
  Detach();
  close_timer_.cancel();
  watchdog_.cancel();
  CutSocket();  // also aborts a write stuck on a client that does not read
  context_.registry.Remove(id_);
  context_.counters.clients.fetch_sub(1, std::memory_order_relaxed);
  InvokeCallback(context_.callbacks.on_close, "on_close", id_);
}

void WsSession::Detach() {
  std::lock_guard lock(mutex_);
  posts_allowed_ = false;
  context_.counters.queued_bytes.fetch_sub(queue_.bytes(), std::memory_order_relaxed);
  queue_.Clear();
}

void WsSession::CountFailure(beast::error_code error) {
  if (error == websocket::error::message_too_big) {
    Increment(context_.counters.oversized_messages);
    spdlog::info("viz server: client {} sent a message over {} bytes: closed", id_,
                 context_.options.max_incoming_message_bytes);
  } else if (error == websocket::condition::protocol_violation) {
    Increment(context_.counters.protocol_errors);
    spdlog::info("viz server: client {} violated the protocol ({}): closed", id_,
                 error.message());
  } else if (error != websocket::error::closed) {
    spdlog::debug("viz server: client {} gone: {}", id_, error.message());
  }
}

void WsSession::CutSocket() {
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

ClientStats WsSession::stats() const {
  std::lock_guard lock(mutex_);
  ClientStats stats;
  stats.queued_frames = queue_.frames();
  stats.queued_bytes = queue_.bytes();
  stats.peak_queue_bytes = queue_.peak_bytes();
  stats.frames_sent = frames_sent_;
  stats.frames_dropped = queue_.dropped();
  stats.bytes_sent = bytes_sent_;
  return stats;
}

}  // namespace topay::viz
