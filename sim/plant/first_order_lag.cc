#include "sim/plant/first_order_lag.h"

#include <algorithm>
#include <cmath>

namespace topay::sim {

FirstOrderLag::FirstOrderLag(double tau_s, double dt_s)
    : alpha_(tau_s > 0.0 ? -std::expm1(-dt_s / tau_s) : 1.0) {}

double LimitChange(double from, double to, double max_change) {
  return std::clamp(to, from - max_change, from + max_change);
}

}  // namespace topay::sim
