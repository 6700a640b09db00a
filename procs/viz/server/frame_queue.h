#pragma once
// A client's bounded queue of outgoing frames. The newest frames matter most to a viewer, so
// when a push would exceed the bounds (frames or bytes) the OLDEST frames are dropped, and
// counted. Not thread-safe: the owner (WsSession) locks around it.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include "procs/viz/server/outgoing_frame.h"

namespace topay::viz {

/// The bounds of a FrameQueue.
struct FrameQueueOptions {
  /// Frames kept at most (>= 1). Default 512.
  std::size_t max_frames = 512;
  /// Payload bytes kept at most (>= 1). Default 16 MiB. A single frame larger than this is
  /// dropped on arrival (counted): keeping it would break the bound.
  std::size_t max_bytes = std::size_t{16} << 20;
};

/// A bounded FIFO of outgoing frames that drops its oldest frames when full.
class FrameQueue {
 public:
  /// An empty queue with `options` (a zero bound counts as 1).
  explicit FrameQueue(FrameQueueOptions options = {});

  /// Appends `frame`, first dropping the oldest frames until it fits both bounds. Returns the
  /// number of frames dropped (the new one included when it alone exceeds max_bytes).
  std::size_t Push(OutgoingFrame frame);
  /// Removes and returns the oldest frame; nullopt when empty.
  std::optional<OutgoingFrame> Pop();
  /// Drops every queued frame (not counted as dropped: the client is gone).
  void Clear();

  /// Whether no frame is queued.
  bool empty() const { return frames_.empty(); }
  /// Frames queued now.
  std::size_t frames() const { return frames_.size(); }
  /// Payload bytes queued now (<= max_bytes).
  std::size_t bytes() const { return bytes_; }
  /// The largest bytes() ever reached (<= max_bytes).
  std::size_t peak_bytes() const { return peak_bytes_; }
  /// Frames pushed so far (dropped ones included).
  std::uint64_t pushed() const { return pushed_; }
  /// Frames dropped so far to keep the bounds.
  std::uint64_t dropped() const { return dropped_; }
  /// The bounds in force (zeros raised to 1).
  const FrameQueueOptions& options() const { return options_; }

 private:
  void DropOldest();

  FrameQueueOptions options_;
  std::deque<OutgoingFrame> frames_;
  std::size_t bytes_ = 0;
  std::size_t peak_bytes_ = 0;
  std::uint64_t pushed_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace topay::viz
