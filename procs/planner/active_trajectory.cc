#include "procs/planner/active_trajectory.h"

#include <algorithm>
#include <cmath>

#include "core/common/angles.h"
#include "core/control/arc_yaw_reference.h"

namespace topay::planner {

std::int64_t ActiveTrajectory::end_utime() const {
  return start_utime + static_cast<std::int64_t>(std::llround(trajectory->duration_s() * 1e6));
}

TrajectorySample ActiveTrajectory::SampleAt(std::int64_t utime) const {
  TrajectorySample sample = trajectory->MakePoint();
  const double t = std::clamp(TimeAt(utime), 0.0, trajectory->duration_s());
  trajectory->Evaluate(t, &sample);
  return sample;
}

const ActiveTrajectory* TrajectoryOnAt(const ActiveTrajectory* newest, const std::deque<ActiveTrajectory>& replaced,
                                       std::int64_t utime) {
  if (newest != nullptr && newest->start_utime <= utime) return newest;
  for (auto it = replaced.rbegin(); it != replaced.rend(); ++it) {
    if (it->start_utime <= utime) return &*it;
  }
  return nullptr;
}

Drift MeasureDrift(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot) {
  const TrajectorySample ref = active.SampleAt(robot.utime);
  Drift drift;
  drift.position_m = std::hypot(robot.state.x_m - ref.state.x_m, robot.state.y_m - ref.state.y_m);
  drift.yaw_rad = std::abs(WrapAngle(robot.state.yaw_rad - ref.state.yaw_rad));
  if (robot.state.q_rad.size() == ref.state.q_rad.size() && ref.state.q_rad.size() > 0) {
    drift.joint_rad = (robot.state.q_rad - ref.state.q_rad).cwiseAbs().maxCoeff();
  }
  return drift;
}

DriftedRobot::DriftedRobot(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot)
    : active_(active), state_time_s_(active.TimeAt(robot.utime)) {
  const TrajectorySample now = active.SampleAt(robot.utime);
  yaw_ref_rad_ = now.state.yaw_rad;
  p_offset_W_m_ = Eigen::Vector2d(robot.state.x_m - now.state.x_m, robot.state.y_m - now.state.y_m);
  yaw_offset_rad_ = WrapAngle(robot.state.yaw_rad - now.state.yaw_rad);
  if (robot.state.q_rad.size() == now.state.q_rad.size()) q_offset_rad_ = robot.state.q_rad - now.state.q_rad;
}

void DriftedRobot::Evaluate(double t_s, TrajectorySample* sample) const {
  const ArcYawTrajectory& trajectory = *active_.trajectory;
  trajectory.Evaluate(std::clamp(t_s, 0.0, trajectory.duration_s()), sample);
  // The base offset turns with the trajectory: a robot beside a bend stays beside it.
  const double turn_rad = WrapAngle(sample->state.yaw_rad - yaw_ref_rad_);
  const Eigen::Vector2d moved_W = Eigen::Rotation2Dd(turn_rad) * p_offset_W_m_;
  sample->state.x_m += moved_W.x();
  sample->state.y_m += moved_W.y();
  sample->state.yaw_rad += yaw_offset_rad_;
  if (q_offset_rad_.size() == sample->state.q_rad.size()) sample->state.q_rad += q_offset_rad_;
}

TrajectorySample PredictDriftedStart(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot,
                                     std::int64_t t0_utime) {
  TrajectorySample start = active.trajectory->MakePoint();
  DriftedRobot(active, robot).Evaluate(active.TimeAt(t0_utime), &start);
  return start;
}

TrajectorySample PredictTrackedStart(TrackedRobotPredictor* predictor, const ActiveTrajectory& active,
                                     const msgs::RobotStateEstimate& robot, std::int64_t t0_utime,
                                     const TrackerLimits& plan_limits, TrackedRobotPredictionSummary* summary) {
  // Times along the trajectory: its t = 0 at 0.
  const TrackerReference reference = MakeArcYawReference(active.trajectory, active.trajectory_id, 0.0);
  MeasuredRobot measured;
  measured.state = robot.state;
  measured.state_time_s = active.TimeAt(robot.utime);
  const int num_joints = robot.state.num_joints();
  measured.rates = ControlCommand::Zero(num_joints);
  measured.rates.v_mps = robot.v_mps;
  measured.rates.omega_radps = robot.omega_radps;
  if (robot.qdot_radps.size() == num_joints) measured.rates.qd_radps = robot.qdot_radps;
  TrajectorySample start = active.trajectory->MakePoint();
  predictor->Predict(reference, measured, std::max(active.TimeAt(t0_utime), measured.state_time_s), &start);
  if (summary != nullptr) *summary = predictor->summary();
  start.a_mps2 = std::clamp(start.a_mps2, -plan_limits.base.a_max_mps2, plan_limits.base.a_max_mps2);
  start.beta_radps2 = std::clamp(start.beta_radps2, -plan_limits.base.beta_max_radps2, plan_limits.base.beta_max_radps2);
  if (plan_limits.qdd_max_radps2.size() == start.qdd_radps2.size()) {
    start.qdd_radps2 = start.qdd_radps2.cwiseMax(-plan_limits.qdd_max_radps2).cwiseMin(plan_limits.qdd_max_radps2);
  }
  return start;
}

Eigen::AlignedBox3d SweptRegion(const ArcYawTrajectory& trajectory, double t_from_s, double t_to_s,
                                double reach_m, double height_m) {
  TrajectorySample point = trajectory.MakePoint();
  Eigen::AlignedBox3d region;
  const double t0 = std::clamp(t_from_s, 0.0, trajectory.duration_s());
  const double t1 = std::clamp(t_to_s, t0, trajectory.duration_s());
  // Base positions every 0.05 s: the base moves at most v_max x 0.05 s (5 cm at 1 m/s)
  // between two, which the reach covers (it is grown by 0.1 m for that).
  const int n = static_cast<int>(std::ceil((t1 - t0) / 0.05));
  for (int k = 0; k <= n; ++k) {
    trajectory.Evaluate(std::min(t0 + 0.05 * k, t1), &point);
    region.extend(Eigen::Vector3d(point.state.x_m, point.state.y_m, 0.0));
  }
  const Eigen::Vector3d grow(reach_m + 0.1, reach_m + 0.1, 0.0);
  return {region.min() - grow, Eigen::Vector3d(region.max().x(), region.max().y(), height_m) + grow};
}

}  // namespace topay::planner
