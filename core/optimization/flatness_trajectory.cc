#include "core/optimization/flatness_trajectory.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/optimization/flat_yaw.h"

namespace topay {
namespace {

const FlatnessTrajectoryData& Checked(const FlatnessTrajectoryData& data) {
  const int D = static_cast<int>(data.head.rows());
  const int M = data.num_pieces();
  if (D < 2 || M < 1 || data.head.cols() != 3 || data.tail.rows() != D || data.tail.cols() != 3 ||
      data.waypoints.rows() != D || data.waypoints.cols() != M - 1) {
    throw std::invalid_argument("FlatnessTrajectory: head/tail must be D x 3 (D >= 2), "
                                "waypoints D x (M - 1) for M = " + std::to_string(M) +
                                " durations");
  }
  if (!std::isfinite(data.start_yaw_rad) || !std::isfinite(data.end_yaw_rad)) {
    throw std::invalid_argument("FlatnessTrajectory: rest headings are not finite");
  }
  return data;
}

}  // namespace

FlatnessTrajectory::FlatnessTrajectory(const FlatnessTrajectoryData& data)
    : data_(Checked(data)),
      minco_(static_cast<int>(data.head.rows()), data.num_pieces()) {
  minco_.Solve(data_.head, data_.tail, data_.waypoints, data_.durations_s);  // throws if bad
  for (Eigen::VectorXd& v : values_) v.setZero(data_.head.rows());
}

void FlatnessTrajectory::Evaluate(double t_s, TrajectorySample* sample) {
  const int N = num_joints();
  double local_t = 0.0;
  const int piece = minco_.LocatePiece(t_s, &local_t);
  for (int order = 0; order < 4; ++order) {
    minco_.EvaluatePiece(piece, local_t, order, values_[order]);
  }
  sample->t_s = t_s;
  sample->state.x_m = values_[0](0);
  sample->state.y_m = values_[0](1);
  sample->state.q_rad = values_[0].tail(N);
  sample->qd_radps = values_[1].tail(N);
  sample->qdd_radps2 = values_[2].tail(N);
  const Eigen::Vector2d u = values_[1].head<2>();
  const Eigen::Vector2d w = values_[2].head<2>();
  const Eigen::Vector2d z = values_[3].head<2>();
  if (u.norm() < 1e-9) {
    // A rest point: the heading by continuity (start or end), no rates.
    const bool at_start = t_s < 0.5 * duration_s();
    sample->state.yaw_rad = at_start ? data_.start_yaw_rad : data_.end_yaw_rad;
    sample->v_mps = 0.0;
    sample->a_mps2 = at_start ? w.norm() : -w.norm();
    sample->omega_radps = 0.0;
    sample->beta_radps2 = 0.0;
    return;
  }
  const FlatYaw flat = ComputeFlatYaw(u, w, z);
  sample->state.yaw_rad = flat.yaw_rad;
  sample->v_mps = flat.v_mps;
  sample->a_mps2 = flat.a_mps2;
  sample->omega_radps = flat.omega_radps;
  sample->beta_radps2 = flat.beta_radps2;
}

SampledTrajectory SampleFlatness(const FlatnessTrajectoryData& data) {
  FlatnessTrajectory check(data);  // validates the data and gives the duration
  SampledTrajectory out;
  out.duration_s = check.duration_s();
  out.num_joints = check.num_joints();
  out.make_sampler = [data]() -> TrajectorySampler {
    auto trajectory = std::make_shared<FlatnessTrajectory>(data);
    return [trajectory](double t_s, TrajectorySample* sample) {
      trajectory->Evaluate(t_s, sample);
    };
  };
  return out;
}

}  // namespace topay
