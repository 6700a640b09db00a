#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "procs/msgs/cloud_input.h"
#include "core/robot/robot_body_filter.h"
#include "procs/mapper/scan_filter_options.h"
#include "procs/mapper/scan_filter_summary.h"

namespace topay::mapper {

/// Turns one checked LiDAR cloud into the obstacle points the map integrates, in W.
/// Stages, cheapest first so the PCL stages see few points:
///  1. range: drops non-finite points and those with |p_SP| outside [range_min_m,
///     range_max_m]; the rest are moved to W (X_WS);
///  2. ground: drops z_W < ground_max_z_m (the floor);
///  3. self: drops the points in the robot's collision model at the given state, inflated by
///     self_margin_m (RobotBodyFilter); skipped, with a warning in the summary, without a
///     usable state;
///  4. voxel grid (pcl::VoxelGrid, leaf voxel_leaf_m; 0: off): one point, the centroid, per
///     occupied leaf;
///  5. outliers (pcl::RadiusOutlierRemoval or pcl::StatisticalOutlierRemoval; or none).
/// PCL's clouds and filters are kept between scans (allocation-light: after the largest scan,
/// only PCL's own per-call work buffers allocate). PCL appears in scan_filter.cc only.
/// The Kinematics (and its model) must outlive the filter. Not thread safe.
class ScanFilter {
 public:
  /// Throws ConfigError for options that fail CheckScanFilterOptions.
  ScanFilter(const ScanFilterOptions& options, const Kinematics& kinematics);
  ~ScanFilter();
  ScanFilter(const ScanFilter&) = delete;
  ScanFilter& operator=(const ScanFilter&) = delete;

  /// Filters `cloud`, taken with the robot at `state` (the scan's time), into *p_WP (cleared
  /// first; its capacity is reused). A missing state, or one that is not finite or has a
  /// joint count other than the model's, skips the self filter (summary warning).
  ScanFilterSummary Filter(const msgs::CheckedCloud& cloud, const std::optional<WholeBodyState>& state,
                           std::vector<Eigen::Vector3f>* p_WP);

  const ScanFilterOptions& options() const { return options_; }

 private:
  struct PclStages;  // PCL's clouds and filters (scan_filter.cc)

  void CropRange(const msgs::CheckedCloud& cloud, std::vector<Eigen::Vector3f>* p_WP,
                 ScanFilterSummary* summary) const;
  void RemoveGround(std::vector<Eigen::Vector3f>* p_WP) const;
  void RemoveSelf(const std::optional<WholeBodyState>& state, const Eigen::Vector3d& p_WS,
                  std::vector<Eigen::Vector3f>* p_WP, ScanFilterSummary* summary);

  ScanFilterOptions options_;
  const Kinematics& kinematics_;
  KinematicsCache cache_;
  RobotBodyFilter body_;
  std::unique_ptr<PclStages> pcl_;
};

}  // namespace topay::mapper
