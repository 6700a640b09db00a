#include "core/estimation/estimator_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/option_checks.h"

namespace topay {
namespace {
constexpr const char* kEstimatorOptions = "EstimatorOptions";  // the owner in error messages
}  // namespace

void EstimatorOptions::Check() const {
  CheckOptionNonNegative(kEstimatorOptions, "translation_var_m2_per_m", translation_var_m2_per_m);
  CheckOptionNonNegative(kEstimatorOptions, "rotation_var_rad2_per_rad", rotation_var_rad2_per_rad);
  CheckOptionNonNegative(kEstimatorOptions, "rotation_var_rad2_per_m", rotation_var_rad2_per_m);
  CheckOptionNonNegative(kEstimatorOptions, "diffusion_xy_m2_per_s", diffusion_xy_m2_per_s);
  CheckOptionNonNegative(kEstimatorOptions, "diffusion_yaw_rad2_per_s", diffusion_yaw_rad2_per_s);
  CheckOptionPositive(kEstimatorOptions, "pose_xy_stddev_m", pose_xy_stddev_m);
  CheckOptionPositive(kEstimatorOptions, "pose_yaw_stddev_rad", pose_yaw_stddev_rad);
  CheckOptionPositive(kEstimatorOptions, "gate_chi2", gate_chi2);
  if (reinit_after_rejections < 1) FailOption(kEstimatorOptions, "reinit_after_rejections", reinit_after_rejections, ">= 1");
  if (history_capacity < 4 || history_capacity > 100000) {
    FailOption(kEstimatorOptions, "history_capacity", history_capacity, "in [4, 100000]");
  }
  CheckOptionPositive(kEstimatorOptions, "max_delay_s", max_delay_s);
}

}  // namespace topay
