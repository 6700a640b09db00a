#include "core/control/arm_pacing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/angles.h"
#include "core/common/option_checks.h"

namespace topay {
namespace {
constexpr const char* kArmPacingOptions = "ArmPacingOptions";  // the owner in error messages
}  // namespace

void ArmPacingOptions::Check() const {
  CheckOptionNonNegative(kArmPacingOptions, "window_s", window_s);
  CheckOptionNonNegative(kArmPacingOptions, "slack_m", slack_m);
  CheckOptionNonNegative(kArmPacingOptions, "yaw_m_per_rad", yaw_m_per_rad);
  CheckOptionPositive(kArmPacingOptions, "resolution_s", resolution_s);
  if (window_s / resolution_s > kMaxSamples - 1) {
    FailOption(kArmPacingOptions, "window_s", window_s, "<= 256 resolution_s");
  }
}

double BasePoseDistance(const WholeBodyState& a, const WholeBodyState& b, double yaw_m_per_rad) {
  return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m) +
         yaw_m_per_rad * std::abs(WrapAngle(a.yaw_rad - b.yaw_rad));
}

double ArmPacedTime(const TrajectorySampler& sampler, double duration_s, double clock_t_s,
                    const WholeBodyState& base, const ArmPacingOptions& options,
                    TrajectorySample* scratch) {
  if (options.window_s <= 0.0) return clock_t_s;
  const double latest_s = std::clamp(clock_t_s, 0.0, duration_s);
  const double earliest_s = std::clamp(clock_t_s - options.window_s, 0.0, latest_s);
  const int steps = std::min(ArmPacingOptions::kMaxSamples - 1,
                             static_cast<int>(std::ceil((latest_s - earliest_s) / options.resolution_s)));
  const auto time_of = [&](int j) { return std::max(earliest_s, latest_s - j * options.resolution_s); };
  // The base within the slack of the clock's pose (normal driving) is on the clock whatever the
  // window's nearest pose (it is >= 0 away): the search is spared on the hot path.
  // Distances at tau_j = latest - j resolution (the last one at the window's start).
  std::array<double, ArmPacingOptions::kMaxSamples> distance_m;
  sampler(latest_s, scratch);
  distance_m[0] = BasePoseDistance(scratch->state, base, options.yaw_m_per_rad);
  if (distance_m[0] <= options.slack_m) return clock_t_s;
  double nearest_m = distance_m[0];
  for (int j = 1; j <= steps; ++j) {
    sampler(time_of(j), scratch);
    distance_m[j] = BasePoseDistance(scratch->state, base, options.yaw_m_per_rad);
    nearest_m = std::min(nearest_m, distance_m[j]);
  }
  for (int j = 0; j <= steps; ++j) {
    if (distance_m[j] <= nearest_m + options.slack_m) return j == 0 ? clock_t_s : time_of(j);
  }
  return clock_t_s;  // not reached: the nearest sample is within the slack of itself
}

}  // namespace topay
