#include "run_report.h"

#include <filesystem>
#include <stdexcept>

#include "tools/report/report_tool.h"
#include "tools/report/summary_format.h"

namespace topay::tools {

void ReportRun(MissionRunRow* row, std::ostream& out) {
  report::ReportOptions options;
  options.log_path = row->run_dir + "/graph.lcmlog";
  if (std::filesystem::exists(row->run_dir + "/room.json")) options.scene_path = row->run_dir + "/room.json";
  options.out_dir = row->run_dir;
  report::RunSummary s;
  try {
    s = report::WriteReport(options);
  } catch (const std::exception& e) {
    if (row->result == "not run") row->result = "NO LOG";
    row->detail = e.what();
    out << "report: " << e.what() << "\n";
    return;
  }
  out << report::FormatSummary(s) << std::flush;
  if (row->result != "TIMEOUT") {
    row->result = s.mission.result == report::MissionResult::kNone ? "NOT FINISHED"
                                                                    : report::ToString(s.mission.result);
  }
  if (row->detail.empty()) row->detail = s.mission.detail;
  row->contact_events = s.collisions.has_sim_status ? s.collisions.contact_events : -1;
  row->mission_time_s = s.mission.elapsed_s;
  row->replans = static_cast<int>(s.planner.replans);
  row->boxes_appeared = static_cast<int>(s.appeared_boxes.size());
  row->position_rms_m = s.tracking.position_m.rms;
  row->estimation_rms_m = s.estimation.pairs > 0 ? s.estimation.position_m.rms : -1.0;
  row->yaw_rms_rad = s.tracking.yaw_rad.rms;
  row->joint_rms_rad = s.tracking.joint_rad.rms;
}

}  // namespace topay::tools
