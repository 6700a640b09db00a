#include "procs/estimator/estimator_config.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::estimator {
namespace {

void Require(bool ok, const char* field, double value, const char* requirement) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + " must be " + requirement + ", got " + std::to_string(value));
  }
}

void ReadFilter(YamlSection s, EstimatorOptions* o) {
  s.Read("translation_var_m2_per_m", &o->translation_var_m2_per_m);
  s.Read("rotation_var_rad2_per_rad", &o->rotation_var_rad2_per_rad);
  s.Read("rotation_var_rad2_per_m", &o->rotation_var_rad2_per_m);
  s.Read("diffusion_xy_m2_per_s", &o->diffusion_xy_m2_per_s);
  s.Read("diffusion_yaw_rad2_per_s", &o->diffusion_yaw_rad2_per_s);
  s.Read("pose_xy_stddev_m", &o->pose_xy_stddev_m);
  s.Read("pose_yaw_stddev_rad", &o->pose_yaw_stddev_rad);
  s.Read("gate_chi2", &o->gate_chi2);
  s.Read("reinit_after_rejections", &o->reinit_after_rejections);
  s.Read("history_capacity", &o->history_capacity);
  s.Read("max_delay_s", &o->max_delay_s);
  s.Finish();
  try {
    o->Check();
  } catch (const std::invalid_argument& e) {
    throw ConfigError(s.source(), "filter", e.what());
  }
}

}  // namespace

void CheckProcessOptions(const EstimatorProcessOptions& o) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  Require(positive(o.publish_rate_hz), "publish_rate_hz", o.publish_rate_hz, "finite and > 0");
  Require(positive(o.odometry_timeout_s), "odometry_timeout_s", o.odometry_timeout_s, "finite and > 0");
  Require(positive(o.joints_timeout_s), "joints_timeout_s", o.joints_timeout_s, "finite and > 0");
  Require(positive(o.pose_timeout_s), "pose_timeout_s", o.pose_timeout_s, "finite and > 0");
  Require(positive(o.gripper_timeout_s), "gripper_timeout_s", o.gripper_timeout_s, "finite and > 0");
  Require(std::isfinite(o.max_future_s) && o.max_future_s >= 0.0, "max_future_s", o.max_future_s, "finite and >= 0");
  Require(o.num_joints >= 0, "num_joints", o.num_joints, ">= 0");
  Require(positive(o.max_speed_mps), "max_speed_mps", o.max_speed_mps, "finite and > 0");
  Require(positive(o.max_yaw_rate_radps), "max_yaw_rate_radps", o.max_yaw_rate_radps, "finite and > 0");
}

EstimatorProcessOptions LoadEstimatorProcessOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  EstimatorProcessOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadFilter(top.Section("filter"), &o.filter);
  top.Read("publish_rate_hz", &o.publish_rate_hz);
  top.Read("odometry_timeout_s", &o.odometry_timeout_s);
  top.Read("joints_timeout_s", &o.joints_timeout_s);
  top.Read("pose_timeout_s", &o.pose_timeout_s);
  top.Read("gripper_timeout_s", &o.gripper_timeout_s);
  top.Read("max_future_s", &o.max_future_s);
  top.Read("num_joints", &o.num_joints);
  top.Read("max_speed_mps", &o.max_speed_mps);
  top.Read("max_yaw_rate_radps", &o.max_yaw_rate_radps);
  top.Finish();
  try {
    CheckProcessOptions(o);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw ConfigError(path, what.substr(0, what.find(' ')), what);
  }
  return o;
}

}  // namespace topay::estimator
