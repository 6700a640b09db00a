#include "tools/report/tracking_summary.h"

namespace topay::report {

TrackingSummary SummarizeTracking(const std::vector<tracker_status_t>& statuses) {
  std::vector<double> position, yaw, joint, solve;
  for (const tracker_status_t& s : statuses) {
    if (s.state != tracker_status_t::TRACKING) continue;
    position.push_back(s.position_error_m);
    yaw.push_back(s.yaw_error_rad);
    joint.push_back(s.joint_error_rad);
    solve.push_back(s.solve_ms);
  }
  return {SummarizeErrors(position), SummarizeErrors(yaw), SummarizeErrors(joint), SummarizeTimings(solve)};
}

}  // namespace topay::report
