#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

#include "procs/msgs/cloud_input.h"

namespace topay::mapper {

/// Which outlier filter runs last (on the downsampled cloud).
enum class OutlierMethod {
  kNone,         ///< No outlier removal.
  kRadius,       ///< pcl::RadiusOutlierRemoval: fewer than min_neighbors within radius_m.
  kStatistical,  ///< pcl::StatisticalOutlierRemoval: mean distance to mean_k neighbours.
};

/// "none", "radius" or "statistical".
const char* OutlierMethodName(OutlierMethod method);

/// The scan filter's stages (scan_filter.h), in the order they run. Every field is a YAML key
/// of the same name (LoadScanFilterOptions); defaults below.
struct ScanFilterOptions {
  /// Checks of the incoming message (YAML section `input`).
  msgs::CloudInputOptions input;
  /// Points nearer than this to the sensor (m, in S) are dropped: the Mid-360's blind zone.
  double range_min_m = 0.1;
  /// Points farther than this (m, in S) are dropped: 20 m reaches across the 20 x 20 m map
  /// from its centre; farther returns are noisier and lie mostly outside the map, and each
  /// costs the OctoMap mirror a ray of range / resolution voxels.
  double range_max_m = 20.0;
  /// Points with z_W below this (m) are the floor, not obstacles, and are dropped. 0.05 m is
  /// the map's bottom voxel layer (z 0 .. 0.05 at 0.05 m); the floor's points (2 cm range
  /// noise) lie within it. Obstacles lower than this are not mapped.
  double ground_max_z_m = 0.05;
  /// The robot's own body (base cylinder and arm spheres at the scan's state) is inflated by
  /// this much (m) before its points are removed. 0.12 m = 6 sigma of the Mid-360's 2 cm range
  /// noise: the noise moves a point along its ray, so a point on the body ends up at most
  /// |noise| from it; the collision spheres already cover the links' surfaces. 4 sigma (0.08 m,
  /// before) lets about 3 body points in 100,000 through: over a mission's ~600 scans some did
  /// (tests/procs/mapper/scan_filter_test.cc: 600 scans of the standing robot), each a voxel
  /// hugging the robot that no later ray clears, and in the fifth-sixth fault campaigns two such
  /// voxels 2 cm from the stowed shoulder kept every plan from rest from turning the base
  /// (docs/reliability.md, finding 29). Measured at 0.08 m on 12 scans: none escaped, 35 at
  /// 0.05 m, half of them at 0. It does not cover the arm's motion during a scan (~0.1 s; a
  /// real sensor's points are not all taken at the pose of the state given). Real obstacles
  /// within the margin of the body are removed too: they are in contact range, which the
  /// planner keeps out of anyway, and were seen from farther before.
  double self_margin_m = 0.12;
  /// Without a usable robot state (none near the scan's time, or a bad one) the body cannot be
  /// filtered: the points within this horizontal distance (m) of the sensor are dropped then,
  /// for they may be the robot's own arm, which would stay in the map for good (the arm hides
  /// the voxels behind it from every later ray; a plan from where the robot stands then fails
  /// on its own arm). 1.5 m covers the arm stretched out (0.3 m sensor offset + ~1 m reach +
  /// the margin). 0 keeps them.
  double no_state_radius_m = 1.5;
  /// Voxel-grid leaf (m): one point (the centroid) per occupied leaf. The map resolution,
  /// 0.05 m: finer points mark no more voxels. 0 turns the stage off.
  double voxel_leaf_m = 0.05;
  /// Outlier removal on the downsampled cloud. Default kNone, by measured cost vs benefit
  /// (tests/bench/scan_filter_bench.cc, Release, one core of a loaded 2-core machine, 64
  /// Tables-room scans of ~11,000 returns, ~5,200 points after the grid): the rest of the
  /// filter takes 0.5 ms (median) per scan, radius removal 30 ms more (p95 45 ms) and
  /// statistical removal 28 ms (p95 46 ms): 5x the mapper's whole 6 ms budget. And on the
  /// simulated sensor, whose only error is range noise, they remove only points of real surfaces
  /// (radius: 9 % of the points; statistical: 2.4 %). Turn one on for a real
  /// sensor that returns isolated spurious points (dust, mixed pixels at edges) if the time
  /// can be spent (e.g. on its own thread).
  OutlierMethod outlier_method = OutlierMethod::kNone;
  /// kRadius: a point with fewer than outlier_min_neighbors others within outlier_radius_m
  /// (m) is removed. 0.15 m = 3 leaves: a surface's downsampled points have ~8 neighbours.
  double outlier_radius_m = 0.15;
  int outlier_min_neighbors = 2;
  /// kStatistical: a point whose mean distance to its outlier_mean_k nearest neighbours
  /// exceeds the mean of that over the cloud by outlier_stddev_mul standard deviations.
  int outlier_mean_k = 8;
  double outlier_stddev_mul = 2.0;

  /// Where the options came from, for errors (file, dotted key prefix).
  std::string source = "(built-in defaults)";
  std::string key_prefix;
};

/// Reads ScanFilterOptions from a YAML map (every key optional; `input` a sub-map with
/// max_points and quaternion_norm_tolerance; outlier_method a name as OutlierMethodName) and
/// checks them. `source` names the file in errors, `key_prefix` the dotted path of the map in
/// it. Throws topay::ConfigError naming file and key for an unknown key, a wrong type, a
/// non-finite number or a value out of range (as CheckScanFilterOptions).
ScanFilterOptions LoadScanFilterOptions(const YAML::Node& node, const std::string& source,
                                        const std::string& key_prefix = "");

/// Throws ConfigError (naming options.source and the key) unless: 0 <= range_min_m <
/// range_max_m; ground_max_z_m finite; self_margin_m >= 0; voxel_leaf_m 0 or large enough that
/// a cube of side 2 range_max_m has fewer than 2^31 leaves (PCL's VoxelGrid indexes leaves
/// with 32-bit integers and skips the stage otherwise: >= 0.032 m at range_max_m = 20 m);
/// outlier radius > 0, min neighbours >= 1, mean_k >= 1, stddev_mul > 0;
/// input.max_points >= 1; input tolerance in (0, 1).
void CheckScanFilterOptions(const ScanFilterOptions& options);

}  // namespace topay::mapper
