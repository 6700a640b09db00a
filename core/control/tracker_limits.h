#pragma once

#include <Eigen/Core>

#include "core/robot/robot_model.h"

namespace topay {

/// The limits every command of the tracker satisfies (see docs/control.md).
///
/// The robot config (config/robot/topay_mm.yaml) has no coupled v-omega field of its own: the
/// stack's coupled bound is the paper's eq. (9) built from v_max and omega_max,
///   |v| / v_max + |omega| / omega_max <= 1,
/// which the validator (core/validate/limit_ratios.h) and the simulated plant enforce, so the
/// tracker enforces it too (`coupled_v_omega`, on by default from a RobotModel).
struct TrackerLimits {
  BaseLimits base;                 ///< v_max, a_max, omega_max, beta_max.
  Eigen::VectorXd qd_max_radps;    ///< Joint velocity limits (N, symmetric).
  Eigen::VectorXd qdd_max_radps2;  ///< Joint acceleration limits (N, symmetric).
  bool coupled_v_omega = true;     ///< Enforce eq. (9)'s diamond |v|/v_max + |omega|/omega_max <= 1.

  int num_joints() const { return static_cast<int>(qd_max_radps.size()); }
  /// Throws std::invalid_argument naming the field unless every limit is finite and > 0
  /// and the joint vectors have equal sizes.
  void Check() const;
};

/// The robot's rate limits as the tracker uses them (coupled bound on).
TrackerLimits MakeTrackerLimits(const RobotModel& robot);

}  // namespace topay
