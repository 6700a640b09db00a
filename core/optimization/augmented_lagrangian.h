#pragma once

#include <string_view>

#include "core/optimization/pose_residual.h"

namespace topay {

/// PHR augmented Lagrangian on the end-effector equality constraint FK(s_f) = p_e (paper
/// eq. (7)), the outer loop both back ends (arc length-yaw and the flatness baseline) run
/// around their L-BFGS solves: minimise with (lambda, rho); lambda <- lambda + rho r;
/// rho <- min(gamma rho, beta), until |r| is within tolerance or the outer limit.
/// Defaults: the authors' code's "Trajectory optimizer figures" unless stated.
struct AugmentedLagrangianOptions {
  double rho_initial = 1e4;  ///< rho_0 (the authors' code).
  double rho_growth = 10.0;  ///< gamma: rho *= growth after every outer iteration...
  double rho_max = 1e10;     ///< beta: ...up to this.
  int max_outer_iterations = 8;
  /// The outer loop stops once |p_WE - p_goal| and the rotation angle are below these. Half
  /// of the success tolerances (BackEndOptions), so the end state keeps a margin (the facts
  /// sheet's 0.01 m is the success tolerance).
  double position_tolerance_m = 0.005;
  double orientation_tolerance_rad = 0.01;
};

/// Throws std::invalid_argument "<owner>: alm.<field> ..." naming the first field out of
/// range.
void CheckAugmentedLagrangianOptions(const AugmentedLagrangianOptions& options,
                                     std::string_view owner);

/// True if the residual r = (position m, rotation vector rad) is within the ALM tolerances.
bool AlmConverged(const AugmentedLagrangianOptions& options, const Vector6d& residual);

/// The PHR update of eq. (7): lambda += rho r, then rho = min(growth rho, rho_max).
void AlmUpdate(const AugmentedLagrangianOptions& options, const Vector6d& residual,
               Vector6d* lambda, double* rho);

}  // namespace topay
