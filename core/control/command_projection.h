#pragma once

#include <Eigen/Core>

#include "core/control/control_command.h"
#include "core/control/tracker_limits.h"

namespace topay {

/// The last step of every solve: whatever the optimizer (whose rate and coupled limits are
/// penalties) returned, each input is moved into the set the limits allow given the input
/// before it (u_prev, dt_s earlier):
///   |v| <= v_max, |omega| <= omega_max,             (speed box)
///   |v - v_prev| <= a_max dt, |omega - omega_prev| <= beta_max dt,   (rate box)
///   |v| / v_max + |omega| / omega_max <= 1          (coupled, eq. (9), if enabled).
/// The result is the Euclidean projection of u onto that convex polygon: the box clamp when
/// it satisfies the coupled bound, else the nearest point of the diamond's faces inside the
/// boxes. When u_prev is so far out of the speed box that the rate and speed boxes do not
/// intersect, the speed box wins (limits before rates); when the boxes miss the diamond, the
/// diamond wins.
Eigen::Vector2d ProjectBaseInput(const Eigen::Vector2d& u, const Eigen::Vector2d& u_prev,
                                 double dt_s, const TrackerLimits& limits);

/// One joint: |qd| <= qd_max and |qd - qd_prev| <= qdd_max dt (the speed limit wins when the
/// two do not intersect).
double ProjectJointVelocity(double qd, double qd_prev, double dt_s, double qd_max,
                            double qdd_max);

/// Projects every input of *inputs in order: step 0 against `last` (first_dt_s earlier),
/// step k against step k - 1 (step_s). Returns how many scalar inputs moved by > 1e-9.
int ProjectInputSequence(const ControlCommand& last, double first_dt_s, double step_s,
                         const TrackerLimits& limits, InputSequence* inputs);

/// The largest value / limit ratio of a sequence over every limit above (speeds, coupled,
/// rates against the input before, joint velocities and accelerations): <= 1 when it is
/// feasible. For tests and the status.
double WorstInputLimitRatio(const ControlCommand& last, double first_dt_s, double step_s,
                            const TrackerLimits& limits, const InputSequence& inputs);

}  // namespace topay
