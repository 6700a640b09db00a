// The simulated localisation (sim/localization/pose_sensor.h): truth without noise, bias,
// seeded noise with the configured spread.

#include "sim/localization/pose_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::sim {
namespace {

TEST(PoseSensor, ReportsTheTruthByDefaultAndAddsBiasAndSeededNoise) {
  PoseSensor exact({}, 1);
  const PlanarPose truth{1.5, -2.0, 3.0};
  const PlanarPose m = exact.Measure(truth);
  EXPECT_EQ(m.x_m, 1.5);
  EXPECT_EQ(m.y_m, -2.0);
  EXPECT_EQ(m.yaw_rad, 3.0);

  PoseNoiseOptions o;
  o.xy_stddev_m = 0.02;
  o.yaw_stddev_rad = 0.01;
  o.bias_x_m = 0.1;
  o.bias_yaw_rad = 0.3;  // 3.0 + 0.3 wraps
  PoseSensor a(o, 4), b(o, 4);
  double sum_x = 0.0, sum_xx = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const PlanarPose pa = a.Measure(truth), pb = b.Measure(truth);
    EXPECT_EQ(pa.x_m, pb.x_m);
    const double dx = pa.x_m - truth.x_m;
    sum_x += dx;
    sum_xx += dx * dx;
    EXPECT_LE(pa.yaw_rad, M_PI);
    EXPECT_GT(pa.yaw_rad, -M_PI);
  }
  const double mean = sum_x / n, stddev = std::sqrt(sum_xx / n - mean * mean);
  EXPECT_NEAR(mean, 0.1, 0.001);
  EXPECT_NEAR(stddev, 0.02, 0.001);
}

}  // namespace
}  // namespace topay::sim
