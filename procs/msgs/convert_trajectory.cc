#include "procs/msgs/convert_trajectory.h"

#include <cmath>

namespace topay::msgs {

Eigen::VectorXd PolyTrajectory::Evaluate(double t_s) const {
  Eigen::VectorXd value = Eigen::VectorXd::Zero(coefficients.cols());
  if (num_pieces() == 0) return value;
  int piece = 0;
  double local = std::max(t_s, 0.0);
  while (piece + 1 < num_pieces() && local > durations_s(piece)) local -= durations_s(piece++);
  local = std::min(local, durations_s(piece));
  double power = 1.0;
  for (int k = 0; k < 6; ++k, power *= local) {
    value += power * coefficients.row(6 * piece + k).transpose();
  }
  return value;
}

PolyTrajectory FromArcYaw(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W_m) {
  PolyTrajectory poly;
  poly.p0_W_m = p0_W_m;
  poly.durations_s = trajectory.minco().durations();
  poly.coefficients = trajectory.minco().coefficients();
  poly.yaw0_rad = poly.coefficients(0, 1);
  return poly;
}

poly_trajectory_t ToMessage(const PolyTrajectory& trajectory) {
  poly_trajectory_t msg;
  msg.utime = trajectory.utime;
  msg.trajectory_id = trajectory.trajectory_id;
  msg.goal_id = trajectory.goal_id;
  msg.start_utime = trajectory.start_utime;
  msg.x0_m = trajectory.p0_W_m.x();
  msg.y0_m = trajectory.p0_W_m.y();
  msg.yaw0_rad = trajectory.yaw0_rad;
  const int m = trajectory.num_pieces();
  const int dims = static_cast<int>(trajectory.coefficients.cols());
  msg.num_pieces = m;
  msg.num_joints = dims - 2;
  msg.durations_s.assign(trajectory.durations_s.data(), trajectory.durations_s.data() + m);
  msg.num_coeffs = m * dims * 6;
  msg.coeffs.resize(msg.num_coeffs);
  for (int p = 0; p < m; ++p) {
    for (int d = 0; d < dims; ++d) {
      for (int k = 0; k < 6; ++k) {
        msg.coeffs[(p * dims + d) * 6 + k] = trajectory.coefficients(6 * p + k, d);
      }
    }
  }
  return msg;
}

std::optional<PolyTrajectory> FromMessage(const poly_trajectory_t& msg, std::string* error) {
  const int m = msg.num_pieces;
  const int dims = msg.num_joints + 2;
  if (m < 1 || msg.num_joints < 0 || msg.durations_s.size() != static_cast<std::size_t>(m)) {
    *error = "poly_trajectory_t.durations_s: need num_pieces >= 1 durations";
    return std::nullopt;
  }
  if (static_cast<std::int64_t>(msg.num_coeffs) != std::int64_t{m} * dims * 6 ||
      msg.coeffs.size() != static_cast<std::size_t>(msg.num_coeffs)) {
    *error = "poly_trajectory_t.num_coeffs: must be num_pieces * (2 + num_joints) * 6";
    return std::nullopt;
  }
  PolyTrajectory poly;
  poly.utime = msg.utime;
  poly.trajectory_id = msg.trajectory_id;
  poly.goal_id = msg.goal_id;
  poly.start_utime = msg.start_utime;
  poly.p0_W_m = {msg.x0_m, msg.y0_m};
  poly.yaw0_rad = msg.yaw0_rad;
  poly.durations_s = Eigen::Map<const Eigen::VectorXd>(msg.durations_s.data(), m);
  if (!(poly.durations_s.array() > 0.0).all() || !poly.durations_s.allFinite()) {
    *error = "poly_trajectory_t.durations_s: every duration must be finite and > 0";
    return std::nullopt;
  }
  poly.coefficients.resize(6 * m, dims);
  for (int p = 0; p < m; ++p) {
    for (int d = 0; d < dims; ++d) {
      for (int k = 0; k < 6; ++k) {
        poly.coefficients(6 * p + k, d) = msg.coeffs[(p * dims + d) * 6 + k];
      }
    }
  }
  if (!poly.coefficients.allFinite() || !poly.p0_W_m.allFinite()) {
    *error = "poly_trajectory_t: coefficients or start position not finite";
    return std::nullopt;
  }
  return poly;
}

}  // namespace topay::msgs
