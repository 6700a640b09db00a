#include "sim/localization/pose_sensor.h"

#include <cmath>
#include <utility>

#include "core/common/angles.h"
#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::sim {

void ReadPoseNoiseOptions(YamlSection& s, PoseNoiseOptions* o) {
  s.Read("xy_stddev_m", &o->xy_stddev_m);
  s.Read("yaw_stddev_rad", &o->yaw_stddev_rad);
  s.Read("bias_x_m", &o->bias_x_m);
  s.Read("bias_y_m", &o->bias_y_m);
  s.Read("bias_yaw_rad", &o->bias_yaw_rad);
  if (!(o->xy_stddev_m >= 0.0) || !std::isfinite(o->xy_stddev_m)) {
    throw ConfigError(s.source(), s.FieldPath("xy_stddev_m"), "must be finite and >= 0");
  }
  if (!(o->yaw_stddev_rad >= 0.0) || !std::isfinite(o->yaw_stddev_rad)) {
    throw ConfigError(s.source(), s.FieldPath("yaw_stddev_rad"), "must be finite and >= 0");
  }
  const std::pair<const char*, double> biases[] = {
      {"bias_x_m", o->bias_x_m}, {"bias_y_m", o->bias_y_m}, {"bias_yaw_rad", o->bias_yaw_rad}};
  for (const auto& [key, value] : biases) {
    if (!std::isfinite(value)) throw ConfigError(s.source(), s.FieldPath(key), "must be finite");
  }
}

PoseSensor::PoseSensor(const PoseNoiseOptions& options, std::uint64_t seed) : options_(options), rng_(seed) {}

PlanarPose PoseSensor::Measure(const PlanarPose& truth) {
  PlanarPose m = truth;
  m.x_m += options_.bias_x_m;
  m.y_m += options_.bias_y_m;
  m.yaw_rad += options_.bias_yaw_rad;
  if (options_.xy_stddev_m > 0.0 || options_.yaw_stddev_rad > 0.0) {
    m.x_m += options_.xy_stddev_m * rng_.Normal();
    m.y_m += options_.xy_stddev_m * rng_.Normal();
    m.yaw_rad += options_.yaw_stddev_rad * rng_.Normal();
  }
  m.yaw_rad = WrapAngle(m.yaw_rad);
  return m;
}

}  // namespace topay::sim
