#pragma once
// Options shared by every CanBus backend (SocketCAN and the user-space UDP bus).

#include <cstdint>
#include <vector>

#include "drivers/can/can_filter.h"

namespace topay::can {

/// Options of a CanBus (OpenCanBus(), SocketCanBus, UdpCanBus). Every field has a documented
/// default; Check() throws std::invalid_argument naming the first bad field.
struct CanBusOptions {
  /// Receive filters (SocketCAN semantics, can_filter.h). Empty (default): receive every frame.
  /// SocketCAN: handed to the kernel (CAN_RAW_FILTER); UDP: applied in user space.
  std::vector<CanFilter> filters;

  /// Whether this node receives the frames it sent itself (SocketCAN: CAN_RAW_RECV_OWN_MSGS).
  /// Default false, as a fresh CAN_RAW socket: other nodes see them, the sender does not.
  bool receive_own_frames = false;

  /// Whether Receive() hands error frames to the caller as well. Default false: error frames
  /// only update the bus state and counters (status()). A recorder (candump) sets it.
  bool deliver_error_frames = false;

  /// Kernel receive buffer (SO_RCVBUF) in bytes; 0 (default) keeps the kernel's default.
  int receive_buffer_bytes = 0;

  /// UDP bus only: this node's sender id in the datagrams (so it can drop its own frames and
  /// detect lost ones per sender). 0 (default): a random id drawn when the bus opens.
  std::uint32_t udp_node_id = 0;

  /// Throws std::invalid_argument naming the first field out of range.
  void Check() const;
};

}  // namespace topay::can
