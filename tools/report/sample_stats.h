#pragma once
// Order statistics and root mean squares of a list of samples (solve times, errors).

#include <cstdint>
#include <vector>

namespace topay::report {

/// The p-th percentile (p in [0, 100]) by linear interpolation between the closest ranks
/// (numpy's default): with the n samples sorted x_0 <= ... <= x_{n-1} and r = p / 100 (n - 1),
/// x_floor(r) + (r - floor(r)) (x_floor(r)+1 - x_floor(r)). The median is p = 50. 0 for no samples.
double Percentile(std::vector<double> samples, double p);

/// sqrt(mean(x^2)); 0 for no samples.
double Rms(const std::vector<double>& samples);

/// The largest sample; 0 for no samples.
double Max(const std::vector<double>& samples);

/// The usual summary of a timing: count, median, p95, p99 and max (all 0 for no samples).
struct TimingStats {
  std::int64_t count = 0;
  double median = 0.0;
  double p95 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};
TimingStats SummarizeTimings(const std::vector<double>& samples);

/// RMS and max of an error (magnitudes: the samples' absolute values).
struct ErrorStats {
  std::int64_t count = 0;
  double rms = 0.0;
  double max = 0.0;
};
ErrorStats SummarizeErrors(const std::vector<double>& samples);

}  // namespace topay::report
