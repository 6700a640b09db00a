#pragma once

#include <vector>

namespace topay {

/// Statistics of a sample; every function returns NaN for an empty sample.

/// Arithmetic mean.
double Mean(const std::vector<double>& values);

/// Median: the middle value, or the mean of the two middle values for an even count.
double Median(std::vector<double> values);

/// Nearest-rank quantile, q in (0, 1]: the smallest value v such that at least a fraction q of
/// the sample is <= v (the value of rank ceil(q n) in ascending order). p95 is q = 0.95.
double NearestRankQuantile(std::vector<double> values, double q);

}  // namespace topay
