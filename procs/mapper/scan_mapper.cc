#include "procs/mapper/scan_mapper.h"

#include <chrono>
#include <cstdio>

namespace topay::mapper {

std::string ScanMapperSummary::Report() const {
  char line[256];
  std::snprintf(line, sizeof(line),
                "\nmap insertion: %d points, %d voxels hit, %d missed, %lld ray steps, %d changes; "
                "times ms: hits %.2f rays %.2f, total %.2f; scan total %.2f",
                insert.num_points_used, insert.num_voxels_hit, insert.num_voxels_missed,
                static_cast<long long>(insert.num_ray_steps), insert.num_changes, insert.hits_s * 1e3,
                insert.rays_s * 1e3, insert.total_s * 1e3, total_ms);
  return filter.Report() + line;
}

ScanMapper::ScanMapper(const ScanFilterOptions& filter, const OccupancyMapOptions& map,
                       const Kinematics& kinematics)
    : filter_(filter, kinematics), map_(map) {}

ScanMapperSummary ScanMapper::Integrate(const msgs::CheckedCloud& cloud,
                                        const std::optional<WholeBodyState>& state,
                                        std::vector<VoxelChange>* changes) {
  const auto start = std::chrono::steady_clock::now();
  ScanMapperSummary summary;
  summary.filter = filter_.Filter(cloud, state, &points_W_);
  summary.insert = map_.InsertScan(cloud.X_WS.translation(), points_W_, changes);
  summary.total_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace topay::mapper
