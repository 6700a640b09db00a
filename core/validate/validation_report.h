#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace topay {

/// What a validation failure is about.
enum class ValidationCheck {
  kNone,                    ///< No failure.
  kInput,                   ///< Bad duration, joint count, sampler, start state or goal pose.
  kSampler,                 ///< The sampler threw or resized the sample.
  kNonFinite,               ///< NaN or infinity in a sampled quantity.
  kStart,                   ///< The state at t = 0 is not the task's start state.
  kBaseCollision,           ///< Base cylinder vs a scene box (eq. (13)).
  kArmCollision,            ///< An arm sphere vs a scene box (eq. (13)).
  kSelfCollision,           ///< Two arm spheres of a self-collision pair (eq. (14)).
  kChassisCollision,        ///< An arm sphere below the chassis top (eq. (14)).
  kLimit,                   ///< A kinematic limit (eqs. (9)-(12)); see Limit.
  kEndNotAtRest,            ///< v, omega or a joint velocity not ~0 at the end (eqs. (18)-(20)).
  kEndEffectorPosition,     ///< End-effector position error at the end (eq. (7)).
  kEndEffectorOrientation,  ///< End-effector orientation error at the end (eq. (7)).
  kStopped,                 ///< The caller's stop (the plan's time limit) ended the check
                            ///< before the last sample: never a success.
};
std::string_view ToString(ValidationCheck check);

/// The limits, in the order they are evaluated at each sample.
enum class Limit {
  kNone,
  kJointPosition,       ///< q in [q_min, q_max] (eq. (11)); ratio |q - mid| / half range.
  kLinearVelocity,      ///< |v| <= v_max.
  kYawRate,             ///< |omega| <= omega_max.
  kCoupledVelocity,     ///< |v_max omega +- omega_max v| <= v_max omega_max (eq. (9)).
  kLinearAcceleration,  ///< |a| <= a_max (eq. (10)).
  kYawAcceleration,     ///< |beta| <= beta_max (eq. (10)).
  kJointVelocity,       ///< |qd| <= qd_max (eq. (11)).
  kJointAcceleration,   ///< |qdd| <= qdd_max (eq. (12)).
};
std::string_view ToString(Limit limit);

/// The first failure found: the earliest sample that fails, and within a sample the first
/// failing check in ValidationCheck order (for limits, the largest ratio of that sample).
struct ValidationFailure {
  ValidationCheck check = ValidationCheck::kNone;
  Limit limit = Limit::kNone;  ///< For kLimit.
  /// The sample time (s); NaN for input errors found before sampling.
  double t_s = std::numeric_limits<double>::quiet_NaN();
  /// Which part: sphere index (arm / chassis), self-collision pair index, joint index
  /// (limits, start, end at rest, non-finite q, qd, qdd); -1 if not applicable (the base).
  int index = -1;
  int box = -1;  ///< For kBaseCollision and kArmCollision: index in Scene::boxes.
  double value = std::numeric_limits<double>::quiet_NaN();      ///< What was measured...
  double threshold = std::numeric_limits<double>::quiet_NaN();  ///< ...and the bound it broke.
  std::string message;  ///< One line: what, which part, when, value vs bound.
};

/// A limit ratio value / limit (1 = at the limit) and where it occurred.
struct LimitRatio {
  double ratio = 0.0;
  Limit limit = Limit::kNone;
  int joint = -1;  ///< For joint limits.
  double t_s = std::numeric_limits<double>::quiet_NaN();
  double value = 0.0;  ///< The quantity (m/s, rad/s, ... ; for kCoupledVelocity the ratio).
  double bound = 0.0;  ///< Its limit.
};

/// Smallest clearance (m) found and where. For obstacles, sphere = -1 means the base
/// cylinder; for self collision, `part` is the self-collision pair index; for the chassis,
/// the sphere index.
struct ClearanceRecord {
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double clearance_m = kInfinity;  ///< +infinity if nothing was ever near (or nothing to check).
  int part = -1;                   ///< Sphere (-1: base cylinder) or pair index.
  int box = -1;                    ///< Obstacles only: index in Scene::boxes.
  double t_s = std::numeric_limits<double>::quiet_NaN();
  std::string name;                ///< Readable part name, e.g. "sphere 5 (link4)".
};

/// Outcome of TrajectoryValidator::Validate.
struct ValidationReport {
  bool ok = false;
  ValidationFailure first_failure;  ///< check kNone if ok.
  int num_failed_samples = 0;       ///< Samples with at least one failing check.
  int num_samples = 0;              ///< Samples evaluated (t = 0, period, ..., the end).
  /// The caller's stop ended the check early (then ok is false, whatever was checked).
  bool stopped = false;
  double duration_s = 0.0;

  ClearanceRecord min_obstacle;  ///< Base cylinder and every sphere vs the scene's boxes.
  ClearanceRecord min_self;      ///< Self-collision pairs: |p_i - p_j| - r_i - r_j.
  ClearanceRecord min_chassis;   ///< Arm spheres above the chassis top: z - r - height.
  LimitRatio worst_limit;        ///< Largest value / limit over every limit and sample.

  /// End effector at the end vs the goal: |p_end - p_goal| and the angle of
  /// R_goal^T R_end. NaN if not computed (non-finite end state or input error).
  double end_position_error_m = std::numeric_limits<double>::quiet_NaN();
  double end_orientation_error_rad = std::numeric_limits<double>::quiet_NaN();

  /// Readable multi-line summary: verdict, first failure, clearances, worst limit, end error.
  std::string Report() const;
};

}  // namespace topay
