#pragma once

#include <optional>
#include <string>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

class EndpointRelief;

/// Options of CheckFeasibilityOnFields: the hard version of the optimizer's constraints.
struct FieldFeasibilityOptions {
  /// Samples at 0, period, 2 period, ... and at the end (the independent validator's 10 ms).
  double sample_period_s = 0.01;
  /// Rate limits pass while |value| / limit <= 1 + rate_tolerance (the validator's 1 %).
  double rate_tolerance = 0.01;
  /// Joints must lie within [q_min - tol, q_max + tol].
  double joint_position_tolerance_rad = 1e-9;
  /// Base: field2(p_WB) >= radius + base_field_margin_m; unset: the field's
  /// exactness_margin_m() (then field-feasible means exactly clear of the boxes the field was built
  /// from, see core/planning/whole_body_validity.h). No safety factor: that is the penalty's.
  std::optional<double> base_field_margin_m;
  /// Arm spheres: field3(p_WS) >= r_s + arm_field_margin_m; unset: sqrt(3) x resolution.
  std::optional<double> arm_field_margin_m;
  /// Self-collision pairs and arm-above-chassis clearances must be >= these (m; exact).
  double self_margin_m = 0.0;
  double chassis_margin_m = 0.0;
};

/// What CheckFeasibilityOnFields found. Clearances are reported beyond their requirement
/// (< 0: violated); the first violation in time is described in words.
struct FieldFeasibilityReport {
  bool feasible = true;
  /// E.g. "base clearance off by 0.0310 m at t = 2.350 s".
  std::string first_violation;
  double min_base_clearance_m = 1e9;
  double min_arm_clearance_m = 1e9;
  double min_self_clearance_m = 1e9;
  double min_chassis_clearance_m = 1e9;
  double max_rate_ratio = 0.0;  ///< Largest |value| / limit (coupled v-omega included).
  std::string worst_rate;       ///< Which one: "v-omega", "a", "beta", "qd3", ...
  double max_joint_excess_rad = -1e9;  ///< Largest distance of a joint beyond a limit.
  int num_samples = 0;
};

/// The violated requirements of a report, worst first within each kind, e.g. "arm clearance
/// short by 0.251 m; a at 4.96 x its limit"; empty if feasible.
std::string DescribeViolations(const FieldFeasibilityReport& report,
                               const FieldFeasibilityOptions& options = {});

/// Samples the trajectory densely and checks what the optimizer penalises, without smoothing,
/// safety factors or penalty margins, on the same distance fields: the rate limits (eq. (9)'s
/// coupled v-omega, a, beta, q', q''), joint position limits, base and arm clearance on the
/// fields, self-collision pairs and arm above the chassis. The optimizer's own success test;
/// the exact-geometry validator (core/validate) is the independent one.
/// With an endpoint relief (the optimizer's, EndpointRelief) the base and arm-sphere
/// requirements near the start and the goal are radius + margin - relief(u), u the sample's
/// piece-index fraction (piece j of M, local time tau: (j + tau / T_j) / M), and the report's
/// clearances are beyond those relieved requirements; null or empty: no relief.
/// Throws std::invalid_argument for a non-positive period or tolerance.
FieldFeasibilityReport CheckFeasibilityOnFields(const ArcYawTrajectory& trajectory,
                                                const Kinematics& kinematics,
                                                const SignedDistanceField2& base_field,
                                                const SignedDistanceField3& arm_field,
                                                const BaseLimits& base_limits,
                                                const FieldFeasibilityOptions& options = {},
                                                const EndpointRelief* relief = nullptr);

}  // namespace topay
