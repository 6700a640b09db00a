#pragma once
// One WebSocket client: Beast's handshake answered with the subprotocol, a read loop handing
// whole messages to the callbacks, and a write loop draining the client's bounded FrameQueue
// one async_write at a time. Everything runs on the server's I/O thread except Enqueue,
// RequestClose and stats, which any thread may call.

#include <cstdint>
#include <memory>
#include <mutex>

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <boost/beast/websocket/stream.hpp>

#include "procs/viz/server/frame_queue.h"
#include "procs/viz/server/http_response.h"
#include "procs/viz/server/server_context.h"

namespace topay::viz {

/// One WebSocket client's connection (see the file comment); owned by its pending handlers
/// and, while open, by the registry.
class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  /// Takes over `stream` (the upgraded HTTP connection). The caller has counted it in
  /// context.ws_sessions; the destructor uncounts it.
  WsSession(boost::beast::tcp_stream&& stream, ServerContext& context);
  /// Uncounts the session (context.ws_sessions, its queued bytes).
  ~WsSession();
  WsSession(const WsSession&) = delete;
  WsSession& operator=(const WsSession&) = delete;

  /// I/O thread: answers the upgrade `request`; on success registers the client, calls
  /// on_open and starts reading.
  void Start(HttpRequest request);
  /// Any thread: queues `frame` (dropping the oldest beyond the bounds) and wakes the write
  /// loop. Ignored once the client is closing or gone.
  void Enqueue(OutgoingFrame frame);
  /// Any thread: starts the close handshake (code 1000); the socket is cut if the client does
  /// not answer within close_timeout_s.
  void RequestClose();
  /// I/O thread: starts the close handshake with `code`.
  void BeginClose(boost::beast::websocket::close_code code);
  /// After the I/O thread stopped (WsServer::Stop): no more frames nor posts; the queue is
  /// emptied.
  void Detach();

  /// The client's id (given at construction, also to clients refused later).
  ClientId id() const { return id_; }
  /// The client's queue and traffic (thread-safe).
  ClientStats stats() const;

 private:
  void ConfigureStream();
  void OnAccept(boost::beast::error_code error);
  void DoRead();
  void OnRead(boost::beast::error_code error, std::size_t bytes);
  void DoWrite();
  void OnWrite(boost::beast::error_code error, std::size_t bytes);
  void End(boost::beast::error_code error);
  void CountFailure(boost::beast::error_code error);
  void CutSocket();
  void ArmWatchdog();
  void OnWatchdog();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  ServerContext& context_;
  const ClientId id_;
  HttpRequest request_;
  boost::beast::flat_buffer read_buffer_;
  boost::asio::steady_timer close_timer_;
  // Beast, failing a connection (bad frame, too big), sends a close frame and then waits for
  // the client to close its end, bounded only by its idle timer: the watchdog ends the input
  // of a connection seen not open on two checks close_timeout_s apart, and cuts it on the
  // third.
  boost::asio::steady_timer watchdog_;
  int not_open_checks_ = 0;
  OutgoingFrame writing_;  // the frame async_write is sending
  bool opened_ = false;    // I/O thread only, like the two below
  bool closing_ = false;
  bool ended_ = false;

  mutable std::mutex mutex_;  // guards what follows
  FrameQueue queue_;
  bool posts_allowed_ = false;    // open and not closing: frames and posts accepted
  bool write_scheduled_ = false;  // a DoWrite is posted or a write is in flight
  std::uint64_t frames_sent_ = 0;
  std::uint64_t bytes_sent_ = 0;
};

}  // namespace topay::viz
