#include "tools/report/sample_stats.h"

#include <algorithm>
#include <cmath>

namespace topay::report {

double Percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(samples.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, samples.size() - 1);
  return samples[below] + (rank - static_cast<double>(below)) * (samples[above] - samples[below]);
}

double Rms(const std::vector<double>& samples) {
  if (samples.empty()) return 0.0;
  double sum = 0.0;
  for (double x : samples) sum += x * x;
  return std::sqrt(sum / static_cast<double>(samples.size()));
}

double Max(const std::vector<double>& samples) {
  return samples.empty() ? 0.0 : *std::max_element(samples.begin(), samples.end());
}

TimingStats SummarizeTimings(const std::vector<double>& samples) {
  return {static_cast<std::int64_t>(samples.size()), Percentile(samples, 50.0), Percentile(samples, 95.0),
          Percentile(samples, 99.0), Max(samples)};
}

ErrorStats SummarizeErrors(const std::vector<double>& samples) {
  std::vector<double> magnitudes;
  magnitudes.reserve(samples.size());
  for (double x : samples) magnitudes.push_back(std::abs(x));
  return {static_cast<std::int64_t>(samples.size()), Rms(magnitudes), Max(magnitudes)};
}

}  // namespace topay::report
