#include "procs/kinematic_sim/kinematic_model.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "core/robot/unicycle_motion.h"

namespace topay::kinsim {
namespace {

template <class T>
void Read(const YAML::Node& root, const char* key, const std::string& path, T* value) {
  if (!root[key]) return;
  try {
    *value = root[key].as<T>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error(path + ":" + std::to_string(root[key].Mark().line + 1) + ": " + key +
                             ": wrong type");
  }
}

}  // namespace

KinematicModelOptions LoadKinematicModelOptions(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  KinematicModelOptions o;
  if (root.IsNull()) return o;
  if (!root.IsMap()) throw std::runtime_error(path + ": expected a mapping");
  const std::set<std::string> known = {"x_m", "y_m", "yaw_rad", "q_rad", "joint_names", "max_step_s", "state_rate_hz"};
  for (const auto& entry : root) {
    // A list, a map or null as a key (`[k]: 1`) has no name: yaml-cpp's bad conversion otherwise.
    if (!entry.first.IsScalar()) {
      throw std::runtime_error(path + ":" + std::to_string(entry.first.Mark().line + 1) +
                               ": a key must be a name, not a list, a map or null");
    }
    const std::string key = entry.first.Scalar();
    if (!known.contains(key)) throw std::runtime_error(path + ": unknown key '" + key + "'");
  }
  Read(root, "x_m", path, &o.x_m);
  Read(root, "y_m", path, &o.y_m);
  Read(root, "yaw_rad", path, &o.yaw_rad);
  Read(root, "q_rad", path, &o.q_rad);
  Read(root, "joint_names", path, &o.joint_names);
  Read(root, "max_step_s", path, &o.max_step_s);
  Read(root, "state_rate_hz", path, &o.state_rate_hz);
  if (!o.joint_names.empty() && o.joint_names.size() != o.q_rad.size()) {
    throw std::runtime_error(path + ": joint_names: " + std::to_string(o.joint_names.size()) +
                             " names for " + std::to_string(o.q_rad.size()) + " joints (q_rad)");
  }
  if (!(o.max_step_s > 0.0)) throw std::runtime_error(path + ": max_step_s: must be > 0");
  if (!(o.state_rate_hz >= 0.0)) throw std::runtime_error(path + ": state_rate_hz: must be >= 0");
  return o;
}

KinematicModel::KinematicModel(const KinematicModelOptions& options) : max_step_s_(options.max_step_s) {
  state_.state.x_m = options.x_m;
  state_.state.y_m = options.y_m;
  state_.state.yaw_rad = options.yaw_rad;
  state_.state.q_rad = Eigen::Map<const Eigen::VectorXd>(options.q_rad.data(), options.q_rad.size());
  state_.qdot_radps = Eigen::VectorXd::Zero(state_.state.num_joints());
  state_.joint_names = options.joint_names;
  state_.gripper = 0.0;
}

bool KinematicModel::Apply(const control_command_t& cmd) {
  const int n = state_.state.num_joints();
  if (cmd.num_joints != n || static_cast<int>(cmd.qdot_radps.size()) != n) return false;
  // Finite is not enough: integrating a rate of 1e308 overflows the state to inf (found by
  // tests/fuzz/sim_inputs_fuzz.cc). No robot moves at kMaxRate.
  const auto plausible = [](double rate) { return std::isfinite(rate) && std::abs(rate) <= kMaxRate; };
  if (!plausible(cmd.v_mps) || !plausible(cmd.omega_radps) || !std::isfinite(cmd.gripper)) return false;
  for (const double qdot : cmd.qdot_radps) {
    if (!plausible(qdot)) return false;
  }
  if (last_utime_ >= 0 && cmd.utime > last_utime_) {
    const double dt = std::min(static_cast<double>(cmd.utime - last_utime_) * 1e-6, max_step_s_);
    // Exact unicycle motion under constant v, omega.
    AdvanceUnicycle(state_.v_mps, state_.omega_radps, dt, &state_.state);
    state_.state.q_rad += dt * state_.qdot_radps;
  }
  if (last_utime_ < 0 || cmd.utime > last_utime_) last_utime_ = cmd.utime;
  state_.utime = last_utime_;
  state_.v_mps = cmd.v_mps;
  state_.omega_radps = cmd.omega_radps;
  state_.qdot_radps = Eigen::Map<const Eigen::VectorXd>(cmd.qdot_radps.data(), n);
  state_.gripper = cmd.gripper;
  ++commands_;
  return true;
}

}  // namespace topay::kinsim
