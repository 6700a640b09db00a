// The sensor factory of a build without sim/lidar and sim/monitor: no LiDAR, no monitor.
#include "procs/sim/sensor_factory.h"

namespace topay::simproc {

std::unique_ptr<ScanSensor> MakeLidar(const SimOptions&, const Kinematics&, std::uint64_t) { return nullptr; }
std::unique_ptr<ContactSensor> MakeMonitor(const SimOptions&, const Kinematics&) { return nullptr; }
bool SensorsAvailable() { return false; }

}  // namespace topay::simproc
