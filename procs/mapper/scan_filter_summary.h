#pragma once

#include <string>

namespace topay::mapper {

/// What one ScanFilter::Filter did: the points left after each stage (in the order the
/// stages run) and each stage's wall-clock time (steady clock, ms).
struct ScanFilterSummary {
  int num_input = 0;         ///< Points in the cloud.
  int num_non_finite = 0;    ///< Dropped for a NaN or infinite coordinate.
  int num_after_range = 0;   ///< Finite, with range in [range_min_m, range_max_m].
  int num_after_ground = 0;  ///< ... and z_W >= ground_max_z_m.
  int num_after_self = 0;    ///< ... and outside the inflated robot body.
  int num_after_voxel = 0;   ///< ... one per voxel-grid leaf.
  int num_output = 0;        ///< ... after outlier removal: the filter's output.
  /// True if the robot's own points were not removed (no robot state, or one that is not
  /// finite or has the wrong joint count); `warning` then says why.
  bool self_filter_skipped = false;
  std::string warning;

  double range_ms = 0.0;    ///< Finite and range checks, transform to W.
  double ground_ms = 0.0;
  double self_ms = 0.0;     ///< Kinematics at the state and the body test.
  double voxel_ms = 0.0;    ///< Copies in and out of PCL included.
  double outlier_ms = 0.0;  ///< Copies in and out of PCL included.
  double total_ms = 0.0;

  /// Two lines, e.g.
  /// "scan filter: 20000 in, 0 non-finite, 19500 in range, 15000 above ground, 14500 not the
  ///  robot, 6000 after voxel grid, 6000 out\n  times ms: range 0.10 ground ..., total 3.20"
  /// plus a third, "  warning: ...", if there is a warning.
  std::string Report() const;
};

}  // namespace topay::mapper
