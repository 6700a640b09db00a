#pragma once

#include <Eigen/Core>

#include "core/common/random.h"

namespace topay {

/// Uniform samples of the informed set of a joint-space path cost (Gammell et al., "Informed
/// RRT*", IROS 2014): with the weighted metric |v|_w = sqrt(sum_i w_i v_i^2), every state q on
/// a path from q_start to q_goal of cost <= c_max satisfies
///   |q - q_start|_w + |q_goal - q|_w <= c_max,
/// a prolate hyperspheroid with foci q_start, q_goal. In the scaled coordinates y = sqrt(w) q
/// it is a Euclidean one, sampled as y = C L x_ball + y_centre (Gammell eq. 6-9) with
/// L = diag(c_max / 2, sqrt(c_max^2 - c_min^2) / 2, ...), c_min = |q_goal - q_start|_w, and
/// C a Householder reflection taking e1 to the focal axis (a reflection instead of Gammell's
/// SVD rotation: it maps the ball to the same ellipsoid, so the distribution is the same).
class InformedJointSampler {
 public:
  /// weights: all > 0, same size as q_start and q_goal.
  InformedJointSampler(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_goal,
                       const Eigen::VectorXd& weights);

  int dimension() const { return static_cast<int>(q_start_.size()); }
  /// c_min = |q_goal - q_start|_w, the cost lower bound.
  double min_cost() const { return min_cost_; }
  /// |a - b|_w.
  double Distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  /// True if |q - q_start|_w + |q_goal - q|_w <= c_max (with a 1e-9 relative tolerance).
  bool InInformedSet(const Eigen::VectorXd& q, double c_max) const;

  /// One uniform draw from the informed set of c_max (>= min_cost()) into *q.
  void Sample(double c_max, Rng* rng, Eigen::VectorXd* q) const;

 private:
  Eigen::VectorXd q_start_;
  Eigen::VectorXd q_goal_;
  Eigen::VectorXd sqrt_weights_;
  Eigen::VectorXd y_centre_;
  Eigen::MatrixXd rotation_;  ///< C: e1 -> focal axis (identity when the foci coincide).
  double min_cost_ = 0.0;
};

}  // namespace topay
