#pragma once
// Order statistics of measured latencies (topay-lcm-latency, benchmarks).

#include <string>
#include <vector>

namespace topay::latency {

struct LatencySummary {
  int count = 0;
  double median_us = 0.0, p95_us = 0.0, p99_us = 0.0, max_us = 0.0;
};

/// Nearest-rank percentiles of `samples_us` (any order; empty: all zero).
LatencySummary Summarize(std::vector<double> samples_us);

/// "n 1000, median 41.2 us, p95 .., p99 .., max .."
std::string Format(const LatencySummary& summary);

}  // namespace topay::latency
