#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"

namespace topay {

class EndpointRelief;

/// The inequality constraints of the TopAY problem (paper eqs. (9)-(14)), each turned into a
/// penalty on the trajectory's time samples (eq. (23)).
enum class PenaltyTerm : int {
  kVelocityOmega = 0,  ///< |v_max omega +- omega_max v| <= v_max omega_max, eq. (9).
  kAcceleration,       ///< a^2 <= a_max^2, eq. (10).
  kYawAcceleration,    ///< beta^2 <= beta_max^2, eq. (10).
  kJointPosition,      ///< q inside [q_min, q_max], eq. (11).
  kJointVelocity,      ///< q'^2 <= q'_max^2, eq. (11).
  kJointAcceleration,  ///< q''^2 <= q''_max^2, eq. (12).
  kBaseObstacle,       ///< Base cylinder on the 2D field, eq. (13).
  kArmObstacle,        ///< Every arm sphere on the 3D field, eq. (13).
  kSelfCollision,      ///< Self-collision sphere pairs, eq. (14).
  kChassis,            ///< Every arm sphere above the chassis top (the authors' code).
};
inline constexpr int kNumPenaltyTerms = 10;
std::string_view ToString(PenaltyTerm term);

/// One value per PenaltyTerm, indexed by static_cast<int>(term).
using PenaltyValues = std::array<double, kNumPenaltyTerms>;
using PenaltyMask = std::array<bool, kNumPenaltyTerms>;

inline PenaltyMask AllPenalties() {
  PenaltyMask mask;
  mask.fill(true);
  return mask;
}
inline PenaltyValues OnesPenaltyValues() {
  PenaltyValues values;
  values.fill(1.0);
  return values;
}
inline PenaltyMask NoPenalties() {
  PenaltyMask mask;
  mask.fill(false);
  return mask;
}

/// Weights, margins and smoothing of the sample penalties. Defaults: the authors' code's stage-2
/// figures (reference implementation), except where a field note says otherwise.
struct SamplePenaltyOptions {
  /// mu of the C2 smoothing (core/optimization/smooth_penalty.h), in the unit of each
  /// constraint value C (m^2/s^4 for a^2 - a_max^2, m for a distance, ...).
  double smoothing_mu = 1e-3;

  // Weights rho_c of eq. (23), per term.
  double velocity_omega_weight = 300.0;
  double acceleration_weight = 3000.0;
  double yaw_acceleration_weight = 3000.0;
  double joint_position_weight = 500.0;
  double joint_velocity_weight = 500.0;
  double joint_acceleration_weight = 500.0;
  double base_obstacle_weight = 5e5;
  double arm_obstacle_weight = 5e5;
  double self_collision_weight = 5e5;
  double chassis_weight = 5e5;  ///< Not in the authors' code; the self-collision weight.

  /// Terms evaluated (all by default); tests switch them one by one.
  PenaltyMask enabled = AllPenalties();

  /// Base cylinder: field2(x, y) >= base_radius_factor x radius + base_field_margin_m.
  /// r_thr of eq. (13): the authors' code's chassis factor 1.05.
  double base_radius_factor = 1.05;
  /// Arm sphere s: field3(p_WS) >= sphere_radius_factor x r_s + arm_field_margin_m (facts
  /// sheet: 1.1). The reference code also clamped radii below 0.055 m up to 0.055 m; not done
  /// here (the paper's radii).
  double sphere_radius_factor = 1.1;
  /// Extra clearance (m) on the 2D field. Unset: the field's exactness_margin_m(), the
  /// bound on how much the interpolated field can exceed the exact distance (the front end's
  /// WholeBodyValidity default), so that a sample the penalty leaves alone is exactly clear.
  /// Not in the reference code, whose success test did not use the exact geometry.
  std::optional<double> base_field_margin_m;
  /// Same for the arm spheres on the 3D field. Unset: sqrt(3) x the 3D field's resolution.
  std::optional<double> arm_field_margin_m;
  /// The rate constraints (v-omega, a, beta, q', q'') are penalised against this fraction of
  /// their limits: the penalty's optimum lies slightly beyond its threshold and the
  /// trajectory peaks between samples, by up to ~1 % in tests, which is all the validator's
  /// tolerance. Not in the reference code.
  double rate_limit_fraction = 0.98;
  /// Joint k: q_k stays this far (rad) inside [q_min, q_max] (the limits are hard in the
  /// validator, and the penalty's optimum lies slightly beyond its threshold). Not in the
  /// reference code. Must be below half of every joint's range.
  double joint_position_margin_rad = 0.01;
  /// Every self-collision pair: |p_i - p_j| - r_i - r_j >= self_margin_m.
  double self_margin_m = 0.01;
  /// Every arm sphere whose height the state can change: z_s - r_s - chassis top >=
  /// chassis_margin_m (spheres on links of fixed height, FixedHeightLinks, are left out: the
  /// TopAY shoulder's lowest sphere sits a constant 5 mm above the top). A margin for the
  /// tracker's joint errors: with 3 mm, link7 dipped 1.2 mm into the chassis top in the closed
  /// loop under load (tests/procs/mission/mission_graph_test.cc). Not in the reference code.
  double chassis_margin_m = 0.02;

