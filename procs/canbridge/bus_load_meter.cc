#include "procs/canbridge/bus_load_meter.h"

#include <algorithm>
#include <stdexcept>

#include "drivers/can/can_frame_bits.h"

namespace topay::canbridge {

BusLoadMeter::BusLoadMeter(double bit_rate_bps, double window_s) : bit_rate_bps_(bit_rate_bps), window_s_(window_s) {
  if (!(bit_rate_bps > 0.0) || !(window_s > 0.0)) throw std::invalid_argument("BusLoadMeter: rate and window must be > 0");
}

void BusLoadMeter::Add(const can::CanFrame& frame, double time_s) {
  if (!can::CheckCanFrame(frame).empty()) return;
  const int bits = can::CanFrameLengthBits(frame);
  if (first_time_s_ < 0.0) first_time_s_ = time_s;
  frames_.emplace_back(time_s, bits);
  window_bits_ += bits;
  total_bits_ += bits;
}

void BusLoadMeter::Expire(double now_s) {
  while (!frames_.empty() && frames_.front().first < now_s - window_s_) {
    window_bits_ -= frames_.front().second;
    frames_.pop_front();
  }
}

double BusLoadMeter::LoadPercent(double now_s) {
  Expire(now_s);
  if (first_time_s_ < 0.0) return 0.0;
  const double span_s = std::clamp(now_s - first_time_s_, 1e-3, window_s_);
  return 100.0 * static_cast<double>(window_bits_) / (bit_rate_bps_ * span_s);
}

}  // namespace topay::canbridge
