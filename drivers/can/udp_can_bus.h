#pragma once
// The user-space CAN bus for kernels without AF_CAN: every node sends each frame as one UDP
// datagram (udp_can_datagram.h) to an IPv4 multicast group and receives everyone's.

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "drivers/can/can_bus.h"
#include "drivers/can/can_url.h"

namespace topay::can {

/// A node on the user-space bus udp://GROUP:PORT. Behaves like a CAN bus as seen by one
/// SocketCAN socket:
///  - every node receives every frame the other nodes send, each sender's frames in the order
///    they were sent (one host, loopback multicast: the kernel does not reorder or drop them
///    unless a receive buffer overflows, which shows as status().lost_frames);
///  - a node does not receive its own frames unless CanBusOptions::receive_own_frames;
///  - the same id/mask filters as SocketCAN, applied in user space;
///  - error frames may be sent (a simulator's way to put the bus into bus-off or error-passive)
///    and update every receiver's status() like a controller's error frames; while a node's
///    state is bus-off its Send() refuses data and remote frames (kBusOff), as SocketCAN's;
///  - malformed datagrams (wrong size or magic, bad DLC or id) are counted
///    (status().malformed) and dropped.
/// The socket: SO_REUSEADDR, bound to GROUP:PORT, group joined on the default interface,
/// multicast TTL 0 (nothing leaves the host) and loopback on, SO_TIMESTAMPNS for kernel
/// receive timestamps, non-blocking.
///
/// Only inside a private network namespace (a graph's or a test's): joining a group in the
/// machine's own namespace is announced on its network.
class UdpCanBus final : public CanBus {
 public:
  /// Opens the bus; nullptr with *error on failure (e.g. no multicast route).
  static std::unique_ptr<UdpCanBus> Open(const CanUrl& url, const CanBusOptions& options, std::string* error);
  ~UdpCanBus() override;

  CanResult Send(const CanFrame& frame) override;
  CanResult Receive(double timeout_s, ReceivedCanFrame* received) override;
  const CanBusStatus& status() const override { return status_; }
  CanResult Reopen() override;
  int fd() const override { return fd_; }
  std::string url() const override { return url_.ToString(); }

  /// This node's sender id in the datagrams.
  std::uint32_t node_id() const { return node_id_; }

 private:
  UdpCanBus(const CanUrl& url, const CanBusOptions& options, std::uint32_t node_id);
  bool OpenSocket(std::string* error);
  void Close();
  CanResult Failure(CanResult::Code code, const std::string& message);
  // Counts a gap in `sender`'s sequence numbers as lost frames.
  void TrackSequence(std::uint32_t sender, std::uint32_t sequence);

  CanUrl url_;
  CanBusOptions options_;
  std::uint32_t node_id_;
  std::uint32_t next_sequence_ = 0;
  std::map<std::uint32_t, std::uint32_t> expected_sequence_;  ///< Per sender: next sequence.
  int fd_ = -1;
  CanBusStatus status_;
};

}  // namespace topay::can
