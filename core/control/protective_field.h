#pragma once
// The protective field: a stop below the planner that needs no map (finding 30,
// docs/tracker.md). The planner cannot avoid an obstacle its map does not show (a map that
// stopped updating, an object that appeared between two map updates); the tracker can still
// see it in the LiDAR's latest scan. Each scan's points that could touch the base are kept (in
// W, the robot's own body already removed); every control cycle the base cylinder is moved
// along the path the robot is about to drive, as far as it needs to stop plus a look-ahead, and
// if enough kept points lie inside it the tracker brakes.
//
// The field is the base's only: the arm is the planner's (its map, its replans). It sees what
// the LiDAR sees: near the robot nothing below the sensor's lowest ray (docs/tracker.md).

#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/control/nmpc_tracker.h"
#include "core/robot/robot_model.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// Ceres style: documented defaults; Check() throws std::invalid_argument naming the first bad
/// field. config/tracker/tracker.yaml (`protective_field:`) restates them.
struct ProtectiveFieldOptions {
  /// false: no field (the tracker ignores POINT_CLOUD).
  bool enabled = true;
  /// From an obstacle entering the LiDAR's view to the brakes acting (s): up to a scan period
  /// (0.1 s) until the scan that shows it is complete, its delivery, a control cycle (0.02 s)
  /// and the command latency (0.02 s), with margin. >= 0.
  double reaction_s = 0.25;
  /// Added along the path beyond the stopping distance (m): the room the stop leaves ahead.
  /// >= 0.
  double lookahead_m = 0.10;
  /// Added to the base cylinder's radius in the field (m). Negative: a point must lie this far
  /// inside the outline to count. The planner may pass obstacles at zero clearance and the
  /// LiDAR's range noise (sigma 0.02 m) puts points of a surface just outside the outline
  /// inside it; -0.05 m ignores a graze and still sees an obstacle on the path. In
  /// (-radius, 0.5].
  double radial_margin_m = -0.05;
  /// Points count between these heights (m): above the floor's returns, below the undersides
  /// of table tops, which the base drives under (0.45-0.55 m in the scenario rooms; with 0.45
  /// the range noise put points of a table top's underside into the field and the robot,
  /// parked under it, stopped for it again and again). The LiDAR (0.22 m up, lowest ray -7
  /// deg) sees this band from 0.1 m on. z_min < z_max.
  double z_min_m = 0.05;
  double z_max_m = 0.35;
  /// The field is entered when at least this many kept points lie inside it (a stray return
  /// does not stop the robot). >= 1.
  int min_points = 5;
  /// A scan older than this (s), or dated this far in the future, is not used: no field (the
  /// planner's stale-map stop and the stale-state stop remain). > 0.
  double max_scan_age_s = 0.35;
  /// Path sampling step (m): consecutive base positions at most this far apart. > 0.
  double step_m = 0.02;
  /// The robot's own body, at its state at the scan's time and inflated by this (m), is removed
  /// from the scan before the points are kept (procs/tracker). The mapper's 0.12 m: 6 sigma of
  /// the range noise (with 0.05 m a few of a scan's ~1,200 self hits stayed, just ahead of the
  /// chassis, where they looked like an obstacle at the bumper). Obstacles nearer the body than
  /// this are not seen by the field. >= 0.
  double self_margin_m = 0.12;

  void Check() const;
};

/// What one check found.
struct ProtectiveFieldCheck {
  bool scan_fresh = false;      ///< A scan younger than max_scan_age_s is held.
  int num_inside = 0;           ///< Kept points inside the field.
  bool entered = false;         ///< num_inside >= min_points.
  double path_length_m = 0.0;   ///< The field's length along the path (m).
  double distance_ahead_m = 0.0;  ///< Arc length to the first pose containing a point (m).
  Eigen::Vector3f p_W_first = Eigen::Vector3f::Zero();  ///< A point inside that pose.
};

/// Holds the latest scan's points and checks paths against them. Allocation-free once the
/// largest scan has been kept. Not thread safe.
class ProtectiveField {
 public:
  /// Throws std::invalid_argument for bad options or a base radius <= -radial_margin_m.
  ProtectiveField(const ProtectiveFieldOptions& options, const BaseCylinder& base,
                  const BaseLimits& limits);

  /// How far the field reaches along the path at base speed |speed_mps| (m):
  /// |v| reaction_s + v^2 / (2 a_max) + lookahead_m (reaction, braking at the limit, room).
  double LengthM(double speed_mps) const;

  /// How far the base axis can be from a point that any field of the robot reaches (m): the
  /// field's length at v_max, the motion until the next scans (max_scan_age_s at v_max) and the
  /// cylinder's radius.
  double ReachM() const;

  /// Keeps the obstacle points p_WP (W, the robot's own body removed) of the scan taken at
  /// scan_time_s that lie in the height band and within ReachM() of the base axis at p_WB.
  void SetScan(std::span<const Eigen::Vector3f> p_WP, double scan_time_s, const Eigen::Vector2d& p_WB);
  /// Forgets the scan (no field until the next).
  void ClearScan();

  /// Checks the base path at now_s: path_W holds positions of the base axis in W, the first
  /// where the robot is about to be, each at most step_m from the one before. A stale (or
  /// missing) scan checks nothing (scan_fresh false).
  ProtectiveFieldCheck Check(std::span<const Eigen::Vector2d> path_W, double now_s) const;

  int num_kept() const { return static_cast<int>(p_W_.size()); }
  const ProtectiveFieldOptions& options() const { return options_; }

 private:
  ProtectiveFieldOptions options_;
  double field_radius_m_;  // base radius + radial margin
  BaseLimits limits_;
  std::vector<Eigen::Vector3f> p_W_;  // kept points
  double scan_time_s_ = 0.0;
  bool has_scan_ = false;
};

/// The base path ahead on `reference` (its sampler; times on the tracker's clock): base
/// positions from now_s on, step_s apart, until they have covered length_m or the trajectory
/// ends (at its end: the robot stops there) or max_horizon_s has passed. *path cleared first;
/// *sample is scratch (allocation-free once sized by a first call). With step_s = step_m /
/// v_max consecutive positions are at most step_m apart.
void BasePathAhead(const TrackerReference& reference, double now_s, double length_m, double step_s,
                   double max_horizon_s, std::vector<Eigen::Vector2d>* path, TrajectorySample* sample);

}  // namespace topay
