#pragma once
// The bus load of the frames a node sent and received: their exact lengths on the wire
// (drivers/can/can_frame_bits.h, stuff bits included) over a sliding window, as a share of the
// bit rate.

#include <cstdint>
#include <deque>
#include <utility>

#include "drivers/can/can_frame.h"

namespace topay::canbridge {

class BusLoadMeter {
 public:
  /// `bit_rate_bps` > 0, `window_s` > 0 (default 1 s).
  explicit BusLoadMeter(double bit_rate_bps, double window_s = 1.0);
  /// A frame on the bus at `time_s` (sent or received; error frames count 0 bits).
  void Add(const can::CanFrame& frame, double time_s);
  /// Percent of the bit rate the frames of the window [now - window, now] used. Before a whole
  /// window has passed since the first frame, the share of the time since then.
  double LoadPercent(double now_s);
  std::int64_t total_bits() const { return total_bits_; }

 private:
  void Expire(double now_s);

  double bit_rate_bps_;
  double window_s_;
  std::deque<std::pair<double, int>> frames_;  // (time, bits)
  std::int64_t window_bits_ = 0;
  std::int64_t total_bits_ = 0;
  double first_time_s_ = -1.0;
};

}  // namespace topay::canbridge
