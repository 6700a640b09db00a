#pragma once
// The CAN bus interface every CAN process uses (the bridge, the motor simulator, recorders),
// whatever carries the frames: SocketCAN (socketcan_bus.h) or the user-space UDP bus
// (udp_can_bus.h). Open one with OpenCanBus() (can_url.h).

#include <cstdint>
#include <string>

#include "drivers/can/can_bus_options.h"
#include "drivers/can/can_error.h"
#include "drivers/can/can_frame.h"

namespace topay::can {

/// Outcome of Send() and Receive(): never an exception for what a bus does at run time (a full
/// queue, a timeout, bus-off); exceptions only for programming errors.
struct CanResult {
  enum class Code {
    kOk,
    kTimeout,       ///< Receive(): no frame within the timeout.
    kTxQueueFull,   ///< Send(): the socket's or driver's queue is full (ENOBUFS/EAGAIN); retry later.
    kBusOff,        ///< Send(): the controller is bus-off; see docs/can.md for recovery.
    kInterfaceDown, ///< The interface is down or gone (ENETDOWN/ENODEV): Reopen() once it is back.
    kInvalidFrame,  ///< Send(): the frame is invalid or cannot be sent on this bus.
    kClosed,        ///< The bus is not open (a failed Reopen()).
    kIoError,       ///< Any other system error (message says which).
  };
  Code code = Code::kOk;
  std::string message;  ///< Empty when ok; else what happened, with the errno text.

  bool ok() const { return code == Code::kOk; }
  static CanResult Ok() { return {}; }
};

/// "ok", "timeout", "tx queue full", ...
const char* ToString(CanResult::Code code);

/// A received frame and when it arrived.
struct ReceivedCanFrame {
  CanFrame frame;
  /// Receive time, ns since the Unix epoch (CLOCK_REALTIME, like candump's timestamps): the
  /// kernel's timestamp of the datagram/frame (SO_TIMESTAMPNS) when available, else the clock
  /// read when Receive() got it.
  std::int64_t timestamp_ns = 0;
  bool kernel_timestamp = false;  ///< Whether timestamp_ns came from the kernel.
};

/// Counters and state of a bus since it was opened (Reopen() keeps them).
struct CanBusStatus {
  CanBusState state = CanBusState::kErrorActive;  ///< From the error frames seen.
  std::uint64_t frames_sent = 0;
  std::uint64_t frames_received = 0;   ///< Delivered by Receive() (after filters), error frames too.
  std::uint64_t error_frames = 0;      ///< Error frames seen (delivered or not).
  std::uint64_t bus_off_count = 0;     ///< Times the state went to bus-off.
  std::uint64_t tx_queue_full = 0;     ///< Sends refused because a queue was full.
  std::uint64_t malformed = 0;         ///< Dropped received data that was not a valid frame.
  std::uint64_t lost_frames = 0;       ///< Frames known to be lost (UDP: sequence gaps).
  std::uint64_t reopen_count = 0;      ///< Successful Reopen() calls.
  std::string last_error;              ///< Last error frame's description or failure message.
};

/// A CAN bus endpoint: sends frames to every other node, receives theirs.
///
/// Ownership: the object owns its socket and closes it in its destructor. Not copyable.
/// Thread-safety: none. Use one bus object from one thread (the usual CAN process loop polls
/// fd() with its other inputs, or calls Receive() with a timeout). Two threads that both need
/// the bus open two bus objects (each is a node of its own), or guard one with a mutex.
class CanBus {
 public:
  virtual ~CanBus() = default;
  CanBus(const CanBus&) = delete;
  CanBus& operator=(const CanBus&) = delete;

  /// Queues `frame` for sending without blocking. Returns kTxQueueFull when the queue is full
  /// (the frame is not sent; the caller decides whether to retry or drop), kInvalidFrame for an
  /// invalid frame, kBusOff / kInterfaceDown when the bus cannot send. Never throws for these.
  virtual CanResult Send(const CanFrame& frame) = 0;

  /// Waits up to `timeout_s` (0: poll, negative: forever) for the next frame that passes the
  /// filters, and stores it in *received. Error frames update status() and are returned only
  /// with CanBusOptions::deliver_error_frames. Returns kTimeout when none came.
  virtual CanResult Receive(double timeout_s, ReceivedCanFrame* received) = 0;

  /// State and counters. Error frames are read by Receive(): a node that only sends must still
  /// call Receive() (e.g. with timeout 0 each cycle) for the state to follow the bus, and for a
  /// bus-off's restart to be seen (Send() refuses while the state is bus-off).
  virtual const CanBusStatus& status() const = 0;

  /// Closes and opens the socket again with the same URL and options (recovery after the
  /// interface went down or away). The state starts error-active again (counters are kept).
  /// On failure the bus is closed (Send/Receive give kClosed) and the result says why; call
  /// again later.
  virtual CanResult Reopen() = 0;

  /// The socket's file descriptor, readable when a frame may be waiting (for poll/epoll in a
  /// process loop); -1 when closed. Still owned by the bus.
  virtual int fd() const = 0;

  /// The URL the bus was opened with, e.g. "udp://239.255.1.1:9000".
  virtual std::string url() const = 0;

 protected:
  CanBus() = default;
};

}  // namespace topay::can

namespace topay::can {

/// Updates status->state, error_frames, bus_off_count and last_error from an error frame (used
/// by both backends; a no-op for other frames).
void ApplyErrorFrame(const CanFrame& frame, CanBusStatus* status);

}  // namespace topay::can
