#pragma once
// Options of the robot plant (sim/plant/plant.h), with their defaults; the YAML section
// `plant:` of config/sim/sim.yaml holds the same keys (documented there and in
// docs/simulator.md). Limits are not here: they are the robot model's (BaseLimits, JointLimits).

#include <cstdint>
#include <string>
#include <vector>

#include "core/robot/robot_model.h"

namespace topay {
class YamlSection;
}

namespace topay::sim {

struct PlantOptions {
  double step_s = 0.002;            ///< plant step, s (500 Hz)
  double command_timeout_s = 0.2;   ///< no command reached the drives for this long: they brake
  struct Base {
    double latency_s = 0.02;        ///< command latency to the wheel drives, s
    double v_tau_s = 0.1;           ///< first-order lag of the forward speed, s (0: none)
    double omega_tau_s = 0.1;       ///< first-order lag of the yaw rate, s (0: none)
  } base;
  struct Joints {
    double latency_s = 0.02;        ///< command latency to the joint drives, s
    double tau_s = 0.05;            ///< first-order lag of every joint rate, s (0: none)
  } joints;
  struct Gripper {
    double latency_s = 0.02;        ///< command latency to the gripper, s
    double open_time_s = 1.0;       ///< full stroke (open <-> closed) time, s
  } gripper;
  struct Wheels {
    double track_m = 0.5;           ///< distance between the wheels' contact points, m (measured wheel rates)
    double radius_m = 0.1;          ///< wheel radius, m (measured wheel rates)
    double slip_stddev = 0.0;       ///< wheel slip: relative error of the true base motion, std dev (0: none)
    double slip_correlation_s = 0.5;  ///< correlation time of the slip (first-order Gauss-Markov), s
  } wheels;
  struct Initial {
    double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;  ///< X_WB at the start
    std::vector<double> q_rad;      ///< joints at the start (empty: the robot's stow pose, else 0 clamped to the limits)
    double gripper = 0.0;           ///< gripper at the start, 0 open .. 1 closed
  } initial;
};

/// Reads the keys of `section` (every key optional, unknown keys rejected by the caller's
/// Finish) into *options. Throws ConfigError naming the file and key for a wrong type or a
/// value out of range (negative latency or lag, non-positive step, timeout, stroke time,
/// track or radius, negative slip).
void ReadPlantOptions(YamlSection& section, PlantOptions* options);

/// Checks the options against the robot (initial.q_rad has one entry per joint, within the
/// position limits). Throws ConfigError(source, "plant.initial.q_rad", ...).
void CheckPlantOptions(const PlantOptions& options, const RobotModel& model, const std::string& source);

}  // namespace topay::sim
