#pragma once

#include <string>
#include <vector>

namespace topay::viz {

/// Axis ticks at "nice" round values for charts.

/// The tick step for an axis spanning `span` (> 0) with about `target_count` intervals: the
/// smallest of 1, 2, 5 x 10^k that is at least span / target_count. Throws
/// std::invalid_argument for a span that is not finite and positive or target_count < 1.
double NiceTickStep(double span, int target_count);

/// Every multiple of `step` in [lo, hi] (within 1e-9 step at either end), increasing, with
/// values within 1e-9 step of zero written as exactly 0. Throws std::invalid_argument if lo >
/// hi, a bound is not finite, step is not finite and positive, or there would be more than
/// 1000 ticks.
std::vector<double> TicksIn(double lo, double hi, double step);

/// A tick label with as many decimals as the step needs (step 0.25 -> "1.25", step 2 -> "4",
/// step 0.001 -> "0.003"), no trailing zeros beyond them, and "0" rather than "-0".
std::string FormatTick(double value, double step);

/// An axis range that covers [lo, hi]: if lo == hi (a constant series) it is widened by
/// max(|lo| 0.1, 1e-3) on both sides; then each end is pushed out by padding x the span.
/// Returns {low, high}; throws std::invalid_argument for non-finite bounds or lo > hi.
std::pair<double, double> PaddedRange(double lo, double hi, double padding);

}  // namespace topay::viz
