#include "procs/viz/trajectory_view.h"

#include <algorithm>
#include <cmath>

#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/trajectory_from_message.h"

namespace topay::viz {

TrajectoryView::TrajectoryView(const RobotView& robot, const TrajectoryViewOptions& options)
    : robot_(&robot), options_(options) {}

std::optional<nlohmann::json> TrajectoryView::Accept(const poly_trajectory_t& msg, std::string* error) {
  if (active_ && msg.trajectory_id == active_id_) return std::nullopt;
  std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(msg, error);
  if (!poly) return std::nullopt;
  if (poly->num_joints() != robot_->model().num_joints()) {
    *error = "trajectory " + std::to_string(msg.trajectory_id) + ": " + std::to_string(poly->num_joints()) +
             " joints, the robot has " + std::to_string(robot_->model().num_joints());
    return std::nullopt;
  }
  std::optional<ArcYawTrajectory> rebuilt = msgs::ToArcYaw(*poly, msgs::TrajectoryRebuildOptions{}, error);
  if (!rebuilt) return std::nullopt;
  active_ = std::move(rebuilt);
  active_id_ = msg.trajectory_id;
  start_utime_ = msg.start_utime;
  point_ = active_->MakePoint();
  return Payload(msg);
}

nlohmann::json TrajectoryView::Payload(const poly_trajectory_t& msg) {
  const double duration = active_->duration_s();
  const int steps = std::clamp(static_cast<int>(std::ceil(duration / options_.sample_dt_s)), 1,
                               std::max(1, options_.max_samples - 1));
  nlohmann::json base = nlohmann::json::array(), ee = nlohmann::json::array();
  nlohmann::json t_s = nlohmann::json::array(), v = nlohmann::json::array(), omega = nlohmann::json::array();
  nlohmann::json a = nlohmann::json::array(), beta = nlohmann::json::array(), q = nlohmann::json::array();
  for (int i = 0; i <= steps; ++i) {
    const double t = duration * i / steps;
    active_->Evaluate(t, &point_);
    const Eigen::Vector3d p_WE = robot_->EndEffectorPosition(point_.state);
    base.push_back({point_.state.x_m, point_.state.y_m});
    ee.push_back({p_WE.x(), p_WE.y(), p_WE.z()});
    t_s.push_back(t);
    v.push_back(point_.v_mps);
    omega.push_back(point_.omega_radps);
    a.push_back(point_.a_mps2);
    beta.push_back(point_.beta_radps2);
    q.push_back(std::vector<double>(point_.state.q_rad.data(), point_.state.q_rad.data() + point_.state.q_rad.size()));
  }
  return {{"trajectory_id", msg.trajectory_id},
          {"goal_id", msg.goal_id},
          {"start_t", msg.start_utime * 1e-6},
          {"duration_s", duration},
          {"base_path_m", std::move(base)},
          {"ee_path_m", std::move(ee)},
          {"samples",
           {{"t_s", std::move(t_s)}, {"v_mps", std::move(v)}, {"omega_radps", std::move(omega)},
            {"a_mps2", std::move(a)}, {"beta_radps2", std::move(beta)}, {"q_rad", std::move(q)}}}};
}

const TrajectorySample* TrajectoryView::PlannedAt(std::int64_t utime) {
  if (!active_) return nullptr;
  const double t = std::clamp((utime - start_utime_) * 1e-6, 0.0, active_->duration_s());
  active_->Evaluate(t, &point_);
  return &point_;
}

}  // namespace topay::viz
