#include "procs/sim/sensor_factory.h"

#include "procs/sim/lidar_adapter.h"
#include "procs/sim/monitor_adapter.h"
#include "sim/lidar/lidar_options.h"

namespace topay::simproc {

std::unique_ptr<ScanSensor> MakeLidar(const SimOptions& options, const Kinematics& kinematics, std::uint64_t seed) {
  if (!options.lidar_enabled) return nullptr;
  sim::LidarOptions lidar;
  if (!options.lidar_file.empty()) {
    lidar = sim::LoadLidarOptionsFile(options.lidar_file);
  } else if (options.lidar_options.IsDefined() && !options.lidar_options.IsNull()) {
    lidar = sim::LoadLidarOptions(options.lidar_options, options.source, "lidar.options");
  }
  return std::make_unique<LidarAdapter>(lidar, kinematics, seed);
}

std::unique_ptr<ContactSensor> MakeMonitor(const SimOptions& options, const Kinematics& kinematics) {
  if (!options.monitor_enabled) return nullptr;
  return std::make_unique<MonitorAdapter>(kinematics);
}

}  // namespace topay::simproc
