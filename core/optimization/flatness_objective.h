#pragma once

#include <stop_token>

#include <Eigen/Core>

#include "core/optimization/end_effector_alm_term.h"
#include "core/optimization/lbfgs_objective.h"
#include <Eigen/Geometry>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/pose_residual.h"
#include "core/optimization/sample_penalties.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/jerk_energy.h"
#include "core/trajectory/minco_s3.h"

namespace topay {

/// Weights and sampling of FlatnessObjective. Defaults: REMANI's public code where it has a figure
/// where it has a figure, else TrajectoryObjectiveOptions' values.
struct FlatnessObjectiveOptions {
  /// Jerk weights: x and y both take the arc length weight, the joints theirs (yaw is not a
  /// trajectory dimension here).
  JerkWeightOptions jerk_weights;
  double time_weight = 50.0;  ///< Per s of total duration (as the TopAY objective).
  /// Trapezoid integration: samples per piece are the K + 1 panel end points (REMANI: 16).
  int panels_per_piece = 16;
  /// Dense samples near the stops: the first and last pieces (which contain the two rest
  /// points) use this many times more panels.
  int stop_panel_factor = 2;
  /// Minimum speed (REMANI: 0.05 m/s) so that yaw = atan2(dy, dx) stays defined: penalty
  /// weight x L(v_floor^2 - v^2) at every sample but the two rest points, with v_floor =
  /// min_speed_mps, ramped linearly to 0 towards a rest point over the first/last piece.
  double min_speed_mps = 0.05;
  double min_speed_weight = 1e5;
  /// mu of the smoothing for the minimum-speed constraint (m^2/s^2; v_floor^2 is 2.5e-3).
  double min_speed_smoothing_mu = 1e-4;
  /// The rest remedy: the flat outputs' acceleration at the start is a_stop along the start
  /// yaw and at the end -a_stop along the (free) end yaw psi_f, so the heading tends to those
  /// yaws at the two rest points (v = 0 there); a_stop = this fraction of the caller's a_max.
  /// In (0, 1). 0.6 (0.48 m/s^2 for a_max 0.8): of 0.25, 0.5, 0.6, 0.75 x a_max, the best on
  /// the test tasks (small values let lateral jerk near the stops spin the yaw: beta fails).
  double stop_acceleration_fraction = 0.6;
  /// The sample penalties (same SamplePenalties as the TopAY objective).
  SamplePenaltyOptions penalties;
};

struct FlatnessTerms {
  bool jerk = true;
  bool time = true;
  bool end_effector = true;  ///< PHR-ALM term of eq. (7).
  bool min_speed = true;
  PenaltyMask penalties = AllPenalties();
};

struct FlatnessBreakdown {
  double jerk = 0.0;
  double time = 0.0;
  double end_effector = 0.0;
  double min_speed = 0.0;
  PenaltyValues penalties{};
  double total = 0.0;
};

/// The REMANI-style flatness baseline's objective : base position x(t),
/// y(t) and the joints as ONE MINCO s = 3 trajectory (minimum jerk; REMANI uses minimum snap,
/// s = 4: our MINCO is s = 3), yaw = atan2(dy, dx) (forward only, eta = +1), decision vector
///   x = [tau (M) | inner waypoints, (M - 1) blocks of D = 2 + N: x, y, xi_1..xi_N |
///        free end (x_f, y_f, psi_f, xi_f,1..N)]        (M + M D + 1 values),
/// durations through the time map (eq. (21)), joints through the joint map (eq. (22)).
/// Head: start position at rest with acceleration a_stop along the start yaw; tail:
/// (x_f, y_f, q_f) at rest with acceleration -a_stop along psi_f (stop_acceleration_fraction).
///
///   f(x) = jerk energy + rho_T sum T_j                                         (eq. (6))
///        + sum_j sum_l w_l T_j / K_j [P(sample) + rho_v L(v_floor^2 - v^2)]    (eq. (23))
///        + rho / 2 |r + lambda / rho|^2                                         (eq. (7))
/// with P the same SamplePenalties as the TopAY objective on (x, y, yaw, v, a, omega, beta,
/// q, q', q''), yaw and rates from flat_yaw.h, r the end-effector residual at
/// (x_f, y_f, psi_f, q_f). Gradient by the chain rule through flat_yaw.h and MINCO's adjoint.
///
/// Construction allocates; Evaluate does not. One object per thread.
class FlatnessObjective : public LbfgsObjective {
 public:
  /// Throws std::invalid_argument for num_pieces < 1, bad options, a start state of the wrong
  /// size or not finite, a non-finite goal (naming them).
  FlatnessObjective(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                    const SignedDistanceField3& arm_field, const BaseLimits& base_limits,
                    const WholeBodyState& start, const Eigen::Isometry3d& X_WE_goal,
                    int num_pieces, const FlatnessObjectiveOptions& options = {});

