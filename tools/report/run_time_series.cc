#include "tools/report/run_time_series.h"

#include <algorithm>
#include <limits>

#include "tools/report/active_trajectory.h"

namespace topay::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double SecondsSince(std::int64_t t0_utime, std::int64_t utime) {
  return static_cast<double>(utime - t0_utime) * 1e-6;
}

void AddMeasured(const msgs::RobotStateEstimate& state, RunTimeSeries* series) {
  series->v_measured_mps.push_back(state.v_mps);
  series->omega_measured_radps.push_back(state.omega_radps);
  for (std::size_t j = 0; j < series->q_measured_rad.size(); ++j) {
    const bool has = static_cast<Eigen::Index>(j) < state.state.q_rad.size();
    series->q_measured_rad[j].push_back(has ? state.state.q_rad(static_cast<Eigen::Index>(j)) : kNaN);
  }
}

void AddPlanned(const LoggedTrajectory* active, std::int64_t utime, TrajectorySample* point,
                RunTimeSeries* series) {
  if (active != nullptr) {
    const ArcYawTrajectory& trajectory = active->trajectory;
    const double t_s = std::clamp(SecondsSince(active->poly.start_utime, utime), 0.0, trajectory.duration_s());
    if (point->state.q_rad.size() != trajectory.num_joints()) *point = trajectory.MakePoint();
    trajectory.Evaluate(t_s, point);
  }
  series->v_planned_mps.push_back(active ? point->v_mps : kNaN);
  series->omega_planned_radps.push_back(active ? point->omega_radps : kNaN);
  for (std::size_t j = 0; j < series->q_planned_rad.size(); ++j) {
    const bool has = active && static_cast<Eigen::Index>(j) < point->state.q_rad.size();
    series->q_planned_rad[j].push_back(has ? point->state.q_rad(static_cast<Eigen::Index>(j)) : kNaN);
  }
}

}  // namespace

RunTimeSeries SampleRunTimeSeries(const RunLog& log) {
  RunTimeSeries series;
  if (log.robot_states.empty()) return series;
  series.t0_utime = log.robot_states.front().utime;
  const std::size_t joints = static_cast<std::size_t>(log.robot_states.front().state.q_rad.size());
  series.q_measured_rad.assign(joints, {});
  series.q_planned_rad.assign(joints, {});
  TrajectorySample point;
  for (const msgs::RobotStateEstimate& state : log.robot_states) {
    series.t_s.push_back(SecondsSince(series.t0_utime, state.utime));
    AddMeasured(state, &series);
    const std::optional<std::size_t> active = ActiveTrajectoryAt(log.trajectories, state.utime);
    AddPlanned(active ? &log.trajectories[*active] : nullptr, state.utime, &point, &series);
  }
  for (std::int64_t utime : TrajectorySwitchUtimes(log.trajectories)) {
    series.switch_t_s.push_back(SecondsSince(series.t0_utime, utime));
  }
  return series;
}

}  // namespace topay::report
