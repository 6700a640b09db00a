#pragma once
// The options of topay-sim, from config/sim/sim.yaml (every key documented there and in
// docs/simulator.md). Command-line flags override some of them (sim_flags in main.cc).

#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

#include "procs/sim/trajectory_follower.h"
#include "sim/localization/pose_sensor.h"
#include "sim/plant/plant_options.h"

namespace topay::simproc {

struct SimOptions {
  std::string source = "(built-in defaults)";  ///< the config file, for errors
  std::uint64_t seed = 1;          ///< master seed: plant slip, pose noise, LiDAR, event jitter
  std::int64_t start_utime = 0;    ///< utime of sim time 0, us since the Unix epoch (0: wall clock at start)
  double rate = 1.0;               ///< real-time factor of the pacing (0: as fast as possible)
  int max_catch_up_steps = 500;    ///< most plant steps run at one wake-up when late (then it lags): 1 s, so a
                                   ///< process stalled by a loaded machine catches up (the planner and the
                                   ///< follower share the clock) instead of lagging for good
  std::string robot_urdf;          ///< robot URDF (empty: the shipped TopAY robot, config/robot/)
  std::string robot_yaml;          ///< robot YAML (empty: the shipped one)
  std::string scene = "tables";    ///< "tables", "cuboids" (generated) or a scene JSON file
  std::uint64_t scene_seed = 1;    ///< seed of a generated scene
  double keep_out_radius_m = 1.2;  ///< generated scenes: no obstacle within this radius of the start
  std::string events_file;         ///< scripted events (empty: none)
  sim::PlantOptions plant;
  double state_rate_hz = 100.0;    ///< ROBOT_STATE and BASE_POSE, Hz (sim time)
  sim::PoseNoiseOptions pose_noise;
  bool lidar_enabled = true;
  std::string lidar_file;          ///< LiDAR options file, config/sim/lidar.yaml's format (its scan_rate_hz is
                                   ///< the POINT_CLOUD rate); empty: lidar_options or the defaults
  YAML::Node lidar_options;        ///< inline LiDAR options (the `lidar.options` map)
  bool monitor_enabled = true;     ///< the ground-truth collision monitor
  double status_rate_hz = 10.0;    ///< SIM_STATUS, Hz (wall time)
  /// The ideal follower (--follow): the plant follows TRAJECTORY exactly instead of integrating
  /// CONTROL_COMMAND (ignored, counted).
  bool follow = false;
  TrajectoryFollowerOptions follower;  ///< the `follower` section
  /// What drives the plant: "control_command" (default: CONTROL_COMMAND, ROBOT_STATE out) or
  /// "actuators" (the CAN mode: ACTUATOR_COMMAND from topay-motorsim and GRIPPER_COMMAND in;
  /// SIM_PLANT_STATE and GRIPPER_STATE out, no ROBOT_STATE; docs/simulator.md "CAN mode").
  std::string plant_input = "control_command";
  /// The plant's checkpoint (--checkpoint, not in YAML; procs/sim/plant_checkpoint.h): read at
  /// start if it exists (the robot starts where it was), written every status period. "" = none.
  std::string checkpoint_file;
  double plant_state_rate_hz = 250.0;  ///< CAN mode: SIM_PLANT_STATE and GRIPPER_STATE, Hz (sim time; every
                                       ///< round(1 / (rate * step)) plant steps: 250 Hz = every 2nd 2 ms step)
};

/// Loads the YAML at `path` (relative paths inside resolved against its folder). Throws
/// ConfigError naming the file and key.
SimOptions LoadSimOptions(const std::string& path);

}  // namespace topay::simproc
