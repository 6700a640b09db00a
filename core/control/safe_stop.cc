#include "core/control/safe_stop.h"

#include <algorithm>
#include <cmath>

namespace topay {
namespace {

// value moved towards 0 by at most step (never past it).
double TowardsZero(double value, double step) {
  return std::copysign(std::max(0.0, std::abs(value) - step), value);
}

}  // namespace

const char* TrackerModeName(TrackerMode mode) {
  switch (mode) {
    case TrackerMode::kTrack: return "track";
    case TrackerMode::kStopNoReference: return "stop (no reference)";
    case TrackerMode::kStopReferenceEnded: return "stop (reference ended)";
    case TrackerMode::kStopStaleState: return "stop (stale state)";
  }
  return "unknown";
}

TrackerMode ChooseTrackerMode(const TrackerSituation& situation, const NmpcOptions& options) {
  // NaN ages fail the comparison and count as stale.
  if (!(std::abs(situation.state_age_s) <= options.stale_state_s)) {
    return TrackerMode::kStopStaleState;
  }
  if (!situation.has_reference) return TrackerMode::kStopNoReference;
  if (!(situation.t_along_s <= situation.reference_duration_s + options.end_settle_s)) {
    return TrackerMode::kStopReferenceEnded;
  }
  return TrackerMode::kTrack;
}

void StopStep(const ControlCommand& last, double dt_s, const TrackerLimits& limits,
              ControlCommand* next) {
  next->v_mps = TowardsZero(last.v_mps, limits.base.a_max_mps2 * dt_s);
  next->omega_radps = TowardsZero(last.omega_radps, limits.base.beta_max_radps2 * dt_s);
  for (int j = 0; j < last.qd_radps.size(); ++j) {
    next->qd_radps(j) = TowardsZero(last.qd_radps(j), limits.qdd_max_radps2(j) * dt_s);
  }
}

void StopSequence(const ControlCommand& last, double dt_s, const TrackerLimits& limits,
                  InputSequence* sequence) {
  double v = last.v_mps;
  double omega = last.omega_radps;
  for (int k = 0; k < sequence->steps(); ++k) {
    v = TowardsZero(v, limits.base.a_max_mps2 * dt_s);
    omega = TowardsZero(omega, limits.base.beta_max_radps2 * dt_s);
    sequence->u_base(0, k) = v;
    sequence->u_base(1, k) = omega;
    for (int j = 0; j < sequence->num_joints(); ++j) {
      const double previous = k == 0 ? last.qd_radps(j) : sequence->qd_radps(j, k - 1);
      sequence->qd_radps(j, k) = TowardsZero(previous, limits.qdd_max_radps2(j) * dt_s);
    }
  }
}

double StopDurationS(const ControlCommand& last, const TrackerLimits& limits) {
  double duration = std::max(std::abs(last.v_mps) / limits.base.a_max_mps2,
                             std::abs(last.omega_radps) / limits.base.beta_max_radps2);
  for (int j = 0; j < last.qd_radps.size(); ++j) {
    duration = std::max(duration, std::abs(last.qd_radps(j)) / limits.qdd_max_radps2(j));
  }
  return duration;
}

}  // namespace topay
