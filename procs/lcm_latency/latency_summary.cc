#include "procs/lcm_latency/latency_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace topay::latency {
namespace {

double Rank(const std::vector<double>& sorted, double q) {
  const auto index = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size()))) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

}  // namespace

LatencySummary Summarize(std::vector<double> samples_us) {
  LatencySummary s;
  if (samples_us.empty()) return s;
  std::sort(samples_us.begin(), samples_us.end());
  s.count = static_cast<int>(samples_us.size());
  s.median_us = Rank(samples_us, 0.5);
  s.p95_us = Rank(samples_us, 0.95);
  s.p99_us = Rank(samples_us, 0.99);
  s.max_us = samples_us.back();
  return s;
}

std::string Format(const LatencySummary& s) {
  char text[160];
  std::snprintf(text, sizeof(text), "n %d, median %.1f us, p95 %.1f us, p99 %.1f us, max %.1f us", s.count,
                s.median_us, s.p95_us, s.p99_us, s.max_us);
  return text;
}

}  // namespace topay::latency
