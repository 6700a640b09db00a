#pragma once
// topay-tracker's options (config/tracker/tracker.yaml): the NMPC's (NmpcOptions, the `nmpc`
// section), how TRAJECTORY messages are rebuilt (`rebuild`) and the process's own (robot
// files, status). The limits come from the robot description, not from here.

#include <string>

#include "core/control/nmpc_options.h"
#include "core/control/protective_field.h"
#include "procs/msgs/trajectory_from_message.h"
#include "procs/tracker/planner_watch.h"

namespace topay::tracker {

struct TrackerOptions {
  std::string source;      ///< The file these came from ("" = defaults).
  std::string robot_urdf;  ///< "" = the shipped robot (config/robot/topay_mm.urdf).
  std::string robot_yaml;  ///< "" = config/robot/topay_mm.yaml.
  /// The NMPC (core/control/nmpc_options.h). Its control_period_s is the process's cycle
  /// (0.02 s: 50 Hz) and its stale_state_s the stale-state limit (0.1 s).
  NmpcOptions nmpc;
  /// TRAJECTORY -> core trajectory (Simpson panels 12, coefficient tolerance 1e-6, yaw0
  /// tolerance 1e-6 rad): the planner's settings.
  msgs::TrajectoryRebuildOptions rebuild;
  /// Below this base speed (m/s), yaw rate (rad/s) and every joint rate (rad/s) a stopped
  /// command counts as at rest (FINISHED rather than STOPPING after the end). > 0.
  double rest_command = 1e-3;
  /// Tracking lost: while tracking, a base position error (m, the measured state against the
  /// reference at its time) above this drops the trajectory; the robot is braked within the
  /// limits and the status is HELD until it is at rest (the planner, seeing HELD, plans anew
  /// from rest where it stopped). A robot far from its reference must not be driven straight
  /// at it through whatever is in between (fault campaign 2026-12-05, finding 19: after a
  /// simulator restart the NMPC chased a reference 0.5 m away into a box). Above the tracking
  /// error of normal driving (at most 0.23 m in the CAN-mode fault campaigns) and the planner's
  /// drift replan (0.3 m). 0: never. >= 0.
  double lost_position_m = 0.35;
  /// A jump of the robot state: a taken ROBOT_STATE farther from the one before than the robot's
  /// own limits allow in their interval (v_max dt, omega_max dt) by more than these (m, rad),
  /// while a trajectory may move the robot, drops it and brakes the same way. The continuity
  /// gate takes small jumps within its slack, and the NMPC then turned the base back onto a
  /// reference 0.17 m and 0.35 rad away, through a box (finding 22: an estimator re-initialised
  /// after a simulator restart). Normal driving in the fifth fault campaign stayed under
  /// 1 mm and 0.001 rad of excess; a restart's jump was 0.13-0.19 m. 0: never. >= 0.
  double jump_position_m = 0.05;
  double jump_yaw_rad = 0.1;
  /// The planner's HEARTBEAT (PlannerWatch): its restart, or its silence for silence_s (3 s),
  /// drops the trajectories it published and brakes the robot the same way (finding 24).
  PlannerWatchOptions planner_watch;
  /// The protective field (core/control/protective_field.h; finding 30): POINT_CLOUD scans
  /// checked every tracking cycle along the base's path ahead, braking for an obstacle the
  /// planner's map lacks. On by default; needs the robot model (TrackerNode's model constructor).
  ProtectiveFieldOptions protective_field;
};

/// Loads options from YAML (every key optional; relative robot paths from the file's folder).
/// Throws ConfigError naming the file and the dotted field for an unreadable file, an unknown
/// (e.g. misspelt) key or a value out of range (NmpcOptions::Check's message).
TrackerOptions LoadTrackerOptions(const std::string& path);

/// The cycle rate (Hz) of `options`: 1 / nmpc.control_period_s.
double CycleRateHz(const TrackerOptions& options);

}  // namespace topay::tracker
