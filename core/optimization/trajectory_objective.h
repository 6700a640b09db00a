#pragma once

#include <memory>
#include <stop_token>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/optimization/end_effector_alm_term.h"
#include "core/optimization/lbfgs_objective.h"
#include "core/optimization/piece_sampler.h"

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/pose_residual.h"
#include "core/optimization/sample_penalties.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_rates.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/jerk_energy.h"
#include "core/trajectory/minco_s3.h"

namespace topay {

/// Weights and sampling of TrajectoryObjective. Defaults: the authors' code's stage-2 figures.
struct TrajectoryObjectiveOptions {
  /// W of eq. (6): (arc length, yaw, joints) = (1, 0.33, 1).
  JerkWeightOptions jerk_weights;
  /// rho of eq. (6), weight of the total duration (per s; authors' code: time weight 50).
  double time_weight = 50.0;
  /// K: constraint samples per piece are its K + 1 panel end points (the Simpson panels of
  /// the x, y integration, authors' code: 12), with trapezoid weights.
  int panels_per_piece = 12;
  /// The inequality penalties (weights, margins, smoothing).
  SamplePenaltyOptions penalties;
  /// Stage 1's path-fit term (authors' code: "path-position terms"): weight per m^2 of base
  /// position error and per rad^2 of yaw and joint error, averaged over the samples of a
  /// piece (trapezoid weights / K, not scaled by the duration, so the fit does not pull on
  /// the time).
  double path_fit_position_weight = 1000.0;
  double path_fit_angle_weight = 100.0;
  /// The pieces are split into this many contiguous chunks, each sampled by its own
  /// PieceSampler; while the geometric terms are on (stage 2) the chunks run as parallel TBB
  /// tasks in the caller's task arena (isolated, so a waiting thread only helps its own
  /// evaluation). The partition is fixed and the chunks' sums are added in chunk order, so
  /// the result does not depend on how many threads run them. 1 = serial. Not in the
  /// reference code (one thread per candidate path only).
  int sample_chunks = 2;
};

/// Which parts of the objective Evaluate includes (all but the path fit by default: stage 2).
struct ObjectiveTerms {
  bool jerk = true;          ///< Weighted jerk energy, eq. (6).
  bool time = true;          ///< rho_T x total duration, eq. (6).
  bool end_effector = true;  ///< PHR augmented Lagrangian term of eq. (7).
  bool path_fit = false;     ///< Stage 1: distance to the reference path at every sample.
  PenaltyMask penalties = AllPenalties();  ///< Sample penalties, eq. (23).
};

/// The parts of the cost at the last evaluation.
struct ObjectiveBreakdown {
  double jerk = 0.0;
  double time = 0.0;
  double end_effector = 0.0;
  double path_fit = 0.0;
  PenaltyValues penalties{};  ///< Time integral of each term's weighted penalty.
  double total = 0.0;
};

/// The objective of the TopAY trajectory optimization (paper Sec. III-C and III-D, eqs. (6)-(23)) as a
/// function of the decision vector
///   x = [tau (M) | inner waypoints, (M - 1) blocks of D = 2 + N: s, yaw, xi_1..xi_N |
///        free end (s_f, yaw_f, xi_f,1..N)],
/// where T_j = T(tau_j) (time map, eq. (21)) and every joint value q = q(xi) (joint map,
/// eq. (22)) onto the limits less SamplePenaltyOptions::joint_position_margin_rad, so
/// durations stay positive and joint waypoints and q_f inside their limits with that margin.
/// The head is the start state (s = 0), at rest unless set_start_rates says otherwise; the tail's velocity and acceleration are zero
/// (conditions (15)-(20)).
///
///   f(x) = jerk energy (W)  +  rho_T sum_j T_j                                    eq. (6)
///        + sum_j sum_{l=0..K} w_l T_j / K  P(sample j, l)                         eq. (23)
///        + rho / 2 | r(x) + lambda / rho |^2                     (PHR-ALM of eq. (7))
///        [+ path fit (stage 1)],
/// w_l the trapezoid weights (1/2 at both ends), P the SamplePenalties, r the 6-D
/// end-effector residual at the end state (PoseResidual: position, rotation vector).
///
/// Gradient by the chain rule: each sample's dP/d(quantities) goes to the piece's
/// coefficients through the quintic basis, to T_j through the sample time t = T_j l / K and
/// the weight, and dP/d(x, y) to the Simpson integration (ArcYawTrajectory::
/// PropagateGradient), which with MINCO's adjoint yields dJ/d(waypoints, T, s_f, yaw_f, q_f);
/// then through the time and joint maps.
///
/// Construction allocates; Evaluate does not. One object per thread. The kinematics and fields
/// must outlive it.
class TrajectoryObjective : public LbfgsObjective {
 public:
  /// Throws std::invalid_argument for num_pieces < 1, panels_per_piece < 1, a start state of
  /// the wrong size or not finite, a non-finite goal, bad limits or options (naming them).
  TrajectoryObjective(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                      const SignedDistanceField3& arm_field, const BaseLimits& base_limits,
                      const WholeBodyState& start, const Eigen::Isometry3d& X_WE_goal,
                      int num_pieces, const TrajectoryObjectiveOptions& options = {});

  int num_pieces() const { return num_pieces_; }
  int num_joints() const { return num_joints_; }
  int num_dims() const { return num_joints_ + 2; }
  int panels_per_piece() const { return options_.panels_per_piece; }
  /// M + M D.
  int num_parameters() const override { return num_pieces_ * (1 + num_dims()); }
  const TrajectoryObjectiveOptions& options() const { return options_; }

