#pragma once
// The simulator core's ScanSensor over sim/lidar's LidarScanner.

#include <cstdint>

#include "core/robot/kinematics.h"
#include "procs/sim/sim_sensors.h"
#include "sim/lidar/lidar_scanner.h"

namespace topay::simproc {

class LidarAdapter : public ScanSensor {
 public:
  LidarAdapter(const sim::LidarOptions& options, const Kinematics& kinematics, std::uint64_t seed)
      : scanner_(options, kinematics, seed) {}
  void SetWorld(const std::vector<OrientedBox>& boxes) override { scanner_.SetWorld(boxes); }
  ScanResult Scan(const WholeBodyState& state, double t_s) override;
  double rate_hz() const override { return scanner_.options().scan_rate_hz; }

 private:
  sim::LidarScanner scanner_;
};

}  // namespace topay::simproc
