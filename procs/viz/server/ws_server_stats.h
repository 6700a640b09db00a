#pragma once
// The counters of the WebSocket server: a plain snapshot for users (WsServerStats,
// ClientStats) and the atomic counters the I/O thread updates (ServerCounters).

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace topay::viz {

/// A snapshot of the server's counters (totals since construction unless "now").
struct WsServerStats {
  std::uint64_t clients = 0;               ///< WebSocket clients open now.
  std::uint64_t http_connections = 0;      ///< TCP connections speaking HTTP now.
  std::uint64_t clients_opened = 0;        ///< WebSocket handshakes completed (on_open calls).
  std::uint64_t connections_accepted = 0;  ///< TCP connections accepted.
  /// TCP connections or WebSocket upgrades refused: no subprotocol (400), max_clients (503),
  /// max_http_connections (closed at once).
  std::uint64_t connections_refused = 0;
  std::uint64_t http_requests = 0;     ///< HTTP requests read (upgrades included).
  std::uint64_t http_errors = 0;       ///< Malformed or timed-out requests, 4xx / 5xx answers.
  std::uint64_t frames_sent = 0;       ///< Frames written to clients.
  std::uint64_t frames_dropped = 0;    ///< Frames dropped by full client queues.
  std::uint64_t bytes_sent = 0;        ///< Payload bytes of frames_sent (before compression).
  std::uint64_t oversized_messages = 0;  ///< Client messages over max_incoming_message_bytes.
  /// WebSocket connections failed by the client's protocol violation (bad frame, unmasked
  /// frame, invalid UTF-8, bad handshake).
  std::uint64_t protocol_errors = 0;
  std::uint64_t queued_bytes = 0;  ///< Payload bytes in all client queues now.
  /// The largest payload bytes any one client's queue ever held (<= max_queue_bytes).
  std::uint64_t peak_queue_bytes = 0;
};

/// One client's queue and traffic.
struct ClientStats {
  std::size_t queued_frames = 0;   ///< Frames in its queue now.
  std::size_t queued_bytes = 0;    ///< Payload bytes in its queue now.
  std::size_t peak_queue_bytes = 0;  ///< The most its queue ever held (<= max_queue_bytes).
  std::uint64_t frames_sent = 0;   ///< Frames written to it.
  std::uint64_t frames_dropped = 0;  ///< Frames dropped by its full queue.
  std::uint64_t bytes_sent = 0;    ///< Payload bytes written to it.
};

/// The live counters behind WsServerStats (thread-safe: relaxed atomics).
class ServerCounters {
 public:
  using Counter = std::atomic<std::uint64_t>;

  Counter clients{0};
  Counter clients_opened{0};
  Counter connections_accepted{0};
  Counter connections_refused{0};
  Counter http_requests{0};
  Counter http_errors{0};
  Counter frames_sent{0};
  Counter frames_dropped{0};
  Counter bytes_sent{0};
  Counter oversized_messages{0};
  Counter protocol_errors{0};
  Counter queued_bytes{0};

  /// Raises peak_queue_bytes to `bytes` if larger.
  void NotePeakQueueBytes(std::uint64_t bytes);
  /// A consistent-enough copy (each counter read once, relaxed).
  WsServerStats Snapshot() const;

 private:
  Counter peak_queue_bytes_{0};
};

/// Adds 1 to `counter` (relaxed).
inline void Increment(ServerCounters::Counter& counter) {
  counter.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace topay::viz
