#include "core/control/command_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace topay {
namespace {

constexpr double kMovedTolerance = 1e-9;

// Clamps value into [lo, hi] = [prev - rate dt, prev + rate dt] intersected with
// [-max, max]; if they do not intersect, the speed bound nearest prev.
double ClampRateAndSpeed(double value, double prev, double rate_dt, double max) {
  const double lo = std::max(-max, prev - rate_dt);
  const double hi = std::min(max, prev + rate_dt);
  if (lo > hi) return std::clamp(prev, -max, max);
  return std::clamp(value, lo, hi);
}

// |v| / v_max + |omega| / omega_max: the coupled ratio of eq. (9).
double CoupledRatio(const Eigen::Vector2d& u, const TrackerLimits& limits) {
  return std::abs(u(0)) / limits.base.v_max_mps + std::abs(u(1)) / limits.base.omega_max_radps;
}


// The box B = rate window intersected with the speed box, per coordinate: [lo, hi]; when
// they do not intersect, the speed bound nearest prev (both ends).
struct Interval {
  double lo;
  double hi;
};

Interval RateAndSpeedInterval(double prev, double rate_dt, double max) {
  Interval interval{std::max(-max, prev - rate_dt), std::min(max, prev + rate_dt)};
  if (interval.lo > interval.hi) interval.lo = interval.hi = std::clamp(prev, -max, max);
  return interval;
}

// Parameters s of p0 + s d (d != 0 in this coordinate or not) with lo <= coordinate <= hi,
// intersected into [*s_lo, *s_hi].
void ClipLine(double p0, double d, const Interval& box, double* s_lo, double* s_hi) {
  if (d == 0.0) {
    if (p0 < box.lo || p0 > box.hi) *s_hi = -1.0;  // empty
    return;
  }
  double a = (box.lo - p0) / d;
  double b = (box.hi - p0) / d;
  if (a > b) std::swap(a, b);
  *s_lo = std::max(*s_lo, a);
  *s_hi = std::min(*s_hi, b);
}

}  // namespace

Eigen::Vector2d ProjectBaseInput(const Eigen::Vector2d& u, const Eigen::Vector2d& u_prev,
                                 double dt_s, const TrackerLimits& limits) {
  const double v_max = limits.base.v_max_mps;
  const double omega_max = limits.base.omega_max_radps;
  const Interval box_v = RateAndSpeedInterval(u_prev(0), limits.base.a_max_mps2 * dt_s, v_max);
  const Interval box_w =
      RateAndSpeedInterval(u_prev(1), limits.base.beta_max_radps2 * dt_s, omega_max);
  // The Euclidean projection onto the box B.
  const Eigen::Vector2d boxed(std::clamp(u(0), box_v.lo, box_v.hi),
                              std::clamp(u(1), box_w.lo, box_w.hi));
  if (!limits.coupled_v_omega || CoupledRatio(boxed, limits) <= 1.0) return boxed;
  // Otherwise the projection onto B and the diamond D lies on D's boundary (were it inside
  // D, it would be the projection onto B): the nearest point of the four faces clipped to B.
  // Face (sv, sw): p(s) = (sv v_max (1 - s), sw omega_max s), s in [0, 1].
  Eigen::Vector2d best = Eigen::Vector2d::Zero();
  double best_distance = std::numeric_limits<double>::infinity();
  for (const double sv : {-1.0, 1.0}) {
    for (const double sw : {-1.0, 1.0}) {
      const Eigen::Vector2d p0(sv * v_max, 0.0);
      const Eigen::Vector2d d(-sv * v_max, sw * omega_max);
      double s_lo = 0.0;
      double s_hi = 1.0;
      ClipLine(p0(0), d(0), box_v, &s_lo, &s_hi);
      ClipLine(p0(1), d(1), box_w, &s_lo, &s_hi);
      if (s_lo > s_hi) continue;  // the face misses B
      const double s = std::clamp((u - p0).dot(d) / d.squaredNorm(), s_lo, s_hi);
      const Eigen::Vector2d point = p0 + s * d;
      const double distance = (point - u).squaredNorm();
      if (distance < best_distance) {
        best_distance = distance;
        best = point;
      }
    }
  }
  if (std::isfinite(best_distance)) {
    // Rounding may leave the point 1 ulp outside the speed box.
    return Eigen::Vector2d(std::clamp(best(0), -v_max, v_max),
                           std::clamp(best(1), -omega_max, omega_max));
  }
  // B misses D entirely (u_prev far outside the limits): limits before rates, the boxed
  // point scaled into D.
  return boxed / CoupledRatio(boxed, limits);
}

double ProjectJointVelocity(double qd, double qd_prev, double dt_s, double qd_max,
                            double qdd_max) {
  return ClampRateAndSpeed(qd, qd_prev, qdd_max * dt_s, qd_max);
}

int ProjectInputSequence(const ControlCommand& last, double first_dt_s, double step_s,
                         const TrackerLimits& limits, InputSequence* inputs) {
  int moved = 0;
  Eigen::Vector2d u_prev(last.v_mps, last.omega_radps);
  for (int k = 0; k < inputs->steps(); ++k) {
    const double dt_s = k == 0 ? first_dt_s : step_s;
    const Eigen::Vector2d u = inputs->u_base.col(k);
    const Eigen::Vector2d projected = ProjectBaseInput(u, u_prev, dt_s, limits);
    moved += (std::abs(projected(0) - u(0)) > kMovedTolerance) +
             (std::abs(projected(1) - u(1)) > kMovedTolerance);
    inputs->u_base.col(k) = projected;
    u_prev = projected;
    for (int j = 0; j < inputs->num_joints(); ++j) {
      const double prev = k == 0 ? last.qd_radps(j) : inputs->qd_radps(j, k - 1);
      const double qd = inputs->qd_radps(j, k);
      const double clamped = ProjectJointVelocity(qd, prev, dt_s, limits.qd_max_radps(j),
                                                  limits.qdd_max_radps2(j));
      moved += std::abs(clamped - qd) > kMovedTolerance;
      inputs->qd_radps(j, k) = clamped;
    }
  }
  return moved;
}

double WorstInputLimitRatio(const ControlCommand& last, double first_dt_s, double step_s,
                            const TrackerLimits& limits, const InputSequence& inputs) {
  double worst = 0.0;
  Eigen::Vector2d u_prev(last.v_mps, last.omega_radps);
  for (int k = 0; k < inputs.steps(); ++k) {
    const double dt_s = k == 0 ? first_dt_s : step_s;
    const Eigen::Vector2d u = inputs.u_base.col(k);
    worst = std::max({worst, std::abs(u(0)) / limits.base.v_max_mps,
                      std::abs(u(1)) / limits.base.omega_max_radps,
                      std::abs(u(0) - u_prev(0)) / (limits.base.a_max_mps2 * dt_s),
                      std::abs(u(1) - u_prev(1)) / (limits.base.beta_max_radps2 * dt_s)});
    if (limits.coupled_v_omega) worst = std::max(worst, CoupledRatio(u, limits));
    u_prev = u;
    for (int j = 0; j < inputs.num_joints(); ++j) {
      const double prev = k == 0 ? last.qd_radps(j) : inputs.qd_radps(j, k - 1);
      const double qd = inputs.qd_radps(j, k);
      worst = std::max({worst, std::abs(qd) / limits.qd_max_radps(j),
                        std::abs(qd - prev) / (limits.qdd_max_radps2(j) * dt_s)});
    }
  }
  return worst;
}

}  // namespace topay
