#pragma once

#include "core/robot/robot_model.h"
#include "core/trajectory/trajectory_sample.h"
#include "core/validate/validation_report.h"

namespace topay {

/// Throws std::invalid_argument naming the field unless every base limit is finite and > 0,
/// and the joint limits have num_joints entries each with q_min < q_max (finite) and
/// finite positive rate limits.
void CheckKinematicLimits(const BaseLimits& base, const JointLimits& joints, int num_joints);

/// The largest value / limit ratio of one sample over the rate limits, eqs. (9)-(12):
/// |v| / v_max, |omega| / omega_max, the coupled ratio
///   max(|omega / omega_max + v / v_max|, |omega / omega_max - v / v_max|)
/// (eq. (9) divided by v_max omega_max), |a| / a_max, |beta| / beta_max, and per joint
/// |qd| / qd_max, |qdd| / qdd_max. Ties go to the first in Limit order. t_s is left NaN.
/// Allocation-free; the sample must have the limits' joint count.
LimitRatio WorstRateRatio(const TrajectorySample& sample, const BaseLimits& base,
                          const JointLimits& joints);

/// The joint position ratio |q - mid| / (half range), mid and half range of [q_min, q_max]
/// (1 on a limit; for symmetric limits eq. (11)'s |q| / q_max), largest over the joints.
LimitRatio WorstJointPositionRatio(const Eigen::VectorXd& q_rad, const JointLimits& joints);

/// How far the joint farthest outside [q_min, q_max] is beyond its limit (rad; <= 0 if all
/// are inside) and which joint (*joint).
double MaxJointPositionExcess(const Eigen::VectorXd& q_rad, const JointLimits& joints,
                              int* joint);

}  // namespace topay
