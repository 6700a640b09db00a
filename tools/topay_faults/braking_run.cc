#include "braking_run.h"

#include <cmath>

namespace topay::tools {

double BrakingRun::Add(const std::vector<double>& axes, double time_s) {
  bool braking = previous_abs_.size() == axes.size();
  previous_abs_.resize(axes.size());
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const double now = std::abs(axes[i]);
    braking = braking && (now < zero_threshold_ || now < previous_abs_[i]);  // NaN: not braking
    previous_abs_[i] = now;
  }
  if (!braking) since_s_ = -1.0;
  else if (since_s_ < 0.0) since_s_ = time_s;
  return since_s_;
}

}  // namespace topay::tools