  /// rho_c of a term.
  double Weight(PenaltyTerm term) const;
};

/// Throws std::invalid_argument naming the first option out of range (weights and margins
/// finite and >= 0, factors and smoothing_mu > 0, rate_limit_fraction in (0, 1]). The
/// SamplePenalties constructor calls it; the planner YAML loader too.
void CheckSamplePenaltyOptions(const SamplePenaltyOptions& options);

/// How much tighter than their options the penalties currently are: the optimizer tightens
/// them when a result violates a hard limit between two samples, where raising a weight does
/// not help (the samples already satisfy their constraint).
struct PenaltyTightening {
  double base_m = 0.0;     ///< Extra clearance of the base cylinder (m, >= 0).
  double arm_m = 0.0;      ///< Extra clearance of every arm sphere (m, >= 0).
  double joint_rad = 0.0;  ///< Extra joint position margin (rad, >= 0).
  double rate_scale = 1.0; ///< Factor on every rate limit (v-omega, a, beta, q', q''), (0, 1].
};

/// The trajectory's quantities at one time sample, as far as the penalties read them; also
/// used for the penalty's gradient with respect to each of them (same layout).
struct SampleQuantities {
  double x_m = 0.0;  ///< Base position p_WB (Simpson).
  double y_m = 0.0;
  double yaw_rad = 0.0;
  double v_mps = 0.0;        ///< s'
  double a_mps2 = 0.0;       ///< s''
  double omega_radps = 0.0;  ///< yaw'
  double beta_radps2 = 0.0;  ///< yaw''
  Eigen::VectorXd q_rad;       ///< N
  Eigen::VectorXd qd_radps;    ///< N
  Eigen::VectorXd qdd_radps2;  ///< N

  /// Zero everything, keeping the vectors' sizes (allocation-free).
  void SetZero();
};

/// The penalty of one time sample, P = sum over enabled terms and their constraints of
/// rho_c L(C) (eq. (23) without the time weight), and its gradient with respect to the
/// sample's quantities. Constraint values C (> 0 = violated; every rate limit below is the
/// caller's times rate_limit_fraction):
///   v-omega: (v_max omega +- omega_max v)^2 - (v_max omega_max)^2          (two, eq. (9))
///   a: a^2 - a_max^2;   beta: beta^2 - beta_max^2                          (eq. (10))
///   q_k: (q_k - m_k)^2 - h_k^2, m_k the middle of the range, h_k its half width minus
///        joint_position_margin_rad;
///   q'_k: q'_k^2 - q'_max,k^2;   q''_k: q''_k^2 - q''_max,k^2               (eqs. (11)-(12))
///   base: threshold - field2(x, y);  sphere s: threshold_s - field3(p_WS)  (eq. (13)),
///        each threshold + its tightening - its endpoint relief at the sample's u
///        (EndpointRelief, only with the Evaluate that takes u and a relief set); where
///        the base is relieved and the 2D field has a primary band, also
///        threshold + tightening - primary relief - primary2(x, y)
///   pair (i, j): margin - (|p_i - p_j| - r_i - r_j)                        (eq. (14))
///   chassis, sphere s: margin - (z_s - r_s - chassis top)
/// The sphere terms need forward kinematics (once per sample, only if one of the four
/// geometric arm terms is enabled); their gradients go through
/// Kinematics::AddPointJacobianTransposeTimes, only for violated constraints.
///
/// Construction allocates; Evaluate does not. Not thread-safe (scratch); one per thread. The
/// kinematics, fields and their model must outlive this object.
class SamplePenalties {
 public:
  /// Throws std::invalid_argument for non-positive or non-finite limits, weights < 0, mu <= 0,
  /// margins or factors that are not finite (naming the option).
  SamplePenalties(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                  const SignedDistanceField3& arm_field, const BaseLimits& base_limits,
                  const SamplePenaltyOptions& options);

