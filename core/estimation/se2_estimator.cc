#include "core/estimation/se2_estimator.h"

#include <cmath>

#include "core/common/stamp_difference.h"
#include "core/estimation/pose_update.h"
#include "core/estimation/se2_motion.h"

namespace topay {
namespace {

constexpr double kSecondsPerUs = 1e-6;

}  // namespace

const char* EstimatorInputName(EstimatorInput input) {
  switch (input) {
    case EstimatorInput::kApplied: return "applied";
    case EstimatorInput::kAppliedDelayed: return "applied (delayed)";
    case EstimatorInput::kRejectedNotFinite: return "not finite";
    case EstimatorInput::kRejectedOutOfOrder: return "out of order";
    case EstimatorInput::kRejectedTooOld: return "too old";
  }
  return "?";
}

const char* PoseOutcomeName(PoseOutcome outcome) {
  switch (outcome) {
    case PoseOutcome::kNone: return "none";
    case PoseOutcome::kInitialised: return "initialised";
    case PoseOutcome::kAccepted: return "accepted";
    case PoseOutcome::kGated: return "gated";
    case PoseOutcome::kReinitialised: return "reinitialised";
  }
  return "?";
}

Se2Estimator::Se2Estimator(const EstimatorOptions& options)
    : options_((options.Check(), options)), R_(PoseMeasurementNoise(options)), events_(options.history_capacity) {}

const EstimatorBelief& Se2Estimator::Newest() const { return events_.empty() ? base_ : events_.back().after; }

EstimatorInput Se2Estimator::AddOdometry(std::int64_t t_us, double v_mps, double omega_radps) {
  if (!std::isfinite(v_mps) || !std::isfinite(omega_radps)) {
    ++summary_.odometry_not_finite;
    return EstimatorInput::kRejectedNotFinite;
  }
  if (any_odometry_ && t_us <= last_odometry_t_us_) {  // dt <= 0 within the stream
    ++summary_.odometry_out_of_order;
    return EstimatorInput::kRejectedOutOfOrder;
  }
  Event event;
  event.t_us = t_us;
  event.kind = Kind::kOdometry;
  event.value = Eigen::Vector3d(v_mps, omega_radps, 0.0);
  const EstimatorInput result = Insert(event);
  if (result == EstimatorInput::kRejectedTooOld) {
    ++summary_.odometry_too_old;
    return result;
  }
  ++summary_.odometry_applied;
  any_odometry_ = true;
  last_odometry_t_us_ = t_us;
  return result;
}

EstimatorInput Se2Estimator::AddPose(std::int64_t t_us, const Eigen::Vector3d& z_WB) {
  last_pose_outcome_ = PoseOutcome::kNone;
  if (!z_WB.allFinite()) {
    ++summary_.poses_not_finite;
    return EstimatorInput::kRejectedNotFinite;
  }
  if (any_pose_ && t_us <= last_pose_t_us_) {
    ++summary_.poses_out_of_order;
    return EstimatorInput::kRejectedOutOfOrder;
  }
  Event event;
  event.t_us = t_us;
  event.kind = Kind::kPose;
  event.value = z_WB;
  const EstimatorInput result = Insert(event);
  if (result == EstimatorInput::kRejectedTooOld) {
    ++summary_.poses_too_old;
    return result;
  }
  any_pose_ = true;
  last_pose_t_us_ = t_us;
  return result;
}

EstimatorInput Se2Estimator::Insert(const Event& event) {
  const std::int64_t newest_t_us = Newest().t_us;
  const auto max_delay_us = static_cast<std::int64_t>(options_.max_delay_s * 1e6);
  if (event.t_us < base_.t_us || StampDifferenceUs(newest_t_us, event.t_us) > max_delay_us) return EstimatorInput::kRejectedTooOld;
  // Position: after every event at or before its time (equal stamps keep their arrival order).
  int i = events_.size();
  while (i > 0 && events_[i - 1].t_us > event.t_us) --i;
  if (events_.full()) {
    if (i == 0) return EstimatorInput::kRejectedTooOld;  // the state before it is no longer kept
    base_ = events_[0].after;
    events_.PopFront();
    --i;
  }
  events_.Insert(i, event);
  // Apply it and re-apply every later event from the stored state before it.
  for (int k = i; k < events_.size(); ++k) {
    const EstimatorBelief& before = k == 0 ? base_ : events_[k - 1].after;
    if (k > i) Count(events_[k], -1);
    Apply(before, &events_[k]);
    Count(events_[k], +1);
  }
  if (event.kind == Kind::kPose) {
    last_pose_outcome_ = events_[i].outcome;
    summary_.last_mahalanobis2 = events_[i].mahalanobis2;
  }
  const int replayed = events_.size() - 1 - i;
  if (replayed == 0) return EstimatorInput::kApplied;
  ++summary_.delayed_inputs;
  summary_.replayed_events += replayed;
  return EstimatorInput::kAppliedDelayed;
}

void Se2Estimator::Apply(const EstimatorBelief& before, Event* event) const {
  EstimatorBelief belief = before;
  Propagate(event->t_us, &belief);
  event->outcome = PoseOutcome::kNone;
  event->mahalanobis2 = 0.0;
  if (event->kind == Kind::kOdometry) {
    belief.v_mps = event->value.x();  // holds from this time on (zero-order hold)
    belief.omega_radps = event->value.y();
    belief.has_odometry = true;
  } else {
    ApplyPose(event, &belief);
  }
  event->after = belief;
}

void Se2Estimator::ApplyPose(Event* event, EstimatorBelief* b) const {
  const Eigen::Vector3d& z_WB = event->value;
  if (!b->initialised) {  // the first pose: start from it, with its own uncertainty
    b->X_WB = z_WB;
    b->P_WB = R_;
    b->initialised = true;
    b->consecutive_rejections = 0;
    event->outcome = PoseOutcome::kInitialised;
    return;
  }
  const Eigen::Vector3d nu = PoseInnovation(z_WB, b->X_WB);
  event->mahalanobis2 = PoseMahalanobis2(nu, b->P_WB, R_);
  if (event->mahalanobis2 <= options_.gate_chi2) {
    UpdatePose(z_WB, R_, &b->X_WB, &b->P_WB);
    b->consecutive_rejections = 0;
    event->outcome = PoseOutcome::kAccepted;
    return;
  }
  if (++b->consecutive_rejections < options_.reinit_after_rejections) {
    event->outcome = PoseOutcome::kGated;
    return;
  }
  // The localisation has disagreed reinit_after_rejections times in a row: the filter is the
  // one that is wrong (a wrong start, a relocalisation). Start again from this pose.
  b->X_WB = z_WB;
  b->P_WB = R_;
  b->consecutive_rejections = 0;
  event->outcome = PoseOutcome::kReinitialised;
}

void Se2Estimator::Propagate(std::int64_t t_us, EstimatorBelief* b) const {
  const double dt_s = static_cast<double>(StampDifferenceUs(t_us, b->t_us)) * kSecondsPerUs;
  if (b->initialised && dt_s > 0.0) {
    PredictPose(OdometryIncrement{b->v_mps, b->omega_radps, dt_s}, options_, &b->X_WB, &b->P_WB);
  }
  if (t_us > b->t_us) b->t_us = t_us;
}

void Se2Estimator::Count(const Event& event, int sign) {
  switch (event.outcome) {
    case PoseOutcome::kNone: break;
    case PoseOutcome::kInitialised: summary_.poses_initialised += sign; break;
    case PoseOutcome::kAccepted: summary_.poses_accepted += sign; break;
    case PoseOutcome::kGated: summary_.poses_gated += sign; break;
    case PoseOutcome::kReinitialised: summary_.reinitialisations += sign; break;
  }
}

void Se2Estimator::Reset(std::int64_t t_us, const Eigen::Vector3d& X_WB, const Eigen::Matrix3d& P_WB) {
  const EstimatorBelief newest = Newest();
  events_.Clear();
  base_ = newest;
  base_.t_us = t_us;
  base_.X_WB = X_WB;
  base_.P_WB = P_WB;
  base_.initialised = true;
  base_.consecutive_rejections = 0;
}

bool Se2Estimator::EstimateAt(std::int64_t t_us, PoseEstimate* estimate) const {
  EstimatorBelief b = Newest();
  if (!b.initialised) return false;
  Propagate(t_us, &b);
  estimate->t_us = b.t_us;
  estimate->X_WB = b.X_WB;
  estimate->P_WB = b.P_WB;
  return true;
}

}  // namespace topay
