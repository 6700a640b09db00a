#include "core/trajectory/offset_trajectory.h"

#include <cmath>
#include <stdexcept>

namespace topay {
namespace {

// Column k (0 position, 1 velocity, 2 acceleration) of the boundary data [s, yaw, q] in a sample.
void PutBoundary(const TrajectorySample& p, Eigen::Ref<Eigen::MatrixXd> boundary) {
  const int n = static_cast<int>(p.state.q_rad.size());
  boundary(0, 0) = p.s_m;
  boundary(0, 1) = p.v_mps;
  boundary(0, 2) = p.a_mps2;
  boundary(1, 0) = p.state.yaw_rad;
  boundary(1, 1) = p.omega_radps;
  boundary(1, 2) = p.beta_radps2;
  boundary.block(2, 0, n, 1) = p.state.q_rad;
  boundary.block(2, 1, n, 1) = p.qd_radps;
  boundary.block(2, 2, n, 1) = p.qdd_radps2;
}

}  // namespace

ArcYawTrajectory OffsetTrajectory(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W, double yaw_offset_rad,
                                  const Eigen::VectorXd& q_offset_rad, const ArcYawTrajectory::Options& options) {
  const int n = trajectory.num_joints();
  const int d = trajectory.num_dims();
  const int m = trajectory.num_pieces();
  if (q_offset_rad.size() != n) throw std::invalid_argument("OffsetTrajectory: q_offset_rad must have one value per joint");
  if (!p0_W.allFinite() || !std::isfinite(yaw_offset_rad) || !q_offset_rad.allFinite()) {
    throw std::invalid_argument("OffsetTrajectory: offsets must be finite");
  }
  const Eigen::VectorXd& durations_s = trajectory.minco().durations();
  if (durations_s.size() != m) throw std::invalid_argument("OffsetTrajectory: the trajectory was never updated");
  Eigen::VectorXd offset = Eigen::VectorXd::Zero(d);
  offset(1) = yaw_offset_rad;
  offset.tail(n) = q_offset_rad;
  TrajectorySample p = trajectory.MakePoint();
  Eigen::MatrixXd head(d, 3), tail(d, 3), waypoints(d, m - 1);
  trajectory.Evaluate(0.0, &p);
  PutBoundary(p, head);
  trajectory.Evaluate(trajectory.duration_s(), &p);
  PutBoundary(p, tail);
  double t_s = 0.0;
  for (int k = 0; k + 1 < m; ++k) {
    t_s += durations_s(k);
    trajectory.Evaluate(t_s, &p);
    waypoints(0, k) = p.s_m;
    waypoints(1, k) = p.state.yaw_rad;
    waypoints.block(2, k, n, 1) = p.state.q_rad;
  }
  head.col(0) += offset;
  tail.col(0) += offset;
  waypoints.colwise() += offset;
  ArcYawTrajectory moved(n, m, options);
  moved.Update(p0_W, head, tail, waypoints, durations_s);
  return moved;
}

}  // namespace topay