  int num_pieces() const { return num_pieces_; }
  int num_joints() const { return num_joints_; }
  int num_dims() const { return num_joints_ + 2; }
  int num_parameters() const override { return num_pieces_ * (1 + num_dims()) + 1; }
  /// Panels of piece j (K, or K x stop_panel_factor for the first and last piece).
  int panels(int piece) const;
  const FlatnessObjectiveOptions& options() const { return options_; }

  void set_terms(const FlatnessTerms& terms);
  const FlatnessTerms& terms() const { return terms_; }
  /// Multiplies each sample penalty's weight (each finite and > 0, else throws).
  void set_penalty_scales(const PenaltyValues& scales);
  void set_multiplier(const Vector6d& lambda, double rho);
  void set_stop_token(std::stop_token stop) { stop_ = std::move(stop); }

  /// x from durations (M, > 0), inner waypoints (D x (M - 1): x, y, q) and the end (D + 1:
  /// x_f, y_f, psi_f, q_f). Throws std::invalid_argument for wrong sizes or non-finite values.
  Eigen::VectorXd Pack(const Eigen::VectorXd& durations_s, const Eigen::MatrixXd& waypoints,
                       const Eigen::VectorXd& end) const;

  /// f(x) and, if gradient is non-null, df/dx. False for a non-finite x or cost, a singular
  /// MINCO system, a zero speed at an inner sample, or a stop request. Allocation-free.
  bool Evaluate(const double* x, double* cost, double* gradient) override;

  const FlatnessBreakdown& breakdown() const { return breakdown_; }
  const Vector6d& end_effector_residual() const { return end_effector_.residual(); }
  /// The trajectory of the last successful Evaluate (copies; allocates).
  FlatnessTrajectoryData TrajectoryData() const;
  bool stopped() const override { return stopped_; }
  int num_evaluations() const override { return num_evaluations_; }

 private:
  bool Decode(const double* x);
  void AddPieceSamples(int piece, bool with_gradient);
  // The steps of AddPieceSamples, at one sample (values_ holds its MINCO values; u, w, z:
  // the flat outputs' velocity, acceleration and jerk).
  /// sample_ from values_: yaw and the base rates from the flat outputs (flat_yaw.h), or the
  /// rest values at a rest point.
  void SetSample(const Eigen::Vector2d& u, const Eigen::Vector2d& w, const Eigen::Vector2d& z,
                 bool rest_start, bool rest_end);
  /// The penalties' gradient (sample_gradient_) with weight w_time into weights_, the flat
  /// outputs' (*dC_du, *dC_dw, *dC_dz) and, at the end rest point, psi_f's.
  void AddPenaltyWeights(double w_time, const Eigen::Vector2d& u, const Eigen::Vector2d& w,
                         const Eigen::Vector2d& z, bool rest, bool rest_end,
                         Eigen::Vector2d* dC_du, Eigen::Vector2d* dC_dw, Eigen::Vector2d* dC_dz);
  void AddEndEffector(bool with_gradient);
  void WriteGradient(double* gradient) const;

  const Kinematics& kinematics_;
  FlatnessObjectiveOptions options_;
  int num_pieces_;
  int num_joints_;
  FlatnessTerms terms_;
  SamplePenalties penalties_;
  EndEffectorAlmTerm end_effector_;  ///< PHR-ALM term of eq. (7).
  double stop_acceleration_mps2_ = 0.0;
  double start_yaw_rad_ = 0.0;
  double end_yaw_rad_ = 0.0;
  Vector6d lambda_ = Vector6d::Zero();
  double rho_ = 1.0;
  std::stop_token stop_;
  bool stopped_ = false;
  bool singular_ = false;
  int num_evaluations_ = 0;
  Eigen::VectorXd jerk_weights_;
  Eigen::VectorXd joint_min_rad_, joint_max_rad_;

  Eigen::MatrixXd head_, tail_, waypoints_;
  Eigen::VectorXd durations_s_, dT_dtau_;
  Eigen::MatrixXd dq_dxi_;
  MincoS3 minco_;
  Eigen::MatrixXd dC_dc_;
  Eigen::VectorXd dC_dT_;
  Eigen::VectorXd dC_dend_direct_;  // D + 1: x_f, y_f, psi_f, q_f
  MincoGradient minco_gradient_;
  SampleQuantities sample_, sample_gradient_;
  Eigen::MatrixXd values_;   // D x 5: derivatives 0..4
  Eigen::MatrixXd weights_;  // D x 4: dCost/d(derivatives 0..3)
  WholeBodyState end_state_;
  FlatnessBreakdown breakdown_;
};

}  // namespace topay
