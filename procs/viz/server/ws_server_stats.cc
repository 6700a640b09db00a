#include "procs/viz/server/ws_server_stats.h"

namespace topay::viz {
namespace {

std::uint64_t Read(const ServerCounters::Counter& counter) {
  return counter.load(std::memory_order_relaxed);
}

}  // namespace

void ServerCounters::NotePeakQueueBytes(std::uint64_t bytes) {
  std::uint64_t peak = Read(peak_queue_bytes_);
  while (bytes > peak &&
         !peak_queue_bytes_.compare_exchange_weak(peak, bytes, std::memory_order_relaxed)) {
  }
}

WsServerStats ServerCounters::Snapshot() const {
  WsServerStats stats;
  stats.clients = Read(clients);
  stats.clients_opened = Read(clients_opened);
  stats.connections_accepted = Read(connections_accepted);
  stats.connections_refused = Read(connections_refused);
  stats.http_requests = Read(http_requests);
  stats.http_errors = Read(http_errors);
  stats.frames_sent = Read(frames_sent);
  stats.frames_dropped = Read(frames_dropped);
  stats.bytes_sent = Read(bytes_sent);
  stats.oversized_messages = Read(oversized_messages);
  stats.protocol_errors = Read(protocol_errors);
  stats.queued_bytes = Read(queued_bytes);
  stats.peak_queue_bytes = Read(peak_queue_bytes_);
  return stats;
}

}  // namespace topay::viz
