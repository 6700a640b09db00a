#include "tools/report/estimation_summary.h"

#include <algorithm>
#include <cmath>

namespace topay::report {
namespace {

double WrappedAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

// The true state at `utime` by linear interpolation of `a` and `b` (a.utime <= utime <= b.utime);
// yaw interpolated along the shorter way.
WholeBodyState Interpolate(const msgs::RobotStateEstimate& a, const msgs::RobotStateEstimate& b,
                           std::int64_t utime) {
  const double span = static_cast<double>(b.utime - a.utime);
  const double s = span > 0.0 ? static_cast<double>(utime - a.utime) / span : 0.0;
  WholeBodyState state = a.state;
  state.x_m += s * (b.state.x_m - a.state.x_m);
  state.y_m += s * (b.state.y_m - a.state.y_m);
  state.yaw_rad += s * WrappedAngle(b.state.yaw_rad - a.state.yaw_rad);
  if (a.state.q_rad.size() == b.state.q_rad.size()) state.q_rad += s * (b.state.q_rad - a.state.q_rad);
  return state;
}

}  // namespace

EstimationSummary SummarizeEstimation(const std::vector<msgs::RobotStateEstimate>& estimates,
                                      const std::vector<msgs::RobotStateEstimate>& truths,
                                      double max_gap_s) {
  EstimationSummary summary;
  std::vector<double> position, yaw, joint;
  const auto gap_us = static_cast<std::int64_t>(max_gap_s * 1e6);
  for (const msgs::RobotStateEstimate& estimate : estimates) {
    const auto after = std::lower_bound(truths.begin(), truths.end(), estimate.utime,
                                        [](const msgs::RobotStateEstimate& t, std::int64_t u) { return t.utime < u; });
    if (after == truths.end() || (after == truths.begin() && after->utime != estimate.utime)) continue;
    const auto before = after->utime == estimate.utime ? after : std::prev(after);
    if (estimate.utime - before->utime > gap_us || after->utime - estimate.utime > gap_us) continue;
    const WholeBodyState truth = Interpolate(*before, *after, estimate.utime);
    position.push_back(std::hypot(estimate.state.x_m - truth.x_m, estimate.state.y_m - truth.y_m));
    yaw.push_back(std::abs(WrappedAngle(estimate.state.yaw_rad - truth.yaw_rad)));
    if (estimate.state.q_rad.size() == truth.q_rad.size() && truth.q_rad.size() > 0) {
      joint.push_back((estimate.state.q_rad - truth.q_rad).cwiseAbs().maxCoeff());
    }
  }
  summary.pairs = static_cast<std::int64_t>(position.size());
  summary.position_m = SummarizeErrors(position);
  summary.yaw_rad = SummarizeErrors(yaw);
  summary.joint_rad = SummarizeErrors(joint);
  return summary;
}

}  // namespace topay::report
