#pragma once
// Builds the LiDAR and the collision monitor of the simulator from its options (adapters over
// sim/lidar/ and sim/monitor/). Returns null when the option disables the sensor.

#include <cstdint>
#include <memory>

#include "core/robot/kinematics.h"
#include "procs/sim/sim_options.h"
#include "procs/sim/sim_sensors.h"

namespace topay::simproc {

/// Throws ConfigError for malformed LiDAR options (file or inline section).
std::unique_ptr<ScanSensor> MakeLidar(const SimOptions& options, const Kinematics& kinematics, std::uint64_t seed);
std::unique_ptr<ContactSensor> MakeMonitor(const SimOptions& options, const Kinematics& kinematics);

}  // namespace topay::simproc
