#include "procs/canbridge/latency_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace topay::canbridge {

void LatencyStats::Add(double seconds) {
  const double ms = seconds * 1e3;
  if (samples_ms_.size() < capacity_) {
    samples_ms_.push_back(ms);
  } else if (capacity_ > 0) {
    samples_ms_[next_] = ms;
    next_ = (next_ + 1) % capacity_;
  }
  ++count_;
  max_ms_ = std::max(max_ms_, ms);
}

LatencySummary LatencyStats::Summary() const {
  LatencySummary summary;
  summary.count = count_;
  summary.max_ms = max_ms_;
  if (samples_ms_.empty()) return summary;
  std::vector<double> sorted = samples_ms_;
  const auto rank = [&sorted](double p) {
    const std::size_t index = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size()))) - 1;
    const auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(std::min(index, sorted.size() - 1));
    std::nth_element(sorted.begin(), nth, sorted.end());
    return *nth;
  };
  summary.median_ms = rank(0.5);
  summary.p99_ms = rank(0.99);
  return summary;
}

std::string LatencyStats::Text() const {
  const LatencySummary s = Summary();
  char text[160];
  std::snprintf(text, sizeof(text), "median %.3f ms, p99 %.3f ms, max %.3f ms (n = %lld)", s.median_ms, s.p99_ms,
                s.max_ms, static_cast<long long>(s.count));
  return text;
}

}  // namespace topay::canbridge
