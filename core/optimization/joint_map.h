#pragma once

namespace topay {

/// The sigmoid-like map that keeps a joint waypoint strictly inside its limits (TopAY paper
/// eq. (22)): with the ratio r = (q - q_min) / (q_max - q) in (0, inf) and the time map's
/// L_c2 (eq. (21), core/optimization/time_map.h),
///   xi = L_c2(r),   q(xi) = (q_min + q_max r) / (1 + r),  r = T(xi),
/// which for symmetric limits q_min = -q_max is the paper's xi = L_c2((q_max + q) / (q_max - q)).
/// Every real xi maps into the open interval (q_min, q_max); q(0) is the middle of the range.

/// q(xi) (rad); if dq_dxi is non-null, also dq/dxi = (q_max - q_min) / (1 + r)^2 * dr/dxi.
/// Requires finite limits with q_min < q_max; not checked here (hot path): callers check the
/// limits once at setup (XiFromJoint throws for bad ones).
double JointFromXi(double xi, double q_min_rad, double q_max_rad, double* dq_dxi = nullptr);

/// xi for a joint value q. q is first moved inside [q_min + e, q_max - e] with
/// e = interior_fraction x (q_max - q_min), so values on or past a limit map to a large but
/// finite xi. Throws std::invalid_argument for a non-finite q, limits that are not finite with
/// q_min < q_max, or interior_fraction outside (0, 0.5).
double XiFromJoint(double q_rad, double q_min_rad, double q_max_rad,
                   double interior_fraction = 1e-6);

}  // namespace topay
