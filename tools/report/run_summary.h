#pragma once
// topay::report: the end-of-run summary of a closed-loop run, from its LCM log alone
// (`<run>/graph.lcmlog`): the mission's result and step times, the planner's replans and
// planning times, the ground-truth collisions, the tracking errors and solve times, the distance
// driven, the boxes that appeared, and the messages per channel. topay-report prints and writes
// it (docs/report.md); other tools (a multi-seed runner) call Summarize for their results table.
//
//   const report::RunSummary s = report::Summarize("out/runs/<t>/graph.lcmlog");
//   row << s.succeeded() << s.collisions.contact_events << s.mission.elapsed_s
//       << s.planner.replans << s.tracking.position_m.rms;

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "tools/report/estimation_summary.h"
#include "tools/report/mission_summary.h"
#include "tools/report/planner_summary.h"
#include "tools/report/run_log.h"
#include "tools/report/tracking_summary.h"

namespace topay::report {

/// Ground-truth collisions (topay-sim's monitor): the last SIM_STATUS's counts since the start.
struct CollisionSummary {
  bool has_sim_status = false;      ///< false: no SIM_STATUS in the log (counts 0)
  std::int64_t contact_events = 0;  ///< contacts started
  std::int64_t contact_steps = 0;   ///< plant steps in contact
  double max_depth_m = 0.0;         ///< deepest penetration, m
  std::int64_t contact_messages = 0;  ///< SIM_CONTACT messages in the log
};

/// A box a SIM_EVENT APPEAR sent at run time (scripted events of `--events` files are applied
/// inside topay-sim and are not on the bus).
struct AppearedBox {
  std::int32_t box_id = 0;
  std::string name;
  bool has_box = false;  ///< false: an existing box made present again (no geometry)
  Eigen::Vector3d center_W_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
  double yaw_rad = 0.0;
};

/// Where topay-report wrote its files (empty when not written).
struct ReportFiles {
  std::string summary_json;
  std::string path_png;
  std::string time_plots_png;
};

struct RunSummary {
  std::string log_path;
  double log_span_s = 0.0;  ///< last - first event timestamp, s
  MissionSummary mission;
  PlannerSummary planner;
  std::int64_t trajectory_messages = 0;  ///< TRAJECTORY messages that decoded
  std::int64_t trajectories_rebuilt = 0; ///< ... and rebuilt into evaluable trajectories
  CollisionSummary collisions;
  TrackingSummary tracking;
  EstimationSummary estimation;  ///< ROBOT_STATE vs SIM_PLANT_STATE (CAN graphs; 0 pairs otherwise)
  double distance_driven_m = 0.0;  ///< sum of |p_WB(k) - p_WB(k-1)| over ROBOT_STATE
  std::vector<AppearedBox> appeared_boxes;
  std::map<std::string, ChannelCount> channels;
  std::int64_t decode_failures = 0;  ///< over every channel
  ReportFiles files;

  /// The mission SUCCEEDED (its last MISSION_STATUS).
  bool succeeded() const { return mission.result == MissionResult::kSucceeded; }
};

/// The summary of a read log (files left empty).
RunSummary Summarize(const RunLog& log);

/// Reads the log (ReadRunLog: throws std::runtime_error "<path>: <what>") and summarises it.
RunSummary Summarize(const std::string& log_path);

}  // namespace topay::report
