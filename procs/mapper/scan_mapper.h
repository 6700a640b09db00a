#pragma once
// One scan into the map: the scan filter (PCL), then the dense occupancy map's insertion.
// The mapper process and topay-bench's sensed maps run this same pipeline.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/map/occupancy_map.h"
#include "core/map/voxel_state.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "procs/msgs/cloud_input.h"
#include "procs/mapper/scan_filter.h"

namespace topay::mapper {

/// What ScanMapper::Integrate did.
struct ScanMapperSummary {
  ScanFilterSummary filter;
  ScanInsertSummary insert;
  double total_ms = 0.0;
  /// Three or four lines: the filter's report and the insertion's counts and times.
  std::string Report() const;
};

/// The scan filter and the occupancy map, with their scratch. The Kinematics must outlive it.
class ScanMapper {
 public:
  /// Throws ConfigError (filter options) or std::invalid_argument (map options).
  ScanMapper(const ScanFilterOptions& filter, const OccupancyMapOptions& map,
             const Kinematics& kinematics);

  /// Filters `cloud` (the robot at `state` at the scan's time; none: no self filter) and
  /// integrates the points into the map from the sensor's origin. Appends every voxel whose
  /// state changed to *changes (may be null).
  ScanMapperSummary Integrate(const msgs::CheckedCloud& cloud, const std::optional<WholeBodyState>& state,
                              std::vector<VoxelChange>* changes);

  /// The last scan's filtered points in W (what went into the map).
  std::span<const Eigen::Vector3f> last_points() const { return points_W_; }
  const OccupancyMap& map() const { return map_; }
  OccupancyMap& mutable_map() { return map_; }

 private:
  ScanFilter filter_;
  OccupancyMap map_;
  std::vector<Eigen::Vector3f> points_W_;
};

}  // namespace topay::mapper
