#include "procs/sim/lidar_adapter.h"

namespace topay::simproc {

ScanResult LidarAdapter::Scan(const WholeBodyState& state, double t_s) {
  sim::LidarScan scan = scanner_.Scan(state, t_s);
  ScanResult r;
  r.t_s = scan.t_s;
  r.X_WS = scan.X_WS;
  r.p_SP = std::move(scan.p_SP);
  r.self_hits = scan.self_hits;
  r.rays = scan.rays;
  return r;
}

}  // namespace topay::simproc
