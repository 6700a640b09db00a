#include "core/control/command_projection.h"

#include <algorithm>
#include <cmath>

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

bool InsideBoxes(const Eigen::Vector2d& u, const Eigen::Vector2d& u_prev, double dt_s,
                 const TrackerLimits& limits) {
  return std::abs(u(0)) <= limits.base.v_max_mps &&
         std::abs(u(1)) <= limits.base.omega_max_radps &&
         std::abs(u(0) - u_prev(0)) <= limits.base.a_max_mps2 * dt_s &&
         std::abs(u(1) - u_prev(1)) <= limits.base.beta_max_radps2 * dt_s;
}

}  // namespace

Eigen::Vector2d ProjectBaseInput(const Eigen::Vector2d& u, const Eigen::Vector2d& u_prev,
                                 double dt_s, const TrackerLimits& limits) {
  Eigen::Vector2d boxed;
  boxed(0) = ClampRateAndSpeed(u(0), u_prev(0), limits.base.a_max_mps2 * dt_s,
                               limits.base.v_max_mps);
  boxed(1) = ClampRateAndSpeed(u(1), u_prev(1), limits.base.beta_max_radps2 * dt_s,
                               limits.base.omega_max_radps);
  if (!limits.coupled_v_omega || CoupledRatio(boxed, limits) <= 1.0) return boxed;
  // Anchor: a point satisfying every limit; u_prev if it does, else the origin.
  const bool prev_feasible =
      CoupledRatio(u_prev, limits) <= 1.0 && InsideBoxes(u_prev, u_prev, dt_s, limits);
  const Eigen::Vector2d anchor = prev_feasible ? u_prev : Eigen::Vector2d::Zero();
  // Largest s in [0, 1] with anchor + s (boxed - anchor) inside the diamond (convex, so the
  // feasible s form an interval [0, s*]); bisection keeps `lo` feasible.
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (CoupledRatio(anchor + mid * (boxed - anchor), limits) <= 1.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return anchor + lo * (boxed - anchor);
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