  void set_terms(const ObjectiveTerms& terms);
  /// Multiplies each sample penalty term's weight (SamplePenalties::set_weight_scales).
  /// Throws std::invalid_argument unless every scale is finite and > 0.
  void set_penalty_scales(const PenaltyValues& scales);
  /// Tighter penalty thresholds (SamplePenalties::set_tightening). Throws
  /// std::invalid_argument unless the clearances and the joint margin are finite and >= 0 and
  /// the rate scale is in (0, 1].
  void set_tightening(const PenaltyTightening& tightening);
  /// Relaxed clearance thresholds near the start and the goal (SamplePenalties::
  /// set_endpoint_relief, at each sample's piece-index fraction; null: none, the default).
  /// The relief must outlive this object's evaluations.
  void set_endpoint_relief(const EndpointRelief* relief);
  const ObjectiveTerms& terms() const { return terms_; }
  /// A moving start (issue 18): the head's velocity and acceleration columns become
  /// [v, omega, qd] and [a, beta, qdd], so every trajectory of x joins the motion under way
  /// C2-continuously at t = 0. The head is data, not a decision variable: the gradient's form
  /// is unchanged. Default: at rest. Throws std::invalid_argument for rates that are not
  /// finite or whose joint vectors are neither empty nor N long.
  void set_start_rates(const WholeBodyRates& rates);
  /// PHR-ALM multiplier lambda (6) and penalty rho > 0 of the end-effector term.
  void set_multiplier(const Vector6d& lambda, double rho);
  /// Throws std::invalid_argument if the sizes do not match M (K + 1) samples and N joints.
  void set_path_reference(const PathReference& reference);
  /// Evaluate fails at once (returns false, stopped() true) once a stop is requested.
  void set_stop_token(std::stop_token stop) { stop_ = std::move(stop); }

  /// x from durations (M, > 0), inner waypoints (D x (M - 1): s, yaw, q in rad) and the free
  /// end (D: s_f, yaw_f, q_f); joints outside their limits are moved just inside (XiFromJoint).
  /// Throws std::invalid_argument for wrong sizes or non-finite values.
  Eigen::VectorXd Pack(const Eigen::VectorXd& durations_s, const Eigen::MatrixXd& waypoints,
                       const Eigen::VectorXd& end) const;
  /// The inverse of Pack (joints in rad). Allocation-free if the outputs are sized.
  void Unpack(const double* x, Eigen::VectorXd* durations_s, Eigen::MatrixXd* waypoints,
              Eigen::VectorXd* end) const;

  /// f(x) and, if gradient is non-null, df/dx (num_parameters()). Returns false if the
  /// trajectory cannot be built (non-finite values, a singular MINCO system from extreme
  /// durations, a failing evaluation) or if a stop was requested. Allocation-free.
  bool Evaluate(const double* x, double* cost, double* gradient) override;

  /// After a successful Evaluate: the cost's parts, the end-effector residual (always
  /// computed, whether the term is on or not) and the trajectory.
  const ObjectiveBreakdown& breakdown() const { return breakdown_; }
  const Vector6d& end_effector_residual() const { return end_effector_.residual(); }
  const ArcYawTrajectory& trajectory() const { return trajectory_; }
  const Eigen::MatrixXd& head() const { return head_; }
  const Eigen::MatrixXd& tail() const { return tail_; }
  const Eigen::MatrixXd& waypoints() const { return waypoints_; }
  const Eigen::VectorXd& durations_s() const { return durations_s_; }
  Eigen::Vector2d p0_W() const { return p0_W_; }
  bool stopped() const override { return stopped_; }
  int num_evaluations() const override { return num_evaluations_; }

 private:
  bool Decode(const double* x);
  bool AnyPenalty() const;
  /// Any term that needs forward kinematics (arm obstacle, self collision, chassis).
  bool NeedsGeometry() const;
  void AddSamples(bool with_gradient);
  void AddEndEffector(bool with_gradient);
  void WriteGradient(double* gradient) const;

  const Kinematics& kinematics_;
  TrajectoryObjectiveOptions options_;
  int num_pieces_;
  int num_joints_;
  ObjectiveTerms terms_;
  /// One per chunk of pieces (sample_chunks, at most M), each with its own penalties.
  std::vector<std::unique_ptr<PieceSampler>> samplers_;
  std::vector<char> sampler_finished_;  // per chunk: Run returned true
  EndEffectorAlmTerm end_effector_;  ///< PHR-ALM term of eq. (7).
  Eigen::Vector2d p0_W_;
  Vector6d lambda_ = Vector6d::Zero();
  double rho_ = 1.0;
  PathReference reference_;
  bool has_reference_ = false;
  std::stop_token stop_;
  bool stopped_ = false;
  int num_evaluations_ = 0;
  Eigen::VectorXd jerk_weights_;
  Eigen::VectorXd joint_min_rad_, joint_max_rad_;

  // Decoded decision vector.
  Eigen::MatrixXd head_, tail_, waypoints_;  // D x 3, D x 3, D x (M - 1)
  Eigen::VectorXd durations_s_, dT_dtau_;
  Eigen::MatrixXd dq_dxi_;  // N x M: inner waypoints 0..M-2, then the end

  ArcYawTrajectory trajectory_;
  // Gradient accumulators.
  Eigen::MatrixXd dC_dc_;   // 6M x D
  Eigen::VectorXd dC_dT_;   // M
  Eigen::Matrix2Xd dC_dp_;  // 2 x (MK + 1)
  Eigen::VectorXd dC_dend_direct_;  // D: the end-effector term's direct d/d(s_f, yaw_f, q_f)
  MincoGradient minco_gradient_;
  // End-effector scratch.
  WholeBodyState end_state_;
  ObjectiveBreakdown breakdown_;
};

}  // namespace topay
