#include "core/planning/informed_joint_sampler.h"

#include <cmath>
#include <stdexcept>

namespace topay {

InformedJointSampler::InformedJointSampler(const Eigen::VectorXd& q_start,
                                           const Eigen::VectorXd& q_goal,
                                           const Eigen::VectorXd& weights)
    : q_start_(q_start), q_goal_(q_goal) {
  const Eigen::Index n = q_start.size();
  if (q_goal.size() != n || weights.size() != n || n == 0) {
    throw std::invalid_argument("InformedJointSampler: sizes of q_start, q_goal, weights differ");
  }
  if (!(weights.array() > 0.0).all() || !weights.allFinite()) {
    throw std::invalid_argument("InformedJointSampler: weights must be positive and finite");
  }
  sqrt_weights_ = weights.cwiseSqrt();
  const Eigen::VectorXd y_start = sqrt_weights_.cwiseProduct(q_start);
  const Eigen::VectorXd y_goal = sqrt_weights_.cwiseProduct(q_goal);
  y_centre_ = 0.5 * (y_start + y_goal);
  min_cost_ = (y_goal - y_start).norm();
  rotation_ = Eigen::MatrixXd::Identity(n, n);
  if (min_cost_ > 0.0) {
    // Householder reflection H = I - 2 v v^T / (v^T v), v = e1 - a1, maps e1 to a1.
    const Eigen::VectorXd a1 = (y_goal - y_start) / min_cost_;
    Eigen::VectorXd v = -a1;
    v(0) += 1.0;
    const double v_norm_sq = v.squaredNorm();
    if (v_norm_sq > 1e-24) rotation_ -= 2.0 * v * v.transpose() / v_norm_sq;
  }
}

double InformedJointSampler::Distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  return sqrt_weights_.cwiseProduct(a - b).norm();
}

bool InformedJointSampler::InInformedSet(const Eigen::VectorXd& q, double c_max) const {
  return Distance(q, q_start_) + Distance(q_goal_, q) <= c_max * (1.0 + 1e-9);
}

void InformedJointSampler::Sample(double c_max, Rng* rng, Eigen::VectorXd* q) const {
  const Eigen::Index n = q_start_.size();
  c_max = std::max(c_max, min_cost_);
  // Uniform in the unit n-ball: a Gaussian direction times a radius U^(1/n).
  Eigen::VectorXd x(n);
  double norm_sq = 0.0;
  do {
    for (Eigen::Index i = 0; i < n; ++i) x(i) = rng->Normal();
    norm_sq = x.squaredNorm();
  } while (norm_sq < 1e-300);
  x *= std::pow(rng->Uniform01(), 1.0 / static_cast<double>(n)) / std::sqrt(norm_sq);
  // Stretch by L: the transverse radius is sqrt(c_max^2 - c_min^2) / 2 (Gammell eq. 9).
  const double transverse = 0.5 * std::sqrt(std::max(0.0, c_max * c_max - min_cost_ * min_cost_));
  x(0) *= 0.5 * c_max;
  for (Eigen::Index i = 1; i < n; ++i) x(i) *= transverse;
  *q = (rotation_ * x + y_centre_).cwiseQuotient(sqrt_weights_);
}

}  // namespace topay
