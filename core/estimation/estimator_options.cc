#include "core/estimation/estimator_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

void Fail(const char* field, double value, const char* requirement) {
  throw std::invalid_argument(std::string("EstimatorOptions: ") + field + " must be " + requirement + ", got " +
                              std::to_string(value));
}

void CheckNonNegative(double value, const char* field) {
  if (!std::isfinite(value) || value < 0.0) Fail(field, value, "finite and >= 0");
}

void CheckPositive(double value, const char* field) {
  if (!std::isfinite(value) || value <= 0.0) Fail(field, value, "finite and > 0");
}

}  // namespace

void EstimatorOptions::Check() const {
  CheckNonNegative(translation_var_m2_per_m, "translation_var_m2_per_m");
  CheckNonNegative(rotation_var_rad2_per_rad, "rotation_var_rad2_per_rad");
  CheckNonNegative(rotation_var_rad2_per_m, "rotation_var_rad2_per_m");
  CheckNonNegative(diffusion_xy_m2_per_s, "diffusion_xy_m2_per_s");
  CheckNonNegative(diffusion_yaw_rad2_per_s, "diffusion_yaw_rad2_per_s");
  CheckPositive(pose_xy_stddev_m, "pose_xy_stddev_m");
  CheckPositive(pose_yaw_stddev_rad, "pose_yaw_stddev_rad");
  CheckPositive(gate_chi2, "gate_chi2");
  if (reinit_after_rejections < 1) Fail("reinit_after_rejections", reinit_after_rejections, ">= 1");
  if (history_capacity < 4 || history_capacity > 100000) {
    Fail("history_capacity", history_capacity, "in [4, 100000]");
  }
  CheckPositive(max_delay_s, "max_delay_s");
}

}  // namespace topay
