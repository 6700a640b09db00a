#include "tools/viz/chart_ticks.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace topay::viz {

double NiceTickStep(double span, int target_count) {
  if (!(std::isfinite(span) && span > 0.0) || target_count < 1) {
    throw std::invalid_argument("NiceTickStep: span must be finite and > 0 and target_count >= 1");
  }
  const double raw = span / target_count;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double mantissa : {1.0, 2.0, 5.0, 10.0}) {
    if (mantissa * decade >= raw * (1.0 - 1e-12)) return mantissa * decade;
  }
  return 10.0 * decade;
}

std::vector<double> TicksIn(double lo, double hi, double step) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw std::invalid_argument("TicksIn: bounds must be finite with lo <= hi");
  }
  if (!(std::isfinite(step) && step > 0.0)) {
    throw std::invalid_argument("TicksIn: step must be finite and > 0");
  }
  const double first = std::ceil(lo / step - 1e-9);
  const double last = std::floor(hi / step + 1e-9);
  if (last - first > 1000.0) throw std::invalid_argument("TicksIn: more than 1000 ticks");
  std::vector<double> ticks;
  for (double k = first; k <= last; k += 1.0) {
    const double value = k * step;
    ticks.push_back(std::abs(value) < 1e-9 * step ? 0.0 : value);
  }
  return ticks;
}

std::string FormatTick(double value, double step) {
  // Decimals: enough that the step's first significant digit shows.
  int decimals = 0;
  if (std::isfinite(step) && step > 0.0) {
    decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 12);
    // A step of 0.25 or 2.5 needs one more digit than its decade.
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) > 1e-6 && decimals < 12) ++decimals;
  }
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  std::string text = out.str();
  if (text.find_first_not_of("-0.") == std::string::npos) return "0";
  return text;
}

std::pair<double, double> PaddedRange(double lo, double hi, double padding) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw std::invalid_argument("PaddedRange: bounds must be finite with lo <= hi");
  }
  if (lo == hi) {
    const double widen = std::max(std::abs(lo) * 0.1, 1e-3);
    lo -= widen;
    hi += widen;
  }
  const double pad = std::max(padding, 0.0) * (hi - lo);
  return {lo - pad, hi + pad};
}

}  // namespace topay::viz
