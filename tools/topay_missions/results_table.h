#pragma once
// The results of topay-missions: one row per seed (the closed-loop mission in its room) and
// the table and JSON they are printed and saved as.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace topay::tools {

/// One seed's run of the closed-loop mission.
struct MissionRunRow {
  std::uint64_t seed = 0;
  std::string result = "not run";  ///< SUCCEEDED, FAILED, ABORTED, TIMEOUT, or why it did not run
  std::int64_t contact_events = -1; ///< the simulator's ground-truth contacts (-1: unknown)
  double mission_time_s = 0.0;      ///< the mission's elapsed time at its end, s
  int replans = 0;                  ///< the planner's replans, summed over the goals
  int boxes_appeared = 0;           ///< scripted boxes that appeared during the run
  double position_rms_m = 0.0;      ///< tracking: base position error RMS, m
  double yaw_rms_rad = 0.0;         ///< tracking: yaw error RMS, rad
  double joint_rms_rad = 0.0;       ///< tracking: largest joint error RMS, rad
  /// The estimator's base position error RMS (ROBOT_STATE vs the plant's truth), m; negative:
  /// not measured (a graph without CAN has no estimator).
  double estimation_rms_m = -1.0;
  std::string run_dir;              ///< the run folder (log, plots, process logs)
  std::string detail;               ///< the mission's last detail or the failure's reason

  /// The mission succeeded and the collision monitor saw no contact.
  bool Success() const { return result == "SUCCEEDED" && contact_events == 0; }
  /// The seed's room has no pick-and-place scenario (topay-scenario found none): no mission ran.
  bool NoScenario() const { return result == "NO SCENARIO"; }
};

/// A Markdown table (seed, success, result, collisions, time, replans, boxes, tracking RMS) and
/// a totals line: successes k of the N missions that ran, collisions summed, median mission
/// time of the successes, and the seeds without a scenario (not counted as missions).
std::string ResultsTable(const std::vector<MissionRunRow>& rows);

nlohmann::json ToJson(const MissionRunRow& row);

}  // namespace topay::tools
