#pragma once
// topay-mission's own options (config/mission/mission.yaml, --config): retries, timeouts,
// arrival tolerances, the gripper's settle time, the status rate. The mission itself (its
// steps) is a separate file (--mission, mission_spec.h).

#include <string>

#include "procs/mission/mission_spec.h"

namespace topay::mission {

struct MissionOptions {
  std::string source;      ///< The file these came from ("" = defaults).
  std::string robot_urdf;  ///< "" = the shipped robot (config/robot/topay_mm.urdf).
  std::string robot_yaml;  ///< "" = config/robot/topay_mm.yaml.
  /// Plans tried per goto / home step: a FAILED plan is sent again with a new goal id until
  /// this many were tried, then the mission fails. >= 1.
  int max_attempts = 3;
  /// A goal the planner reports CANCELLED (another sender's goal superseded it: an operator, a
  /// forged or corrupted copy) is sent again with a new goal id after retry_delay_s without
  /// using up an attempt, up to this many times per step; one more fails the mission ("goal
  /// superseded N times"). >= 0.
  int max_preemptions = 10;
  /// A failed plan is sent again after this long (s): the map grows meanwhile. >= 0.
  double retry_delay_s = 0.5;
  /// A goto / home step that has not arrived after this long (s) fails the mission (a step's
  /// own timeout_s replaces it). > 0.
  double step_timeout_s = 120.0;
  /// Arrival tolerance of goto / home steps without their own (default 3 cm, 0.1 rad).
  ArrivalTolerance tolerance;
  /// The planner reported the goal reached (and the tracker FINISHED) but the end effector is
  /// outside the tolerance for this long (s): the attempt failed ("ended ... from the target")
  /// and the goal is sent again (a plan from where the robot stands corrects what the tracker
  /// left, e.g. a lateral offset after a corner), up to max_attempts. > 0.
  double arrival_settle_s = 1.0;
  /// A gripper step waits this long (s) after its command unless it sets settle_s. >= 0.
  double gripper_settle_s = 1.0;
  /// The goal in hand is published again, the same message (id and content), this often (s)
  /// while its step waits: a planner restarted meanwhile (kill -9: it lost the goal) or a GOAL
  /// lost on the bus gets it; the planner ignores repeats of the goal it has. 0: never. >= 0.
  double goal_repeat_period_s = 1.0;
  /// MISSION_STATUS goes out on every change and at least this often (s): 2 Hz. > 0.
  double status_period_s = 0.5;
  /// The mission starts once a ROBOT_STATE (its start pose) and, with wait_for_planner, a
  /// PLANNER_STATUS (the planner is up) have come; it fails if they do not come within
  /// start_timeout_s (s, > 0).
  bool wait_for_planner = true;
  double start_timeout_s = 30.0;
};

/// Loads options from YAML (every key optional, robot paths relative to the file's folder).
/// Throws ConfigError naming the file and the field for an unreadable file, an unknown key or
/// a value out of range.
MissionOptions LoadMissionOptions(const std::string& path);

/// Throws ConfigError (source `source`) for the first value out of range.
void CheckMissionOptions(const MissionOptions& options, const std::string& source);

}  // namespace topay::mission
