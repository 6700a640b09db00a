#include "procs/viz/server/frame_queue.h"

#include <algorithm>
#include <utility>

namespace topay::viz {

FrameQueue::FrameQueue(FrameQueueOptions options) : options_(options) {
  options_.max_frames = std::max<std::size_t>(options_.max_frames, 1);
  options_.max_bytes = std::max<std::size_t>(options_.max_bytes, 1);
}

std::size_t FrameQueue::Push(OutgoingFrame frame) {
  ++pushed_;
  const std::size_t size = frame.size();
  if (size > options_.max_bytes) {
    ++dropped_;
    return 1;
  }
  std::size_t dropped = 0;
  while (!frames_.empty() &&
         (frames_.size() >= options_.max_frames || bytes_ + size > options_.max_bytes)) {
    DropOldest();
    ++dropped;
  }
  bytes_ += size;
  frames_.push_back(std::move(frame));
  peak_bytes_ = std::max(peak_bytes_, bytes_);
  return dropped;
}

std::optional<OutgoingFrame> FrameQueue::Pop() {
  if (frames_.empty()) return std::nullopt;
  OutgoingFrame frame = std::move(frames_.front());
  frames_.pop_front();
  bytes_ -= frame.size();
  return frame;
}

void FrameQueue::Clear() {
  frames_.clear();
  bytes_ = 0;
}

void FrameQueue::DropOldest() {
  bytes_ -= frames_.front().size();
  frames_.pop_front();
  ++dropped_;
}

}  // namespace topay::viz
