#pragma once

#include <stop_token>

#include <Eigen/Core>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/sample_penalties.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// Stage 1's reference: for every sample (piece j, panel end l = 0..K, index j (K + 1) + l),
/// the initial path's base position, yaw (unwrapped) and joints at the same fraction of the
/// same piece of the warm start (core/optimization/warm_start.h).
struct PathReference {
  Eigen::Matrix2Xd p_W;     ///< 2 x M (K + 1).
  Eigen::VectorXd yaw_rad;  ///< M (K + 1).
  Eigen::MatrixXd q_rad;    ///< N x M (K + 1).
};

/// Weights of stage 1's path fit (TrajectoryObjectiveOptions holds them).
struct PathFitWeights {
  double position = 1000.0;  ///< Per m^2 of base position error.
  double angle = 100.0;      ///< Per rad^2 of yaw and joint error.
};

/// What one evaluation shares between the samplers: the trajectory (read), and the gradient
/// blocks each piece owns alone (written: rows 6j..6j+5 of dC_dc and entry j of dC_dT belong
/// to piece j).
struct PieceSampleContext {
  const ArcYawTrajectory* trajectory = nullptr;
  const Eigen::VectorXd* durations_s = nullptr;
  const PathReference* reference = nullptr;  ///< Non-null: add the path fit.
  bool penalties_on = false;
  bool with_gradient = false;
  Eigen::MatrixXd* dC_dc = nullptr;  ///< 6M x D.
  Eigen::VectorXd* dC_dT = nullptr;  ///< M.
};

/// The sample part of TrajectoryObjective for a range of pieces: eq. (23)'s penalty
/// integral (and stage 1's path fit) with its gradient with respect to the pieces'
/// coefficients and durations, and to the Simpson positions. Each sampler has its own
/// scratch, so that several evaluate disjoint piece ranges at once; their position
/// gradients, costs and breakdowns are summed by the caller (the Simpson sample at a piece
/// boundary belongs to two pieces, possibly of two samplers). Sample l of piece j is
/// penalised at ramp coordinate u = (j + l / K) / M (PieceFraction), the endpoint relief's
/// (SamplePenalties::set_endpoint_relief).
///
/// Construction allocates; Run does not.
class PieceSampler {
 public:
  /// Throws std::invalid_argument for bad limits or penalty options (SamplePenalties).
  PieceSampler(const Kinematics& kinematics, const SignedDistanceField2& base_field,
               const SignedDistanceField3& arm_field, const BaseLimits& base_limits,
               const SamplePenaltyOptions& penalty_options, const PathFitWeights& fit_weights,
               int num_pieces, int panels_per_piece);

  SamplePenalties& penalties() { return penalties_; }

  /// Zeroes this sampler's sums, then adds pieces [first, end) to them and to the context's
  /// gradient blocks. Returns false if a stop was requested (polled once per piece).
  bool Run(const PieceSampleContext& context, int first, int end, const std::stop_token& stop);

  /// This sampler's sums from the last Run: the time integral of each penalty term, the path
  /// fit, and dCost/d(Simpson position g) (2 x (MK + 1), zero outside its pieces' samples).
  const PenaltyValues& penalty_costs() const { return penalty_costs_; }
  double path_fit() const { return path_fit_; }
  const Eigen::Matrix2Xd& dC_dp() const { return dC_dp_; }

 private:
  void AddPiece(const PieceSampleContext& context, int piece);
  // The steps of AddPiece, at one sample (values_ holds its MINCO values).
  /// sample_ from values_ and the Simpson position p_W.
  void SetSample(const Eigen::Ref<const Eigen::Vector2d>& p_W);
  /// The penalties' gradient (sample_gradient_) with weight w_time into weights_ and dC_dp_
  /// (Simpson sample g).
  void AddPenaltyWeights(double w_time, int g);
  /// Stage 1's path fit against reference sample r with weight w_fit (into path_fit_, and
  /// its gradient into weights_ and dC_dp_ when with_gradient).
  void AddPathFit(const PathReference& reference, int r, double w_fit,
                  const Eigen::Ref<const Eigen::Vector2d>& p_W, int g, bool with_gradient);

  int num_joints_;
  int num_pieces_;
  int panels_per_piece_;
  PathFitWeights fit_weights_;
  SamplePenalties penalties_;
  PenaltyValues penalty_costs_{};
  double path_fit_ = 0.0;
  Eigen::Matrix2Xd dC_dp_;
  // Scratch.
  SampleQuantities sample_, sample_gradient_;
  Eigen::MatrixXd values_;   // D x 4: position, 1st, 2nd, 3rd derivative
  Eigen::MatrixXd weights_;  // D x 3: dCost/d(position, 1st, 2nd derivative) of the sample
};

}  // namespace topay
