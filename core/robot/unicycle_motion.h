#pragma once

#include "core/robot/whole_body_state.h"

namespace topay {

/// Moves the base of `state` (x_m, y_m, yaw_rad) exactly as a unicycle driven at constant
/// forward speed v_mps and yaw rate omega_radps for dt_s seconds: along the arc of radius
/// v / omega (a straight line when |omega| < 1e-9 rad/s), yaw wrapped to [-pi, pi]. The
/// joints are left alone. Used by the simulators (sim/plant, procs/kinematic_sim).
void AdvanceUnicycle(double v_mps, double omega_radps, double dt_s, WholeBodyState* state);

}  // namespace topay
