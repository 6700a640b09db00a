// EstimatorOptions: the defaults pass Check(); each bad field is named.

#include "core/estimation/estimator_options.h"

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace topay {
namespace {

void ExpectRejected(const std::function<void(EstimatorOptions*)>& spoil, const std::string& field) {
  EstimatorOptions options;
  spoil(&options);
  try {
    options.Check();
    ADD_FAILURE() << field << " accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(EstimatorOptions, DefaultsPass) { EXPECT_NO_THROW(EstimatorOptions{}.Check()); }

TEST(EstimatorOptions, BadFieldsAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ExpectRejected([](EstimatorOptions* o) { o->translation_var_m2_per_m = -1e-3; }, "translation_var_m2_per_m");
  ExpectRejected([&](EstimatorOptions* o) { o->rotation_var_rad2_per_rad = nan; }, "rotation_var_rad2_per_rad");
  ExpectRejected([](EstimatorOptions* o) { o->rotation_var_rad2_per_m = -1.0; }, "rotation_var_rad2_per_m");
  ExpectRejected([](EstimatorOptions* o) { o->diffusion_xy_m2_per_s = -1.0; }, "diffusion_xy_m2_per_s");
  ExpectRejected([](EstimatorOptions* o) { o->diffusion_yaw_rad2_per_s = -1.0; }, "diffusion_yaw_rad2_per_s");
  ExpectRejected([](EstimatorOptions* o) { o->pose_xy_stddev_m = 0.0; }, "pose_xy_stddev_m");
  ExpectRejected([](EstimatorOptions* o) { o->pose_yaw_stddev_rad = -0.1; }, "pose_yaw_stddev_rad");
  ExpectRejected([](EstimatorOptions* o) { o->gate_chi2 = 0.0; }, "gate_chi2");
  ExpectRejected([](EstimatorOptions* o) { o->reinit_after_rejections = 0; }, "reinit_after_rejections");
  ExpectRejected([](EstimatorOptions* o) { o->history_capacity = 3; }, "history_capacity");
  ExpectRejected([](EstimatorOptions* o) { o->max_delay_s = 0.0; }, "max_delay_s");
}

}  // namespace
}  // namespace topay
