#pragma once
// Median, p99 and maximum of a stream of durations (the bridge's command -> CAN frame latency
// and its cycle jitter), over the last `capacity` samples (default 4096: 20 s of 200 Hz cycles;
// the maximum over all of them).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace topay::canbridge {

struct LatencySummary {
  std::int64_t count = 0;  ///< Samples ever added.
  double median_ms = 0.0;
  double p99_ms = 0.0;
  double max_ms = 0.0;     ///< Over every sample ever added.
};

class LatencyStats {
 public:
  explicit LatencyStats(std::size_t capacity = 4096) : capacity_(capacity) {}
  void Add(double seconds);
  /// Over the kept samples (nearest-rank percentiles); zeros when there are none.
  LatencySummary Summary() const;
  /// "median 0.031 ms, p99 0.120 ms, max 0.410 ms (n = 1234)".
  std::string Text() const;

 private:
  std::size_t capacity_;
  std::vector<double> samples_ms_;  // a ring once full
  std::size_t next_ = 0;
  std::int64_t count_ = 0;
  double max_ms_ = 0.0;
};

}  // namespace topay::canbridge
