#pragma once
// Everything topay-sim builds from its options before it runs: the robot (URDF + YAML), the
// scene (file or generator, the start kept clear), the scripted events, the LiDAR and the
// monitor, the core. Every file error is a ConfigError naming the file and key.

#include <memory>
#include <string>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "procs/sim/sim_core.h"
#include "procs/sim/sim_options.h"

namespace topay::simproc {

struct SimAssembly {
  std::unique_ptr<RobotModel> model;
  std::unique_ptr<Kinematics> kinematics;
  std::unique_ptr<SimCore> core;   // declared last: destroyed first (its sensors use kinematics)
  std::string scene_description;  ///< "tables seed 1, 164 boxes"
  int num_scripted_events = 0;
  std::string resumed_from;  ///< "" or the checkpoint the plant starts from ("<file> (x, y, yaw)")
};

/// Builds the simulator. options.robot_urdf / robot_yaml must be set. With a checkpoint file
/// that exists, the plant starts from it (the scene's keep-out stays at the configured start).
/// Throws ConfigError.
SimAssembly AssembleSim(const SimOptions& options);

}  // namespace topay::simproc
