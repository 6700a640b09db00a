#include "sim/plant/plant_options.h"

#include <cmath>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::sim {
namespace {

void Require(bool ok, const YamlSection& section, const char* key, const std::string& what) {
  if (!ok) throw ConfigError(section.source(), section.FieldPath(key), what);
}

void ReadPositive(YamlSection& s, const char* key, double* value) {
  s.Read(key, value);
  Require(std::isfinite(*value) && *value > 0.0, s, key, "must be a finite number > 0");
}

void ReadNonNegative(YamlSection& s, const char* key, double* value) {
  s.Read(key, value);
  Require(std::isfinite(*value) && *value >= 0.0, s, key, "must be a finite number >= 0");
}

}  // namespace

void ReadPlantOptions(YamlSection& section, PlantOptions* o) {
  ReadPositive(section, "step_s", &o->step_s);
  ReadPositive(section, "command_timeout_s", &o->command_timeout_s);
  {
    YamlSection s = section.Section("base");
    ReadNonNegative(s, "latency_s", &o->base.latency_s);
    ReadNonNegative(s, "v_tau_s", &o->base.v_tau_s);
    ReadNonNegative(s, "omega_tau_s", &o->base.omega_tau_s);
    s.Finish();
  }
  {
    YamlSection s = section.Section("joints");
    ReadNonNegative(s, "latency_s", &o->joints.latency_s);
    ReadNonNegative(s, "tau_s", &o->joints.tau_s);
    s.Finish();
  }
  {
    YamlSection s = section.Section("gripper");
    ReadNonNegative(s, "latency_s", &o->gripper.latency_s);
    ReadPositive(s, "open_time_s", &o->gripper.open_time_s);
    s.Finish();
  }
  {
    YamlSection s = section.Section("wheels");
    ReadPositive(s, "track_m", &o->wheels.track_m);
    ReadPositive(s, "radius_m", &o->wheels.radius_m);
    ReadNonNegative(s, "slip_stddev", &o->wheels.slip_stddev);
    ReadPositive(s, "slip_correlation_s", &o->wheels.slip_correlation_s);
    s.Finish();
  }
  {
    YamlSection s = section.Section("initial");
    s.Read("x_m", &o->initial.x_m);
    s.Read("y_m", &o->initial.y_m);
    s.Read("yaw_rad", &o->initial.yaw_rad);
    s.Read("q_rad", &o->initial.q_rad);
    s.Read("gripper", &o->initial.gripper);
    Require(std::isfinite(o->initial.x_m) && std::isfinite(o->initial.y_m) && std::isfinite(o->initial.yaw_rad), s,
            "x_m", "the initial pose must be finite");
    Require(o->initial.gripper >= 0.0 && o->initial.gripper <= 1.0, s, "gripper", "must be in [0, 1]");
    s.Finish();
  }
}

void CheckPlantOptions(const PlantOptions& options, const RobotModel& model, const std::string& source) {
  const std::vector<double>& q = options.initial.q_rad;
  if (q.empty()) return;
  const int n = model.num_joints();
  if (static_cast<int>(q.size()) != n) {
    throw ConfigError(source, "plant.initial.q_rad",
                      std::to_string(q.size()) + " values for a robot with " + std::to_string(n) + " joints");
  }
  for (int i = 0; i < n; ++i) {
    if (q[i] < model.joint_limits.q_min_rad[i] || q[i] > model.joint_limits.q_max_rad[i]) {
      throw ConfigError(source, "plant.initial.q_rad[" + std::to_string(i) + "]",
                        "outside the joint's position limits");
    }
  }
}

}  // namespace topay::sim