  const SamplePenaltyOptions& options() const { return options_; }
  void set_enabled(const PenaltyMask& enabled) { options_.enabled = enabled; }
  /// Multiplies each term's weight (all 1 by default; the optimizer raises those of the
  /// constraints a result violates). Each must be finite and > 0 (not checked here).
  void set_weight_scales(const PenaltyValues& scales) { weight_scales_ = scales; }
  const PenaltyValues& weight_scales() const { return weight_scales_; }
  /// Tighter thresholds (none by default; values not checked here): the clearances grow by
  /// base_m and arm_m, the joint ranges shrink by joint_rad on each side (to at least
  /// 1 mrad of half range), every rate limit is multiplied by rate_scale.
  void set_tightening(const PenaltyTightening& tightening) { tightening_ = tightening; }
  const PenaltyTightening& tightening() const { return tightening_; }
  /// Relaxes the clearance thresholds near a start or goal inside them (none by default;
  /// null: none). Applies to the Evaluate that takes the sample's ramp coordinate u. The
  /// relief must outlive its use here; its sphere deficits are indexed like
  /// RobotModel::spheres.
  void set_endpoint_relief(const EndpointRelief* relief) { relief_ = relief; }
  const EndpointRelief* endpoint_relief() const { return relief_; }
  int num_joints() const { return kinematics_.num_joints(); }

  /// Quantities sized for this robot (allocates; reuse).
  SampleQuantities MakeQuantities() const;

  /// P for the sample at ramp coordinate u in [0, 1] (PieceFraction: (piece + local
  /// fraction) / M), with the endpoint relief at u if one is set. If gradient is non-null
  /// (sized by MakeQuantities) it is overwritten with dP/d(each quantity). If costs is
  /// non-null, each term's part of P is added to it. The relief is a constant at a given u,
  /// so the gradient has no part through it.
  double Evaluate(const SampleQuantities& sample, double u, SampleQuantities* gradient,
                  PenaltyValues* costs = nullptr);
  /// The same without any endpoint relief (whether one is set or not): the flatness baseline
  /// and the dense checks.
  double Evaluate(const SampleQuantities& sample, SampleQuantities* gradient,
                  PenaltyValues* costs = nullptr);

  /// The clearance thresholds (m) without the extra clearances: base, and per sphere.
  double base_threshold_m() const { return base_threshold_m_; }
  const Eigen::VectorXd& sphere_thresholds_m() const { return sphere_thresholds_m_; }
  /// The spheres penalised on the 3D field (SpheresToCheckOnArmField), increasing.
  const std::vector<int>& arm_field_spheres() const { return arm_field_spheres_; }
  const Kinematics& kinematics() const { return kinematics_; }
  const SignedDistanceField2& base_field() const { return base_field_; }
  const SignedDistanceField3& arm_field() const { return arm_field_; }

 private:
  bool enabled(PenaltyTerm term) const { return options_.enabled[static_cast<int>(term)]; }
  /// Adds w L(C) to the total and the term's cost; returns w L'(C) (0 if inactive).
  double Add(PenaltyTerm term, double constraint, double* total, PenaltyValues* costs) const;
  /// Both Evaluates: relief null for none.
  double EvaluateWith(const SampleQuantities& sample, const EndpointRelief* relief, double u,
                      SampleQuantities* gradient, PenaltyValues* costs);
  void EvaluateBase(const SampleQuantities& sample, const EndpointRelief* relief, double u,
                    SampleQuantities* gradient, double* total, PenaltyValues* costs);
  void EvaluateJoints(const SampleQuantities& sample, SampleQuantities* gradient, double* total,
                      PenaltyValues* costs);
  void EvaluateGeometry(const SampleQuantities& sample, const EndpointRelief* relief, double u,
                        SampleQuantities* gradient, double* total, PenaltyValues* costs);
  // The steps of EvaluateGeometry (cache_ holds the sample's kinematics): each adds its term
  // to *total and *costs and, with_gradient, its gradient to gradient_z_; true if it did.
  bool AddArmObstacle(const EndpointRelief* relief, double u, bool with_gradient, double* total,
                      PenaltyValues* costs);
  bool AddSelfCollision(bool with_gradient, double* total, PenaltyValues* costs);
  bool AddChassis(bool with_gradient, double* total, PenaltyValues* costs);

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  BaseLimits limits_;  // rate_limit_fraction x the caller's
  SamplePenaltyOptions options_;
  PenaltyValues weight_scales_ = OnesPenaltyValues();
  PenaltyTightening tightening_;
  const EndpointRelief* relief_ = nullptr;
  double base_threshold_m_ = 0.0;
  Eigen::VectorXd sphere_thresholds_m_;
  /// Spheres penalised on the 3D field: all but the rigid ones the base field covers
  /// (SpheresToCheckOnArmField; the base penalty keeps them clear).
  std::vector<int> arm_field_spheres_;
  /// Spheres penalised above the chassis: those whose height the state changes.
  std::vector<int> chassis_spheres_;
  Eigen::VectorXd qd_max_radps_;    // rate_limit_fraction x the joint limits
  Eigen::VectorXd qdd_max_radps2_;
  Eigen::VectorXd joint_middle_rad_;
  Eigen::VectorXd joint_half_range_rad_;
  // Scratch.
  WholeBodyState state_;
  KinematicsCache cache_;
  Eigen::VectorXd gradient_z_;  // dP/dz, z = [x, y, yaw, q]
};

}  // namespace topay
